// Footfall — reading scenario files (docs/file-formats.md).
#include "footfall/io/scenario_file.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>
#include <tuple>

#include "footfall/io/steersuite.hpp"
#include "io/json_reader.hpp"
#include "io/param_json.hpp"

namespace footfall {

using namespace detail;

namespace {

// Each agent's own character: the scenario's, scaled by its "scale", with
// its "character" overrides (which win). Agents with the same scale and
// overrides share one (a planner each, not per agent).
void read_agent_characters(const Json& agents, Scenario& scenario) {
  std::map<std::string, std::shared_ptr<const CharacterParams>> made;
  for (size_t i = 0; i < agents.size(); ++i) {
    const double scale = scenario.agents[i].scale;
    const Json overrides = agents[i].contains("character") ? agents[i]["character"] : Json::object();
    const std::string path = child(item("agents", i), "character");
    CharacterParams character = scale == 1.0 ? scenario.character : scaled(scenario.character, scale);
    read_character(overrides, path, character);
    if (overrides.empty() && scale == 1.0) continue;
    auto& shared = made[overrides.dump() + " x" + Json(scale).dump()];
    if (!shared) shared = std::make_shared<const CharacterParams>(std::move(character));
    scenario.agents[i].character = shared;
  }
}

Scenario read_scenario(const Json& root) {
  expect_header(root, "footfall-scenario", 1);
  expect_object(root, "",
                {"format", "version", "obstacles", "ground", "agents", "character", "planner"});
  Scenario scenario;
  if (root.contains("obstacles")) scenario.obstacles = read_obstacles(root["obstacles"]);
  if (root.contains("ground")) scenario.ground = read_ground(root["ground"]);
  if (root.contains("agents")) {
    const Json& agents = array(root["agents"], "agents");
    for (size_t i = 0; i < agents.size(); ++i) {
      const std::string path = item("agents", i);
      expect_object(agents[i], path,
                    {"name", "position", "facing", "goals", "leave_at_goal", "character",
                     "time_limit", "start_delay", "goal_wait", "scale", "end_facing", "goal_facings"});
      AgentSpec agent;
      agent.name = agents[i].contains("name") ? string(agents[i]["name"], child(path, "name"))
                                              : "agent" + std::to_string(i);
      std::tie(agent.position, agent.height) =
          point_and_height(require(agents[i], path, "position"), child(path, "position"));
      const std::string goals_path = child(path, "goals");
      const Json& goals = array(require(agents[i], path, "goals"), goals_path);
      for (size_t k = 0; k < goals.size(); ++k) {
        const auto [goal, height] = point_and_height(goals[k], item(goals_path, k));
        agent.goals.push_back(goal);
        agent.goal_heights.push_back(height);
      }
      if (std::none_of(agent.goal_heights.begin(), agent.goal_heights.end(),
                       [](const std::optional<double>& h) { return h.has_value(); }))
        agent.goal_heights.clear();
      // Facing defaults to the direction of the first goal.
      if (agents[i].contains("facing")) {
        agent.facing = number(agents[i]["facing"], child(path, "facing"));
      } else if (!agent.goals.empty() && !(agent.goals[0] == agent.position)) {
        agent.facing = angle_of(agent.goals[0] - agent.position);
      }
      if (agents[i].contains("leave_at_goal"))
        agent.leave_at_goal = boolean(agents[i]["leave_at_goal"], child(path, "leave_at_goal"));
      if (agents[i].contains("time_limit")) {
        agent.time_limit = number(agents[i]["time_limit"], child(path, "time_limit"));
        if (!(agent.time_limit > 0.0 && agent.time_limit <= kMaxTimeLimit))
          fail(child(path, "time_limit"), "must be in (0, 100000] s");
      }
      if (agents[i].contains("start_delay"))
        agent.start_delay = number(agents[i]["start_delay"], child(path, "start_delay"));
      if (agents[i].contains("goal_wait"))
        agent.goal_wait = number(agents[i]["goal_wait"], child(path, "goal_wait"));
      if (agents[i].contains("end_facing"))
        agent.end_facing = number(agents[i]["end_facing"], child(path, "end_facing"));
      if (agents[i].contains("goal_facings")) {
        const std::string facings_path = child(path, "goal_facings");
        const Json& facings = array(agents[i]["goal_facings"], facings_path);
        for (size_t k = 0; k < facings.size(); ++k)
          agent.goal_facings.push_back(facings[k].is_null() ? std::nullopt
                                                            : std::optional(number(facings[k], item(facings_path, k))));
      }
      if (agents[i].contains("scale")) {
        agent.scale = number(agents[i]["scale"], child(path, "scale"));
        if (!in_scale_range(agent.scale))
          fail(child(path, "scale"), kScaleRange);
      }
      scenario.agents.push_back(std::move(agent));
    }
  }
  if (root.contains("character"))
    read_character(root["character"], "character", scenario.character);
  if (root.contains("agents")) read_agent_characters(root["agents"], scenario);
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

Scenario load_scenario_file(const std::string& path) {
  const bool xml = path.size() >= 4 && path.compare(path.size() - 4, 4, ".xml") == 0;
  return xml ? load_steersuite(path) : load_scenario(path);
}

}  // namespace footfall
