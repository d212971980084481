// Footfall — the body the full-body planner tests: one motion per behaviour
// (built in, or sampled from the rig's clips) and each behaviour's clearance.
#pragma once

#include <array>

#include "footfall/model/body.hpp"
#include "footfall/model/footstep.hpp"
#include "footfall/model/params.hpp"

namespace footfall {

/// Phases per cycle of the built-in motions.
constexpr int kBuiltinPhases = 32;

/// The built-in motion of `behavior`, sized from `character`
/// (docs/full-body.md): `walk` swings the hands out to arm_swing_width,
/// `arms_in` holds them against the body within shoulder_width, `side_step`
/// turns the body across the direction of travel and steps sideways.
BehaviorMotion builtin_motion(Behavior behavior, const CharacterParams& character);

/// The lateral half-extent of a motion: the largest distance across the
/// direction of travel from the root to the surface of any capsule, over
/// every pose. [m]
double lateral_extent(const BehaviorMotion& motion);

/// The character's three motions and their clearances c1 < c2 < c3
/// (side_step < arms_in < walk).
class BodyModel {
 public:
  /// Takes the character's motions (built in where it gives none) and the
  /// clearances (derived where it gives 0). Throws std::invalid_argument
  /// naming the field for a bad motion, or clearances out of order.
  explicit BodyModel(const CharacterParams& character);

  const BehaviorMotion& motion(Behavior behavior) const { return motions_[index(behavior)]; }
  /// The clearance the navigation mesh keeps for `behavior`. [m]
  double clearance(Behavior behavior) const { return clearances_[index(behavior)]; }
  double speed(Behavior behavior) const { return motion(behavior).speed; }
  /// One step: half the cycle. [s]
  double step_duration(Behavior behavior) const { return 0.5 * motion(behavior).cycle_duration; }
  /// The pose `time` seconds into the motion (cyclic, interpolated between
  /// samples), written to `pose`.
  void pose_at(Behavior behavior, double time, BodyPose& pose) const;
  /// The behaviour's pose standing (stopping, waiting, pivoting): its
  /// sampled pose with the feet nearest together, the legs straight under
  /// the hips, the feet flat and the arms hanging.
  const BodyPose& standing(Behavior behavior) const { return standing_[index(behavior)]; }

 private:
  static int index(Behavior behavior) { return static_cast<int>(behavior); }
  std::array<BehaviorMotion, 3> motions_;
  std::array<double, 3> clearances_{};
  std::array<BodyPose, 3> standing_{};
};

/// Checks a sampled motion; throws std::invalid_argument naming `path`'s field.
void validate(const BehaviorMotion& motion, const std::string& path);

}  // namespace footfall
