// Footfall — the body as capsules, and a behaviour's motion as body poses
// sampled over one step cycle (the full-body planner's model, docs/full-body.md).
#pragma once

#include <array>
#include <vector>

#include "footfall/model/geometry3.hpp"

namespace footfall {

/// The body's limbs, one capsule each.
enum class Limb {
  kHead,
  kShoulders,  ///< Across the chest, shoulder joint to shoulder joint.
  kTorso,      ///< From the pelvis up the spine to the neck.
  kPelvis,     ///< Across the hips.
  kUpperArmLeft,
  kUpperArmRight,
  kForearmLeft,  ///< Elbow to the end of the hand.
  kForearmRight,
  kThighLeft,
  kThighRight,
  kShinLeft,
  kShinRight,
  kFootLeft,  ///< Heel to toe.
  kFootRight,
};
constexpr int kLimbCount = 14;
/// The file and Python name of a limb: "head", "upper_arm_left", ...
const char* to_string(Limb limb);

/// Every limb's capsule, in the travel frame: the root on the ground under
/// the pelvis, +X the direction of travel, +Y to the left, +Z up. [m]
using BodyPose = std::array<Capsule, kLimbCount>;

/// One behaviour's motion: the poses at evenly spaced phases of one step
/// cycle (two steps), and how fast it travels.
struct BehaviorMotion {
  double cycle_duration = 0;   ///< Duration of the cycle. [s] (0, 10]
  double speed = 0;            ///< Travel speed of the root. [m/s] (0, 10]
  std::vector<BodyPose> poses; ///< Pose i at phase i / poses.size(). [>= 1]

  bool empty() const { return poses.empty(); }
};

}  // namespace footfall
