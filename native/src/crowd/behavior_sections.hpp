// Footfall — each agent's annotated way: the full-body planner's sections
// from its start through its goals.
#pragma once

#include <vector>

#include "crowd/character_planners.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/fullbody/collision_scene.hpp"

namespace footfall::detail {

/// Plans the annotated way of every agent of `scenario` (its obstacles in
/// `scene`, each agent's body from `planners`) into agents[i].sections
/// (agents: the scenario's, in its order): from its start to its first goal,
/// on to the next, as far as there is a way. Agents that `fixed` (empty, or
/// one per agent) gives a plan keep that plan's sections.
void plan_sections(const Scenario& scenario, const CollisionScene& scene,
                   const CharacterPlanners& planners, std::vector<AgentSpec>& agents,
                   const std::vector<const AgentPlan*>& fixed);

}  // namespace footfall::detail
