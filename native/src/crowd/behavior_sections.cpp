// Footfall — each agent's annotated way.
#include "crowd/behavior_sections.hpp"

#include <map>
#include <memory>
#include <utility>

#include "footfall/fullbody/behavioral_planner.hpp"

namespace footfall::detail {

void plan_sections(const Scenario& scenario, const CollisionScene& scene,
                   const CharacterPlanners& planners, std::vector<AgentSpec>& agents,
                   const std::vector<const AgentPlan*>& fixed) {
  // A planner per body. It puts point obstacles into its mesh while it
  // works: a mesh of its own, not the one the agents share.
  std::map<const BodyModel*, std::pair<NavMesh, std::unique_ptr<BehavioralPlanner>>> by_body;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    AgentSpec& agent = agents[i];
    if (!fixed.empty() && fixed[i] != nullptr) {
      agent.sections = fixed[i]->sections;
      continue;
    }
    const BodyModel& body = planners.body(agent);
    auto found = by_body.find(&body);
    if (found == by_body.end()) {
      found = by_body.emplace(&body, std::make_pair(navmesh_of(scenario), nullptr)).first;
      found->second.second =
          std::make_unique<BehavioralPlanner>(found->second.first, scene, body, scenario.planner);
    }
    BehavioralPlanner& planner = *found->second.second;
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
