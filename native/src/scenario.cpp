#include "footfall/scenario.hpp"

#include <set>
#include <stdexcept>

#include "footfall/footstep.hpp"
#include "footfall/planner.hpp"
#include "json_reader.hpp"
#include "param_fields.hpp"

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

using namespace detail;

void validate(const Scenario& scenario) {
  validate(scenario.character, "character");
  validate(scenario.planner, "planner");
  const ObstacleMap obstacles(scenario.obstacles);
  const FootstepPlanner planner(scenario.character, scenario.planner, obstacles);
  std::set<std::string> names;
  for (size_t i = 0; i < scenario.agents.size(); ++i) {
    const AgentSpec& agent = scenario.agents[i];
    const std::string path = item("agents", i);
    if (agent.name.empty()) fail(child(path, "name"), "must not be empty");
    if (!names.insert(agent.name).second)
      fail(child(path, "name"), "\"" + agent.name + "\" is used twice");
    if (!in_world(agent.position))
      fail(child(path, "position"), "must be finite and within 1e9 m of the origin");
    if (!std::isfinite(agent.facing)) fail(child(path, "facing"), "must be finite");
    if (agent.goals.empty()) fail(child(path, "goals"), "needs at least one goal");
    const FootstepState standing = standing_state(agent.position, agent.facing, scenario.character);
    if (planner.collides(standing)) {
      int hit = -1;
      for (const Circle& c : torso_circles(standing.com, standing.facing, scenario.character)) {
        if (hit < 0) hit = obstacles.first_overlap(c);
      }
      for (const Vec2& foot : standing.feet) {
        if (hit < 0) hit = obstacles.first_overlap({foot, scenario.character.foot_radius});
      }
      fail(child(path, "position"),
           "the standing agent overlaps obstacles[" + std::to_string(hit) + "]");
    }
    for (size_t k = 0; k < agent.goals.size(); ++k) {
      if (!in_world(agent.goals[k])) {
        fail(item(child(path, "goals"), k), "must be finite and within 1e9 m of the origin");
      }
      for (int o = 0; o < static_cast<int>(scenario.obstacles.size()); ++o) {
        if (obstacles.contains(o, agent.goals[k])) {
          fail(item(child(path, "goals"), k), "inside obstacles[" + std::to_string(o) + "]");
        }
      }
    }
  }
}

namespace {

Scenario read_scenario(const Json& root) {
  expect_header(root, "footfall-scenario", 1);
  expect_object(root, "", {"format", "version", "obstacles", "agents", "character", "planner"});
  Scenario scenario;
  if (root.contains("obstacles")) scenario.obstacles = read_obstacles(root["obstacles"]);
  if (root.contains("agents")) {
    const Json& agents = array(root["agents"], "agents");
    for (size_t i = 0; i < agents.size(); ++i) {
      const std::string path = item("agents", i);
      expect_object(agents[i], path, {"name", "position", "facing", "goals", "leave_at_goal"});
      AgentSpec agent;
      agent.name = agents[i].contains("name") ? string(agents[i]["name"], child(path, "name"))
                                              : "agent" + std::to_string(i);
      agent.position = point(require(agents[i], path, "position"), child(path, "position"));
      const std::string goals_path = child(path, "goals");
      const Json& goals = array(require(agents[i], path, "goals"), goals_path);
      for (size_t k = 0; k < goals.size(); ++k)
        agent.goals.push_back(point(goals[k], item(goals_path, k)));
      // Facing defaults to the direction of the first goal.
      if (agents[i].contains("facing")) {
        agent.facing = number(agents[i]["facing"], child(path, "facing"));
      } else if (!agent.goals.empty() && !(agent.goals[0] == agent.position)) {
        agent.facing = angle_of(agent.goals[0] - agent.position);
      }
      if (agents[i].contains("leave_at_goal"))
        agent.leave_at_goal = boolean(agents[i]["leave_at_goal"], child(path, "leave_at_goal"));
      scenario.agents.push_back(std::move(agent));
    }
  }
  if (root.contains("character"))
    read_character(root["character"], "character", scenario.character);
  if (root.contains("planner")) read_planner(root["planner"], "planner", scenario.planner);
  validate(scenario);
  return scenario;
}

}  // namespace

Scenario parse_scenario(const std::string& text, const std::string& source) {
  const Json root = parse_json(text, source);
  try {
    return read_scenario(root);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
}

Scenario load_scenario(const std::string& path) { return parse_scenario(read_file(path), path); }

}  // namespace footfall
