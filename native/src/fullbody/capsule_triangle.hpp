// Footfall — distance between a segment and a triangle: the exact test under
// every capsule-obstacle check of the full-body planner.
#pragma once

#include "footfall/model/geometry3.hpp"

namespace footfall::detail {

/// Nearest points of a segment and a triangle.
struct SegmentTriangleDistance {
  double squared = 0;  ///< Squared distance. [m^2]
  Vec3 on_segment;     ///< The segment's nearest point. [m]
  Vec3 on_triangle;    ///< The triangle's nearest point. [m]
};

/// The nearest points of segment [p, q] and triangle (a, b, c) (which may be
/// degenerate).
SegmentTriangleDistance segment_triangle_distance(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c);

}  // namespace footfall::detail
