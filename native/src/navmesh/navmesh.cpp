// Footfall — building and updating the navigation mesh. Walkability is kept
// as a winding number per face, repaired locally after every update: faces
// inside the changed obstacle are shifted, faces CGAL created are re-derived
// from their known neighbours across the edges between them, and those that
// fill a removed vertex's hole take the number around it.
#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <CGAL/Polygon_2_algorithms.h>

#include "navmesh/face_numbers.hpp"
#include "navmesh/navmesh_impl.hpp"
#include "navmesh/obstacle_distance.hpp"
#include "navmesh/outline_simplify.hpp"

namespace footfall {
namespace {

std::string where(const std::string& name, std::size_t vertex) {
  return (name.empty() ? std::string("polygon") : name) + " vertex " + std::to_string(vertex);
}

/// Checked vertices, without repeats in a row or a closing repeat.
std::vector<Vec2> clean_polygon(const std::vector<Vec2>& polygon, const std::string& name) {
  if (polygon.empty())
    throw std::invalid_argument((name.empty() ? std::string("polygon") : name) +
                                " has no vertices");
  std::vector<Vec2> out;
  out.reserve(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    if (!in_world(polygon[i]))
      throw std::invalid_argument(where(name, i) + " is not a finite coordinate within 1e9 m");
    if (out.empty() || !(out.back() == polygon[i])) out.push_back(polygon[i]);
  }
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

/// The part of `polygon` inside the rectangle [lo, hi] (Sutherland-Hodgman).
/// Concave polygons may come back with zero-width bridges along the boundary;
/// their winding numbers inside the rectangle are those of the input. Keeping
/// every vertex in the rectangle keeps the triangulation's hull the domain's.
std::vector<Vec2> clip_to_rectangle(std::vector<Vec2> polygon, Vec2 lo, Vec2 hi) {
  if (std::all_of(polygon.begin(), polygon.end(), [&](Vec2 p) {
        return p.x >= lo.x && p.y >= lo.y && p.x <= hi.x && p.y <= hi.y;
      })) {
    // Nothing to cut: the polygon as the four passes leave it, each starting
    // one vertex on (the start decides CGAL's insertion order).
    std::rotate(polygon.begin(), polygon.begin() + static_cast<long>(4 % polygon.size()),
                polygon.end());
    return polygon;
  }
  // Each side of the rectangle: inside test and where an edge crosses it.
  struct Side {
    int axis;      // 0: x, 1: y
    double bound;  // the side's coordinate
    bool keep_above;
  };
  const Side sides[4] = {{0, lo.x, true}, {0, hi.x, false}, {1, lo.y, true}, {1, hi.y, false}};
  auto coord = [](Vec2 p, int axis) { return axis == 0 ? p.x : p.y; };
  for (const Side& side : sides) {
    auto inside = [&](Vec2 p) {
      return side.keep_above ? coord(p, side.axis) >= side.bound
                             : coord(p, side.axis) <= side.bound;
    };
    auto crossing = [&](Vec2 a, Vec2 b) {
      // The same point whichever way the edge runs: a wall (there and back)
      // must not come out as a sliver with two crossing points.
      if (std::tie(a.x, a.y) > std::tie(b.x, b.y)) std::swap(a, b);
      const double t =
          (side.bound - coord(a, side.axis)) / (coord(b, side.axis) - coord(a, side.axis));
      Vec2 p = a + t * (b - a);
      (side.axis == 0 ? p.x : p.y) = side.bound;  // exactly on the side
      return p;
    };
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      if (inside(b)) {
        if (!inside(a)) out.push_back(crossing(a, b));
        out.push_back(b);
      } else if (inside(a)) {
        out.push_back(crossing(a, b));
      }
    }
    polygon = std::move(out);
  }
  std::vector<Vec2> out;
  for (Vec2 p : polygon)
    if (out.empty() || !(out.back() == p)) out.push_back(p);
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

/// Twice the signed area of `polygon` (positive counter-clockwise).
double twice_signed_area(const std::vector<Vec2>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    sum += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return sum;
}

/// Winding number of `polygon` around `p`, with CGAL's exact orientation test.
int winding_number(const std::vector<Vec2>& polygon, const Point& p) {
  int winding = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point a = to_point(polygon[i]), b = to_point(polygon[(i + 1) % polygon.size()]);
    if (a.y() <= p.y()) {
      if (b.y() > p.y() && CGAL::orientation(a, b, p) == CGAL::LEFT_TURN) ++winding;
    } else if (b.y() <= p.y() && CGAL::orientation(a, b, p) == CGAL::RIGHT_TURN) {
      --winding;
    }
  }
  return winding;
}

Point centroid(Face f) {
  return CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
}

/// True if `p` lies strictly inside face `f` (exact orientation tests).
bool strictly_inside(Face f, const Point& p) {
  for (int i = 0; i < 3; ++i)
    if (CGAL::orientation(f->vertex(Cdt::ccw(i))->point(), f->vertex(Cdt::cw(i))->point(), p) !=
        CGAL::LEFT_TURN)
      return false;
  return true;
}

std::vector<Vertex> constraint_vertices(const Cdt& cdt, Cdt::Constraint_id constraint) {
  std::vector<Vertex> out(cdt.vertices_in_constraint_begin(constraint),
                          cdt.vertices_in_constraint_end(constraint));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// The edge from `a` to `b` whichever way it runs.
std::pair<Point, Point> undirected(const Point& a, const Point& b) {
  return a < b ? std::pair{a, b} : std::pair{b, a};
}

/// Inserts the closed `outline` as one constraint. Where the outline runs
/// along one of its edges more than once (a wall: there and back), every pass
/// must follow the same mesh vertices. Inserted again as a straight segment, a
/// pass runs beside its first copy, which rounded crossing points have bent
/// to both sides of the line; CGAL then crosses two nearly collinear segments
/// and may snap the pass to distant vertices, so that the wall encloses ground.
/// Such an outline gets each of its edges inserted once first (every one: an
/// edge inserted later could bend a retraced one again), then the outline
/// along the vertices they found (every piece already a constrained edge),
/// and then the first copies removed.
Cdt::Constraint_id insert_outline(Cdt& cdt, const LocateHints& hints,
                                  const std::vector<Point>& outline) {
  const std::size_t n = outline.size();
  std::vector<std::pair<Point, Point>> sides;
  sides.reserve(n);
  for (std::size_t i = 0; i < n; ++i) sides.push_back(undirected(outline[i], outline[(i + 1) % n]));
  std::sort(sides.begin(), sides.end());
  if (std::adjacent_find(sides.begin(), sides.end()) == sides.end())
    return cdt.insert_polyline(outline, true, hints.near(outline.front()));
  std::map<std::pair<Point, Point>, Cdt::Constraint_id> edges;
  for (const auto& side : sides) edges.emplace(side, nullptr);
  for (auto& [edge, copy] : edges)
    copy = cdt.insert_polyline({edge.first, edge.second}, false, hints.near(edge.first));
  std::vector<Point> along;
  for (std::size_t i = 0; i < n; ++i) {
    const Cdt::Constraint_id copy = edges.at(undirected(outline[i], outline[(i + 1) % n]));
    std::vector<Point> pass;
    for (auto v = cdt.vertices_in_constraint_begin(copy); v != cdt.vertices_in_constraint_end(copy);
         ++v)
      pass.push_back((*v)->point());
    if (pass.front() != outline[i]) std::reverse(pass.begin(), pass.end());
    along.insert(along.end(), pass.begin(), std::prev(pass.end()));  // the next pass starts there
  }
  const Cdt::Constraint_id constraint = cdt.insert_polyline(along, true, hints.near(along.front()));
  for (const auto& [edge, copy] : edges) cdt.remove_polyline(copy);
  return constraint;
}

}  // namespace

int NavMeshState::winding_step(Face f, int i) const {
  if (!f->is_constrained(i)) return 0;
  const Vertex va = f->vertex(Cdt::ccw(i)), vb = f->vertex(Cdt::cw(i));
  int step = 0;
  // Each look-up of an edge's contexts is a search of a map over every
  // constrained edge of the mesh, comparing points: one, not one per context.
  const auto end = cdt.contexts_end(va, vb);
  for (auto context = cdt.contexts_begin(va, vb); context != end; ++context) {
    const int weight = context->id() == domain ? 1 : -1;
    // f lies left of va -> vb: crossing to the right leaves a constraint that runs va -> vb.
    step += *context->current() == va ? -weight : weight;
  }
  return step;
}

void NavMeshState::repair_windings(const std::vector<Vertex>& seeds) {
  constexpr int kPending = FaceInfo::kUnknown + 1;
  std::vector<Face> region, known;
  region.reserve(64);  // a few dozen faces around an obstacle's vertices: one allocation
  known.reserve(64);
  auto collect = [&](Face f) {
    if (f->info().winding != FaceInfo::kUnknown) return;
    if (cdt.is_infinite(f)) {
      f->info().winding = 0;
      return;
    }
    f->info().winding = kPending;
    region.push_back(f);
  };
  for (Vertex v : seeds) {
    auto faces = cdt.incident_faces(v), end = faces;
    do collect(faces);
    while (++faces != end);
  }
  for (std::size_t k = 0; k < region.size(); ++k)
    for (int i = 0; i < 3; ++i) collect(region[k]->neighbor(i));
  for (Face f : region)
    for (int i = 0; i < 3; ++i)
      if (f->neighbor(i)->info().winding != kPending) known.push_back(f->neighbor(i));
  // Each face takes its number over the fewest constrained edges: first all
  // it can reach across free edges (no step), then one constrained crossing
  // from what is known, and so on. A constrained piece shared by nearly
  // collinear outlines may miss one of them among its contexts (CGAL splits
  // it at a rounded crossing); a free path round it is exact.
  std::vector<Face> crossed;
  while (!known.empty()) {
    for (std::size_t k = 0; k < known.size(); ++k) {
      const Face f = known[k];
      for (int i = 0; i < 3; ++i) {
        const Face n = f->neighbor(i);
        if (n->info().winding != kPending || f->is_constrained(i)) continue;
        n->info().winding = f->info().winding;
        known.push_back(n);
      }
    }
    crossed.clear();
    for (const Face f : known) {
      for (int i = 0; i < 3; ++i) {
        const Face n = f->neighbor(i);
        if (n->info().winding != kPending) continue;
        n->info().winding = f->info().winding + winding_step(f, i);
        crossed.push_back(n);
      }
    }
    known.swap(crossed);
  }
}

void NavMeshState::forget_windings(const std::vector<Vertex>& vertices) {
  for (Vertex v : vertices) {
    auto faces = cdt.incident_faces(v), end = faces;
    do faces->info().winding = FaceInfo::kUnknown;
    while (++faces != end);
  }
}

void NavMeshState::shift_enclosed(Cdt::Constraint_id constraint, int sign) {
  // The winding numbers are those of the constraint as it lies in the mesh,
  // crossing points included: they are rounded off the caller's lines, and a
  // sliver face beside one can be outside the triangulated outline while its
  // centroid is inside the caller's polygon (which flooded the whole domain).
  std::vector<Vec2> outline;
  outline.reserve(16);  // most outlines are short: one allocation
  // The constraint's own edges join consecutive vertices of its outline;
  // asking the hierarchy's contexts instead is a search over the whole mesh.
  std::vector<std::pair<const void*, const void*>> own;
  own.reserve(16);
  auto key = [](Vertex a, Vertex b) {
    const void *pa = &*a, *pb = &*b;
    return pa < pb ? std::pair{pa, pb} : std::pair{pb, pa};
  };
  Vertex previous;
  for (auto v = cdt.vertices_in_constraint_begin(constraint);
       v != cdt.vertices_in_constraint_end(constraint); ++v) {
    outline.push_back(to_vec((*v)->point()));
    if (previous != Vertex()) own.push_back(key(previous, *v));
    previous = *v;
  }
  std::sort(own.begin(), own.end());
  auto on_constraint = [&](Face f, int i) {
    return f->is_constrained(i) &&
           std::binary_search(own.begin(), own.end(),
                              key(f->vertex(Cdt::ccw(i)), f->vertex(Cdt::cw(i))));
  };
  FaceNumbers seen;
  std::vector<Face> stack;
  stack.reserve(16);
  auto flood = [&](Face start) {
    if (cdt.is_infinite(start) || seen.contains(start)) return;
    // A sliver's rounded centroid can fall outside it, onto the far side of
    // a nearly collinear edge; such a face is flooded from a neighbour.
    const Point c = centroid(start);
    if (!strictly_inside(start, c)) return;
    seen.insert(start);
    const int inside = winding_number(outline, c);
    if (inside == 0) return;
    stack.push_back(start);
    while (!stack.empty()) {
      const Face f = stack.back();
      stack.pop_back();
      if (f->info().winding != FaceInfo::kUnknown) f->info().winding -= sign * inside;
      for (int i = 0; i < 3; ++i)
        if (!on_constraint(f, i) && seen.insert(f->neighbor(i)).second)
          stack.push_back(f->neighbor(i));
    }
  };
  auto v = cdt.vertices_in_constraint_begin(constraint);
  for (auto next = std::next(v); next != cdt.vertices_in_constraint_end(constraint); ++v, ++next) {
    Face f;
    int i;
    if (*v == *next || !cdt.is_edge(*v, *next, f, i)) continue;
    flood(f);
    flood(f->neighbor(i));
  }
}

void NavMeshState::remove_if_orphan(Vertex v) {
  if (v->info().points != 0 || cdt.are_there_incident_constraints(v)) return;
  // No constraint runs through v, so the faces around it share one winding
  // number, and so do the faces CGAL fills its hole with: found from the
  // faces across the hole's rim, which stay. (Re-deriving them from their
  // neighbours would visit every face round v's neighbours, mostly faces no
  // other part of the update touches: cache misses in a large mesh.)
  const int winding = v->face()->info().winding;
  std::vector<std::pair<Face, int>> rim;  // the face across each rim edge, and that edge in it
  rim.reserve(16);                        // six on average: one allocation
  auto faces = cdt.incident_faces(v), end = faces;
  do {
    const int i = faces->index(v);
    rim.emplace_back(faces->neighbor(i), cdt.mirror_index(faces, i));
  } while (++faces != end);
  hints.forget(v);
  cdt.remove(v);
  std::vector<Face> fill;
  fill.reserve(3 * rim.size());
  for (const auto& [face, edge] : rim) fill.push_back(face->neighbor(edge));
  while (!fill.empty()) {
    const Face f = fill.back();
    fill.pop_back();
    if (f->info().winding != FaceInfo::kUnknown) continue;
    f->info().winding = winding;
    for (int i = 0; i < 3; ++i) fill.push_back(f->neighbor(i));
  }
}

NavMesh::NavMesh(Vec2 min_corner, Vec2 max_corner) {
  if (!in_world(min_corner) || !in_world(max_corner))
    throw std::invalid_argument("domain corners must be finite coordinates within 1e9 m");
  if (!(min_corner.x < max_corner.x && min_corner.y < max_corner.y))
    throw std::invalid_argument("domain is empty: min_corner must be below max_corner on x and y");
  impl_ = std::make_unique<NavMeshState>(min_corner, max_corner);
  const std::vector<Point> corners{to_point(min_corner),
                                   {max_corner.x, min_corner.y},
                                   to_point(max_corner),
                                   {min_corner.x, max_corner.y}};
  impl_->domain = impl_->cdt.insert_constraint(corners.begin(), corners.end(), true);
  for (Face f : impl_->cdt.all_face_handles())
    f->info().winding = impl_->cdt.is_infinite(f) ? 0 : 1;
}

NavMesh::~NavMesh() = default;
NavMesh::NavMesh(NavMesh&&) noexcept = default;
NavMesh& NavMesh::operator=(NavMesh&&) noexcept = default;

Cdt::Constraint_id NavMeshState::add_ring(const std::vector<Point>& points) {
  const Cdt::Constraint_id ring = insert_outline(cdt, hints, points);
  const std::vector<Vertex> touched = constraint_vertices(cdt, ring);
  for (Vertex v : touched) hints.keep(cdt, v);
  forget_windings(touched);
  shift_enclosed(ring, +1);
  repair_windings(touched);
  return ring;
}

namespace {

/// A ring as the mesh takes it: checked, clipped to the domain, turned
/// counter-clockwise (`ccw`) or clockwise. A detailed counter-clockwise
/// outline (a footprint from a fine mesh) enters a little larger and with
/// fewer vertices; one that crosses itself enters as it is.
std::vector<Point> ring_points(const NavMeshState& m, const std::vector<Vec2>& ring, const std::string& name,
                               bool ccw) {
  std::vector<Vec2> cleaned = clip_to_rectangle(clean_polygon(ring, name), m.min_corner, m.max_corner);
  if ((twice_signed_area(cleaned) < 0) == ccw) std::reverse(cleaned.begin(), cleaned.end());
  std::vector<Point> points;
  points.reserve(cleaned.size());
  for (Vec2 p : cleaned) points.push_back(to_point(p));
  if (ccw && points.size() > kSimplifyAbove && CGAL::is_simple_2(points.begin(), points.end(), Kernel())) {
    points.clear();
    for (Vec2 p : simplify_outward(cleaned, kOutlineTolerance)) points.push_back(to_point(p));
  }
  return points;
}

}  // namespace

int NavMesh::add_polygon(const std::vector<Vec2>& polygon, const std::string& name) {
  NavMeshState& m = *impl_;
  // Counter-clockwise, so that overlapping obstacles add up instead of
  // cancelling (the non-zero rule per obstacle).
  const std::vector<Point> points = ring_points(m, polygon, name, true);
  if (points.size() == 1) return add_point(to_vec(points.front()), name);
  if (points.empty()) return add_empty();  // wholly outside: blocks nothing, keeps its id
  NavMeshState::Obstacle obstacle;
  obstacle.rings.push_back(m.add_ring(points));
  m.obstacles.emplace(m.next_id, std::move(obstacle));
  return m.next_id++;
}

int NavMesh::add_region(const std::vector<std::vector<Vec2>>& outlines, const std::vector<std::vector<Vec2>>& holes,
                        const std::string& name) {
  NavMeshState& m = *impl_;
  NavMeshState::Obstacle obstacle;
  for (const bool outer : {true, false})
    for (const std::vector<Vec2>& ring : outer ? outlines : holes) {
      const std::vector<Point> points = ring_points(m, ring, name, outer);
      if (points.size() >= 3) obstacle.rings.push_back(m.add_ring(points));
    }
  m.obstacles.emplace(m.next_id, std::move(obstacle));
  return m.next_id++;
}

int NavMesh::add_empty() {
  impl_->obstacles.emplace(impl_->next_id, NavMeshState::Obstacle{});
  return impl_->next_id++;
}

int NavMesh::add_point(Vec2 point, const std::string& name) {
  if (!in_world(point))
    throw std::invalid_argument((name.empty() ? std::string("point") : name) +
                                " is not a finite coordinate within 1e9 m");
  NavMeshState& m = *impl_;
  NavMeshState::Obstacle obstacle;
  if (!m.in_domain(point)) {
    m.obstacles.emplace(m.next_id, std::move(obstacle));  // outside: blocks nothing
    return m.next_id++;
  }
  obstacle.point = m.cdt.insert(to_point(point), m.hints.near(to_point(point)));
  m.hints.keep(m.cdt, obstacle.point);
  obstacle.point->info().points += 1;
  m.forget_windings({obstacle.point});
  m.repair_windings({obstacle.point});
  m.obstacles.emplace(m.next_id, std::move(obstacle));
  return m.next_id++;
}

void NavMesh::remove(int id) {
  NavMeshState& m = *impl_;
  const auto found = m.obstacles.find(id);
  if (found == m.obstacles.end())
    throw std::out_of_range("no obstacle with id " + std::to_string(id));
  const NavMeshState::Obstacle obstacle = std::move(found->second);
  m.obstacles.erase(found);
  std::vector<Vertex> touched;
  for (auto ring = obstacle.rings.rbegin(); ring != obstacle.rings.rend(); ++ring) {
    const std::vector<Vertex> on_ring = constraint_vertices(m.cdt, *ring);
    touched.insert(touched.end(), on_ring.begin(), on_ring.end());
    m.shift_enclosed(*ring, -1);
    m.cdt.remove_polyline(*ring);
  }
  if (obstacle.point != Vertex()) {
    obstacle.point->info().points -= 1;
    touched = {obstacle.point};
  }
  for (Vertex v : touched) m.remove_if_orphan(v);  // vertices nothing holds any more go
}

bool NavMesh::contains(int id) const { return impl_->obstacles.count(id) > 0; }

double NavMesh::clearance(Vec2 point) const {
  const NavMeshState& m = *impl_;
  if (!in_world(point)) throw std::invalid_argument("clearance: point is not finite");
  const Face f = m.cdt.locate(to_point(point), m.hints.near(to_point(point)));
  if (!m.walkable(f)) return 0.0;
  return obstacle_distance(m, f, point, point);
}

double NavMesh::clearance_between(Vec2 a, Vec2 b, double limit) const {
  const NavMeshState& m = *impl_;
  if (!in_world(a) || !in_world(b))
    throw std::invalid_argument("clearance_between: points are not finite");
  if (!m.in_domain(a) || !m.in_domain(b)) return 0.0;
  const Face f = m.cdt.locate(to_point(a), m.hints.near(to_point(a)));
  if (!m.walkable(f)) return 0.0;
  return obstacle_distance(m, f, a, b, limit);
}

bool NavMesh::line_of_sight(Vec2 a, Vec2 b) const { return lines_of_sight(a, {b}).front() != 0; }

std::vector<char> NavMesh::lines_of_sight(Vec2 from, const std::vector<Vec2>& to) const {
  constexpr double kTouch = 1e-9;  // [m]
  const NavMeshState& m = *impl_;
  if (!in_world(from) || !std::all_of(to.begin(), to.end(), [](Vec2 p) { return in_world(p); }))
    throw std::invalid_argument("line_of_sight: points are not finite");
  std::vector<char> seen(to.size(), 0);
  if (!m.in_domain(from)) return seen;
  const Face f = m.cdt.locate(to_point(from), m.hints.near(to_point(from)));
  if (!m.walkable(f)) return seen;
  for (std::size_t k = 0; k < to.size(); ++k)
    seen[k] = m.in_domain(to[k]) && footfall::line_of_sight(m, f, from, to[k], kTouch);
  return seen;
}

std::vector<NavTriangle> NavMesh::triangles() const {
  const NavMeshState& m = *impl_;
  std::vector<NavTriangle> out;
  out.reserve(m.cdt.number_of_faces());
  for (Face f : m.cdt.finite_face_handles()) {
    NavTriangle t;
    t.walkable = m.walkable(f);
    for (int i = 0; i < 3; ++i) {
      t.corners[i] = to_vec(f->vertex(i)->point());
      t.constrained[i] = f->is_constrained(i);
      if (t.walkable) t.corner_clearance[i] = 0.5 * corner_width(m, f, i);
    }
    out.push_back(t);
  }
  return out;
}

std::size_t NavMesh::triangle_count() const { return impl_->cdt.number_of_faces(); }
Vec2 NavMesh::min_corner() const { return impl_->min_corner; }
Vec2 NavMesh::max_corner() const { return impl_->max_corner; }

const char* to_string(PathStatus status) {
  switch (status) {
    case PathStatus::kFound:
      return "found";
    case PathStatus::kNoPath:
      return "no_path";
    case PathStatus::kStartBlocked:
      return "start_blocked";
    case PathStatus::kGoalBlocked:
      return "goal_blocked";
    case PathStatus::kOutside:
      return "outside";
  }
  return "unknown";
}

}  // namespace footfall
