#include "footfall/animate/upper_body.hpp"

#include <algorithm>
#include <cmath>

namespace footfall::animate {

double body_facing(const AgentPlan& plan, double t) {
  const std::array<FootPose, 2> feet = feet_at(plan, t);
  const double between = std::atan2(std::sin(feet[0].orientation) + std::sin(feet[1].orientation),
                                    std::cos(feet[0].orientation) + std::cos(feet[1].orientation));
  const auto later = std::upper_bound(plan.footsteps.begin(), plan.footsteps.end(), t,
                                      [](double time, const Footstep& s) { return time < s.start_time; });
  if (later == plan.footsteps.begin()) return between;
  const Footstep& step = *(later - 1);
  if (step.kind != StepKind::kSideStep) return between;
  double across = std::atan2(step.com_end.y - step.com_start.y, step.com_end.x - step.com_start.x) + kPi / 2;
  if (std::cos(across - between) < 0) across -= kPi;
  return across;
}

UpperBodyFollower::UpperBodyFollower(const AgentPlan& plan, double full_speed)
    : plan_(plan), full_speed_(std::max(full_speed, 1e-9)) {
  for (const Footstep& s : plan.footsteps) {
    if (s.kind != StepKind::kWalk && s.kind != StepKind::kStart) continue;
    const double duration = std::max(s.end_time - s.start_time, 1e-9);
    const double speed = length(s.com_end - s.com_start) / duration;
    swing_times_.push_back(0.5 * (s.start_time + s.end_time));
    swings_.push_back(std::clamp(speed / std::max(full_speed, 1e-9), kLeastSwing, 1.0));
  }
}

double UpperBodyFollower::swing_at(double t) const {
  if (swings_.empty()) return 1.0;
  const auto later = std::upper_bound(swing_times_.begin(), swing_times_.end(), t);
  if (later == swing_times_.begin()) return swings_.front();
  if (later == swing_times_.end()) return swings_.back();
  const std::size_t k = static_cast<std::size_t>(later - swing_times_.begin());
  const double u = (t - swing_times_[k - 1]) / (swing_times_[k] - swing_times_[k - 1]);
  return swings_[k - 1] + u * (swings_[k] - swings_[k - 1]);
}

double UpperBodyFollower::look_at(double t) const {
  if (plan_.footsteps.empty()) return 0.0;
  const double end = plan_.end_time();
  // A standing body turns whole, in its pivots, as the planner tests it (in
  // a door frame, a chest turned ahead of them would swing the arms into
  // it): the look fades with the speed.
  const double speed = length(com_at(plan_, std::min(t, end)).velocity);
  const double moving = std::min(1.0, speed / full_speed_);
  if (moving == 0.0) return 0.0;
  const double now = body_facing(plan_, std::min(t, end));
  double sum = 0;
  for (int k = 1; k <= kLookSamples; ++k)
    sum += wrap_angle(body_facing(plan_, std::min(t + kLookAhead * k / kLookSamples, end)) - now);
  return moving * std::clamp(sum / kLookSamples, -kMostLook, kMostLook);
}

double UpperBodyFollower::twist_at(double t) const {
  const auto& steps = plan_.footsteps;
  if (steps.empty()) return 0.0;
  const double end = plan_.end_time();
  const double at = std::clamp(t, steps.front().start_time, end);
  auto later = std::upper_bound(steps.begin(), steps.end(), at,
                                [](double time, const Footstep& s) { return time < s.start_time; });
  const std::size_t k = later == steps.begin() ? 0 : static_cast<std::size_t>(later - steps.begin()) - 1;
  double heading = steps[k].phi;
  const double into = at - steps[k].start_time;
  if (k > 0 && into < kTwistEase) {
    const double u = into / kTwistEase, eased = u * u * (3 - 2 * u);
    heading = steps[k - 1].phi + eased * wrap_angle(steps[k].phi - steps[k - 1].phi);
  }
  return std::clamp(wrap_angle(heading - body_facing(plan_, at)), -kMostTwist, kMostTwist);
}

}  // namespace footfall::animate
