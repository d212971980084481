// Footfall — the navigation mesh's private state: CGAL's constrained Delaunay
// triangulation (exact predicates) with the constraint hierarchy that gives
// every obstacle an id, and per-face winding numbers for walkability.
#pragma once

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <climits>
#include <unordered_map>
#include <vector>

#include "footfall/navmesh.hpp"

namespace footfall {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;

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

using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<
    FaceInfo, Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_triangulation_plus_2<
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>>;
using Face = Cdt::Face_handle;
using Vertex = Cdt::Vertex_handle;

inline Vec2 to_vec(const Point& p) { return {p.x(), p.y()}; }
inline Point to_point(Vec2 v) { return {v.x, v.y}; }

struct NavMeshState {
  /// One obstacle as the caller gave it.
  struct Obstacle {
    Cdt::Constraint_id constraint = nullptr;  ///< Polygons, walls and segments.
    Vertex point;                             ///< Point obstacles (null outside the domain).
  };

  Cdt cdt;
  Cdt::Constraint_id domain = nullptr;
  Vec2 min_corner, max_corner;
  std::unordered_map<int, Obstacle> obstacles;
  int next_id = 0;

  bool in_domain(Vec2 p) const {
    return p.x >= min_corner.x && p.y >= min_corner.y && p.x <= max_corner.x && p.y <= max_corner.y;
  }
  bool walkable(Face f) const { return !cdt.is_infinite(f) && f->info().winding == 1; }
  /// Winding number change from `f` to its neighbour across edge `i`.
  int winding_step(Face f, int i) const;
  /// Marks the faces around `vertices` unknown. Needed after every insertion:
  /// splitting a constrained edge, CGAL flips a face across it and keeps its
  /// old info, so a face next to a new vertex may carry the other side's winding.
  void forget_windings(const std::vector<Vertex>& vertices);
  /// Gives every face marked unknown near `seeds` its winding number again.
  void repair_windings(const std::vector<Vertex>& seeds);
  /// Adds `sign` times the winding number of the closed `constraint` to the
  /// faces it encloses.
  void shift_enclosed(Cdt::Constraint_id constraint, int sign);
  /// Removes a vertex that no constraint and no point obstacle uses any more.
  void remove_if_orphan(Vertex v);
};

}  // namespace footfall
