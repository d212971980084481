// Footfall — annotated ways and footstep behaviours.
#include "crowd/behavior_sections.hpp"

#include <limits>

#include "footfall/fullbody/behavioral_planner.hpp"

namespace footfall::detail {
namespace {

/// A footstep farther than this from its agent's annotated way (the crowd
/// pushed it aside) keeps walking: no section speaks for it. [m]
constexpr double kNearWay = 0.75;

// The behaviour of the section nearest to `point`, or walk when none is near.
Behavior section_behavior(const std::vector<BehaviorSection>& sections, Vec2 point) {
  double nearest = kNearWay * kNearWay;
  Behavior behavior = Behavior::kWalk;
  for (const BehaviorSection& section : sections) {
    for (std::size_t k = 1; k < section.points.size(); ++k) {
      const double d = squared_distance_to_segment(point, section.points[k - 1], section.points[k]);
      if (d < nearest) {
        nearest = d;
        behavior = section.behavior;
      }
    }
  }
  return behavior;
}

Behavior step_behavior(const Footstep& step, const std::vector<BehaviorSection>& sections) {
  if (step.kind == StepKind::kSideStep) return Behavior::kSideStep;
  const Behavior section = section_behavior(sections, 0.5 * (step.com_start + step.com_end));
  // A frontal step cannot side-step: the narrowest frontal behaviour.
  if (section == Behavior::kSideStep && step.kind == StepKind::kWalk) return Behavior::kArmsIn;
  return section;
}

}  // namespace

void annotate_behaviors(const Scenario& scenario, Plan& plan) {
  NavMesh mesh = navmesh_of(scenario);
  const CollisionScene scene(scenario.obstacles);
  const BodyModel body(scenario.character);
  BehavioralPlanner planner(mesh, scene, body, scenario.planner);
  for (std::size_t i = 0; i < plan.agents.size(); ++i) {
    AgentPlan& agent = plan.agents[i];
    Vec2 from = scenario.agents[i].position;
    for (const Vec2 goal : scenario.agents[i].goals) {
      BehaviorPath path = planner.plan(from, goal);
      if (path.sections.empty()) break;
      for (BehaviorSection& section : path.sections) agent.sections.push_back(std::move(section));
      from = goal;
    }
    for (Footstep& step : agent.footsteps) step.behavior = step_behavior(step, agent.sections);
  }
}

}  // namespace footfall::detail
