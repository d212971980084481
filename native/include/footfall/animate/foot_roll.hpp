// Footfall — heel-toe roll: the foot's pitch through each stance and swing,
// and where the ankle goes so that the point the foot rolls on stays put.
// The model is documented in docs/animation.md; the add-on's Apply and the
// headless writer both use this one (core/foot_roll.py calls it).
#pragma once

#include <vector>

#include "footfall/ground/foothold.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall::animate {

constexpr double kHeelStrike = 0.2617993877991494;  ///< 15 deg: toes up at heel strike, at full speed
constexpr double kToeOff = 0.5235987755982988;      ///< 30 deg: heel up at toe-off, at full speed
constexpr double kFlatAt = 0.15;     ///< of the stance: the foot is flat from here
constexpr double kHeelOffAt = 0.6;   ///< of the stance: the heel rises from here
/// [m] a step landing this much above or below the other foot is a stair's:
/// the foot is set down flat, as people do on stairs (no heel strike, no roll).
constexpr double kStairRise = 0.02;
/// Per footstep of `plan`: +1 where it climbs a stair (a walking step whose
/// foot lands over kStairRise above where that foot last stood), -1 where it
/// goes down one, 0 elsewhere. Sections of such steps play a rig's own stair
/// clips, where it has them.
std::vector<int> stair_climbs(const AgentPlan& plan);

/// Of the foot's length behind the ankle, without a mesh: as the planner's sole.
constexpr double kHeelShare = footfall::kHeelShare;

/// The foot seen from the side, flat on the ground, from the point under the
/// ankle: the ankle's height, the heel's contact behind it, the ball (toe
/// joint) ahead of and above it [m]; and the most the heel rises in a stance
/// [rad] (steepest_toe_off).
struct FootShape {
  double ankle_height = 0;
  double heel_back = 0;
  double ball_ahead = 0;
  double ball_height = 0;
  double toe_off_limit = kToeOff;
};

/// [m] a vertex of the sole this near the ground touches it.
constexpr double kSoleTouching = 0.002;
/// [m] the most a vertex of the sole may slide while it touches, as the heel rises.
constexpr double kSoleSlide = 0.004;

/// A vertex of a foot's skin at rest, seen from the side: ahead of the point
/// under the ankle and above the ground [m], and its skin weights on the
/// foot bone and on the toe bone.
struct SoleVertex {
  double ahead = 0;
  double height = 0;
  double foot_weight = 0;
  double toe_weight = 0;
};

/// The most the heel may rise in a stance [rad, at most kToeOff]. The foot
/// turns about the toe joint, above the sole, while the toes stay flat: a
/// skin vertex under the joint, weighted partly to the foot, slides back as
/// it turns. The heel rises until a vertex of `skin` (those weighted at
/// least half to the foot and toe) that still touches the ground would
/// slide over kSoleSlide. Without vertices: kToeOff.
double steepest_toe_off(const FootShape& shape, const std::vector<SoleVertex>& skin);

/// A foot's pitch [rad, toes up positive] and the ankle's displacement from
/// where it stands with the foot flat, along the foot's forward and up. [m]
struct FootRoll {
  double pitch = 0;
  double forward = 0;
  double up = 0;
};

/// The ankle's offset at `pitch`: turning on the heel (toes up) or the ball.
FootRoll roll_at_pitch(const FootShape& shape, double pitch);

/// A plan's footsteps as the roll needs them.
struct RollStep {
  double start = 0, end = 0;  ///< [s]
  int foot = 0;               ///< 0 left, 1 right
  /// The body goes over the feet (a walk, start or stop; not a side step,
  /// nor a stair's step, rising or dropping over kStairRise from the step before).
  bool forward = true;
  double speed = 0;           ///< the COM's speed over the step [m/s]
};

/// The roll of both feet of one agent's plan, step by step.
class FootRoller {
 public:
  /// `full_speed`: the speed at which the amplitudes are full (the
  /// character's preferred speed) [m/s]; an agent that `leaves` walks on
  /// past its last step: its feet roll as if another step followed.
  FootRoller(std::vector<RollStep> steps, double full_speed, bool leaves);
  FootRoller(const AgentPlan& plan, double full_speed);
  /// Foot `side` (0 left, 1 right) at time `t`, where the plan has it
  /// `planted` or not.
  FootRoll at(double t, int side, bool planted, const FootShape& shape) const;

 private:
  std::vector<RollStep> steps_;
  bool leaves_;
  std::vector<double> strike_;   ///< per step: pitch at its heel strike
  std::vector<double> toe_off_;  ///< per step: pitch at its toe-off
  std::vector<char> rolling_;    ///< per step: the body goes over the feet at some speed
  double walk_on_ = 0;           ///< the strike of the step a leaving agent would take next
};

}  // namespace footfall::animate
