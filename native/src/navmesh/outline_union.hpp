// Footfall — obstacles that overlap, as the one region they cover together:
// entered as their union, they cost the mesh what the union costs instead of
// a vertex at every crossing of their outlines.
#pragma once

#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall {

/// The area some overlapping outlines cover: its outer outlines and holes.
struct Region {
  std::vector<std::vector<Vec2>> outlines, holes;
};

/// A group of outlines that overlap one another (directly or through others
/// of the group), and the region they cover.
struct OverlapGroup {
  std::vector<int> members;  ///< indices into the outlines given, increasing
  Region region;
};

/// The groups of two or more simple polygons among `outlines` (at least
/// three vertices, not crossing themselves; others are left alone) whose
/// areas overlap (touching along a boundary is not overlapping). In order
/// of their first members.
std::vector<OverlapGroup> overlapping_groups(const std::vector<std::vector<Vec2>>& outlines);

}  // namespace footfall
