// Footfall — nearest-obstacle distances over the navigation mesh.
#include "navmesh/obstacle_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "navmesh/face_numbers.hpp"
#include "util/scratch_vector.hpp"

namespace footfall {
namespace {

/// The part of [p, q] inside the wedge at `apex` from ray `from` counter-
/// clockwise to ray `to` (an angle below pi); false if none of it is.
bool clip_to_wedge(Vec2 apex, Vec2 from, Vec2 to, Vec2& p, Vec2& q) {
  double t0 = 0.0, t1 = 1.0;
  // Inside: left of apex->from and right of apex->to.
  const Vec2 normals[2] = {perp(from - apex), -1.0 * perp(to - apex)};
  for (const Vec2& n : normals) {
    const double fp = dot(n, p - apex), fq = dot(n, q - apex);
    if (fp < 0 && fq < 0) return false;
    if (fp < 0) t0 = std::max(t0, fp / (fp - fq));
    if (fq < 0) t1 = std::min(t1, fp / (fp - fq));
  }
  if (t0 > t1) return false;
  const Vec2 d = q - p;
  q = p + t1 * d;
  p = p + t0 * d;
  return true;
}

}  // namespace

double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segments_cross(a, b, c, d)) return 0.0;
  return std::sqrt(std::min(
      std::min(squared_distance_to_segment(a, c, d), squared_distance_to_segment(b, c, d)),
      std::min(squared_distance_to_segment(c, a, b), squared_distance_to_segment(d, a, b))));
}

double obstacle_distance(const NavMeshState& mesh, Face start, Vec2 a, Vec2 b, double limit,
                         NearestObstacle* nearest) {
  double best = limit;
  auto consider = [&](double d, NearestObstacle found) {
    if (d >= best) return;
    best = d;
    if (nearest != nullptr) *nearest = found;
  };
  FaceNumbers seen;
  seen.insert(start);
  // (face, the edge the walk came in through): that edge and its ends were
  // measured in the face before, so only the far vertex and the other two
  // edges are new (3: the start, all new).
  ScratchVector<std::pair<Face, int>> storage;
  std::vector<std::pair<Face, int>>& stack = *storage;
  stack.push_back({start, 3});
  while (!stack.empty()) {
    const auto [f, entry] = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      if (entry == 3 || i == entry) {
        const Vec2 v = to_vec(f->vertex(i)->point());
        consider(distance_to_segment(v, a, b), {v, v, v});
      }
      if (i == entry) continue;
      const Vec2 c = to_vec(f->vertex(Cdt::ccw(i))->point()),
                 d = to_vec(f->vertex(Cdt::cw(i))->point());
      const double gap = segment_distance(a, b, c, d);
      if (f->is_constrained(i)) {
        if (gap >= best) continue;
        // Off the edge's ends (its vertices are seen above), the nearest
        // point is the foot of a or b on the edge.
        const Vec2 foot_a = closest_on_segment(a, c, d), foot_b = closest_on_segment(b, c, d);
        consider(gap, {distance(a, foot_a) <= distance(b, foot_b) ? foot_a : foot_b, c, d});
      } else if (gap < best && !mesh.cdt.is_infinite(f->neighbor(i)) &&
                 seen.insert(f->neighbor(i)).second) {
        stack.push_back({f->neighbor(i), f->neighbor(i)->index(f)});
      }
    }
  }
  return best;
}

bool line_of_sight(const NavMeshState& mesh, Face start, Vec2 a, Vec2 b, double room) {
  const Point pa = to_point(a), pb = to_point(b);
  const auto near = [&](Vertex v) { return distance_to_segment(to_vec(v->point()), a, b) < room; };
  const auto side = [&](Vertex v) { return CGAL::orientation(pa, pb, v->point()); };
  // Edge i of f runs from c = vertex(ccw(i)) to d = vertex(cw(i)), f on its
  // left; the segment leaves f there if c is right of the line a->b, d left
  // of it, and b beyond the edge. Every vertex met is first checked to be
  // `room` off the segment, so none lies on it.
  const auto beyond = [&](Face f, int i) {
    return CGAL::orientation(f->vertex(Cdt::ccw(i))->point(), f->vertex(Cdt::cw(i))->point(),
                             pb) == CGAL::RIGHT_TURN;
  };
  Face f = start;
  for (int i = 0; i < 3; ++i)
    if (near(f->vertex(i))) return false;
  int exit = 0;
  while (exit < 3 && !(side(f->vertex(Cdt::ccw(exit))) == CGAL::RIGHT_TURN &&
                       side(f->vertex(Cdt::cw(exit))) == CGAL::LEFT_TURN && beyond(f, exit)))
    ++exit;
  for (;;) {
    if (exit == 3) return true;  // b lies in f
    if (f->is_constrained(exit)) return false;
    const Face next = f->neighbor(exit);
    if (mesh.cdt.is_infinite(next)) return false;
    const int entry = next->index(f);
    f = next;
    // Entered across the edge from vertex(ccw(entry)), left of the line, to
    // vertex(cw(entry)), right of it; the far vertex's side picks which of the
    // other two edges the line crosses (on the line, it lies beyond b).
    const Vertex far = f->vertex(entry);
    if (near(far)) return false;
    const int crossed = side(far) == CGAL::LEFT_TURN ? Cdt::ccw(entry) : Cdt::cw(entry);
    exit = beyond(f, crossed) ? crossed : 3;
  }
}

bool portal_covered(Face f, int edge, double radius) {
  if (radius <= 0) return false;  // a point crosses between the ends
  const Vec2 a = to_vec(f->vertex(Cdt::ccw(edge))->point());
  const Vec2 d = to_vec(f->vertex(Cdt::cw(edge))->point()) - a;
  const double len2 = dot(d, d), len = std::sqrt(len2);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // The parameters t of the points a + t d nearer than `radius` to the far
  // vertex of each face (a chord of its circle) and to each constrained
  // side edge between its ends (a strip along its line, cut where the foot
  // leaves the edge). The ends a and b cover t < radius / len and beyond
  // 1 - radius / len.
  std::array<std::pair<double, double>, 6> near;
  int count = 0;
  auto near_vertex = [&](Vec2 p) {
    const double h = cross(d, p - a) / len2, mid = dot(d, p - a) / len2;
    const double half2 = radius * radius / len2 - h * h;
    if (half2 > 0) near[count++] = {mid - std::sqrt(half2), mid + std::sqrt(half2)};
  };
  auto near_edge = [&](Vec2 c, Vec2 e) {
    const Vec2 u = e - c;
    double t0 = -kInf, t1 = kInf;
    auto keep = [&](double at_a, double slope, double lo, double hi) {  // lo < at_a + slope t < hi
      if (slope == 0) {
        if (!(at_a > lo && at_a < hi)) t0 = kInf;
        return;
      }
      const double x = (lo - at_a) / slope, y = (hi - at_a) / slope;
      t0 = std::max(t0, std::min(x, y));
      t1 = std::min(t1, std::max(x, y));
    };
    const double ul = length(u);
    keep(cross(u, a - c) / ul, cross(u, d) / ul, -radius, radius);
    keep(dot(u, a - c), dot(u, d), 0.0, ul * ul);
    if (t0 < t1) near[count++] = {t0, t1};
  };
  const Face other = f->neighbor(edge);
  for (const auto& [g, far] : {std::pair{f, edge}, std::pair{other, other->index(f)}}) {
    near_vertex(to_vec(g->vertex(far)->point()));
    for (const int side : {Cdt::ccw(far), Cdt::cw(far)})
      if (g->is_constrained(side))
        near_edge(to_vec(g->vertex(Cdt::ccw(side))->point()),
                  to_vec(g->vertex(Cdt::cw(side))->point()));
  }
  // Covered from a's end on, as far as the intervals overlap (one that only
  // touches leaves a point clear).
  double covered = radius / len;
  const double to_b = 1.0 - radius / len;
  for (bool grew = true; grew && covered <= to_b;) {
    grew = false;
    for (int k = 0; k < count; ++k)
      if (near[k].first < covered && near[k].second > covered) {
        covered = near[k].second;
        grew = true;
      }
  }
  return covered > to_b;
}

double corner_width(const NavMeshState& mesh, Face f, int corner, double limit) {
  const Vec2 apex = to_vec(f->vertex(corner)->point());
  const Vec2 from = to_vec(f->vertex(Cdt::ccw(corner))->point());
  const Vec2 to = to_vec(f->vertex(Cdt::cw(corner))->point());
  return wedge_width(mesh, f, corner, from, to,
                     std::min(limit, std::min(distance(apex, from), distance(apex, to))));
}

double wedge_width(const NavMeshState& mesh, Face f, int corner, Vec2 from, Vec2 to, double limit) {
  const Vec2 apex = to_vec(f->vertex(corner)->point());
  double best = limit;
  // Edges still to look across: (face, edge index), all beyond the opposite edge.
  ScratchVector<std::pair<Face, int>> storage;
  std::vector<std::pair<Face, int>>& stack = *storage;
  stack.push_back({f, corner});
  FaceNumbers seen;
  seen.insert(f);
  while (!stack.empty()) {
    const auto [g, i] = stack.back();
    stack.pop_back();
    Vec2 p = to_vec(g->vertex(Cdt::ccw(i))->point()), q = to_vec(g->vertex(Cdt::cw(i))->point());
    if (!clip_to_wedge(apex, from, to, p, q)) continue;
    if (g->is_constrained(i)) {
      best = std::min(best, distance_to_segment(apex, p, q));
      continue;
    }
    const Face n = g->neighbor(i);
    if (!seen.insert(n).second || mesh.cdt.is_infinite(n)) continue;
    const int back = n->index(g);
    Vec2 far = to_vec(n->vertex(back)->point()), far_copy = far;
    if (clip_to_wedge(apex, from, to, far, far_copy)) best = std::min(best, distance(apex, far));
    for (int j : {Cdt::ccw(back), Cdt::cw(back)}) {
      Vec2 c = to_vec(n->vertex(Cdt::ccw(j))->point()), d = to_vec(n->vertex(Cdt::cw(j))->point());
      if (clip_to_wedge(apex, from, to, c, d) && distance_to_segment(apex, c, d) < best)
        stack.push_back({n, j});
    }
  }
  return best;
}

}  // namespace footfall
