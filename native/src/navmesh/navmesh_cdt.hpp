// Footfall — the navigation mesh's triangulation: CGAL's constrained Delaunay
// triangulation (exact predicates, crossings rounded from exact ones) with the
// constraint hierarchy that gives every obstacle an id, per-face winding
// numbers, and polylines inserted from a located start and removed safely.
#pragma once

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <climits>
#include <cstdint>
#include <vector>

#include "footfall/model/geometry.hpp"
#include "util/open_hash_map.hpp"

namespace footfall {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

/// The triangulation's geometry: the kernel's, except where two constraints
/// cross. The kernel's crossing point can be off by an ulp even where the
/// exact one is a double (two grid-aligned box edges crossing at (4, 7.5)
/// come out at y = 7.5000000000000009); an edge later drawn to the exact
/// point then runs beside a vertex a hair away instead of through it, and
/// the outlines no longer follow each other. So crossings are computed
/// exactly and rounded: exact wherever a double can hold them.
struct CdtTraits : Kernel {
  struct Intersect_2 {
    using Segment = Kernel::Segment_2;
    boost::optional<boost::variant<Point, Segment>> operator()(const Segment& a,
                                                               const Segment& b) const;
  };
  Intersect_2 intersect_2_object() const { return {}; }
};

/// Per face: the winding number of the domain (+1 inside) plus that of every
/// obstacle (-1 inside each), so a face is walkable exactly when it is 1.
struct FaceInfo {
  static constexpr int kUnknown = INT_MIN;  ///< Set by CGAL on new faces; repaired locally.
  int winding = kUnknown;
};

/// Per vertex: how many point obstacles sit on it.
struct VertexInfo {
  int points = 0;
};

using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, CdtTraits>;
using FaceBase =
    CGAL::Triangulation_face_base_with_info_2<FaceInfo, CdtTraits,
                                              CGAL::Constrained_triangulation_face_base_2<CdtTraits>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using CdtBase = CGAL::Constrained_triangulation_plus_2<
    CGAL::Constrained_Delaunay_triangulation_2<CdtTraits, Tds, CGAL::Exact_predicates_tag>>;

}  // namespace footfall

namespace CGAL {
/// The map from face to mark that CGAL's get_bounded_faces keeps, for our
/// face handles. It runs for every constraint edge inserted across faces
/// (Constrained_triangulation_plus_2 then discards what it found), and
/// CGAL's own map allocates and fills a large table each time: ours keeps
/// its first 64 slots inline.
template <>
class Unique_hash_map<footfall::CdtBase::Face_handle, bool, Handle_hash_function,
                      std::allocator<bool>> {
 public:
  using Data = bool;
  /// The mark of `f` (false until set); valid until the next new face.
  bool& operator[](const footfall::CdtBase::Face_handle& f) {
    return *marks_.insert(&*f, false).first;
  }

 private:
  footfall::util::OpenHashMap<const void*, bool, footfall::util::AddressHash, 64> marks_;
};
}  // namespace CGAL

namespace footfall {

/// CGAL's triangulation with one addition. Its insert_constraint locates a
/// polyline's first point from the hull, a walk across the whole mesh (on
/// the 10,000-box scene most of the time it takes to add a box); this one
/// starts the walk at a face the caller knows to be near.
class Cdt : public CdtBase {
 public:
  /// Inserts the polyline through `points` (closed: back to the first) as
  /// one constraint, as CdtBase::insert_constraint(first, last, closed)
  /// does, locating the first point from `hint` (may be null: the hull).
  Constraint_id insert_polyline(const std::vector<Point>& points, bool closed, Face_handle hint) {
    std::vector<Vertex_handle> vertices;
    for (const Point& p : points) {
      const Vertex_handle v = insert(p, hint);
      hint = v->face();
      if (vertices.empty() || vertices.back() != v) vertices.push_back(v);
    }
    if (closed && vertices.size() > 1 && vertices.front() != vertices.back())
      vertices.push_back(vertices.front());
    if (vertices.size() < 2) return nullptr;
    const Constraint_id id = hierarchy.insert_constraint(vertices[0], vertices[1]);
    insert_subconstraint(vertices[0], vertices[1]);
    for (std::size_t j = 1; j + 1 < vertices.size(); ++j) {
      hierarchy.append_constraint(id, vertices[j], vertices[j + 1]);
      insert_subconstraint(vertices[j], vertices[j + 1]);
    }
    return id;
  }

  /// Removes the constraint `id` as CdtBase::remove_constraint does, with two
  /// pieces of its outline skipped: a vertex joined to itself (where another
  /// constraint runs along this one, CGAL 5.5's hierarchy can list a vertex
  /// twice in a row) and a piece no longer an edge (a retraced piece whose
  /// first pass's removal flipped it away). CGAL's own removal assumes both
  /// away and then works on an arbitrary edge.
  void remove_polyline(Constraint_id id) {
    const std::vector<Vertex_handle> vertices(vertices_in_constraint_begin(id),
                                              vertices_in_constraint_end(id));
    hierarchy.remove_constraint(id);
    for (std::size_t j = 0; j + 1 < vertices.size(); ++j) {
      const Vertex_handle a = vertices[j], b = vertices[j + 1];
      Face_handle f;
      int i;
      if (a != b && !is_subconstraint(a, b) && Triangulation::is_edge(a, b, f, i))
        Triangulation::remove_constrained_edge(f, i);
    }
  }
};

using Face = Cdt::Face_handle;
using Vertex = Cdt::Vertex_handle;

inline Vec2 to_vec(const Point& p) { return {p.x(), p.y()}; }
inline Point to_point(Vec2 v) { return {v.x, v.y}; }

}  // namespace footfall
