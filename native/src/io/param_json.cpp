// Footfall — the parameter structs and obstacles read from and written to
// JSON (io/param_fields.hpp).
#include <stdexcept>

#include "io/json_reader.hpp"
#include "io/param_fields.hpp"

namespace footfall {
namespace detail {

namespace {

// Looks `key` up in `table`; applies a number to the field. False if unknown.
template <typename Struct, size_t N>
bool read_double(const DoubleField<Struct> (&table)[N], const std::string& key, const Json& value,
                 const std::string& path, Struct& target) {
  for (const auto& field : table) {
    if (key == field.name) {
      target.*field.member = number(value, path);
      return true;
    }
  }
  return false;
}

void read_foot_limits(const Json& json, const std::string& path, FootLimits& limits) {
  if (!json.is_object()) fail(path, "expected an object, got " + type_name(json));
  for (auto it = json.begin(); it != json.end(); ++it) {
    if (!read_double(kFootLimitFields, it.key(), it.value(), child(path, it.key()), limits)) {
      fail(child(path, it.key()), "unknown field");
    }
  }
}

template <typename Struct, size_t N>
Json fields_to_json(const DoubleField<Struct> (&table)[N], const Struct& source) {
  Json json = Json::object();
  for (const auto& field : table) json[field.name] = source.*field.member;
  return json;
}

}  // namespace

void read_character(const Json& json, const std::string& path, CharacterParams& params) {
  if (!json.is_object()) fail(path, "expected an object, got " + type_name(json));
  for (auto it = json.begin(); it != json.end(); ++it) {
    const std::string& key = it.key();
    const std::string field = child(path, key);
    if (read_double(kCharacterFields, key, it.value(), field, params)) continue;
    if (key == "left" || key == "right") continue;  // applied below
    if (read_double(kFootLimitFields, key, it.value(), field, params.left)) {
      read_double(kFootLimitFields, key, it.value(), field, params.right);
    } else {
      fail(field, "unknown field");
    }
  }
  // Per-foot objects win over flat keys, whatever their order in the file.
  for (const char* side : {"left", "right"}) {
    if (json.contains(side)) {
      read_foot_limits(json[side], child(path, side), side[0] == 'l' ? params.left : params.right);
    }
  }
}

void read_planner(const Json& json, const std::string& path, PlannerParams& params) {
  if (!json.is_object()) fail(path, "expected an object, got " + type_name(json));
  for (auto it = json.begin(); it != json.end(); ++it) {
    const std::string& key = it.key();
    const std::string field = child(path, key);
    if (read_double(kPlannerFields, key, it.value(), field, params)) continue;
    if (key == "max_expansions" || key == "stall_expansions") {
      const long long low = key == "max_expansions" ? 1 : 0;
      const long long value = integer(it.value(), field);
      if (value < low || value > 1000000)
        fail(field,
             "must be in [" + std::to_string(low) + ", 1000000], got " + std::to_string(value));
      (key == "max_expansions" ? params.max_expansions : params.stall_expansions) =
          static_cast<int>(value);
    } else if (key == "gaits") {
      params.gaits.clear();
      const Json& gaits = array(it.value(), field);
      for (size_t i = 0; i < gaits.size(); ++i) {
        const std::string gait_path = item(field, i);
        expect_object(gaits[i], gait_path, {"speed", "duration"});
        params.gaits.push_back(
            {number(require(gaits[i], gait_path, "speed"), child(gait_path, "speed")),
             number(require(gaits[i], gait_path, "duration"), child(gait_path, "duration"))});
      }
    } else if (key == "turn_angles") {
      params.turn_angles.clear();
      const Json& angles = array(it.value(), field);
      for (size_t i = 0; i < angles.size(); ++i)
        params.turn_angles.push_back(number(angles[i], item(field, i)));
    } else {
      fail(field, "unknown field");
    }
  }
}

std::vector<Obstacle> read_obstacles(const Json& json) {
  std::vector<Obstacle> result;
  const Json& obstacles = array(json, "obstacles");
  for (size_t i = 0; i < obstacles.size(); ++i) {
    const std::string path = item("obstacles", i);
    expect_object(obstacles[i], path, {"polygon", "height"});
    Obstacle obstacle;
    const std::string polygon_path = child(path, "polygon");
    const Json& polygon = array(require(obstacles[i], path, "polygon"), polygon_path);
    for (size_t k = 0; k < polygon.size(); ++k) {
      obstacle.polygon.push_back(point(polygon[k], item(polygon_path, k)));
    }
    if (obstacles[i].contains("height")) {
      obstacle.height = number(obstacles[i]["height"], child(path, "height"));
    }
    result.push_back(std::move(obstacle));
  }
  return result;
}

Json character_to_json(const CharacterParams& params) {
  Json json = fields_to_json(kCharacterFields, params);
  json["left"] = fields_to_json(kFootLimitFields, params.left);
  json["right"] = fields_to_json(kFootLimitFields, params.right);
  return json;
}

}  // namespace detail

}  // namespace footfall
