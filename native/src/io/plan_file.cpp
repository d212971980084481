#include "footfall/io/plan_file.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/json_reader.hpp"
#include "io/param_json.hpp"
#include "util/quoted.hpp"

namespace footfall {

using namespace detail;

namespace {

Json footstep_to_json(const Footstep& step) {
  return Json{
      {"foot", to_string(step.foot)},
      {"kind", to_string(step.kind)},
      {"start_time", step.start_time},
      {"end_time", step.end_time},
      {"foot_position", to_json(step.foot_position)},
      {"foot_orientation", step.foot_orientation},
      {"orientation_interval",
       Json::array({step.orientation_interval.inner, step.orientation_interval.outer})},
      {"com_start", to_json(step.com_start)},
      {"com_end", to_json(step.com_end)},
      {"com_velocity_start", to_json(step.com_velocity_start)},
      {"com_velocity_end", to_json(step.com_velocity_end)},
      {"phi", step.phi},
      {"speed", step.speed},
      {"alpha", step.alpha},
      {"behavior", to_string(step.behavior)},
      {"cost", step.cost.total()},
      {"cost_terms",
       {{"fixed_rate", step.cost.fixed_rate},
        {"speed_change", step.cost.speed_change},
        {"curvature", step.cost.curvature}}},
  };
}

Json agent_to_json(const AgentPlan& agent) {
  Json json{
      {"name", agent.name},
      {"status", to_string(agent.status)},
      {"start",
       {{"position", to_json(agent.start.com)},
        {"facing", agent.start.facing},
        {"left_foot", to_json(agent.start.feet[0])},
        {"right_foot", to_json(agent.start.feet[1])}}},
  };
  if (agent.leaves) json["leaves"] = true;
  if (agent.character) json["character"] = character_to_json(*agent.character);
  if (agent.scale != 1.0) json["scale"] = agent.scale;
  if (agent.status != AgentStatus::kReached) {
    json["reason"] = agent.reason;
    json["stopped_at"] = to_json(agent.stuck_at);
  }
  Json steps = Json::array();
  for (const Footstep& step : agent.footsteps) steps.push_back(footstep_to_json(step));
  json["footsteps"] = std::move(steps);
  if (!agent.sections.empty()) {
    Json sections = Json::array();
    for (const BehaviorSection& section : agent.sections) {
      Json points = Json::array();
      for (const Vec2 p : section.points) points.push_back(to_json(p));
      sections.push_back({{"behavior", to_string(section.behavior)},
                          {"clearance", section.clearance},
                          {"points", std::move(points)},
                          {"length", section.length}});
    }
    json["sections"] = std::move(sections);
  }
  json["stats"] = {
      {"goals_reached", agent.goals_reached},     {"searches", agent.searches},
      {"nodes_generated", agent.nodes_generated}, {"nodes_expanded", agent.nodes_expanded},
      {"total_cost", agent.total_cost()},         {"end_time", agent.end_time()}};
  return json;
}

// Reads an enum by its to_string name.
template <typename Enum, size_t N>
Enum read_enum(const Json& value, const std::string& path, const Enum (&choices)[N]) {
  const std::string name = string(value, path);
  std::string expected;
  for (const Enum choice : choices) {
    if (name == to_string(choice)) return choice;
    expected += std::string(expected.empty() ? "" : ", ") + "\"" + to_string(choice) + "\"";
  }
  fail(path, user_text(name) + " is not one of " + expected);
}

Footstep read_footstep(const Json& json, const std::string& path) {
  expect_object(json, path,
                {"foot", "kind", "start_time", "end_time", "foot_position", "foot_orientation",
                 "orientation_interval", "com_start", "com_end", "com_velocity_start",
                 "com_velocity_end", "phi", "speed", "alpha", "behavior", "cost", "cost_terms"});
  const auto field = [&](const char* key) -> const Json& { return require(json, path, key); };
  Footstep step;
  step.foot = read_enum(field("foot"), child(path, "foot"), {Foot::kLeft, Foot::kRight});
  if (json.contains("kind"))
    step.kind = read_enum(json["kind"], child(path, "kind"),
                          {StepKind::kWalk, StepKind::kStop, StepKind::kSideStep, StepKind::kStart});
  step.start_time = number(field("start_time"), child(path, "start_time"));
  step.end_time = number(field("end_time"), child(path, "end_time"));
  if (!(step.end_time > step.start_time)) fail(child(path, "end_time"), "must be after start_time");
  for (const auto& [key, time] : {std::pair{"start_time", step.start_time}, {"end_time", step.end_time}})
    if (time < 0.0 || time > kMaxPlanTime)
      fail(child(path, key), "must be in [0, " + std::to_string(std::lround(kMaxPlanTime)) +
                                 "] s, got " + std::to_string(time));
  step.foot_position = point(field("foot_position"), child(path, "foot_position"));
  step.foot_orientation = number(field("foot_orientation"), child(path, "foot_orientation"));
  step.orientation_interval = {step.foot_orientation, step.foot_orientation};
  if (json.contains("orientation_interval")) {
    const Vec2 bounds = point(json["orientation_interval"], child(path, "orientation_interval"));
    step.orientation_interval = {bounds.x, bounds.y};
  }
  step.com_start = point(field("com_start"), child(path, "com_start"));
  step.com_end = point(field("com_end"), child(path, "com_end"));
  step.com_velocity_start = point(field("com_velocity_start"), child(path, "com_velocity_start"));
  step.com_velocity_end = point(field("com_velocity_end"), child(path, "com_velocity_end"));
  // The torso faces along the COM chord unless phi says otherwise.
  step.phi = json.contains("phi") ? number(json["phi"], child(path, "phi"))
                                  : angle_of(step.com_end - step.com_start);
  if (json.contains("speed")) step.speed = number(json["speed"], child(path, "speed"));
  if (json.contains("alpha")) step.alpha = number(json["alpha"], child(path, "alpha"));
  step.behavior = read_enum(field("behavior"), child(path, "behavior"),
                            {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep});
  // The total is what the file states; the terms are kept when given.
  const double cost = number(field("cost"), child(path, "cost"));
  if (json.contains("cost_terms")) {
    const std::string terms_path = child(path, "cost_terms");
    const Json& terms = json["cost_terms"];
    expect_object(terms, terms_path, {"fixed_rate", "speed_change", "curvature"});
    step.cost.fixed_rate =
        number(require(terms, terms_path, "fixed_rate"), child(terms_path, "fixed_rate"));
    step.cost.speed_change =
        number(require(terms, terms_path, "speed_change"), child(terms_path, "speed_change"));
    step.cost.curvature =
        number(require(terms, terms_path, "curvature"), child(terms_path, "curvature"));
  } else {
    step.cost.fixed_rate = cost;
  }
  return step;
}

// Agents' own characters by their JSON text: those with the same share one.
using Characters = std::map<std::string, std::shared_ptr<const CharacterParams>>;

AgentPlan read_agent(const Json& json, const std::string& path, const CharacterParams& shared,
                     Characters& characters) {
  expect_object(
      json, path,
      {"name", "status", "leaves", "reason", "stopped_at", "start", "footsteps", "sections",
       "stats", "character", "scale"});
  AgentPlan agent;
  if (json.contains("character")) {
    auto& own = characters[json["character"].dump()];
    if (!own) {
      CharacterParams read = shared;
      read_character(json["character"], child(path, "character"), read);
      validate(read, child(path, "character"));
      own = std::make_shared<const CharacterParams>(std::move(read));
    }
    agent.character = own;
  }
  const CharacterParams& character = character_of(agent, shared);
  agent.name = string(require(json, path, "name"), child(path, "name"));
  agent.status = read_enum(require(json, path, "status"), child(path, "status"),
                           {AgentStatus::kReached, AgentStatus::kPartial});
  if (json.contains("leaves")) agent.leaves = boolean(json["leaves"], child(path, "leaves"));
  if (json.contains("scale")) {
    agent.scale = number(json["scale"], child(path, "scale"));
    if (!in_scale_range(agent.scale))
      fail(child(path, "scale"), kScaleRange);
  }
  if (json.contains("reason")) agent.reason = string(json["reason"], child(path, "reason"));
  if (json.contains("stopped_at"))
    agent.stuck_at = point(json["stopped_at"], child(path, "stopped_at"));
  const std::string steps_path = child(path, "footsteps");
  const Json& steps = array(require(json, path, "footsteps"), steps_path);
  for (size_t i = 0; i < steps.size(); ++i) {
    agent.footsteps.push_back(read_footstep(steps[i], item(steps_path, i)));
    if (i > 0 && agent.footsteps[i].start_time < agent.footsteps[i - 1].end_time - 1e-9) {
      fail(child(item(steps_path, i), "start_time"), "starts before the previous step ends");
    }
  }
  if (json.contains("sections")) {
    const std::string sections_path = child(path, "sections");
    const Json& sections = array(json["sections"], sections_path);
    for (std::size_t i = 0; i < sections.size(); ++i) {
      const std::string at = item(sections_path, i);
      expect_object(sections[i], at, {"behavior", "clearance", "points", "length"});
      BehaviorSection section;
      section.behavior = read_enum(require(sections[i], at, "behavior"), child(at, "behavior"),
                                   {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep});
      section.clearance = number(require(sections[i], at, "clearance"), child(at, "clearance"));
      const std::string points_path = child(at, "points");
      const Json& points = array(require(sections[i], at, "points"), points_path);
      for (std::size_t k = 0; k < points.size(); ++k)
        section.points.push_back(point(points[k], item(points_path, k)));
      if (section.points.size() < 2) fail(points_path, "needs at least 2 points");
      section.length = number(require(sections[i], at, "length"), child(at, "length"));
      agent.sections.push_back(std::move(section));
    }
  }
  // The start: as written, or standing where the first step begins.
  if (json.contains("start")) {
    const std::string start_path = child(path, "start");
    const Json& start = json["start"];
    expect_object(start, start_path, {"position", "facing", "left_foot", "right_foot"});
    agent.start = standing_state(
        point(require(start, start_path, "position"), child(start_path, "position")),
        number(require(start, start_path, "facing"), child(start_path, "facing")), character);
    if (start.contains("left_foot"))
      agent.start.feet[0] = point(start["left_foot"], child(start_path, "left_foot"));
    if (start.contains("right_foot"))
      agent.start.feet[1] = point(start["right_foot"], child(start_path, "right_foot"));
  } else if (!agent.footsteps.empty()) {
    const Footstep& first = agent.footsteps.front();
    agent.start = standing_state(first.com_start, first.phi, character);
  } else {
    fail(child(path, "start"), "missing (needed when there are no footsteps)");
  }
  if (json.contains("stats")) {
    const Json& stats = json["stats"];
    const std::string stats_path = child(path, "stats");
    if (!stats.is_object()) fail(stats_path, "expected an object, got " + type_name(stats));
    if (stats.contains("goals_reached"))
      agent.goals_reached =
          int(integer(stats["goals_reached"], child(stats_path, "goals_reached")));
    if (stats.contains("searches"))
      agent.searches = int(integer(stats["searches"], child(stats_path, "searches")));
    if (stats.contains("nodes_generated"))
      agent.nodes_generated =
          integer(stats["nodes_generated"], child(stats_path, "nodes_generated"));
    if (stats.contains("nodes_expanded"))
      agent.nodes_expanded = integer(stats["nodes_expanded"], child(stats_path, "nodes_expanded"));
  }
  return agent;
}

Plan read_plan(const Json& root) {
  expect_header(root, "footfall-plan", 1);
  expect_object(root, "", {"format", "version", "character", "obstacles", "agents", "stats"});
  Plan plan;
  if (root.contains("obstacles")) {
    plan.obstacles = read_obstacles(root["obstacles"]);
    ObstacleMap checked(plan.obstacles);  // the same checks as a scenario's obstacles
  }
  if (root.contains("character")) read_character(root["character"], "character", plan.character);
  validate(plan.character, "character");
  // The top-level stats are derived when writing; read, they must only be an object.
  if (root.contains("stats") && !root["stats"].is_object())
    fail("stats", "expected an object, got " + type_name(root["stats"]));
  const Json& agents = array(require(root, "", "agents"), "agents");
  Characters characters;
  for (size_t i = 0; i < agents.size(); ++i)
    plan.agents.push_back(read_agent(agents[i], item("agents", i), plan.character, characters));
  return plan;
}

}  // namespace

std::string plan_to_json(const Plan& plan) {
  Json agents = Json::array();
  long long footsteps = 0, searches = 0, generated = 0, expanded = 0;
  int reached = 0;
  for (const AgentPlan& agent : plan.agents) {
    agents.push_back(agent_to_json(agent));
    footsteps += static_cast<long long>(agent.footsteps.size());
    searches += agent.searches;
    generated += agent.nodes_generated;
    expanded += agent.nodes_expanded;
    reached += agent.status == AgentStatus::kReached ? 1 : 0;
  }
  Json obstacles = Json::array();
  for (const Obstacle& obstacle : plan.obstacles) obstacles.push_back(obstacle_to_json(obstacle));
  const Json root{
      {"format", "footfall-plan"},
      {"version", 1},
      {"character", character_to_json(plan.character)},
      {"obstacles", std::move(obstacles)},
      {"agents", std::move(agents)},
      {"stats",
       {{"status", to_string(plan.status)},
        {"agents", plan.agents.size()},
        {"agents_reached", reached},
        {"footsteps", footsteps},
        {"searches", searches},
        {"nodes_generated", generated},
        {"nodes_expanded", expanded}}},
  };
  return root.dump(1) + "\n";
}

Plan parse_plan(const std::string& text, const std::string& source) {
  const Json root = parse_json(text, source);
  try {
    return read_plan(root);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
}

Plan load_plan(const std::string& path) { return parse_plan(read_file(path), path); }

void write_plan_file(const Plan& plan, const std::string& path) {
  write_file_atomically(path, plan_to_json(plan));
}

}  // namespace footfall
