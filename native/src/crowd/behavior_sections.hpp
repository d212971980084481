// Footfall — each agent's annotated way: the full-body planner's sections
// from its start through its goals, or to where it stands short of a goal no
// way leads to for its body.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "crowd/character_planners.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/fullbody/behavioral_planner.hpp"
#include "footfall/fullbody/collision_scene.hpp"

namespace footfall::detail {

/// The full-body planner for each body of a scenario's agents, made when
/// first asked. Not thread-safe: a query changes its planner's mesh.
class SectionPlanners {
 public:
  /// `scene` and `planners` must outlive it.
  SectionPlanners(const Scenario& scenario, const CollisionScene& scene,
                  const CharacterPlanners& planners);

  /// The annotated way of `agent` from `from` through its goals from
  /// `first_goal` on, joined end to end, as far as there is a way.
  std::vector<BehaviorSection> plan(const AgentSpec& agent, Vec2 from, std::size_t first_goal) {
    return plan_legs(agent, from, first_goal).first;
  }

  /// Makes `agent` stop short of the first goal no way leads to for its body
  /// (short_of_goal): that goal becomes where it stands, and those after it
  /// go. Plans its annotated way from its start; its narrowest point if it
  /// stops short.
  std::optional<Narrowest> plan_short(AgentSpec& agent);

 private:
  // plan(), with the number of goals the way reaches.
  std::pair<std::vector<BehaviorSection>, std::size_t> plan_legs(const AgentSpec& agent, Vec2 from,
                                                                 std::size_t first_goal);
  // The planner of agent's body, and its mesh.
  std::pair<NavMesh, std::unique_ptr<BehavioralPlanner>>& planner_of(const AgentSpec& agent);

  const Scenario& scenario_;
  const CollisionScene& scene_;
  const CharacterPlanners& planners_;
  // A planner per body. It puts point obstacles into its mesh while it
  // works: a mesh of its own, not the one the agents share.
  std::map<const BodyModel*, std::pair<NavMesh, std::unique_ptr<BehavioralPlanner>>> by_body_;
};

/// Plans the annotated way of every agent (the scenario's, in its order)
/// into agents[i].sections: from its start to its first goal, on to the
/// next, or short of a goal no way leads to for its body
/// (SectionPlanners::plan_short; then its narrowest point, per agent).
/// Agents that `fixed` (empty, or one per agent) gives a plan keep that
/// plan's sections.
std::vector<std::optional<Narrowest>> plan_sections(SectionPlanners& sections,
                                                    std::vector<AgentSpec>& agents,
                                                    const std::vector<const AgentPlan*>& fixed);

}  // namespace footfall::detail
