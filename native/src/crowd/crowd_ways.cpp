// Footfall — a walker's way to its goal (crowd_ways.hpp).
#include "crowd/crowd_ways.hpp"

#include <limits>

namespace footfall::crowd {
namespace {

/// The annotated way to the goal from `from`: from the nearest point of the
/// guide on, when that point is within kGuideReach and in sight (the torso
/// circle passes); else nothing, and the way is measured on the mesh.
constexpr double kGuideReach = 1.0;  // [m]
bool guided_way(const std::vector<Vec2>& guide, const NavMesh* mesh,
                const CharacterParams& character, Vec2 from, Way& way) {
  if (guide.size() < 2) return false;
  double nearest = std::numeric_limits<double>::infinity();
  std::size_t piece = 0;
  Vec2 join;
  for (std::size_t k = 1; k < guide.size(); ++k) {
    const Vec2 p = closest_on_segment(from, guide[k - 1], guide[k]);
    const double d = distance(from, p);
    if (d < nearest) {
      nearest = d;
      piece = k;
      join = p;
    }
  }
  if (nearest > kGuideReach) return false;
  if (mesh != nullptr && nearest > 0.0 &&
      mesh->clearance_between(from, join, character.torso_radius) < character.torso_radius)
    return false;
  way.points = {from};
  if (!(join == from)) way.points.push_back(join);
  way.points.insert(way.points.end(), guide.begin() + static_cast<long>(piece), guide.end());
  way.length = polyline_length(way.points);
  return true;
}

/// The way from `from` to `goal` (walker w's, or a point on the way to it):
/// one of its known ways if
/// one starts and ends there (the mesh does not change while the agents plan,
/// so it would come out the same); else its annotated way where it has one
/// (unless it takes the roomiest ways, stuck once); else measured anew, a
/// roomy way out of a tight place passing none of the agents it sees
/// (`seen`, where they stand `now`), or round a crowd on it (`crowd`, if
/// any: congestion.hpp).
Way way_toward(const Walker& w, const NavMesh* mesh, const CrowdDensity* crowd,
               const CharacterParams& character, Vec2 from, Vec2 goal,
               const std::vector<std::size_t>& seen, const Snapshot& now) {
  for (const KnownWay& k : w.ways)
    if (k.from == from && k.goal == goal) return k.way;
  Way way;
  if (!w.roomy && w.goal < w.guides.size() &&
      guided_way(w.guides[w.goal], mesh, character, from, way))
    return way;
  std::vector<Vec2> others;
  if (w.roomy)
    for (const std::size_t j : seen)
      if (now.present[j]) others.push_back(now.com[j]);
  way = footfall::way_toward(mesh, character, from, goal, w.roomy, others, w.roomy_at);
  if (mesh == nullptr || crowd == nullptr || w.roomy) return way;
  std::optional<Way> round = crowd->way_round(way, *mesh, sway_room(character));
  return round ? std::move(*round) : way;
}

}  // namespace

int CrowdWays::layer_of(const FootstepState& state) const {
  if (layered == nullptr) return 0;
  return layered->layer_under(state.com,
                              state.foot_heights[1 - static_cast<int>(state.last_foot)]);
}

LayerWay way_on(const Walker& w, const CrowdWays& ways, const CharacterParams& character,
                const FootstepState& from, const std::vector<std::size_t>& seen,
                const Snapshot& now) {
  const Vec2 goal = w.spec->goals[w.goal];
  const int here = ways.layer_of(from);
  const NavMesh* mesh = ways.mesh_of(here);
  const CrowdDensity* crowd = now.crowds.empty() ? nullptr : &now.crowds[here];
  const auto direct = [&] {
    return LayerWay{way_toward(w, mesh, crowd, character, from.com, goal, seen, now),
                    std::nullopt};
  };
  if (ways.layered == nullptr || ways.layered->layers() == 1) return direct();
  const std::vector<std::optional<double>>& heights = w.spec->goal_heights;
  const double goal_height = w.goal < heights.size() && heights[w.goal]
                                 ? *heights[w.goal]
                                 : -std::numeric_limits<double>::infinity();  // the lowest
  const int there = ways.layered->layer_under(goal, goal_height);
  const PathQuery query{from.com, goal, character.torso_radius};
  if (here == there && mesh->find_path(query).status == PathStatus::kFound) return direct();
  const LayeredPath route = ways.layered->route(query, here, there);
  std::size_t k = 1;
  while (k < route.layers.size() && route.layers[k] == route.layers[k - 1]) ++k;
  if (route.path.status != PathStatus::kFound || k >= route.layers.size()) return direct();
  const std::vector<Vec2>& points = route.path.points;
  LayerWay on{way_toward(w, mesh, crowd, character, from.com, points[k - 1], seen, now),
              points[k]};
  for (std::size_t j = k; j < points.size(); ++j)
    on.way.length += distance(points[j - 1], points[j]);
  return on;
}

}  // namespace footfall::crowd
