// Footfall — the plan file (JSON, "footfall-plan"): written as version 2, compact, each
// agent's footsteps as columns; versions 1 and 2 read (docs/file-formats.md).
#pragma once

#include <string>

#include "footfall/plan/plan.hpp"

namespace footfall {

/// The plan as JSON text, the same as write_plan_file writes: read back, it
/// is the same plan to the bit.
std::string plan_to_json(const Plan& plan);

/// Parses plan JSON (as written by plan_to_json, by an older Footfall, or by
/// hand). Errors are std::invalid_argument: "SOURCE: FIELD.PATH: what is wrong".
Plan parse_plan(const std::string& text, const std::string& source = "<string>");

/// Writes the plan file agent by agent (never the whole text in memory),
/// atomically: to a temporary file beside `path`
/// (".NAME.<pid>-<n>.partial", unique to the write), then renamed, so a
/// failure leaves no half-written file and two writers of one path do not
/// collide. Temporaries that stopped runs left are removed first. A NUL byte
/// in `path` is std::invalid_argument; other failures footfall::Error.
void write_plan_file(const Plan& plan, const std::string& path);

/// Reads a plan file (errors as parse_plan).
Plan load_plan(const std::string& path);

}  // namespace footfall
