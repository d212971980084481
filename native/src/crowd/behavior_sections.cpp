// Footfall — each agent's annotated way.
#include "crowd/behavior_sections.hpp"

namespace footfall::detail {

SectionPlanners::SectionPlanners(const Scenario& scenario, const CollisionScene& scene,
                                 const CharacterPlanners& planners)
    : scenario_(scenario), scene_(scene), planners_(planners) {}

std::vector<BehaviorSection> SectionPlanners::plan(const AgentSpec& agent, Vec2 from,
                                                   std::size_t first_goal) {
  const BodyModel& body = planners_.body(agent);
  auto found = by_body_.find(&body);
  if (found == by_body_.end()) {
    found = by_body_.emplace(&body, std::make_pair(navmesh_of(scenario_), nullptr)).first;
    found->second.second = std::make_unique<BehavioralPlanner>(found->second.first, scene_,
                                                               body, scenario_.planner);
  }
  BehavioralPlanner& planner = *found->second.second;
  std::vector<BehaviorSection> sections;
  for (std::size_t goal = first_goal; goal < agent.goals.size(); ++goal) {
    BehaviorPath path = planner.plan(from, agent.goals[goal]);
    if (path.status != BehaviorPathStatus::kFound) break;
    for (BehaviorSection& section : path.sections) sections.push_back(std::move(section));
    from = agent.goals[goal];
  }
  return sections;
}

void plan_sections(SectionPlanners& sections, std::vector<AgentSpec>& agents,
                   const std::vector<const AgentPlan*>& fixed) {
  for (std::size_t i = 0; i < agents.size(); ++i) {
    AgentSpec& agent = agents[i];
    agent.sections = !fixed.empty() && fixed[i] != nullptr
                         ? fixed[i]->sections
                         : sections.plan(agent, agent.position, 0);
  }
}

}  // namespace footfall::detail
