// Footfall — how the animation follows the ground under a plan: each planted
// sole on its foothold and along its slope, each swinging foot lifted clear of
// the ground between its footholds (a tread's nosing, a kerb), the body riding
// up and down with its feet, and the upper body leaning into a climb. The
// model is documented in docs/animation.md; the add-on's Apply and the
// headless writer both use this one.
#pragma once

#include <array>
#include <map>

#include "footfall/ground/ground.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall::animate {

constexpr double kSwingClearance = 0.05;  ///< [m] a climbing swing's sole over the ground it passes
constexpr double kLeanShare = 0.3;        ///< of the climb's angle the upper body leans by
constexpr double kMostLean = 0.21;        ///< [rad] 12 deg: the most forward lean
constexpr double kMostLeanBack = 0.087;   ///< [rad] 5 deg: the most backward lean, going down
constexpr double kLeanWindow = 0.3;       ///< [s] the climb is measured over this either side

/// A rig's foot seen from above, in the plan's metres: its heel behind the
/// point under the ankle, its toe tip ahead of it, and its width.
struct FootExtent {
  double heel_back = 0;
  double toe_ahead = 0;
  double width = 0;
};

/// A foot on the ground at one instant.
struct FootOnGround {
  Vec3 sole;            ///< The sole's point under the ankle. [m]
  double heading = 0;   ///< Which way the foot points. [rad]
  Vec3 normal{0, 0, 1};  ///< The sole's plane: the ground's where planted. Unit.
};

/// The ground's part in one agent's motion. Without ground (Ground::empty)
/// the feet are the plan's, their lift straight up, the body on z = 0.
class GroundFollower {
 public:
  /// `character`: the agent's (its body's height is the headroom its ground
  /// must have).
  GroundFollower(const AgentPlan& plan, const CharacterParams& character, const Ground& ground,
                 FootExtent foot);

  /// The foot `pose` (one of feet_at's) on the ground. Planted: on the
  /// standable ground under it, along its slope. Swinging: on the plan's arc
  /// from foothold to foothold where that clears the ground the foot passes
  /// over; else (up a stair, over a kerb) it rises first, crosses at
  /// kSwingClearance over the highest ground on its way, and comes down onto
  /// its foothold, its travel overlapping the rise and the fall as far as
  /// the ground lets it. Its sole turns from one foothold's slope to the other's.
  FootOnGround foot(const FootPose& pose) const;
  /// The height of the ground the body rides over with `feet` (feet_at's):
  /// the mean of its feet's grounds, a swinging foot's passing from one
  /// foothold's to the other's as it travels. [m]
  double body_height(const std::array<FootPose, 2>& feet) const;
  /// How far the upper body leans forward at `t` [rad, back negative]:
  /// kLeanShare of the angle the body climbs at over kLeanWindow either side
  /// (its rise over its travel, the travel taken as at least 0.3 m, so that
  /// a body standing on a stair does not lean), within kMostLean forward and
  /// kMostLeanBack back.
  double lean(double t) const;

 private:
  /// A swing's vertical course: its footholds' heights and normals, and how
  /// it clears the ground between.
  struct Swing {
    double from_z = 0, to_z = 0;
    Vec3 from_normal{0, 0, 1}, to_normal{0, 0, 1};
    bool rises = false;       ///< False: the plan's arc clears the ground.
    double top = 0;           ///< Rising: the height it crosses at. [m]
    double travel_start = 0;  ///< Rising: the phase its travel starts at (ends at 1 - it).
  };
  const Swing& swing_of(const FootPose& pose) const;
  Swing plan_swing(const FootPose& pose) const;
  /// Where a swinging foot is at phase u by `swing`'s course.
  FootOnGround swinging(const FootPose& pose, const Swing& swing, double u) const;
  /// The highest ground under the foot at `sole` turned to `heading`, below `ceiling`.
  double highest_under(Vec3 sole, double heading, double ceiling) const;
  /// The standable ground under a foot at `p`: of its levels, the nearest
  /// `near` (the plan's height for the foot; 0 where there is none).
  GroundPoint under(Vec2 p, double near) const;

  const AgentPlan& plan_;
  const Ground& ground_;
  FootExtent extent_;
  double headroom_;
  /// Each swing's course, found once: keyed by its ends and their heights.
  mutable std::map<std::array<double, 6>, Swing> swings_;
};

}  // namespace footfall::animate
