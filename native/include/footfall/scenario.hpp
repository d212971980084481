// Footfall — the scenario: obstacles, agents and parameters, read from the
// scenario JSON format (docs/file-formats.md).
#pragma once

#include <string>
#include <vector>

#include "footfall/agent_planner.hpp"
#include "footfall/obstacles.hpp"
#include "footfall/params.hpp"

namespace footfall {

/// Everything needed to plan a scene: plain data.
struct Scenario {
  std::vector<Obstacle> obstacles;  ///< Static obstacles.
  std::vector<AgentSpec> agents;    ///< Agents, each planned on its own.
  CharacterParams character;        ///< Shared character parameters.
  PlannerParams planner;            ///< Shared planner parameters.
};

/// Checks what the parser cannot: parameter ranges, obstacle polygons, unique
/// agent names, agents and goals clear of obstacles. Throws
/// std::invalid_argument with the field path ("agents[1].position: ...").
void validate(const Scenario& scenario);

/// Parses and validates scenario JSON. Every error is a std::invalid_argument
/// of one line: "SOURCE: FIELD.PATH: what is wrong".
Scenario parse_scenario(const std::string& text, const std::string& source = "<string>");

/// Reads, parses and validates a scenario file (errors as parse_scenario; an
/// unreadable file is a std::invalid_argument naming it).
Scenario load_scenario(const std::string& path);

}  // namespace footfall
