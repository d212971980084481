// Footfall — each agent's annotated way.
#include "crowd/behavior_sections.hpp"

#include "footfall/fullbody/behavioral_planner.hpp"

namespace footfall::detail {

void plan_sections(const Scenario& scenario, const CollisionScene& scene, const BodyModel& body,
                   std::vector<AgentSpec>& agents) {
  // The planner puts point obstacles into its mesh while it works: a mesh of
  // its own, not the one the agents share.
  NavMesh mesh = navmesh_of(scenario);
  BehavioralPlanner planner(mesh, scene, body, scenario.planner);
  for (AgentSpec& agent : agents) {
    agent.sections.clear();
    Vec2 from = agent.position;
    for (const Vec2 goal : agent.goals) {
      BehaviorPath path = planner.plan(from, goal);
      if (path.status != BehaviorPathStatus::kFound) break;
      for (BehaviorSection& section : path.sections) agent.sections.push_back(std::move(section));
      from = goal;
    }
  }
}

}  // namespace footfall::detail
