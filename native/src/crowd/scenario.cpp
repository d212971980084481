// Footfall — checking a scenario, its navigation mesh, and planning it whole.
#include "footfall/crowd/scenario.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <vector>

#include "crowd/behavior_sections.hpp"
#include "crowd/character_planners.hpp"
#include "footfall/crowd/navigation.hpp"
#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/step_body_test.hpp"
#include "footfall/model/footstep.hpp"
#include "footfall/planner/planner.hpp"
#include "footfall/ground/foothold.hpp"
#include "footfall/ground/ground.hpp"
#include "navmesh/outline_union.hpp"
#include "util/field_path.hpp"
#include "util/quoted.hpp"

namespace footfall {

using detail::child;
using detail::fail;
using detail::item;
using detail::user_text;

namespace {

// Refuses two agents whose standing bodies (torso circles and feet) overlap:
// neither could take a step. Swept along x, so that a crowd of thousands
// costs about a sort.
void check_standing_apart(const Scenario& scenario, const Ground& ground,
                          const detail::CharacterPlanners& planners) {
  struct Body {
    std::size_t agent;
    std::array<Circle, 5> circles;
    double reach = 0.0;   // from the COM [m]
    double ground = 0.0;  // the height it stands at [m]
  };
  std::vector<Body> bodies;
  bodies.reserve(scenario.agents.size());
  double widest = 0.0;
  for (std::size_t i = 0; i < scenario.agents.size(); ++i) {
    const AgentSpec& agent = scenario.agents[i];
    const CharacterParams& character = planners.character(agent);
    const FootstepState s =
        standing_on_ground(ground, character, agent.position, agent.facing, agent.height);
    const auto torso = torso_circles(s.com, s.facing, character);
    Body body{i,
              {torso[0], torso[1], torso[2], Circle{s.feet[0], character.foot_radius},
               Circle{s.feet[1], character.foot_radius}},
              0.0,
              std::max(s.foot_heights[0], s.foot_heights[1])};
    for (const Circle& c : body.circles)
      body.reach = std::max(body.reach, distance(c.center, s.com) + c.radius);
    widest = std::max(widest, body.reach);
    bodies.push_back(body);
  }
  const auto x = [&](const Body& b) { return scenario.agents[b.agent].position.x; };
  std::sort(bodies.begin(), bodies.end(), [&](const Body& a, const Body& b) {
    return x(a) != x(b) ? x(a) < x(b) : a.agent < b.agent;
  });
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (std::size_t j = i + 1; j < bodies.size() && x(bodies[j]) - x(bodies[i]) < 2 * widest; ++j) {
      const Body& a = bodies[i];
      const Body& b = bodies[j];
      if (levels_apart(a.ground, b.ground, scenario.character.body_height)) continue;
      bool overlap = false;
      for (const Circle& p : a.circles)
        for (const Circle& q : b.circles)
          overlap = overlap || distance(p.center, q.center) < p.radius + q.radius;
      if (!overlap) continue;
      const std::size_t first = std::min(a.agent, b.agent), second = std::max(a.agent, b.agent);
      fail(child(item("agents", second), "position"),
           "the standing agent overlaps agents[" + std::to_string(first) + "] (" +
               user_text(scenario.agents[first].name) + ")");
    }
  }
}

std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f m", value);
  return text;
}

/// Why a point of an agent is over no ground to stand on, or has a height
/// (`height`) not within kHeightReach of the ground there (without ground,
/// of z = 0); nothing if it has none of these.
std::optional<std::string> standing_height_problem(const Ground& ground, Vec2 p,
                                                   std::optional<double> height,
                                                   double headroom) {
  if (ground.empty()) {
    if (height && std::fabs(*height) > kHeightReach)
      return "at a height of " + metres(*height) +
             ", but the scenario has no ground: its floor is z = 0";
    return std::nullopt;
  }
  const std::vector<GroundPoint> levels = ground.standable_at(p, headroom);
  if (levels.empty()) return "over no ground to stand on";
  if (!height && levels.size() > 1)
    return std::to_string(levels.size()) + " levels of ground under it, at " +
           metres(levels[0].z) + " and " + metres(levels[1].z) +
           ": give its height, [x, y, z]";
  if (height && std::none_of(levels.begin(), levels.end(), [&](const GroundPoint& level) {
        return std::fabs(level.z - *height) <= kHeightReach;
      }))
    return "no ground to stand on within 0.50 m of its height " + metres(*height) +
           " (the ground there is at " + metres(levels.front().z) + ")";
  return std::nullopt;
}

/// Why a body standing at `position` facing `facing`, on the ground near
/// `height` (standing_on_ground), has a foot that is not on a foothold (each
/// foot as a foothold of its own, beside the other, swung from nowhere);
/// nothing if both are.
std::optional<std::string> standing_feet_problem(const Ground& ground,
                                                 const CharacterParams& character, Vec2 position,
                                                 double facing, std::optional<double> height) {
  const FootstepState standing = standing_on_ground(ground, character, position, facing, height);
  const auto at = [&](int f) {
    return Vec3{standing.feet[f].x, standing.feet[f].y, standing.foot_heights[f]};
  };
  // A foot over nothing first: the other's fault would be its rise from nowhere.
  std::array<FootholdFault, 2> faults{};
  for (int f = 0; f < 2; ++f)
    faults[f] = ground.standable_at(standing.feet[f], character.body_height).empty()
                    ? FootholdFault::kOffGround
                    : FootholdFault::kNone;
  if (faults[0] == FootholdFault::kNone && faults[1] == FootholdFault::kNone)
    for (int f = 0; f < 2; ++f)
      faults[f] = foothold_fault(ground, character, standing.feet[f], standing.foot_orientation[f],
                                 at(1 - f), at(f));
  for (const Foot foot : {Foot::kLeft, Foot::kRight}) {
    const FootholdFault fault = faults[static_cast<int>(foot)];
    if (fault != FootholdFault::kNone)
      return std::string("the standing agent's ") + to_string(foot) +
             " foot is not on the ground (" +
             (fault == FootholdFault::kUnsupported ? "too little of its sole is held"
              : fault == FootholdFault::kRise      ? "a step above or below the other foot"
                                                   : "no ground it can stand on under it") +
             ")";
  }
  return std::nullopt;
}

/// Refuses a point of an agent (`field`) standing_height_problem finds a problem with.
void check_standing_height(const Ground& ground, Vec2 p, std::optional<double> height,
                           double headroom, const std::string& field) {
  if (const auto problem = standing_height_problem(ground, p, height, headroom))
    fail(field, *problem);
}

/// Refuses agents and goals off the ground or its height
/// (check_standing_height); returns the ground's layers (for the scenario's
/// character).
GroundLayers check_on_ground(const Scenario& scenario, const Ground& ground,
                             const detail::CharacterPlanners& planners) {
  for (std::size_t i = 0; i < scenario.agents.size(); ++i) {
    const AgentSpec& agent = scenario.agents[i];
    const std::string path = item("agents", i);
    const double headroom = planners.character(agent).body_height;
    check_standing_height(ground, agent.position, agent.height, headroom, child(path, "position"));
    for (std::size_t k = 0; k < agent.goals.size(); ++k)
      check_standing_height(ground, agent.goals[k],
                            k < agent.goal_heights.size() ? agent.goal_heights[k] : std::nullopt,
                            headroom, item(child(path, "goals"), k));
  }
  GroundLayers layers = layers_for(ground, scenario.character);
  if (ground.empty()) return layers;
  for (std::size_t i = 0; i < scenario.agents.size(); ++i) {
    const AgentSpec& agent = scenario.agents[i];
    if (const auto problem = standing_feet_problem(ground, planners.character(agent),
                                                   agent.position, agent.facing, agent.height))
      fail(child(item("agents", i), "position"), *problem);
  }
  return layers;
}

// validate(), on the scenario's ground built once by its caller; returns its layers.
GroundLayers validate_on(const Scenario& scenario, const Ground& ground) {
  validate(scenario.character, "character");
  validate(scenario.planner, "planner");
  for (size_t i = 0; i < scenario.agents.size(); ++i) {
    if (scenario.agents[i].character)
      validate(*scenario.agents[i].character, child(item("agents", i), "character"));
  }
  // Their motions and clearances are checked as they are made.
  const detail::CharacterPlanners planners(scenario, nullptr, &ground);
  std::set<std::string> names;
  for (size_t i = 0; i < scenario.agents.size(); ++i) {
    const AgentSpec& agent = scenario.agents[i];
    const std::string path = item("agents", i);
    const CharacterParams& character = planners.character(agent);
    const ObstacleMap& obstacles = planners.obstacles(agent);
    if (agent.name.empty()) fail(child(path, "name"), "must not be empty");
    if (!names.insert(agent.name).second)
      fail(child(path, "name"), user_text(agent.name) + " is used twice");
    if (!in_world(agent.position))
      fail(child(path, "position"), "must be finite and within 1e9 m of the origin");
    if (!std::isfinite(agent.facing)) fail(child(path, "facing"), "must be finite");
    if (agent.goals.empty()) fail(child(path, "goals"), "needs at least one goal");
    if (!(agent.time_limit >= 0.0 && agent.time_limit <= kMaxTimeLimit))
      fail(child(path, "time_limit"), "must be in (0, 100000] s");
    if (!(agent.start_delay >= 0.0 && agent.start_delay <= kMaxTimeLimit))
      fail(child(path, "start_delay"), "must be in [0, 100000] s");
    if (!(agent.goal_wait >= 0.0 && agent.goal_wait <= kMaxTimeLimit))
      fail(child(path, "goal_wait"), "must be in [0, 100000] s");
    if (!in_scale_range(agent.scale))
      fail(child(path, "scale"), kScaleRange);
    if (const auto problem = facings_problem(agent)) fail(child(path, problem->first), problem->second);
    const FootstepState standing = standing_state(agent.position, agent.facing, character);
    if (planners.planner(agent).validity().collides(standing)) {
      int hit = -1;
      for (const Circle& c : torso_circles(standing.com, standing.facing, character)) {
        if (hit < 0) hit = obstacles.first_overlap(c);
      }
      for (const Vec2& foot : standing.feet) {
        if (hit < 0) hit = obstacles.first_overlap({foot, character.foot_radius});
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
  check_standing_apart(scenario, ground, planners);
  return check_on_ground(scenario, ground, planners);
}

/// plan_scenario, with the agents that `fixed` (empty, or one per agent)
/// gives a plan keeping it.
Plan plan_among(const Scenario& scenario, const RunControl& control,
                const std::vector<const AgentPlan*>& fixed) {
  const Ground ground(scenario.ground);
  const GroundLayers layers = validate_on(scenario, ground);
  const CollisionScene scene(scenario.obstacles);
  const detail::CharacterPlanners planners(scenario, &scene, &ground);
  Plan plan;
  plan.character = scenario.character;
  plan.obstacles = scenario.obstacles;
  plan.ground = scenario.ground;
  std::vector<AgentSpec> agents = scenario.agents;
  std::vector<const FootstepPlanner*> each;
  for (const AgentSpec& agent : agents) each.push_back(&planners.planner(agent));
  if (layers.count() > 1) {
    // Levels above one another: ways over the layers, none annotated.
    for (std::size_t i = 0; i < agents.size(); ++i)
      if (!fixed.empty() && fixed[i] != nullptr) agents[i].sections = fixed[i]->sections;
    plan.agents = plan_agents(agents, each, LayeredNavigation(scenario, layers), control, fixed);
    if (control.cancelled()) plan.status = Status::kCancelled;
    return plan;
  }
  const NavMesh mesh = layer_navmesh(scenario, layers, 0);
  detail::SectionPlanners sections(scenario, scene, planners);
  const std::vector<std::optional<Narrowest>> narrowest =
      detail::plan_sections(sections, agents, fixed);
  const Annotator annotate = [&](std::size_t i, Vec2 from, std::size_t first_goal) {
    return sections.plan(agents[i], from, first_goal);
  };
  plan.agents = plan_agents(agents, each, &mesh, control, fixed, annotate);
  // One that stops short stands at its last goal: none of the scenario's.
  for (std::size_t i = 0; i < agents.size(); ++i) {
    if (!narrowest[i]) continue;
    AgentPlan& agent = plan.agents[i];
    agent.status = AgentStatus::kPartial;
    agent.reason = "unreachable";
    agent.narrowest = narrowest[i];
    agent.goals_reached =
        std::min(agent.goals_reached, static_cast<int>(agents[i].goals.size()) - 1);
  }
  if (control.cancelled()) plan.status = Status::kCancelled;
  return plan;
}

}  // namespace

void validate(const Scenario& scenario) { validate_on(scenario, Ground(scenario.ground)); }

std::optional<std::string> standing_problem(const Ground& ground, const CharacterParams& character,
                                            Vec2 position, double facing,
                                            std::optional<double> height) {
  if (auto problem = standing_height_problem(ground, position, height, character.body_height))
    return problem;
  if (ground.empty()) return std::nullopt;
  return standing_feet_problem(ground, character, position, facing, height);
}

Plan plan_scenario(const Scenario& scenario, const RunControl& control) {
  return plan_among(scenario, control, {});
}

Plan replan_agents(const Scenario& scenario, const Plan& fixed,
                   const std::vector<std::string>& names, const RunControl& control) {
  if (names.empty()) throw std::invalid_argument("agents: name at least one agent to plan");
  std::set<std::string> chosen;
  for (const std::string& name : names) {
    const bool known = std::any_of(scenario.agents.begin(), scenario.agents.end(),
                                   [&](const AgentSpec& agent) { return agent.name == name; });
    if (!known) fail("agents", user_text(name) + " is not an agent of the scenario");
    chosen.insert(name);
  }
  std::map<std::string, const AgentPlan*> planned;
  for (const AgentPlan& agent : fixed.agents) planned.emplace(agent.name, &agent);
  std::vector<const AgentPlan*> each;
  for (const AgentSpec& agent : scenario.agents) {
    if (chosen.count(agent.name) > 0) {
      each.push_back(nullptr);
      continue;
    }
    const auto found = planned.find(agent.name);
    if (found == planned.end())
      fail("fixed", "has no plan for agent " + user_text(agent.name) +
                        ", which is not among the agents to plan");
    each.push_back(found->second);
  }
  return plan_among(scenario, control, each);
}


}  // namespace footfall
