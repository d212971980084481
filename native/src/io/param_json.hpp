// Footfall — the parameter structs and obstacles in scenario and plan files,
// read and written through the parameter tables (model/params.hpp).
#pragma once

#include <string>
#include <vector>

#include "footfall/model/obstacles.hpp"
#include "footfall/model/params.hpp"
#include "io/json_reader.hpp"

namespace footfall::detail {

/// Applies the overrides in `json` (an object, unknown keys refused) to `params`.
/// Flat foot-limit keys set both feet; "left" and "right" objects set one.
void read_character(const Json& json, const std::string& path, CharacterParams& params);
/// Applies the overrides in `json` to `params`.
void read_planner(const Json& json, const std::string& path, PlannerParams& params);
/// The "obstacles" array of a scenario or plan (its shape; ObstacleMap checks the values).
std::vector<Obstacle> read_obstacles(const Json& json);
/// The "ground" array of a scenario or plan: the obstacles' shapes, a
/// prism's "base" defaulting to min(0, height) (Ground checks the values).
std::vector<Obstacle> read_ground(const Json& json);
/// One obstacle as the files write it ("base" only when above the ground).
Json obstacle_to_json(const Obstacle& obstacle);
/// All character parameters as JSON; without `ground`, not those only ground
/// uses (kGroundCharacterFields): flat plans' files stay as they were.
Json character_to_json(const CharacterParams& params, bool ground = true);

}  // namespace footfall::detail
