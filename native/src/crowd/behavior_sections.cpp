// Footfall — each agent's annotated way.
#include "crowd/behavior_sections.hpp"

#include "crowd/unreachable.hpp"

namespace footfall::detail {

SectionPlanners::SectionPlanners(const Scenario& scenario, const CollisionScene& scene,
                                 const CharacterPlanners& planners)
    : scenario_(scenario), scene_(scene), planners_(planners) {}

std::pair<NavMesh, std::unique_ptr<BehavioralPlanner>>& SectionPlanners::planner_of(
    const AgentSpec& agent) {
  const BodyModel& body = planners_.body(agent);
  auto found = by_body_.find(&body);
  if (found == by_body_.end()) {
    found = by_body_.emplace(&body, std::make_pair(navmesh_of(scenario_), nullptr)).first;
    found->second.second = std::make_unique<BehavioralPlanner>(found->second.first, scene_,
                                                               body, scenario_.planner);
  }
  return found->second;
}

std::pair<std::vector<BehaviorSection>, std::size_t> SectionPlanners::plan_legs(
    const AgentSpec& agent, Vec2 from, std::size_t first_goal) {
  BehavioralPlanner& planner = *planner_of(agent).second;
  std::vector<BehaviorSection> sections;
  std::size_t goal = first_goal;
  for (; goal < agent.goals.size(); ++goal) {
    BehaviorPath path = planner.plan(from, agent.goals[goal]);
    if (path.status != BehaviorPathStatus::kFound) break;
    for (BehaviorSection& section : path.sections) sections.push_back(std::move(section));
    from = agent.goals[goal];
  }
  return {std::move(sections), goal};
}

std::optional<Narrowest> SectionPlanners::plan_short(AgentSpec& agent) {
  auto [sections, reached] = plan_legs(agent, agent.position, 0);
  agent.sections = std::move(sections);
  if (reached == agent.goals.size()) return std::nullopt;
  const Vec2 from = reached == 0 ? agent.position : agent.goals[reached - 1];
  const std::optional<ShortOfGoal> short_of =
      short_of_goal(planner_of(agent).first, planners_.body(agent).clearance(Behavior::kSideStep),
                    from, agent.goals[reached]);
  if (!short_of) return std::nullopt;
  agent.goals.resize(reached + 1);
  agent.goals.back() = short_of->stand;
  if (!agent.goal_facings.empty()) {
    agent.goal_facings.resize(reached + 1);
    agent.goal_facings.back().reset();
  }
  agent.end_facing.reset();
  agent.leave_at_goal = false;  // it stands there
  std::vector<BehaviorSection> last = plan_legs(agent, from, reached).first;
  agent.sections.insert(agent.sections.end(), last.begin(), last.end());
  return short_of->narrowest;
}

std::vector<std::optional<Narrowest>> plan_sections(SectionPlanners& sections,
                                                    std::vector<AgentSpec>& agents,
                                                    const std::vector<const AgentPlan*>& fixed) {
  std::vector<std::optional<Narrowest>> narrowest(agents.size());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    if (!fixed.empty() && fixed[i] != nullptr)
      agents[i].sections = fixed[i]->sections;
    else
      narrowest[i] = sections.plan_short(agents[i]);
  }
  return narrowest;
}

}  // namespace footfall::detail
