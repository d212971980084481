// Footfall — a path query's answer as JSON (what `footfall path` prints).
#pragma once

#include <string>

#include "footfall/navmesh/navmesh.hpp"

namespace footfall {

/// A path result as one line of JSON: {"status", "points", "length", "min_clearance"}.
std::string to_json(const PathResult& result);

}  // namespace footfall
