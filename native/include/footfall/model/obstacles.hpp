// Footfall — static obstacles in 3-D (prisms and triangle meshes) and their
// footprints on the ground, with a uniform grid for fast circle queries.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "footfall/model/geometry.hpp"
#include "footfall/model/geometry3.hpp"

namespace footfall {

/// Any shape, as triangles. [m]
struct TriangleMesh {
  std::vector<Vec3> vertices;                 ///< [m]
  std::vector<std::array<int, 3>> triangles;  ///< Indices into `vertices`.
};

/// A static obstacle: a polygon in the ground plane extruded from `base` to
/// `height` (a prism: a box, a table top, a beam), or any `mesh`.
struct Obstacle {
  std::vector<Vec2> polygon;  ///< Vertices in order, either winding; not closed. [m] [>= 3]
  double height = 2.0;        ///< Elevation of the top. [m] (0, 1000]
  double base = 0.0;          ///< Elevation of the underside. [m] [0, height)
  TriangleMesh mesh;          ///< With triangles, the obstacle is this mesh, not a prism.

  bool is_mesh() const { return !mesh.triangles.empty() || !mesh.vertices.empty(); }
};

/// A prism obstacle.
inline Obstacle prism(std::vector<Vec2> polygon, double height = 2.0, double base = 0.0) {
  Obstacle obstacle;
  obstacle.polygon = std::move(polygon);
  obstacle.height = height;
  obstacle.base = base;
  return obstacle;
}

/// Checks one obstacle; throws std::invalid_argument naming the field
/// (`name` + ".polygon[1]", ".base", ".mesh.triangles[4][2]", ...).
void validate(const Obstacle& obstacle, const std::string& name);

/// The ground projection of the part of `obstacle` below `cut_height`: the
/// polygon of a prism whose base lies below it; the convex hull of a mesh's
/// part below it (a point or segment where that part is flat on edge); empty
/// when the obstacle lies wholly at or above the cut. [m]
std::vector<Vec2> footprint(const Obstacle& obstacle, double cut_height);

/// The static obstacles of a scene, indexed for circle-overlap queries on
/// their footprints. Immutable after construction, so it can be shared
/// between threads.
class ObstacleMap {
 public:
  /// Indexes the footprints of `obstacles` below `cut_height` (the body's
  /// height: what lies wholly above the head blocks no footstep). Throws
  /// std::invalid_argument naming the obstacle ("obstacles[3].polygon[1]:
  /// ...") for fewer than 3 vertices, a non-finite coordinate, a height or
  /// base out of range, or a bad mesh.
  explicit ObstacleMap(std::vector<Obstacle> obstacles = {},
                       double cut_height = std::numeric_limits<double>::infinity());
  /// The same with a cut per obstacle (on ground, the body's height above
  /// the ground under each: cut_heights() in ground/ground.hpp).
  ObstacleMap(std::vector<Obstacle> obstacles, const std::vector<double>& cut_heights);

  /// Index of an obstacle that the circle touches or overlaps, or -1.
  int first_overlap(const Circle& circle) const;
  /// True if the circle touches or overlaps an obstacle.
  bool overlaps(const Circle& circle) const { return first_overlap(circle) >= 0; }
  /// Appends to `out` (once each) the obstacles whose bounding boxes meet the
  /// bounding box of `region`: the only ones a circle inside `region` can touch.
  void gather(const Circle& region, std::vector<int>& out) const;
  /// Index of an obstacle among `candidates` that the circle touches, or -1.
  int first_overlap(const Circle& circle, const std::vector<int>& candidates) const;
  /// True if `point` lies inside obstacle `index`'s footprint (even-odd rule).
  bool contains(int index, Vec2 point) const;
  /// The obstacles, as given.
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  /// Obstacle `index`'s footprint (footprint()). [m]
  const std::vector<Vec2>& footprint_of(int index) const { return footprints_.at(index); }

 private:
  /// Checks the obstacles and indexes their footprints below the cuts.
  void index_footprints(const std::vector<double>& cut_heights);
  bool circle_overlaps(int index, const Circle& circle) const;
  // Calls visit(index) once for each obstacle whose box meets the circle's box,
  // until visit returns true; returns that index, or -1.
  template <typename Visit>
  int visit_near(const Circle& circle, Visit visit) const;
  int cell_of(double v, double origin, int count) const;

  std::vector<Obstacle> obstacles_;
  std::vector<std::vector<Vec2>> footprints_;
  std::vector<Box> boxes_;
  Box bounds_{};
  double cell_size_ = 1.0;
  int columns_ = 0;
  int rows_ = 0;
  std::vector<std::vector<int>> cells_;  // obstacle indices whose box meets the cell
};

}  // namespace footfall
