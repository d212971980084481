// Footfall — a prism obstacle's surface as triangles: its walls, and its caps
// cut into triangles by ear clipping.
#pragma once

#include <array>
#include <vector>

#include "footfall/model/geometry3.hpp"
#include "footfall/model/obstacles.hpp"

namespace footfall::detail {

/// The triangles of a prism's walls, bottom and top.
std::vector<std::array<Vec3, 3>> prism_surface(const Obstacle& prism);

/// Triangles (as index triples) covering a simple polygon of either winding;
/// a polygon with no ear left (self-crossing) is finished as a fan.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec2>& polygon);

}  // namespace footfall::detail
