// Footfall — checking a scenario, its navigation mesh, and planning it whole.
#include "footfall/crowd/scenario.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "footfall/model/footstep.hpp"
#include "footfall/planner/planner.hpp"
#include "util/field_path.hpp"
#include "util/quoted.hpp"

namespace footfall {

using detail::child;
using detail::fail;
using detail::item;
using detail::user_text;

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
      fail(child(path, "name"), user_text(agent.name) + " is used twice");
    if (!in_world(agent.position))
      fail(child(path, "position"), "must be finite and within 1e9 m of the origin");
    if (!std::isfinite(agent.facing)) fail(child(path, "facing"), "must be finite");
    if (agent.goals.empty()) fail(child(path, "goals"), "needs at least one goal");
    const FootstepState standing = standing_state(agent.position, agent.facing, scenario.character);
    if (planner.validity().collides(standing)) {
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

Plan plan_scenario(const Scenario& scenario, const RunControl& control) {
  validate(scenario);
  const ObstacleMap obstacles(scenario.obstacles);
  const FootstepPlanner planner(scenario.character, scenario.planner, obstacles);
  const NavMesh mesh = navmesh_of(scenario);
  Plan plan;
  plan.character = scenario.character;
  plan.obstacles = scenario.obstacles;
  plan.agents = plan_agents(scenario.agents, planner, &mesh, control);
  if (control.cancelled()) plan.status = Status::kCancelled;
  return plan;
}

NavMesh navmesh_of(const Scenario& scenario, double margin) {
  if (!(margin > 0)) throw std::invalid_argument("navmesh_of: margin must be > 0");
  Vec2 lo{0, 0}, hi{0, 0};
  bool any = false;
  auto grow = [&](Vec2 p) {
    lo = any ? Vec2{std::min(lo.x, p.x), std::min(lo.y, p.y)} : p;
    hi = any ? Vec2{std::max(hi.x, p.x), std::max(hi.y, p.y)} : p;
    any = true;
  };
  for (const Obstacle& o : scenario.obstacles)
    for (Vec2 p : o.polygon) grow(p);
  for (const AgentSpec& a : scenario.agents) {
    grow(a.position);
    for (Vec2 g : a.goals) grow(g);
  }
  // The margin stops at the world's edge: everything lies within it already.
  const auto inside = [](double v) { return std::clamp(v, -kMaxCoordinate, kMaxCoordinate); };
  NavMesh mesh({inside(lo.x - margin), inside(lo.y - margin)},
               {inside(hi.x + margin), inside(hi.y + margin)});
  for (std::size_t i = 0; i < scenario.obstacles.size(); ++i)
    mesh.add_polygon(scenario.obstacles[i].polygon, "obstacles[" + std::to_string(i) + "]");
  return mesh;
}

}  // namespace footfall
