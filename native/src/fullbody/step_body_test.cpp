// Footfall — the full-body test of footsteps.
#include "footfall/fullbody/step_body_test.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

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
  placement.height = step.foot_height;  // on the stance foot's ground
}

StepBodyTest::StepBodyTest(const CollisionScene& scene, const BodyModel& body, double pose_rate)
    : scene_(scene), body_(body), pose_rate_(pose_rate) {
  if (!(pose_rate >= 1 && pose_rate <= 1000))
    throw std::invalid_argument("pose rate: must be in [1, 1000] poses per second");
  for (Behavior behavior : {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep}) {
    auto& boxes = limb_boxes_[static_cast<int>(behavior)];
    // A pose between two samples, or between standing and walking, is a
    // blend of theirs: within the box of both.
    const auto take_in = [&](const BodyPose& pose) {
      for (int limb = 0; limb < kLimbCount; ++limb) {
        const Capsule& c = pose[limb];
        const Vec3 r{c.radius, c.radius, c.radius};
        for (const Vec3 p : {c.a, c.b}) boxes[limb].take_in(p - r, p + r);
      }
    };
    for (const BodyPose& pose : body.motion(behavior).poses) take_in(pose);
    take_in(body.standing(behavior));
  }
}

bool StepBodyTest::hits(const Footstep& step) const {
  // The step's ends and the instants between them on the grid of
  // 1/pose_rate s from time 0, where the plan's check (check_body) poses it.
  // A stop that leaves the COM where it is (a wait, a pivot) holds one
  // standing pose in one place: one test is all of them.
  thread_local std::vector<double> times;
  times.assign(1, step.start_time);
  if (!(step.kind == StepKind::kStop && step.com_start == step.com_end)) {
    for (long long k = static_cast<long long>(std::floor(step.start_time * pose_rate_)) + 1;
         static_cast<double>(k) / pose_rate_ < step.end_time; ++k)
      times.push_back(static_cast<double>(k) / pose_rate_);
    times.push_back(step.end_time);
  }
  // The COM's range at the tested times, in the travel frame at the step's
  // start; each limb's box there is its box in the motion moved over that range.
  const double heading = step.behavior == Behavior::kSideStep ? step.phi - 0.5 * kPi : step.phi;
  const Vec2 along = unit(heading);
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const double t : times) {
    const Vec2 d = com_at(step, t).position - step.com_start;
    const double x = dot(d, along), y = cross(along, d);
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  std::array<FrameBox, kLimbCount> swept = limb_boxes_[static_cast<int>(step.behavior)];
  for (FrameBox& box : swept) {
    box.min = box.min + Vec3{x0, y0, step.foot_height};
    box.max = box.max + Vec3{x1, y1, step.foot_height};
  }
  thread_local LimbSurfaces near;
  scene_.near_limbs(step.com_start, heading, swept, near);
  if (near.empty()) return false;
  BodyPose pose;
  GroundPlacement placement;
  for (const double t : times) {
    pose_during(body_, step, t, pose, placement);
    if (scene_.test(pose, placement, near)) return true;
  }
  return false;
}

}  // namespace footfall
