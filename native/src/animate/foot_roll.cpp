#include "animate/foot_roll.hpp"

#include <algorithm>
#include <cmath>

namespace footfall::animate {

FootRoll roll_at_pitch(const FootShape& shape, double pitch) {
  // The ankle seen from the pivot: the heel's contact, or the ball.
  const bool toes_up = pitch > 0.0;
  const double vx = toes_up ? shape.heel_back : -shape.ball_ahead;
  const double vz = toes_up ? shape.ankle_height : shape.ankle_height - shape.ball_height;
  const double c = std::cos(pitch), s = std::sin(pitch);
  return {pitch, c * vx - s * vz - vx, s * vx + c * vz - vz};
}

FootRoller::FootRoller(const AgentPlan& plan, double full_speed)
    : plan_(&plan), leaves_(plan.leaves) {
  const auto& steps = plan.footsteps;
  const std::size_t n = steps.size();
  std::vector<double> amplitude(n, 0.0);
  rolling_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Footstep& s = steps[i];
    const bool forward = s.kind == StepKind::kWalk || s.kind == StepKind::kStop;
    const double speed = length(s.com_end - s.com_start) / std::max(s.end_time - s.start_time, 1e-9);
    amplitude[i] = forward ? std::clamp(speed / full_speed, 0.0, 1.0) : 0.0;
    rolling_[i] = amplitude[i] > 0.0;
  }
  strike_.assign(n, 0.0);
  toe_off_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    // A foot rolls in only from a moving step by the other foot, and off only into one.
    const bool after = i > 0 && rolling_[i] && rolling_[i - 1] && steps[i].foot != steps[i - 1].foot;
    const bool before = i + 1 < n ? rolling_[i] && rolling_[i + 1] && steps[i].foot != steps[i + 1].foot
                                  : leaves_ && rolling_[i];
    if (after) strike_[i] = kHeelStrike * amplitude[i];
    if (before) toe_off_[i] = -kToeOff * amplitude[i];
  }
  if (n > 0 && leaves_) walk_on_ = kHeelStrike * amplitude[n - 1];
}

namespace {
double smooth(double w) {
  w = std::clamp(w, 0.0, 1.0);
  return w * w * (3.0 - 2.0 * w);
}
}  // namespace

FootRoll FootRoller::at(double t, int side, bool planted, const FootShape& shape) const {
  const auto& steps = plan_->footsteps;
  const std::size_t n = steps.size();
  if (n == 0) return {};
  const auto later = std::upper_bound(steps.begin(), steps.end(), t,
                                      [](double time, const Footstep& s) { return time < s.start_time; });
  const std::size_t k = later == steps.begin() ? 0 : static_cast<std::size_t>(later - steps.begin()) - 1;
  const Footstep& step = steps[k];
  if (t < step.start_time) return {};
  const double u = std::clamp((t - step.start_time) / std::max(step.end_time - step.start_time, 1e-9), 0.0, 1.0);
  const bool own = static_cast<int>(step.foot) == side;
  if (own && planted) {
    const double in_strike = std::clamp(1.0 - u / kFlatAt, 0.0, 1.0) * strike_[k];
    const double in_off = std::clamp((u - kHeelOffAt) / (1.0 - kHeelOffAt), 0.0, 1.0) * toe_off_[k];
    return roll_at_pitch(shape, in_strike + in_off);
  }
  if (own || planted || !rolling_[k]) return {};
  // A walking step by the other foot: this one swings from its toe-off (the
  // step before) to its heel strike (the step after).
  const double from = k > 0 ? toe_off_[k - 1] : 0.0;
  const double to = k + 1 < n ? strike_[k + 1] : walk_on_;
  const double w = smooth(u);
  const FootRoll a = roll_at_pitch(shape, from), b = roll_at_pitch(shape, to);
  return {(1 - w) * from + w * to, (1 - w) * a.forward + w * b.forward, (1 - w) * a.up + w * b.up};
}

}  // namespace footfall::animate
