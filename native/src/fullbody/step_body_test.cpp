// Footfall — the full-body test of footsteps.
#include "footfall/fullbody/step_body_test.hpp"

#include <algorithm>
#include <cmath>
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
  }
  placement.position = com_at(step, t).position;
  placement.heading = step.behavior == Behavior::kSideStep ? step.phi - 0.5 * kPi : step.phi;
}

StepBodyTest::StepBodyTest(const CollisionScene& scene, const BodyModel& body, double pose_rate)
    : scene_(scene), body_(body), pose_rate_(pose_rate) {
  if (!(pose_rate >= 1 && pose_rate <= 1000))
    throw std::invalid_argument("pose rate: must be in [1, 1000] poses per second");
  for (Behavior behavior : {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep}) {
    const int i = static_cast<int>(behavior);
    for (const BodyPose& pose : body.motion(behavior).poses)
      for (const Capsule& c : pose)
        for (const Vec3 p : {c.a, c.b}) {
          reach_[i] = std::max(reach_[i], std::hypot(p.x, p.y) + c.radius);
          top_[i] = std::max(top_[i], p.z + c.radius);
        }
  }
}

bool StepBodyTest::hits(const Footstep& step) const {
  const int i = static_cast<int>(step.behavior);
  // The box of the whole sweep: the COM's chord (a step's COM stays within
  // its sway of it) grown by the body's reach.
  const double grow = reach_[i] + 0.1;
  const Vec3 lo{std::min(step.com_start.x, step.com_end.x) - grow,
                std::min(step.com_start.y, step.com_end.y) - grow, 0.0};
  const Vec3 hi{std::max(step.com_start.x, step.com_end.x) + grow,
                std::max(step.com_start.y, step.com_end.y) + grow, top_[i]};
  if (!scene_.near(lo, hi)) return false;
  BodyPose pose;
  GroundPlacement placement;
  const double span = step.end_time - step.start_time;
  const long long count = std::max(1LL, static_cast<long long>(std::ceil(span * pose_rate_)));
  for (long long k = 0; k <= count; ++k) {
    pose_during(body_, step,
                step.start_time + span * static_cast<double>(k) / static_cast<double>(count), pose,
                placement);
    if (scene_.test(pose, placement)) return true;
  }
  return false;
}

}  // namespace footfall
