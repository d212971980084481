// Test oracle: an independent check that a plan keeps every collision circle
// off every obstacle, sampled far more densely than the planner samples, with
// its own point-to-polygon geometry.
#pragma once

#include <string>
#include <vector>

#include "footfall/plan/plan.hpp"

namespace footfall::testing {

/// Distance from `p` to the polygon's area: 0 inside, else to the nearest edge.
double distance_to_polygon(const std::vector<Vec2>& polygon, Vec2 p);

/// A description of the first moment the torso's centre circle or a planted
/// foot's circle of `plan` touches an obstacle, sampled every `dt` seconds;
/// empty if none does. The torso's side circles are left out: the planner
/// tests the shoulders and arms in 3-D (check_body), over low obstacles too.
std::string first_contact(const AgentPlan& plan, const CharacterParams& character,
                          const std::vector<Obstacle>& obstacles, double dt = 0.002);

}  // namespace footfall::testing
