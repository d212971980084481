// Footfall — navigation meshes of a scenario's ground layers, and ways over them.
#include "footfall/crowd/navigation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <stdexcept>
#include <utility>

#include "footfall/crowd/crowd_planner.hpp"
#include "footfall/ground/foothold.hpp"
#include "navmesh/outline_union.hpp"

namespace footfall {
namespace {

constexpr double kGroundWallWidth = 0.02;  // [m] a ground wall's obstacle in the mesh
constexpr double kCrossingSpacing = 1.0;   // [m] between the points a way may cross a portal at
constexpr double kCrossingRoom = 0.01;     // [m] beyond the disc, from the portal's walls

std::string two_places(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

/// A place a way may stand at: on one layer, at a point (the start, the
/// goal, or one side of a crossing between layers).
struct Stop {
  Vec2 at;
  int layer = 0;
  int twin = -1;  ///< The crossing's other side, on another layer; -1 for the start and the goal.
};

}  // namespace

NavMesh layer_navmesh(const Scenario& scenario, const GroundLayers& layers, int layer,
                      double margin) {
  if (!(margin > 0)) throw std::invalid_argument("navmesh_of: margin must be > 0");
  Vec2 lo{0, 0}, hi{0, 0};
  bool any = false;
  auto grow = [&](Vec2 p) {
    lo = any ? Vec2{std::min(lo.x, p.x), std::min(lo.y, p.y)} : p;
    hi = any ? Vec2{std::max(hi.x, p.x), std::max(hi.y, p.y)} : p;
    any = true;
  };
  const double headroom = scenario.character.body_height;
  const std::vector<double> cuts =
      layers.count() > 1 ? cut_heights(layers, scenario.obstacles, layer)
                         : cut_heights(layers.ground(), scenario.obstacles, headroom);
  std::vector<std::vector<Vec2>> footprints;
  for (std::size_t i = 0; i < scenario.obstacles.size(); ++i) {
    footprints.push_back(footprint(scenario.obstacles[i], cuts[i]));
    for (Vec2 p : footprints.back()) grow(p);
  }
  // The layer's walls: the edges of its ground no one steps across, as thin
  // obstacles after the obstacles.
  for (const GroundWall& wall : layers.walls(layer)) {
    const Vec2 side = (0.5 * kGroundWallWidth / distance(wall.a, wall.b)) * perp(wall.b - wall.a);
    footprints.push_back({wall.a - side, wall.b - side, wall.b + side, wall.a + side});
    for (Vec2 p : footprints.back()) grow(p);
  }
  for (const AgentSpec& a : scenario.agents) {
    grow(a.position);
    for (Vec2 g : a.goals) grow(g);
  }
  // The margin stops at the world's edge: everything lies within it already.
  const auto inside = [](double v) { return std::clamp(v, -kMaxCoordinate, kMaxCoordinate); };
  NavMesh mesh({inside(lo.x - margin), inside(lo.y - margin)},
               {inside(hi.x + margin), inside(hi.y + margin)});
  // Obstacle i gets id i; one wholly above the head (no footprint) blocks
  // nothing. Overlapping ones enter as their union, under the first one's id.
  std::vector<int> merged_into(footprints.size(), -1);
  std::map<int, Region> regions;
  for (OverlapGroup& group : overlapping_groups(footprints)) {
    for (int i : group.members) merged_into[i] = group.members.front();
    regions[group.members.front()] = std::move(group.region);
  }
  for (std::size_t i = 0; i < footprints.size(); ++i) {
    const std::string name =
        i < scenario.obstacles.size()
            ? "obstacles[" + std::to_string(i) + "]"
            : "ground wall " + std::to_string(i - scenario.obstacles.size());
    const int first = merged_into[i];
    if (footprints[i].empty() || (first >= 0 && first != static_cast<int>(i)))
      mesh.add_empty();
    else if (first >= 0)
      mesh.add_region(regions[first].outlines, regions[first].holes, name);
    else
      mesh.add_polygon(footprints[i], name);
  }
  return mesh;
}

NavMesh navmesh_of(const Scenario& scenario, double margin) {
  const Ground ground(scenario.ground);
  return layer_navmesh(scenario, layers_for(ground, scenario.character), 0, margin);
}

LayeredNavigation::LayeredNavigation(const Scenario& scenario, double margin)
    : owned_(std::make_unique<const Ground>(scenario.ground)),
      ground_(owned_.get()),
      layers_(layers_for(*ground_, scenario.character)) {
  make_meshes(scenario, margin);
}

LayeredNavigation::LayeredNavigation(const Scenario& scenario, GroundLayers layers, double margin)
    : ground_(&layers.ground()), layers_(std::move(layers)) {
  make_meshes(scenario, margin);
}

void LayeredNavigation::make_meshes(const Scenario& scenario, double margin) {
  for (int layer = 0; layer < layers_.count(); ++layer)
    meshes_.push_back(layer_navmesh(scenario, layers_, layer, margin));
}

int LayeredNavigation::layer_at(Vec2 p, std::optional<double> z, const std::string& field) const {
  if (ground_->empty()) return 0;
  const std::vector<GroundPoint> levels = ground_->standable_at(p, layers_.headroom());
  const std::string where = "(" + two_places(p.x) + ", " + two_places(p.y) + ")";
  if (levels.empty())
    throw std::invalid_argument(field + ": " + where + " is over no ground to stand on");
  if (z) {
    const std::optional<GroundPoint> nearest = ground_->standable_near(p, *z, layers_.headroom());
    if (std::fabs(nearest->z - *z) > kHeightReach)
      throw std::invalid_argument(field + ": no ground to stand on within 0.50 m of the height " +
                                  two_places(*z) + " m at " + where);
    return layers_.layer_of(*nearest);
  }
  if (levels.size() > 1)
    throw std::invalid_argument(field + ": " + std::to_string(levels.size()) + " levels at " +
                                where + ", at " + two_places(levels[0].z) + " and " +
                                two_places(levels[1].z) + " m: give its height (X,Y,Z)");
  return layers_.layer_of(levels.front());
}

PathResult LayeredNavigation::find_path(const PathQuery& query, int from_layer,
                                        int to_layer) const {
  LayeredPath way = route(query, from_layer, to_layer);
  if (ground_->empty()) return std::move(way.path);
  for (std::size_t k = 0; k < way.path.points.size(); ++k) {
    const std::optional<GroundPoint> level = layers_.level_on(way.path.points[k], way.layers[k]);
    const std::vector<double>& heights = way.path.heights;
    way.path.heights.push_back(level ? level->z : heights.empty() ? 0.0 : heights.back());
  }
  return std::move(way.path);
}

int LayeredNavigation::layer_under(Vec2 p, double z) const {
  if (layers() == 1) return 0;
  const std::optional<GroundPoint> level = ground_->standable_near(p, z, layers_.headroom());
  return level ? layers_.layer_of(*level) : 0;
}

LayeredPath LayeredNavigation::route(const PathQuery& query, int from_layer, int to_layer) const {
  if (layers() == 1) {
    PathResult path = meshes_.front().find_path(query);
    std::vector<int> on(path.points.size(), 0);
    return {std::move(path), std::move(on)};
  }
  // The start, the goal, and both sides of points along each portal.
  std::vector<Stop> stops{{query.from, from_layer}, {query.to, to_layer}};
  const double off = query.radius + 0.5 * kGroundWallWidth + kCrossingRoom;
  for (const GroundPortal& portal : layers_.portals()) {
    const double span = distance(portal.a, portal.b), usable = span - 2 * off;
    if (usable < 0) continue;
    const Vec2 along = (1.0 / span) * (portal.b - portal.a);
    // Points spread along it, and where the straight way and the ends' own
    // nearest points meet it.
    std::vector<double> places;
    const int spread = 1 + static_cast<int>(std::floor(usable / kCrossingSpacing));
    for (int k = 0; k < spread; ++k)
      places.push_back(spread == 1 ? 0.5 * usable : usable * k / (spread - 1));
    const Vec2 way = query.to - query.from;
    const double across_way = cross(way, along);
    if (across_way != 0.0)
      places.push_back(cross(way, query.from - portal.a) / across_way - off);
    for (const Vec2 end : {query.from, query.to})
      places.push_back(dot(end - portal.a, along) - off);
    for (double& place : places) place = std::clamp(place, 0.0, usable);
    std::sort(places.begin(), places.end());
    places.erase(std::unique(places.begin(), places.end()), places.end());
    for (const double place : places) {
      const Vec2 p = portal.a + (off + place) * along;
      const int near = static_cast<int>(stops.size());
      stops.push_back({p - off * portal.across, portal.from, near + 1});
      stops.push_back({p + off * portal.across, portal.to, near});
    }
  }
  // Dijkstra's search over the stops, each leg on one layer found as it is needed.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> cost(stops.size(), inf);
  std::vector<int> before(stops.size(), -1);
  std::vector<PathResult> leg(stops.size());  // the way from `before` to each stop on its layer
  std::vector<bool> done(stops.size(), false);
  bool start_blocked = false, goal_blocked = false, outside = false;
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[0] = 0;
  open.push({0, 0});
  while (!open.empty()) {
    const double c = open.top().first;  // not bound: lambdas below take them
    const int s = open.top().second;
    open.pop();
    if (done[s]) continue;
    done[s] = true;
    if (s == 1) break;
    const auto reach = [&](int t, PathResult way) {
      if (done[t] || !(c + way.length < cost[t])) return;
      cost[t] = c + way.length;
      before[t] = s;
      leg[t] = std::move(way);
      open.push({cost[t], t});
    };
    if (stops[s].twin >= 0) {
      const Stop& twin = stops[stops[s].twin];
      PathResult jump{PathStatus::kFound, {stops[s].at, twin.at}, distance(stops[s].at, twin.at),
                      query.radius, {}};
      reach(stops[s].twin, std::move(jump));
    }
    for (int t = 1; t < static_cast<int>(stops.size()); ++t) {
      if (t == s || done[t] || stops[t].layer != stops[s].layer) continue;
      PathResult way = meshes_[stops[s].layer].find_path(
          {stops[s].at, stops[t].at, query.radius, query.arc_tolerance});
      start_blocked = start_blocked || way.status == PathStatus::kStartBlocked;
      goal_blocked = goal_blocked || way.status == PathStatus::kGoalBlocked;
      outside = outside || way.status == PathStatus::kOutside;
      if (way.status == PathStatus::kFound) reach(t, std::move(way));
    }
  }
  if (before[1] < 0) {
    LayeredPath none;
    none.path.status = outside         ? PathStatus::kOutside
                       : start_blocked ? PathStatus::kStartBlocked
                       : goal_blocked  ? PathStatus::kGoalBlocked
                                       : PathStatus::kNoPath;
    return none;
  }
  std::vector<int> chain{1};
  while (chain.back() != 0) chain.push_back(before[chain.back()]);
  std::reverse(chain.begin(), chain.end());
  LayeredPath joined;
  PathResult& result = joined.path;
  result.status = PathStatus::kFound;
  result.min_clearance = inf;
  for (std::size_t k = 1; k < chain.size(); ++k) {
    const PathResult& piece = leg[chain[k]];
    const bool crossing = stops[chain[k - 1]].twin == chain[k];
    for (std::size_t i = result.points.empty() ? 0 : 1; i < piece.points.size(); ++i) {
      result.points.push_back(piece.points[i]);
      joined.layers.push_back(crossing && i == 1 ? stops[chain[k]].layer
                                                 : stops[chain[k - 1]].layer);
    }
    result.length += piece.length;
    result.min_clearance = std::min(result.min_clearance, piece.min_clearance);
  }
  return joined;
}

}  // namespace footfall
