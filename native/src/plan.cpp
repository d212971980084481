#include "footfall/plan.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace footfall {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxLift = 0.12;          // [m] swing height of a full stride
constexpr double kLiftPerStride = 0.15;    // swing height per metre of stride
constexpr double kProgressInterval = 0.2;  // [s] between progress reports

// Index of the step under way at time t: the last one that started at or
// before t (clamped to the first and last). Plans are never empty here.
int step_index(const AgentPlan& plan, double t) {
  const auto& steps = plan.footsteps;
  const auto after =
      std::upper_bound(steps.begin(), steps.end(), t,
                       [](double time, const Footstep& s) { return time < s.start_time; });
  return std::max(0, static_cast<int>(after - steps.begin()) - 1);
}

double smoothstep(double u) { return u * u * (3.0 - 2.0 * u); }

}  // namespace

Plan plan_scenario(const Scenario& scenario, const RunControl& control) {
  validate(scenario);
  const ObstacleMap obstacles(scenario.obstacles);
  const FootstepPlanner planner(scenario.character, scenario.planner, obstacles);
  Plan plan;
  plan.character = scenario.character;
  auto last_report = std::chrono::steady_clock::now();
  for (size_t i = 0; i < scenario.agents.size(); ++i) {
    if (control.cancelled()) {
      plan.status = Status::kCancelled;
      break;
    }
    plan.agents.push_back(plan_agent(scenario.agents[i], planner, control));
    const auto now = std::chrono::steady_clock::now();
    const bool last = i + 1 == scenario.agents.size();
    if (control.progress &&
        (last || std::chrono::duration<double>(now - last_report).count() >= kProgressInterval)) {
      control.progress(static_cast<double>(i + 1) / static_cast<double>(scenario.agents.size()));
      last_report = now;
    }
  }
  if (control.cancelled()) plan.status = Status::kCancelled;
  return plan;
}

ComSample com_at(const AgentPlan& plan, double t) {
  if (plan.footsteps.empty()) return {plan.start.com, {0.0, 0.0}};
  return com_at(plan.footsteps[step_index(plan, t)], t);
}

double facing_at(const AgentPlan& plan, double t) {
  if (plan.footsteps.empty() || t < plan.footsteps.front().start_time) return plan.start.facing;
  return plan.footsteps[step_index(plan, t)].phi;
}

std::array<FootPose, 2> feet_at(const AgentPlan& plan, double t) {
  std::array<FootPose, 2> feet;
  for (int f = 0; f < 2; ++f) feet[f] = {plan.start.feet[f], plan.start.facing, 0.0, true};
  const auto& steps = plan.footsteps;
  if (steps.empty() || t < steps.front().start_time) return feet;
  const int k = step_index(plan, t);
  // Every foot where it was last planted by step k.
  for (int i = 0; i <= k; ++i) {
    feet[static_cast<int>(steps[i].foot)] = {steps[i].foot_position, steps[i].foot_orientation, 0.0,
                                             true};
  }
  const Footstep& step = steps[k];
  const int swing = static_cast<int>(other(step.foot));
  const bool next_lands_it =
      k + 1 < static_cast<int>(steps.size()) && steps[k + 1].foot == other(step.foot);
  if (step.kind != StepKind::kWalk || !next_lands_it || t >= step.end_time) return feet;
  // The other foot swings from lift-off at the step's start to landing at its end.
  const Footstep& landing = steps[k + 1];
  const double u = std::clamp((t - step.start_time) / step.duration(), 0.0, 1.0);
  const double s = smoothstep(u);
  FootPose& foot = feet[swing];
  const double stride = distance(foot.position, landing.foot_position);
  foot.position = foot.position + s * (landing.foot_position - foot.position);
  foot.orientation += s * wrap_angle(landing.foot_orientation - foot.orientation);
  foot.lift = std::min(kMaxLift, kLiftPerStride * stride) * std::sin(kPi * u);
  foot.planted = false;
  return feet;
}

std::vector<Circle> collision_circles(const AgentPlan& plan, const CharacterParams& character,
                                      double t) {
  const auto torso = torso_circles(com_at(plan, t).position, facing_at(plan, t), character);
  std::vector<Circle> circles(torso.begin(), torso.end());
  for (const FootPose& foot : feet_at(plan, t)) {
    if (foot.planted) circles.push_back({foot.position, character.foot_radius});
  }
  return circles;
}

}  // namespace footfall
