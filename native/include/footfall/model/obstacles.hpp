// Footfall — static obstacles as 2-D polygons, with a uniform grid for fast
// circle queries.
#pragma once

#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall {

/// A static obstacle: a polygon in the ground plane extruded to a height.
struct Obstacle {
  std::vector<Vec2> polygon;  ///< Vertices in order, either winding; not closed. [m] [>= 3]
  double height = 2.0;        ///< Height above the ground. [m] (0, 1000]
};

/// The static obstacles of a scene, indexed for circle-overlap queries.
/// Immutable after construction, so it can be shared between threads.
class ObstacleMap {
 public:
  /// Indexes `obstacles`. Throws std::invalid_argument naming the obstacle
  /// ("obstacles[3].polygon[1]: ...") for fewer than 3 vertices, a non-finite
  /// coordinate or a height out of range.
  explicit ObstacleMap(std::vector<Obstacle> obstacles = {});

  /// Index of an obstacle that the circle touches or overlaps, or -1.
  int first_overlap(const Circle& circle) const;
  /// True if the circle touches or overlaps an obstacle.
  bool overlaps(const Circle& circle) const { return first_overlap(circle) >= 0; }
  /// Appends to `out` (once each) the obstacles whose bounding boxes meet the
  /// bounding box of `region`: the only ones a circle inside `region` can touch.
  void gather(const Circle& region, std::vector<int>& out) const;
  /// Index of an obstacle among `candidates` that the circle touches, or -1.
  int first_overlap(const Circle& circle, const std::vector<int>& candidates) const;
  /// True if `point` lies inside obstacle `index` (even-odd rule).
  bool contains(int index, Vec2 point) const;
  /// The obstacles, as given.
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }

 private:
  bool circle_overlaps(int index, const Circle& circle) const;
  // Calls visit(index) once for each obstacle whose box meets the circle's box,
  // until visit returns true; returns that index, or -1.
  template <typename Visit>
  int visit_near(const Circle& circle, Visit visit) const;
  int cell_of(double v, double origin, int count) const;

  std::vector<Obstacle> obstacles_;
  std::vector<Box> boxes_;
  Box bounds_{};
  double cell_size_ = 1.0;
  int columns_ = 0;
  int rows_ = 0;
  std::vector<std::vector<int>> cells_;  // obstacle indices whose box meets the cell
};

}  // namespace footfall
