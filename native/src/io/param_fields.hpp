// Private: the JSON names of the parameter fields, one table per struct, so the
// readers and writers cannot disagree.
#pragma once

#include <vector>

#include "footfall/model/obstacles.hpp"
#include "footfall/model/params.hpp"
#include "io/json_reader.hpp"

namespace footfall::detail {

template <typename Struct>
struct DoubleField {
  const char* name;
  double Struct::*member;
};

inline constexpr DoubleField<CharacterParams> kCharacterFields[] = {
    {"com_height", &CharacterParams::com_height},
    {"mass", &CharacterParams::mass},
    {"energy_rate", &CharacterParams::energy_rate},
    {"curvature_weight", &CharacterParams::curvature_weight},
    {"foot_offset", &CharacterParams::foot_offset},
    {"torso_width", &CharacterParams::torso_width},
    {"torso_radius", &CharacterParams::torso_radius},
    {"shoulder_radius", &CharacterParams::shoulder_radius},
    {"foot_radius", &CharacterParams::foot_radius},
    {"preferred_speed", &CharacterParams::preferred_speed},
    {"preferred_step_duration", &CharacterParams::preferred_step_duration},
    {"max_foot_turn", &CharacterParams::max_foot_turn},
};

inline constexpr DoubleField<FootLimits> kFootLimitFields[] = {
    {"min_step_duration", &FootLimits::min_step_duration},
    {"max_step_duration", &FootLimits::max_step_duration},
    {"min_step_length", &FootLimits::min_step_length},
    {"max_step_length", &FootLimits::max_step_length},
    {"min_speed", &FootLimits::min_speed},
    {"max_speed", &FootLimits::max_speed},
};

inline constexpr DoubleField<PlannerParams> kPlannerFields[] = {
    {"heuristic_weight", &PlannerParams::heuristic_weight},
    {"goal_tolerance", &PlannerParams::goal_tolerance},
    {"local_goal_distance", &PlannerParams::local_goal_distance},
    {"max_time", &PlannerParams::max_time},
    {"stop_duration", &PlannerParams::stop_duration},
    {"collision_sample_spacing", &PlannerParams::collision_sample_spacing},
    {"min_progress", &PlannerParams::min_progress},
};

/// Applies the overrides in `json` (an object, unknown keys refused) to `params`.
/// Flat foot-limit keys set both feet; "left" and "right" objects set one.
void read_character(const Json& json, const std::string& path, CharacterParams& params);
/// Applies the overrides in `json` to `params`.
void read_planner(const Json& json, const std::string& path, PlannerParams& params);
/// The "obstacles" array of a scenario or plan (its shape; ObstacleMap checks the values).
std::vector<Obstacle> read_obstacles(const Json& json);
/// All character parameters as JSON.
Json character_to_json(const CharacterParams& params);

}  // namespace footfall::detail
