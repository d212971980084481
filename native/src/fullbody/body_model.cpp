// Footfall — the body model: motions, their clearances, poses in time.
#include "footfall/fullbody/body_model.hpp"

#include <cmath>
#include <limits>
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

// The behaviour standing: its pose with the feet nearest together across the
// ground, the legs then straightened under the hips with the feet flat
// beside each other, pointing as they did, and the arms hanging straight
// below the shoulders.
BodyPose standing_pose(const BehaviorMotion& motion) {
  const auto centre = [](const Capsule& c) { return 0.5 * (c.a + c.b); };
  const auto at = [](const BodyPose& pose, Limb limb) -> const Capsule& {
    return pose[static_cast<int>(limb)];
  };
  const BodyPose* nearest = &motion.poses.front();
  double best = std::numeric_limits<double>::infinity();
  for (const BodyPose& pose : motion.poses) {
    const Vec3 d = centre(at(pose, Limb::kFootLeft)) - centre(at(pose, Limb::kFootRight));
    const double apart = d.x * d.x + d.y * d.y;
    if (apart < best) {
      best = apart;
      nearest = &pose;
    }
  }
  BodyPose pose = *nearest;
  const Limb legs[2][3] = {{Limb::kThighLeft, Limb::kShinLeft, Limb::kFootLeft},
                           {Limb::kThighRight, Limb::kShinRight, Limb::kFootRight}};
  const Limb arms[2][2] = {{Limb::kUpperArmLeft, Limb::kForearmLeft},
                           {Limb::kUpperArmRight, Limb::kForearmRight}};
  for (const auto& arm : arms) {
    Capsule& upper = pose[static_cast<int>(arm[0])];
    Capsule& fore = pose[static_cast<int>(arm[1])];
    const double upper_length = length(upper.b - upper.a), fore_length = length(fore.b - fore.a);
    upper.b = upper.a - Vec3{0.0, 0.0, upper_length};
    fore.a = upper.b;
    fore.b = upper.b - Vec3{0.0, 0.0, fore_length};
  }
  for (const auto& leg : legs) {
    Capsule& thigh = pose[static_cast<int>(leg[0])];
    Capsule& shin = pose[static_cast<int>(leg[1])];
    Capsule& foot = pose[static_cast<int>(leg[2])];
    const double upper = length(thigh.b - thigh.a), lower = length(shin.b - shin.a);
    const double foot_length = length(foot.b - foot.a);
    const Vec3 hip = thigh.a;
    const Vec3 ankle{hip.x, hip.y, foot.radius};
    const Vec3 knee = hip + (upper / std::max(upper + lower, 1e-9)) * (ankle - hip);
    thigh.b = knee;
    shin.a = knee;
    shin.b = ankle;
    const Vec3 along = foot.b - foot.a;
    const double flat = std::hypot(along.x, along.y);
    const Vec3 toward = flat > 1e-9 ? Vec3{along.x / flat, along.y / flat, 0.0} : Vec3{1, 0, 0};
    foot.a = ankle - (0.25 * foot_length) * toward;
    foot.b = ankle + (0.75 * foot_length) * toward;
  }
  return pose;
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
    standing_[i] = standing_pose(motions_[i]);
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
