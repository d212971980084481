// Footfall — path queries: A* over (triangle, entry edge) states that skips
// traversals too narrow for the disc, the funnel through the chosen channel,
// and an exact clearance check of the result.
//
// The narrowness tests (portal length and corner width, both at least 2r)
// are necessary conditions, so the search never drops a channel a disc could
// pass. They are not sufficient everywhere (an obstacle beside a long portal
// can pinch a channel they accept), so every path is measured against the
// obstacles before it is returned; a channel that fails is banned at the
// traversal where it came too close, and the search runs again.
#include <algorithm>
#include <cmath>
#include <queue>
#include <set>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "channel_funnel.hpp"
#include "navmesh_impl.hpp"
#include "obstacle_distance.hpp"

namespace footfall {
namespace {

constexpr int kNoEdge = 3;
constexpr int kMaxChannelRetries = 32;
/// Rounding allowance when comparing a measured clearance with the radius. [m]
constexpr double kClearanceSlack = 1e-9;

/// A traversal: through `face`, in by edge `entry` (kNoEdge at the start), out by edge `exit`.
using Traversal = std::tuple<Face, int, int>;

struct Node {
  Face face;
  int entry;
  int parent;
  Vec2 point;  // where the search assumes the path crosses the entry edge
  double g;
};

/// The point of portal [a, b], kept `radius` from both ends, nearest to `p`.
Vec2 nearest_on_portal(Vec2 p, Vec2 a, Vec2 b, double radius) {
  const Vec2 d = b - a;
  const double len = length(d);
  const double lo = std::min(radius / len, 0.5), hi = std::max(1.0 - radius / len, 0.5);
  const double t = std::clamp(dot(p - a, d) / (len * len), lo, hi);
  return a + t * d;
}

class ChannelSearch {
 public:
  ChannelSearch(const NavMeshState& mesh, const PathQuery& q, Face start, Face goal)
      : mesh_(mesh), q_(q), start_(start), goal_(goal) {}

  /// The portals of the best channel found, or false.
  bool run(const std::set<Traversal>& banned, std::vector<Portal>& portals,
           std::vector<Traversal>& traversals) {
    nodes_.clear();
    closed_.clear();
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    nodes_.push_back({start_, kNoEdge, -1, q_.from, 0.0});
    open.push({distance(q_.from, q_.to), 0});
    while (!open.empty()) {
      const int index = open.top().second;
      open.pop();
      const Node node = nodes_[index];
      if (!closed_[node.face].insert(node.entry).second) continue;
      if (node.face == goal_ && node.entry != kNoEdge) {
        unwind(index, portals, traversals);
        return true;
      }
      for (int exit = 0; exit < 3; ++exit) {
        if (exit == node.entry || !passable(node, exit, banned)) continue;
        const Face next = node.face->neighbor(exit);
        const Vec2 a = to_vec(node.face->vertex(Cdt::ccw(exit))->point());
        const Vec2 b = to_vec(node.face->vertex(Cdt::cw(exit))->point());
        const Vec2 crossing = nearest_on_portal(node.point, a, b, q_.radius);
        const double g = node.g + distance(node.point, crossing);
        nodes_.push_back({next, next->index(node.face), index, crossing, g});
        open.push({g + distance(crossing, q_.to), static_cast<int>(nodes_.size() - 1)});
      }
    }
    return false;
  }

 private:
  bool passable(const Node& node, int exit, const std::set<Traversal>& banned) const {
    const Face f = node.face;
    if (f->is_constrained(exit) || !mesh_.walkable(f->neighbor(exit))) return false;
    const double need = 2 * q_.radius;
    const Vec2 a = to_vec(f->vertex(Cdt::ccw(exit))->point());
    const Vec2 b = to_vec(f->vertex(Cdt::cw(exit))->point());
    if (distance(a, b) < need) return false;
    if (banned.count({f, node.entry, exit})) return false;
    if (node.entry == kNoEdge) return true;
    return corner_width(mesh_, f, 3 - node.entry - exit, need) >= need;
  }

  void unwind(int index, std::vector<Portal>& portals, std::vector<Traversal>& traversals) const {
    portals.clear();
    traversals.clear();
    int exit = kNoEdge;
    for (int i = index; i >= 0; i = nodes_[i].parent) {
      const Node& n = nodes_[i];
      traversals.push_back({n.face, n.entry, exit});
      if (n.parent >= 0) {
        // Walking out of the parent through this edge: its ends as seen from the parent.
        const Face from = nodes_[n.parent].face;
        const int edge = from->index(n.face);
        portals.push_back({to_vec(from->vertex(Cdt::cw(edge))->point()),
                           to_vec(from->vertex(Cdt::ccw(edge))->point())});
        exit = edge;
      }
    }
    std::reverse(portals.begin(), portals.end());
    std::reverse(traversals.begin(), traversals.end());
  }

  const NavMeshState& mesh_;
  const PathQuery& q_;
  Face start_, goal_;
  std::vector<Node> nodes_;
  std::unordered_map<Face, std::set<int>> closed_;
};

/// Smallest clearance along `points` and the index of the segment where it is.
double polyline_clearance(const NavMeshState& mesh, const std::vector<Vec2>& points,
                          std::size_t& worst) {
  double best = std::numeric_limits<double>::infinity();
  Face hint;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    hint = mesh.cdt.locate(to_point(points[k]), hint);
    const double d = mesh.walkable(hint) ? obstacle_distance(mesh, hint, points[k], points[k + 1])
                                         : 0.0;
    if (d < best) {
      best = d;
      worst = k;
    }
  }
  return best;
}

double polyline_length(const std::vector<Vec2>& points) {
  double total = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) total += distance(points[k], points[k + 1]);
  return total;
}

/// The traversal of the channel whose face holds `p`, or the middle one.
Traversal traversal_at(const NavMeshState& mesh, const std::vector<Traversal>& channel, Vec2 p) {
  const Face f = mesh.cdt.locate(to_point(p));
  for (const Traversal& t : channel)
    if (std::get<0>(t) == f) return t;
  return channel[channel.size() / 2];
}

}  // namespace

PathResult NavMesh::find_path(const PathQuery& q) const {
  if (!in_world(q.from) || !in_world(q.to))
    throw std::invalid_argument("find_path: start and goal must be finite coordinates within 1e9 m");
  if (!(q.radius >= 0) || !std::isfinite(q.radius))
    throw std::invalid_argument("find_path: radius must be a finite number >= 0");
  if (!(q.arc_tolerance > 0) || !std::isfinite(q.arc_tolerance))
    throw std::invalid_argument("find_path: arc_tolerance must be a finite number > 0");
  const NavMeshState& m = *impl_;
  PathResult result;
  if (!m.in_domain(q.from) || !m.in_domain(q.to)) {
    result.status = PathStatus::kOutside;
    return result;
  }
  const Face start = m.cdt.locate(to_point(q.from)), goal = m.cdt.locate(to_point(q.to), start);
  auto blocked = [&](Face f, Vec2 p) {
    return !m.walkable(f) || obstacle_distance(m, f, p, p, q.radius) < q.radius;
  };
  if (blocked(start, q.from)) {
    result.status = PathStatus::kStartBlocked;
    return result;
  }
  if (blocked(goal, q.to)) {
    result.status = PathStatus::kGoalBlocked;
    return result;
  }
  auto accept = [&](std::vector<Vec2> points, std::size_t& worst) {
    const double clearance = polyline_clearance(m, points, worst);
    if (clearance < q.radius - kClearanceSlack) return false;
    result.status = PathStatus::kFound;
    result.length = polyline_length(points);
    result.min_clearance = clearance;
    result.points = std::move(points);
    return true;
  };
  std::size_t worst = 0;
  if (start == goal && accept({q.from, q.to}, worst)) return result;
  ChannelSearch search(m, q, start, goal);
  std::set<Traversal> banned;
  std::vector<Portal> portals;
  std::vector<Traversal> channel;
  for (int attempt = 0; attempt < kMaxChannelRetries; ++attempt) {
    if (!search.run(banned, portals, channel)) break;
    FunnelPath path = funnel(q.from, q.to, portals, q.radius, q.arc_tolerance);
    if (!path.ok) {
      banned.insert(channel[path.failed_portal + 1]);
      continue;
    }
    const std::vector<Vec2> points = path.points;
    if (accept(std::move(path.points), worst)) return result;
    const Vec2 near = 0.5 * (points[worst] + points[worst + 1]);
    banned.insert(traversal_at(m, channel, near));
  }
  result.status = PathStatus::kNoPath;
  return result;
}

}  // namespace footfall
