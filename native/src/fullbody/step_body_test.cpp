// Footfall — the full-body test of footsteps.
#include "footfall/fullbody/step_body_test.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace footfall {

void pose_during(const BodyModel& body, const Footstep& step, double t, BodyPose& pose,
                 GroundPlacement& placement) {
  if (step.kind == StepKind::kStop) {
    pose = body.standing(step.behavior);
  } else {
    const double span = std::max(step.end_time - step.start_time, 1e-9);
    const double fraction = std::clamp((t - step.start_time) / span, 0.0, 1.0);
    const double phase = 0.5 * fraction + (step.foot == Foot::kLeft ? 0.0 : 0.5);
    body.pose_at(step.behavior, phase * body.motion(step.behavior).cycle_duration, pose);
    // A walk from standing parts the feet over the step: the motion's pose at
    // its start has a foot a stride behind, where none stands yet (beside a
    // wall behind, every way out would seem to kick it). The legs go from
    // the standing pose to the motion's as the feet do; the arms swing as
    // the animation swings them, with the motion.
    if (step.kind != StepKind::kSideStep && step.com_velocity_start == Vec2{0.0, 0.0}) {
      const BodyPose& standing = body.standing(step.behavior);
      for (std::size_t c = static_cast<std::size_t>(Limb::kThighLeft); c < pose.size(); ++c) {
        pose[c].a = standing[c].a + fraction * (pose[c].a - standing[c].a);
        pose[c].b = standing[c].b + fraction * (pose[c].b - standing[c].b);
        pose[c].radius = standing[c].radius + fraction * (pose[c].radius - standing[c].radius);
      }
    }
  }
  placement.position = com_at(step, t).position;
  placement.heading = step.behavior == Behavior::kSideStep ? step.phi - 0.5 * kPi : step.phi;
}

StepBodyTest::StepBodyTest(const CollisionScene& scene, const BodyModel& body, double pose_rate)
    : scene_(scene), body_(body), pose_rate_(pose_rate) {
  if (!(pose_rate >= 1 && pose_rate <= 1000))
    throw std::invalid_argument("pose rate: must be in [1, 1000] poses per second");
  for (Behavior behavior : {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep}) {
    Extent& extent = extents_[static_cast<int>(behavior)];
    const auto take_in = [&](const BodyPose& pose) {
      for (const Capsule& c : pose)
        for (const Vec3 p : {c.a, c.b}) {
          extent.ahead = std::max(extent.ahead, p.x + c.radius);
          extent.behind = std::max(extent.behind, c.radius - p.x);
          extent.side = std::max(extent.side, std::fabs(p.y) + c.radius);
          extent.top = std::max(extent.top, p.z + c.radius);
        }
    };
    for (const BodyPose& pose : body.motion(behavior).poses) take_in(pose);
    take_in(body.standing(behavior));
  }
}

bool StepBodyTest::hits(const Footstep& step) const {
  const Extent& extent = extents_[static_cast<int>(step.behavior)];
  // The box of the whole sweep: the body's box in its travel frame, turned
  // to the step's heading, at both ends of the COM's chord, grown by 0.1 m
  // (a step's COM stays within its sway of the chord).
  const double heading = step.behavior == Behavior::kSideStep ? step.phi - 0.5 * kPi : step.phi;
  const Vec2 along = unit(heading), across = perp(along);
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), 0.0};
  Vec3 hi{-lo.x, -lo.y, extent.top};
  for (const Vec2 root : {step.com_start, step.com_end})
    for (const double x : {extent.ahead, -extent.behind})
      for (const double y : {extent.side, -extent.side}) {
        const Vec2 corner = root + x * along + y * across;
        lo = {std::min(lo.x, corner.x), std::min(lo.y, corner.y), 0.0};
        hi = {std::max(hi.x, corner.x), std::max(hi.y, corner.y), extent.top};
      }
  constexpr double kSway = 0.1;  // [m]
  if (!scene_.near({lo.x - kSway, lo.y - kSway, 0.0}, {hi.x + kSway, hi.y + kSway, hi.z})) return false;
  BodyPose pose;
  GroundPlacement placement;
  const double span = step.end_time - step.start_time;
  // A stop that leaves the COM where it is (a wait, a pivot) holds one
  // standing pose in one place: one test is all of them.
  const bool still = step.kind == StepKind::kStop && step.com_start == step.com_end;
  const long long count =
      still ? 0 : std::max(1LL, static_cast<long long>(std::ceil(span * pose_rate_)));
  for (long long k = 0; k <= count; ++k) {
    const double share = count == 0 ? 0.0 : static_cast<double>(k) / static_cast<double>(count);
    const double t = step.start_time + span * share;
    pose_during(body_, step, t, pose, placement);
    if (scene_.test(pose, placement)) return true;
  }
  return false;
}

}  // namespace footfall
