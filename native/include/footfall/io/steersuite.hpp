// Footfall — SteerSuite test cases (XML, namespace
// http://www.magix.ucla.edu/steerbench) read as scenarios.
//
// SteerSuite is Y-up, its agents walk on the X-Z plane; a point (x, y, z) of
// a test case is the point (x, -z, y) of Footfall's Z-up frame (the same
// right-handed turn as glTF's Y-up), so ground positions map (x, z) -> (x, -z)
// and a rotation thetaY about +Y is a rotation about +Z.
#pragma once

#include <cstdint>
#include <string>

#include "footfall/crowd/scenario.hpp"

namespace footfall {

/// Parses and validates a SteerSuite test case. Boxes, oriented boxes,
/// circles (as circumscribed 16-gons) and random obstacle regions; agents and
/// agent regions with seekStaticTarget goal sequences, random positions,
/// directions and targets drawn from `seed` (the same seed, the same scene).
/// Any other goal type is refused naming the agent and the type. Errors are
/// std::invalid_argument: "SOURCE: WHERE: what is wrong".
Scenario parse_steersuite(const std::string& text, const std::string& source = "<string>",
                          std::uint64_t seed = 1);

/// Reads a SteerSuite test-case file (errors as parse_steersuite).
Scenario load_steersuite(const std::string& path, std::uint64_t seed = 1);

}  // namespace footfall
