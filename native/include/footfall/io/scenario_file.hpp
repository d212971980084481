// Footfall — scenario files: Footfall's scenario JSON (docs/file-formats.md),
// and either kind by its name.
#pragma once

#include <string>

#include "footfall/crowd/scenario.hpp"

namespace footfall {

/// Parses and validates scenario JSON. Every error is a std::invalid_argument
/// of one line: "SOURCE: FIELD.PATH: what is wrong".
Scenario parse_scenario(const std::string& text, const std::string& source = "<string>");

/// Reads, parses and validates a scenario file (errors as parse_scenario; an
/// unreadable file is a std::invalid_argument naming it).
Scenario load_scenario(const std::string& path);

/// Reads a scenario file of either kind: SteerSuite XML when the name ends in
/// ".xml", Footfall's scenario JSON otherwise.
Scenario load_scenario_file(const std::string& path);

}  // namespace footfall
