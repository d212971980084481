// Footfall — path queries: a search over (triangle, entry edge) states that
// skips traversals too narrow for the disc, the funnel through each channel
// it offers, and an exact clearance check of every funnel path.
//
// Channels come out in order of a lower bound on the length of any path
// through them (the shortest start-portal-goal detour over each portal, kept
// r from its ends), so the first clear funnel path whose length is at most
// the next channel's bound is the shortest of all channels searched. The
// narrowness tests (portal length and corner width, both at least 2r) are
// necessary conditions: they never drop a channel a disc could pass. They are
// not sufficient everywhere (an obstacle beside a long portal can pinch a
// channel they accept), which is why every funnel path is measured against
// the obstacles; a channel that fails is skipped and the search goes on.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "channel_funnel.hpp"
#include "navmesh_impl.hpp"
#include "obstacle_distance.hpp"

namespace footfall {
namespace {

constexpr int kNoEdge = 3;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// A state is expanded again by a channel whose estimated length to it is
/// below this factor times the best so far: the estimate (straight lines
/// between crossing points) overrates channels that wind through many small
/// triangles, so a rival that looks a little longer may be the shorter.
constexpr double kRivalSlack = 1.25;
/// How far back a new triangle is looked for in its own channel.
constexpr int kLoopCheck = 8;
/// How often one (triangle, entry edge) state may be expanded, by channels
/// that reach it with a shorter estimate each time: enough for the few
/// channels that compete, and it bounds the work to a few passes over the mesh.
constexpr int kMaxExpansions = 4;
/// The search stops once no channel left can be shorter than the best path
/// by more than this fraction: the path is within 0.5 % of the shortest
/// through any channel, and long queries over open ground stop at the first.
constexpr double kLengthTolerance = 0.005;
/// Rounding allowance when comparing a measured clearance with the radius. [m]
constexpr double kClearanceSlack = 1e-9;

struct Node {
  Face face;
  int entry;
  int parent;
  Vec2 point;    // where the estimate assumes the path crosses the entry edge
  double g;      // estimated length from the start to `point`
  double bound;  // no path through the channel so far is shorter
};

/// The point of portal [a, b], kept `radius` from both ends, nearest to `p`.
Vec2 nearest_on_portal(Vec2 p, Vec2 a, Vec2 b, double radius) {
  const Vec2 d = b - a;
  const double len = length(d);
  const double lo = std::min(radius / len, 0.5), hi = std::max(1.0 - radius / len, 0.5);
  const double t = std::clamp(dot(p - a, d) / (len * len), lo, hi);
  return a + t * d;
}

/// The shortest |from - q| + |q - to| over q on portal [a, b] kept `radius`
/// from its ends: a lower bound on any path through it.
double detour_bound(Vec2 from, Vec2 to, Vec2 a, Vec2 b, double radius) {
  const Vec2 d = b - a;
  const double len = length(d);
  const Vec2 u = d * (1.0 / len);
  const Vec2 lo = a + std::min(radius, 0.5 * len) * u, hi = b - std::min(radius, 0.5 * len) * u;
  // Mirror `to` to the far side of the portal's line; the straight line from
  // `from` then meets the line where the detour is shortest, and the detour
  // is convex along the line, so clamping to the portal gives its minimum.
  const double sf = cross(u, from - a), st = cross(u, to - a);
  const Vec2 mirrored = (sf > 0) == (st > 0) && sf != 0 ? to - 2 * st * perp(u) : to;
  const double sm = cross(u, mirrored - a);
  const double along = sf == sm ? dot(from - lo, u) : dot(from + (sf / (sf - sm)) * (mirrored - from) - lo, u);
  const Vec2 q = lo + std::clamp(along, 0.0, length(hi - lo)) * u;
  return distance(from, q) + distance(q, to);
}

/// Triangles from start to goal and the portals between them: portal k
/// joins faces[k] and faces[k + 1].
struct Channel {
  std::vector<Face> faces;
  std::vector<Portal> portals;
};

class ChannelSearch {
 public:
  ChannelSearch(const NavMeshState& mesh, const PathQuery& q, Face start, Face goal)
      : mesh_(mesh), q_(q), goal_(goal) {
    faces_.reserve(1024);
    nodes_.push_back({start, kNoEdge, -1, q_.from, 0.0, distance(q_.from, q_.to)});
    open_.push({nodes_[0].bound, nodes_[0].bound, 0});
  }

  /// The next channel to the goal, in order of `bound`, the lower bound on
  /// the length of a path through it; false when none is left.
  bool next(Channel& channel, double& bound) {
    while (!open_.empty()) {
      const int index = std::get<2>(open_.top());
      open_.pop();
      const Node node = nodes_[index];
      if (node.face == goal_ && node.entry != kNoEdge) {
        unwind(index, channel);
        bound = node.bound;
        return true;
      }
      State& state = faces_[node.face].entries[node.entry];
      const bool better = node.g < state.best_g;
      if (!better && (state.expansions >= kMaxExpansions || node.g >= kRivalSlack * state.best_g))
        continue;
      ++state.expansions;
      state.best_g = std::min(state.best_g, node.g);
      for (int exit = 0; exit < 3; ++exit)
        if (exit != node.entry && passable(node, exit)) push_child(index, exit);
    }
    return false;
  }

 private:
  struct State {
    int expansions = 0;
    double best_g = std::numeric_limits<double>::infinity();
  };

  /// True if the channel ending at node `index` passed through `face` in its
  /// last kLoopCheck steps: a channel that circles back is never the shortest.
  bool circles_back(int index, Face face) const {
    for (int i = index, k = 0; i >= 0 && k < kLoopCheck; i = nodes_[i].parent, ++k)
      if (nodes_[i].face == face) return true;
    return false;
  }

  void push_child(int index, int exit) {
    const Node& node = nodes_[index];
    const Face next = node.face->neighbor(exit);
    if (circles_back(index, next)) return;
    const Vec2 a = to_vec(node.face->vertex(Cdt::ccw(exit))->point());
    const Vec2 b = to_vec(node.face->vertex(Cdt::cw(exit))->point());
    const Vec2 crossing = nearest_on_portal(node.point, a, b, q_.radius);
    const double g = node.g + distance(node.point, crossing);
    const double bound = std::max(node.bound, detour_bound(q_.from, q_.to, a, b, q_.radius));
    nodes_.push_back({next, next->index(node.face), index, crossing, g, bound});
    open_.push({bound, g + distance(crossing, q_.to), static_cast<int>(nodes_.size() - 1)});
  }

  bool passable(const Node& node, int exit) {
    const Face f = node.face;
    if (f->is_constrained(exit) || !mesh_.walkable(f->neighbor(exit))) return false;
    const double need = 2 * q_.radius;
    const Vec2 a = to_vec(f->vertex(Cdt::ccw(exit))->point());
    const Vec2 b = to_vec(f->vertex(Cdt::cw(exit))->point());
    if (distance(a, b) < need) return false;
    if (node.entry == kNoEdge) return true;
    // Each corner's width is measured once per query, however often its
    // face is expanded (the walk behind it is the costly part).
    double& width = faces_[f].corner_width[3 - node.entry - exit];
    if (std::isnan(width)) width = corner_width(mesh_, f, 3 - node.entry - exit, need);
    return width >= need;
  }

  void unwind(int index, Channel& channel) const {
    channel.portals.clear();
    channel.faces = {nodes_[index].face};
    for (int i = index; nodes_[i].parent >= 0; i = nodes_[i].parent) {
      // Walking out of the parent through this edge: its ends as seen from the parent.
      const Face from = nodes_[nodes_[i].parent].face;
      const int edge = from->index(nodes_[i].face);
      channel.portals.push_back({to_vec(from->vertex(Cdt::cw(edge))->point()),
                                 to_vec(from->vertex(Cdt::ccw(edge))->point())});
      channel.faces.push_back(from);
    }
    std::reverse(channel.portals.begin(), channel.portals.end());
    std::reverse(channel.faces.begin(), channel.faces.end());
  }

  const NavMeshState& mesh_;
  const PathQuery& q_;
  Face goal_;
  std::vector<Node> nodes_;
  /// (bound, estimated total length, node): lowest bound first, then the estimate.
  using Entry = std::tuple<double, double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open_;
  /// What the search knows of one face: its states by entry edge, and its
  /// corners' widths (NaN until measured).
  struct FaceSearch {
    std::array<State, 4> entries;
    std::array<double, 3> corner_width{kNaN, kNaN, kNaN};
  };
  std::unordered_map<Face, FaceSearch> faces_;
};

double polyline_length(const std::vector<Vec2>& points) {
  double total = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) total += distance(points[k], points[k + 1]);
  return total;
}

/// Where a polyline comes nearest to the obstacles.
struct Pinch {
  double clearance = std::numeric_limits<double>::infinity();
  NearestObstacle obstacle;  ///< The obstacle point there, and its edge.
  Vec2 path_point;  ///< The polyline's point nearest to it.
  Vec2 heading;     ///< The polyline's direction there.
  double along = 0.0;       ///< Length of the polyline up to `path_point`.
  bool in_free_space = true;  ///< False if a point of the polyline is not walkable.
};

/// Where `points` come nearest to the obstacles, looking only within `reach`
/// of them (clearance infinite if nothing is that near): the walk then stays
/// in the faces along the path.
Pinch find_pinch_within(const NavMeshState& mesh, const std::vector<Vec2>& points, double reach) {
  Pinch pinch;
  pinch.clearance = reach;
  Face hint;
  double along = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const Vec2 a = points[k], b = points[k + 1];
    hint = mesh.cdt.locate(to_point(a), hint);
    if (!mesh.walkable(hint)) {
      pinch.clearance = 0.0;
      pinch.in_free_space = false;
      return pinch;
    }
    NearestObstacle obstacle;
    const double d = obstacle_distance(mesh, hint, a, b, pinch.clearance, &obstacle);
    if (d < pinch.clearance) {
      const Vec2 on_path = closest_on_segment(obstacle.point, a, b);
      pinch = {d, obstacle, on_path, b - a, along + distance(a, on_path), true};
    }
    along += distance(a, b);
  }
  if (pinch.clearance == reach && pinch.in_free_space)
    pinch.clearance = std::numeric_limits<double>::infinity();
  return pinch;
}

/// Where `points` come nearest to the obstacles. A path that wraps a corner
/// touches its circle, so for a disc of `radius` the walk first looks only a
/// little beyond it, and further only for a path that met nothing so near.
Pinch find_pinch(const NavMeshState& mesh, const std::vector<Vec2>& points, double radius) {
  const Pinch near = find_pinch_within(mesh, points, 2 * radius + 0.1);
  if (near.clearance < std::numeric_limits<double>::infinity()) return near;
  return find_pinch_within(mesh, points, std::numeric_limits<double>::infinity());
}

/// An obstacle point outside the channel that its funnel path came too near
/// to: it becomes one more corner for the funnel to wrap (the query-time
/// counterpart of refining LCT's disturbances).
struct ExtraCorner {
  std::size_t face;  ///< Index of the channel face where the path came near it.
  double along;      ///< How far along the path that was.
  Vec2 point;
  bool left;         ///< On the walker's left.
};

/// The channel's portals with a portal at each extra corner, placed in the
/// face where it was met; its other end is a vertex of that face on the
/// other side.
std::vector<Portal> portals_with(const Channel& channel, std::vector<ExtraCorner> extra) {
  std::sort(extra.begin(), extra.end(), [](const ExtraCorner& a, const ExtraCorner& b) {
    return std::tie(a.face, a.along) < std::tie(b.face, b.along);
  });
  const std::vector<Portal>& portals = channel.portals;
  std::vector<Portal> out;
  std::size_t k = 0;
  for (std::size_t i = 0; i <= portals.size(); ++i) {
    for (; k < extra.size() && extra[k].face == i; ++k) {
      const Portal& beside = portals[i > 0 ? i - 1 : 0];  // both ends are vertices of face i
      out.push_back(extra[k].left ? Portal{extra[k].point, beside.right}
                                  : Portal{beside.left, extra[k].point});
    }
    if (i < portals.size()) out.push_back(portals[i]);
  }
  return out;
}

/// Index of the channel face nearest to `p` (the one holding it, up to rounding).
std::size_t face_index(const Channel& channel, Vec2 p) {
  std::size_t best = 0;
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < channel.faces.size(); ++i) {
    const Face f = channel.faces[i];
    double gap = 0.0;
    for (int e = 0; e < 3; ++e) {
      const Vec2 a = to_vec(f->vertex(Cdt::ccw(e))->point()), b = to_vec(f->vertex(Cdt::cw(e))->point());
      if (cross(b - a, p - a) < 0) gap = std::max(gap, distance_to_segment(p, a, b));
    }
    if (gap < best_gap) {
      best_gap = gap;
      best = i;
    }
  }
  return best;
}

constexpr int kMaxExtraCorners = 16;

/// The shortest path through `channel` that clears the radius, wrapping
/// obstacles beside the channel as they turn up. False if the channel is too
/// narrow, or its path would not be shorter than `give_up_length`.
bool clear_path(const NavMeshState& mesh, const PathQuery& q, const Channel& channel,
                double give_up_length, std::vector<Vec2>& points, double& clearance) {
  std::vector<ExtraCorner> extra;
  for (int pass = 0; pass <= kMaxExtraCorners; ++pass) {
    FunnelPath path = funnel(q.from, q.to, portals_with(channel, extra), q.radius, q.arc_tolerance);
    if (!path.ok || polyline_length(path.points) >= give_up_length) return false;
    const Pinch pinch = find_pinch(mesh, path.points, q.radius);
    if (pinch.clearance >= q.radius - kClearanceSlack) {
      points = std::move(path.points);
      clearance = pinch.clearance;
      return true;
    }
    if (!pinch.in_free_space) return false;
    // Near an edge, its ends are the corners to wrap (its foot slides along
    // as the path bends); the foot itself only once both ends are in.
    const NearestObstacle& near = pinch.obstacle;
    const bool left = cross(pinch.heading, near.point - pinch.path_point) > 0;
    auto known = [&](Vec2 p) {
      return std::any_of(extra.begin(), extra.end(), [&](const ExtraCorner& c) { return c.point == p; });
    };
    const Vec2 candidates[3] = {near.edge_from, near.edge_to, near.point};
    const Vec2* corner = std::find_if(std::begin(candidates), std::end(candidates),
                                      [&](Vec2 p) { return !known(p); });
    if (corner == std::end(candidates)) return false;  // all wrapped already: no progress
    extra.push_back({face_index(channel, *corner), pinch.along, *corner, left});
  }
  return false;
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
  double best = std::numeric_limits<double>::infinity();
  auto keep = [&](std::vector<Vec2> points, double clearance) {
    best = polyline_length(points);
    result.status = PathStatus::kFound;
    result.length = best;
    result.min_clearance = clearance;
    result.points = std::move(points);
  };
  std::vector<Vec2> points;
  double clearance = 0.0;
  if (start == goal) {
    const Pinch pinch = find_pinch(m, {q.from, q.to}, q.radius);
    if (pinch.clearance >= q.radius - kClearanceSlack) {
      keep({q.from, q.to}, pinch.clearance);
      return result;  // nothing is shorter
    }
  }
  ChannelSearch search(m, q, start, goal);
  Channel channel;
  double bound = 0.0;
  while (search.next(channel, bound) && bound * (1 + kLengthTolerance) < best)
    if (clear_path(m, q, channel, best, points, clearance)) keep(std::move(points), clearance);
  return result;  // kNoPath unless a channel gave a path
}

}  // namespace footfall
