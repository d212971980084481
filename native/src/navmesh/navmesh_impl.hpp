// Footfall — the navigation mesh's private state: the triangulation
// (navmesh_cdt.hpp), the obstacles by id, and the local repairs of the
// per-face winding numbers that say what is walkable.
#pragma once

#include <unordered_map>
#include <vector>

#include "footfall/navmesh/navmesh.hpp"
#include "navmesh/locate_hints.hpp"
#include "navmesh/navmesh_cdt.hpp"

namespace footfall {

struct NavMeshState {
  /// One obstacle as the caller gave it.
  struct Obstacle {
    /// Its closed outlines: a polygon's, a wall's or a segment's one; a
    /// region's outer outlines and holes.
    std::vector<Cdt::Constraint_id> rings;
    Vertex point;  ///< Point obstacles (null outside the domain).
  };

  NavMeshState(Vec2 lo, Vec2 hi) : min_corner(lo), max_corner(hi), hints(lo, hi) {}

  Cdt cdt;
  Cdt::Constraint_id domain = nullptr;
  Vec2 min_corner, max_corner;
  LocateHints hints;  ///< Where point locations start (updates change it, queries read it).
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
  /// Inserts a closed outline (its vertices in order, the first not repeated)
  /// and shifts the faces it encloses by its winding number.
  Cdt::Constraint_id add_ring(const std::vector<Point>& points);
  /// Removes a vertex that no constraint and no point obstacle uses any more,
  /// giving the faces that fill its hole the winding number around it.
  void remove_if_orphan(Vertex v);
};

}  // namespace footfall
