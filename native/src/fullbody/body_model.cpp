// Footfall — the body model: motions, their clearances, poses in time.
#include "footfall/fullbody/body_model.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace footfall {
namespace {

constexpr int kMaxPoses = 1000;
constexpr double kMaxReach = 10.0;  // [m] from the root
/// Added to a motion's lateral extent to make its derived clearance: a path
/// hugging a corner at exactly the clearance would otherwise graze it, and
/// the limbs ahead of and behind the root swing wide of the arc. [m]
constexpr double kClearanceMargin = 0.02;

[[noreturn]] void refuse(const std::string& field, const std::string& what) {
  throw std::invalid_argument(field + ": " + what);
}

}  // namespace

void validate(const BehaviorMotion& motion, const std::string& path) {
  if (!(motion.cycle_duration > 0 && motion.cycle_duration <= 10))
    refuse(path + ".cycle_duration", "must be in (0, 10] s");
  if (!(motion.speed > 0 && motion.speed <= 10)) refuse(path + ".speed", "must be in (0, 10] m/s");
  if (motion.poses.empty() || motion.poses.size() > kMaxPoses)
    refuse(path + ".poses", "must hold 1 to " + std::to_string(kMaxPoses) + " poses, got " +
                                std::to_string(motion.poses.size()));
  for (std::size_t i = 0; i < motion.poses.size(); ++i) {
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const Capsule& c = motion.poses[i][limb];
      const std::string at =
          path + ".poses[" + std::to_string(i) + "]." + to_string(static_cast<Limb>(limb));
      for (const Vec3 p : {c.a, c.b})
        if (!is_finite(p) || std::fabs(p.x) > kMaxReach || std::fabs(p.y) > kMaxReach ||
            std::fabs(p.z) > kMaxReach)
          refuse(at, "capsule ends must be finite and within 10 m of the root");
      if (!(c.radius > 0 && c.radius <= 1)) refuse(at, "radius must be in (0, 1] m");
    }
  }
}

double lateral_extent(const BehaviorMotion& motion) {
  double extent = 0;
  for (const BodyPose& pose : motion.poses)
    for (const Capsule& c : pose)
      extent = std::max({extent, std::fabs(c.a.y) + c.radius, std::fabs(c.b.y) + c.radius});
  return extent;
}

BodyModel::BodyModel(const CharacterParams& character) {
  const double overrides[3] = {character.walk_clearance, character.arms_in_clearance,
                               character.side_step_clearance};
  for (Behavior behavior : {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep}) {
    const int i = index(behavior);
    const BehaviorMotion& given = character.motions[i];
    if (given.empty()) {
      motions_[i] = builtin_motion(behavior, character);
    } else {
      validate(given, std::string("character.behaviors.") + to_string(behavior));
      motions_[i] = given;
    }
    clearances_[i] =
        overrides[i] > 0 ? overrides[i] : lateral_extent(motions_[i]) + kClearanceMargin;
  }
  const double c1 = clearance(Behavior::kSideStep), c2 = clearance(Behavior::kArmsIn),
               c3 = clearance(Behavior::kWalk);
  if (!(c1 < c2 && c2 < c3)) {
    std::ostringstream message;
    message << "character: the behaviours' clearances must rise, side_step < arms_in < walk; got "
            << c1 << ", " << c2 << ", " << c3 << " m (set side_step_clearance, "
            << "arms_in_clearance, walk_clearance, or change the motions)";
    throw std::invalid_argument(message.str());
  }
}

void BodyModel::pose_at(Behavior behavior, double time, BodyPose& pose) const {
  const BehaviorMotion& m = motion(behavior);
  const int count = static_cast<int>(m.poses.size());
  double cycles = time / m.cycle_duration;
  cycles -= std::floor(cycles);
  const double at = cycles * count;
  const int i = std::min(static_cast<int>(at), count - 1);
  const double t = at - i;
  const BodyPose& p = m.poses[i];
  const BodyPose& q = m.poses[(i + 1) % count];
  for (int limb = 0; limb < kLimbCount; ++limb) {
    pose[limb] = {p[limb].a + t * (q[limb].a - p[limb].a), p[limb].b + t * (q[limb].b - p[limb].b),
                  p[limb].radius + t * (q[limb].radius - p[limb].radius)};
  }
}

}  // namespace footfall
