// The `footfall bench` command: per-plan time and search effort on the
// standard single-character workloads.
#pragma once

#include <ostream>

namespace footfall::tools {

/// Runs every workload `repeat` times and prints a table to `out`.
void run_bench(int repeat, std::ostream& out);

}  // namespace footfall::tools
