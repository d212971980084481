// Footfall — the scenario: obstacles, agents and parameters as plain data
// (read from files by io/scenario_file.hpp), and planning it whole.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "footfall/crowd/crowd_planner.hpp"
#include "footfall/ground/ground.hpp"
#include "footfall/navmesh/navmesh.hpp"
#include "footfall/model/obstacles.hpp"
#include "footfall/model/params.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {

/// Everything needed to plan a scene: plain data.
struct Scenario {
  std::vector<Obstacle> obstacles;  ///< Static obstacles.
  /// The walkable ground (ground/ground.hpp's surfaces); empty: the plane
  /// z = 0 everywhere.
  std::vector<Obstacle> ground;
  std::vector<AgentSpec> agents;    ///< Agents, each planned on its own.
  CharacterParams character;        ///< Shared character parameters.
  PlannerParams planner;            ///< Shared planner parameters.
};

/// Checks what the parser cannot: parameter ranges, obstacle polygons, unique
/// agent names, agents and goals clear of obstacles. Throws
/// std::invalid_argument with the field path ("agents[1].position: ...").
void validate(const Scenario& scenario);

/// Why a body of `character` cannot stand at `position` facing `facing` on
/// `ground` (at `height`, where given: within 0.5 m of it), as validate()
/// says it of an agent's position ("over no ground to stand on", "the
/// standing agent's left foot is not on the ground (...)"); nothing if it
/// can. Without ground, only a height over 0.5 m from z = 0 is a problem.
std::optional<std::string> standing_problem(const Ground& ground, const CharacterParams& character,
                                            Vec2 position, double facing,
                                            std::optional<double> height);

/// Plans every agent of a scenario together on its navigation mesh
/// (plan_agents). Deterministic: the same scenario gives bit-identical plans,
/// whatever the number of threads.
Plan plan_scenario(const Scenario& scenario, const RunControl& control = {});

/// Plans the agents of `scenario` named in `names` again, among the others,
/// which keep their plans in `fixed` (found by name) as they are: plan_agents
/// with those plans fixed. The plan lists every agent of the scenario, in
/// its order. Throws std::invalid_argument ("agents: ..." or "fixed: ...")
/// for no names, a name that is no agent of the scenario, or an agent
/// neither named nor planned in `fixed`.
Plan replan_agents(const Scenario& scenario, const Plan& fixed,
                   const std::vector<std::string>& names, const RunControl& control = {});

/// The navigation mesh of a scenario. The domain is the bounding box of its
/// obstacles, agent positions and goals, grown by `margin` on every side (up
/// /// to kMaxCoordinate); obstacle i gets id i. Obstacles whose footprints
/// overlap (simple polygons whose areas share more than a boundary) enter as
/// one region, their union, under the id of the first of them; the ids of
/// the others block nothing. The ground's walls follow the obstacles. [m]
/// [margin > 0]
constexpr double kNavMeshMargin = 5.0;
NavMesh navmesh_of(const Scenario& scenario, double margin = kNavMeshMargin);

}  // namespace footfall
