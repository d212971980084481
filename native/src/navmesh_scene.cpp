// Footfall — the navigation mesh of a scenario, and path results as JSON.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "footfall/navmesh.hpp"
#include "footfall/scenario.hpp"

namespace footfall {

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
  NavMesh mesh(lo - Vec2{margin, margin}, hi + Vec2{margin, margin});
  for (std::size_t i = 0; i < scenario.obstacles.size(); ++i)
    mesh.add_polygon(scenario.obstacles[i].polygon, "obstacles[" + std::to_string(i) + "]");
  return mesh;
}

std::string to_json(const PathResult& result) {
  nlohmann::json points = nlohmann::json::array();
  for (Vec2 p : result.points) points.push_back({p.x, p.y});
  return nlohmann::ordered_json{{"status", to_string(result.status)},
                        {"points", points},
                        {"length", result.length},
                        {"min_clearance", result.min_clearance}}
      .dump();
}

}  // namespace footfall
