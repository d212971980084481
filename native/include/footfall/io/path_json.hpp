// Footfall — a path query's answer as JSON (what `footfall path` prints).
#pragma once

#include <string>

#include "footfall/fullbody/behavioral_planner.hpp"
#include "footfall/navmesh/navmesh.hpp"

namespace footfall {

/// A path result as one line of JSON: {"status", "points", "length",
/// "min_clearance"}; its points [x, y, z] where it has heights, else [x, y].
std::string to_json(const PathResult& result);
/// An annotated path as one line of JSON: the same fields (the points of
/// every section joined), then "sections" [{"behavior", "clearance",
/// "points", "length"}], "point_obstacles", "poses_tested" and, when there
/// is no path, "reason".
std::string to_json(const BehaviorPath& path);

}  // namespace footfall
