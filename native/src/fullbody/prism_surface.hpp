// Footfall — a prism obstacle's surface as triangles: its walls, and its caps
// cut into triangles by a constrained triangulation.
#pragma once

#include <array>
#include <vector>

#include "footfall/model/geometry3.hpp"
#include "footfall/model/obstacles.hpp"

namespace footfall::detail {

/// The triangles of a prism's walls, bottom and top.
std::vector<std::array<Vec3, 3>> prism_surface(const Obstacle& prism);

/// Triangles covering a polygon of either winding (a self-crossing one: the
/// parts inside an odd number of times), in O(n log n).
std::vector<std::array<Vec2, 3>> triangulate_polygon(const std::vector<Vec2>& polygon);

}  // namespace footfall::detail
