#include "navmesh/navmesh_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <queue>
#include <sstream>
#include <utility>

// A shortest path for a disc of radius r is made of segments tangent to circles
// of radius r around obstacle corners (polygon vertices and points) and arcs of
// those circles: it never bends anywhere else, not at the domain's boundary (the
// shrunk rectangle is convex) nor where inflated obstacles meet (those corners
// point away from the free space). So the graph's nodes are the exact tangent
// points between every two circles and from the start and goal to every circle;
// its edges are the tangent segments and the arcs between neighbouring nodes on
// a circle, each checked against every obstacle exactly.

namespace footfall::testing {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// An axis-aligned bounding box.
struct Box {
  Vec2 lo;
  Vec2 hi;
};

Box bounds(Vec2 a, Vec2 b) {
  return {{std::min(a.x, b.x), std::min(a.y, b.y)}, {std::max(a.x, b.x), std::max(a.y, b.y)}};
}

/// A lower bound of the distance between anything in `a` and anything in `b`.
double box_gap(const Box& a, const Box& b) {
  const double dx = std::max({0.0, a.lo.x - b.hi.x, b.lo.x - a.hi.x});
  const double dy = std::max({0.0, a.lo.y - b.hi.y, b.lo.y - a.hi.y});
  return std::hypot(dx, dy);
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return length(p - (a + t * ab));
}

/// Touching and collinear segments are left to the endpoint distances,
/// which are then 0.
double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segments_cross(a, b, c, d)) return 0.0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d),
                   point_segment_distance(c, a, b), point_segment_distance(d, a, b)});
}

/// Winding number of `polygon` around `p`.
int winding(const std::vector<Vec2>& polygon, Vec2 p) {
  int turns = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const double side = cross(b - a, p - a);
    if (a.y <= p.y && b.y > p.y && side > 0) ++turns;
    if (b.y <= p.y && a.y > p.y && side < 0) --turns;
  }
  return turns;
}

/// The scene's obstacles with bounding boxes, for many distance queries.
class Obstacles {
 public:
  explicit Obstacles(const NavScene& scene) : scene_(scene) {
    for (const std::vector<Vec2>& polygon : scene.polygons) {
      Box box{polygon.at(0), polygon.at(0)};
      for (size_t i = 0; i < polygon.size(); ++i) {
        const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        edges_.push_back({a, b, bounds(a, b)});
        box = {bounds(box.lo, a).lo, bounds(box.hi, a).hi};
      }
      polygon_boxes_.push_back(box);
    }
    // A point obstacle is an edge of zero length.
    for (Vec2 p : scene.points) edges_.push_back({p, p, bounds(p, p)});
  }

  /// True if `p` is outside the domain or inside a polygon.
  bool blocked(Vec2 p) const {
    if (p.x < scene_.min_corner.x || p.x > scene_.max_corner.x || p.y < scene_.min_corner.y ||
        p.y > scene_.max_corner.y) {
      return true;
    }
    for (size_t i = 0; i < polygon_boxes_.size(); ++i) {
      if (box_gap(polygon_boxes_[i], bounds(p, p)) > 0.0) continue;
      if (winding(scene_.polygons[i], p) != 0) return true;
    }
    return false;
  }

  /// Distance from the segment [a, b] to the nearest obstacle, or `cap` if
  /// that is smaller (obstacles farther than the best so far are skipped).
  double segment_clearance(Vec2 a, Vec2 b, double cap) const {
    // A segment entering a polygon from outside crosses an edge; one leaving
    // the (convex) domain has an endpoint outside.
    if (blocked(a) || blocked(b)) return 0.0;
    double best = std::min({cap, boundary_distance(a), boundary_distance(b)});
    const Box box = bounds(a, b);
    for (const Edge& edge : edges_) {
      if (box_gap(box, edge.box) >= best) continue;
      best = std::min(best, segment_distance(a, b, edge.a, edge.b));
    }
    return best;
  }

 private:
  struct Edge {
    Vec2 a;
    Vec2 b;
    Box box;
  };

  double boundary_distance(Vec2 p) const {
    return std::min({p.x - scene_.min_corner.x, scene_.max_corner.x - p.x,
                     p.y - scene_.min_corner.y, scene_.max_corner.y - p.y});
  }

  const NavScene& scene_;
  std::vector<Box> polygon_boxes_;
  std::vector<Edge> edges_;
};

/// A node of the tangent graph: the start, the goal, or a point on a corner's circle.
struct Node {
  Vec2 p;
  int circle = -1;         // Index of the circle's centre; -1 for the start and goal.
  double angle = 0.0;      // Of p around the circle's centre. [rad]
  std::vector<int> links;  // Nodes joined to this one by a tangent segment.
  int ccw = -1;            // Next node counter-clockwise on the circle.
  int cw = -1;             // Next node clockwise on the circle.
};

/// How a path step goes from one node to the next.
enum class Move { kSegment, kCounterClockwise, kClockwise };

/// Tangent segments and circle arcs around every corner; nodes 0 and 1 are the
/// start and the goal.
struct TangentGraph {
  std::vector<Vec2> centres;  // Obstacle corners.
  double rho = 0.0;           // Circle radius, a hair above the disc's. [m]
  std::vector<Node> nodes;
};

/// Polygon vertices and point obstacles, each once.
std::vector<Vec2> corner_centres(const NavScene& scene) {
  std::vector<Vec2> centres = scene.points;
  for (const std::vector<Vec2>& polygon : scene.polygons) {
    centres.insert(centres.end(), polygon.begin(), polygon.end());
  }
  const auto less = [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  std::sort(centres.begin(), centres.end(), less);
  centres.erase(std::unique(centres.begin(), centres.end()), centres.end());
  return centres;
}

int add_node(TangentGraph& graph, Vec2 p, int circle) {
  Node node;
  node.p = p;
  node.circle = circle;
  if (circle >= 0) node.angle = angle_of(p - graph.centres[circle]);
  graph.nodes.push_back(node);
  return static_cast<int>(graph.nodes.size()) - 1;
}

void add_segment(TangentGraph& graph, int circle_a, Vec2 a, int circle_b, Vec2 b) {
  const int u = add_node(graph, a, circle_a), v = add_node(graph, b, circle_b);
  graph.nodes[u].links.push_back(v);
  graph.nodes[v].links.push_back(u);
}

/// The two points where lines through `q` touch the circle (c, rho); false if
/// `q` is not outside it.
bool tangent_points(Vec2 q, Vec2 c, double rho, Vec2 (&touch)[2]) {
  const double d = distance(q, c);
  if (!(d > rho)) return false;
  const double base = angle_of(q - c), spread = std::acos(rho / d);
  touch[0] = c + rho * unit(base + spread);
  touch[1] = c + rho * unit(base - spread);
  return true;
}

/// Tangent segments from the start or goal (node `terminal`) to every circle.
void add_terminal_tangents(TangentGraph& graph, int terminal) {
  const Vec2 q = graph.nodes[terminal].p;
  for (size_t c = 0; c < graph.centres.size(); ++c) {
    Vec2 touch[2];
    if (!tangent_points(q, graph.centres[c], graph.rho, touch)) continue;
    for (Vec2 t : touch) {
      const int v = add_node(graph, t, static_cast<int>(c));
      graph.nodes[terminal].links.push_back(v);
      graph.nodes[v].links.push_back(terminal);
    }
  }
}

/// The four common tangents of two circles of equal radius (two if they overlap).
void add_bitangents(TangentGraph& graph, int i, int j) {
  const Vec2 a = graph.centres[i], b = graph.centres[j];
  const Vec2 offset = graph.rho * (1.0 / distance(a, b)) * perp(b - a);
  add_segment(graph, i, a + offset, j, b + offset);
  add_segment(graph, i, a - offset, j, b - offset);
  // Crossing tangents pass through the midpoint, symmetric about it.
  const Vec2 mid = 0.5 * (a + b);
  Vec2 touch[2];
  if (!tangent_points(mid, a, graph.rho, touch)) return;
  for (Vec2 t : touch) add_segment(graph, i, t, j, 2.0 * mid - t);
}

/// Links every node to its neighbours in angle on its circle.
void order_circles(TangentGraph& graph) {
  std::vector<std::vector<int>> on_circle(graph.centres.size());
  for (size_t n = 0; n < graph.nodes.size(); ++n) {
    if (graph.nodes[n].circle >= 0) on_circle[graph.nodes[n].circle].push_back(static_cast<int>(n));
  }
  for (std::vector<int>& ring : on_circle) {
    std::sort(ring.begin(), ring.end(),
              [&](int u, int v) { return graph.nodes[u].angle < graph.nodes[v].angle; });
    for (size_t k = 0; k < ring.size(); ++k) {
      graph.nodes[ring[k]].ccw = ring[(k + 1) % ring.size()];
      graph.nodes[ring[k]].cw = ring[(k + ring.size() - 1) % ring.size()];
    }
  }
}

TangentGraph build_graph(const NavScene& scene, Vec2 from, Vec2 to, double rho) {
  TangentGraph graph;
  graph.centres = corner_centres(scene);
  graph.rho = rho;
  add_node(graph, from, -1);
  add_node(graph, to, -1);
  graph.nodes[0].links.push_back(1);
  graph.nodes[1].links.push_back(0);
  add_terminal_tangents(graph, 0);
  add_terminal_tangents(graph, 1);
  for (size_t i = 0; i < graph.centres.size(); ++i) {
    for (size_t j = i + 1; j < graph.centres.size(); ++j) {
      add_bitangents(graph, static_cast<int>(i), static_cast<int>(j));
    }
  }
  order_circles(graph);
  return graph;
}

/// The polyline of one step from node u to node v. An arc is replaced by
/// segments tangent to its circle, each turning at most one `sides`-th of a
/// turn: they stay outside the circle and exceed the arc's length by the
/// factor tan(phi / 2) / (phi / 2) for a piece of angle phi.
std::vector<Vec2> step_polyline(const TangentGraph& graph, int u, int v, Move move, int sides) {
  const Node& a = graph.nodes[u];
  const Node& b = graph.nodes[v];
  if (move == Move::kSegment) return {a.p, b.p};
  double sweep = b.angle - a.angle;
  if (move == Move::kCounterClockwise && sweep < 0.0) sweep += 2.0 * kPi;
  if (move == Move::kClockwise && sweep > 0.0) sweep -= 2.0 * kPi;
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::fabs(sweep) * sides / (2 * kPi))));
  const double piece = sweep / pieces;
  const double corner_radius = graph.rho / std::cos(0.5 * piece);
  std::vector<Vec2> line{a.p};
  for (int k = 0; k < pieces; ++k) {
    line.push_back(graph.centres[a.circle] + corner_radius * unit(a.angle + (k + 0.5) * piece));
  }
  line.push_back(b.p);
  return line;
}

bool polyline_clear(const Obstacles& obstacles, const std::vector<Vec2>& line, double radius) {
  for (size_t i = 1; i < line.size(); ++i) {
    if (obstacles.segment_clearance(line[i - 1], line[i], radius) < radius) return false;
  }
  return true;
}

/// A* from node 0 to node 1 (straight-line distance is a consistent
/// heuristic: no step is shorter than its chord). Edges are checked against
/// the obstacles only when they would improve a node.
class Search {
 public:
  Search(const TangentGraph& graph, const Obstacles& obstacles, double radius, int sides)
      : graph_(graph),
        obstacles_(obstacles),
        radius_(radius),
        sides_(sides),
        cost_(graph.nodes.size(), kInfinity),
        came_from_(graph.nodes.size(), {-1, Move::kSegment}),
        done_(graph.nodes.size(), false) {}

  /// True if the goal is reached.
  bool run() {
    cost_[0] = 0.0;
    open_.push({distance(graph_.nodes[0].p, graph_.nodes[1].p), 0});
    while (!open_.empty()) {
      const int u = open_.top().second;
      open_.pop();
      if (done_[u]) continue;
      if (u == 1) return true;
      done_[u] = true;
      for (int v : graph_.nodes[u].links) relax(u, v, Move::kSegment);
      relax(u, graph_.nodes[u].ccw, Move::kCounterClockwise);
      relax(u, graph_.nodes[u].cw, Move::kClockwise);
    }
    return false;
  }

  /// The path found by run(), as a polyline from start to goal.
  std::vector<Vec2> path() const {
    std::vector<int> chain;  // Goal back to start.
    for (int v = 1; v != 0; v = came_from_[v].first) chain.push_back(v);
    std::vector<Vec2> points{graph_.nodes[0].p};
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const auto [u, move] = came_from_[*it];
      const std::vector<Vec2> line = step_polyline(graph_, u, *it, move, sides_);
      points.insert(points.end(), line.begin() + 1, line.end());
    }
    return points;
  }

 private:
  using Entry = std::pair<double, int>;  // (cost + heuristic, node)

  void relax(int u, int v, Move move) {
    if (v < 0 || v == u || done_[v]) return;
    const std::vector<Vec2> line = step_polyline(graph_, u, v, move, sides_);
    const double through_u = cost_[u] + polyline_length(line);
    if (through_u >= cost_[v] || !polyline_clear(obstacles_, line, radius_)) return;
    cost_[v] = through_u;
    came_from_[v] = {u, move};
    open_.push({through_u + distance(graph_.nodes[v].p, graph_.nodes[1].p), v});
  }

  const TangentGraph& graph_;
  const Obstacles& obstacles_;
  double radius_;
  int sides_;
  std::vector<double> cost_;
  std::vector<std::pair<int, Move>> came_from_;  // Previous node and the step from it.
  std::vector<bool> done_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open_;
};

}  // namespace

std::string describe(const NavScene& scene, Vec2 from, Vec2 to, double radius) {
  std::ostringstream out;
  out << std::setprecision(17);
  const auto point = [&](Vec2 p) { out << "{" << p.x << ", " << p.y << "}"; };
  out << "NavScene scene{";
  point(scene.min_corner);
  out << ", ";
  point(scene.max_corner);
  out << ", {";
  for (const std::vector<Vec2>& polygon : scene.polygons) {
    out << "\n    {";
    for (size_t i = 0; i < polygon.size(); ++i) {
      if (i > 0) out << ", ";
      point(polygon[i]);
    }
    out << "},";
  }
  out << "},\n    {";
  for (Vec2 p : scene.points) {
    point(p);
    out << ", ";
  }
  out << "}};\nfrom ";
  point(from);
  out << " to ";
  point(to);
  out << " radius " << radius << "\n";
  return out.str();
}

double clearance(const NavScene& scene, Vec2 p) {
  return Obstacles(scene).segment_clearance(p, p, kInfinity);
}

double path_clearance(const NavScene& scene, const std::vector<Vec2>& polyline) {
  if (polyline.size() == 1) return clearance(scene, polyline[0]);
  const Obstacles obstacles(scene);
  double best = kInfinity;
  for (size_t i = 1; i < polyline.size(); ++i) {
    best = obstacles.segment_clearance(polyline[i - 1], polyline[i], best);
  }
  return best;
}

OraclePath shortest_path(const NavScene& scene, Vec2 from, Vec2 to, double radius,
                         int circle_sides) {
  const Obstacles obstacles(scene);
  if (obstacles.segment_clearance(from, from, radius) < radius ||
      obstacles.segment_clearance(to, to, radius) < radius) {
    return {};
  }
  // Circles a hair larger than the disc, so that segments tangent to them
  // clear the disc's radius despite rounding.
  const TangentGraph graph = build_graph(scene, from, to, radius * (1 + 1e-9) + 1e-9);
  Search search(graph, obstacles, radius, circle_sides);
  if (!search.run()) return {};
  OraclePath result;
  result.found = true;
  result.points = search.path();
  result.length = polyline_length(result.points);
  return result;
}

double oracle_excess(int circle_sides) {
  // The arcs' polylines (see step_polyline), plus 1e-6 for the circles being
  // r * 1e-9 + 1e-9 too large: that adds as much per radian of turning, and a
  // path is at least r long per radian, so relatively 1e-9 + 1e-9 / r at most.
  const double half_piece = kPi / circle_sides;
  return std::tan(half_piece) / half_piece - 1.0 + 1e-6;
}

OracleAnswer judge_query(const NavScene& scene, Vec2 from, Vec2 to, double radius) {
  constexpr double kStep = 1e-3;
  OracleAnswer answer;
  answer.path = shortest_path(scene, from, to, radius);
  const OraclePath below = shortest_path(scene, from, to, radius * (1 - kStep));
  const OraclePath above = shortest_path(scene, from, to, radius * (1 + kStep));
  // A smaller disc has more room, so no path of the radius beats the true
  // shortest one below it, which the oracle overestimates by oracle_excess at
  // most. Taken below rather than at the radius, the bound also holds when the
  // arcs' polylines close a passage that is open by less than their bulge.
  answer.lower_bound = below.found ? below.length / (1 + oracle_excess()) : 0.0;
  // Within one way around the obstacles the length grows with the radius by
  // the path's total turning, which is at most length / radius: by 2e-3 from
  // below to above, plus the oracle's excess. More means a passage closed.
  constexpr double kLongestSmoothGrowth = 3e-3;
  answer.ambiguous = below.found != above.found || below.found != answer.path.found ||
                     (above.found && above.length > below.length * (1 + kLongestSmoothGrowth));
  return answer;
}

}  // namespace footfall::testing
