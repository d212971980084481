// Footfall — each agent's annotated way (the full-body planner's sections)
// and the behaviour of each of its footsteps.
#pragma once

#include "footfall/crowd/scenario.hpp"

namespace footfall::detail {

/// Plans every agent's annotated way, from its start through its goals, into
/// plan.agents[i].sections, and gives each footstep the behaviour of the
/// section it lies in (docs/full-body.md): a lateral step is side_step
/// always; a walking step in a side_step section walks with the arms in.
void annotate_behaviors(const Scenario& scenario, Plan& plan);

}  // namespace footfall::detail
