#include "footfall/animate/foot_roll.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace footfall::animate {

std::vector<int> stair_climbs(const AgentPlan& plan) {
  std::array<double, 2> stood = plan.start.foot_heights;
  std::vector<int> climbs;
  for (const Footstep& step : plan.footsteps) {
    const int foot = static_cast<int>(step.foot);
    const double rise = step.foot_height - stood[foot];
    const bool climbs_or_drops = step.kind == StepKind::kWalk && std::fabs(rise) > kStairRise;
    climbs.push_back(climbs_or_drops ? (rise > 0 ? 1 : -1) : 0);
    stood[foot] = step.foot_height;
  }
  return climbs;
}

FootRoll roll_at_pitch(const FootShape& shape, double pitch) {
  // The ankle seen from the pivot: the heel's contact, or the ball.
  const bool toes_up = pitch > 0.0;
  const double vx = toes_up ? shape.heel_back : -shape.ball_ahead;
  const double vz = toes_up ? shape.ankle_height : shape.ankle_height - shape.ball_height;
  const double c = std::cos(pitch), s = std::sin(pitch);
  return {pitch, c * vx - s * vz - vx, s * vx + c * vz - vz};
}

double steepest_toe_off(const FootShape& shape, const std::vector<SoleVertex>& skin) {
  std::vector<SoleVertex> sole;
  double ground = std::numeric_limits<double>::infinity();
  for (const SoleVertex& v : skin)
    if (v.foot_weight + v.toe_weight >= 0.5) ground = std::min(ground, v.height);
  for (const SoleVertex& v : skin)
    if (v.foot_weight + v.toe_weight >= 0.5 && v.height - ground <= kSoleTouching) sole.push_back(v);
  // Heel up by ever more: each vertex moves with its foot weight about the
  // toe joint (the toes stay put); one that rises off the ground is done.
  constexpr int kTurns = 120;
  std::vector<char> lifted(sole.size(), 0);
  for (int i = 1; i <= kTurns; ++i) {
    const double pitch = -kToeOff * i / kTurns;
    const double c = std::cos(pitch), s = std::sin(pitch);
    for (std::size_t k = 0; k < sole.size(); ++k) {
      const SoleVertex& v = sole[k];
      const double vx = v.ahead - shape.ball_ahead, vz = v.height - shape.ball_height;
      const double back = v.foot_weight * (c * vx - s * vz - vx);
      const double rise = v.foot_weight * (s * vx + c * vz - vz);
      if (lifted[k] || v.height - ground + rise > kSoleTouching) {
        lifted[k] = 1;
        continue;
      }
      if (std::fabs(back) > kSoleSlide) return kToeOff * (i - 1) / kTurns;
    }
  }
  return kToeOff;
}

namespace {

std::vector<RollStep> roll_steps(const AgentPlan& plan) {
  std::vector<RollStep> steps;
  const auto& footsteps = plan.footsteps;
  for (std::size_t k = 0; k < footsteps.size(); ++k) {
    const Footstep& s = footsteps[k];
    const bool stair = k > 0 && std::fabs(s.foot_height - footsteps[k - 1].foot_height) > kStairRise;
    steps.push_back({s.start_time, s.end_time, static_cast<int>(s.foot),
                     s.kind != StepKind::kSideStep && !stair,
                     length(s.com_end - s.com_start) / std::max(s.end_time - s.start_time, 1e-9)});
  }
  return steps;
}

}  // namespace

FootRoller::FootRoller(const AgentPlan& plan, double full_speed)
    : FootRoller(roll_steps(plan), full_speed, plan.leaves) {}

FootRoller::FootRoller(std::vector<RollStep> steps, double full_speed, bool leaves)
    : steps_(std::move(steps)), leaves_(leaves) {
  const std::size_t n = steps_.size();
  std::vector<double> amplitude(n, 0.0);
  rolling_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    amplitude[i] = steps_[i].forward ? std::clamp(steps_[i].speed / full_speed, 0.0, 1.0) : 0.0;
    rolling_[i] = amplitude[i] > 0.0;
  }
  strike_.assign(n, 0.0);
  toe_off_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    // A foot rolls in only from a moving step by the other foot, and off only into one.
    const bool after = i > 0 && rolling_[i] && rolling_[i - 1] && steps_[i].foot != steps_[i - 1].foot;
    const bool before = i + 1 < n ? rolling_[i] && rolling_[i + 1] && steps_[i].foot != steps_[i + 1].foot
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
  const std::size_t n = steps_.size();
  if (n == 0) return {};
  const auto later = std::upper_bound(steps_.begin(), steps_.end(), t,
                                      [](double time, const RollStep& s) { return time < s.start; });
  const std::size_t k = later == steps_.begin() ? 0 : static_cast<std::size_t>(later - steps_.begin()) - 1;
  const RollStep& step = steps_[k];
  if (t < step.start) return {};
  const double u = std::clamp((t - step.start) / std::max(step.end - step.start, 1e-9), 0.0, 1.0);
  const bool own = step.foot == side;
  if (own && planted) {
    const double in_strike = std::clamp(1.0 - u / kFlatAt, 0.0, 1.0) * strike_[k];
    const double in_off = std::clamp((u - kHeelOffAt) / (1.0 - kHeelOffAt), 0.0, 1.0) *
                          std::max(toe_off_[k], -shape.toe_off_limit);
    return roll_at_pitch(shape, in_strike + in_off);
  }
  if (own || planted || !rolling_[k]) return {};
  // A walking step by the other foot: this one swings from its toe-off (the
  // step before) to its heel strike (the step after).
  const double from = k > 0 ? std::max(toe_off_[k - 1], -shape.toe_off_limit) : 0.0;
  const double to = k + 1 < n ? strike_[k + 1] : walk_on_;
  const double w = smooth(u);
  const FootRoll a = roll_at_pitch(shape, from), b = roll_at_pitch(shape, to);
  return {(1 - w) * from + w * to, (1 - w) * a.forward + w * b.forward, (1 - w) * a.up + w * b.up};
}

}  // namespace footfall::animate
