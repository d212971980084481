// The `footfall bench` command: per-plan time and search effort on the
// standard single-character workloads, and with --crowds on the crowd
// workloads of the footstep paper's table 1.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

#include "footfall/crowd/scenario.hpp"

namespace footfall::tools {

/// Runs every workload `repeat` times and prints a table to `out`.
void run_bench(int repeat, std::ostream& out);

/// Plans each crowd workload `repeat` times on `threads` threads and prints,
/// per workload, the searches' effort and the planning time per plan and per
/// agent per 20 Hz tick of the fastest run to `out` (the plans are the same
/// every time; on a shared machine the fastest run is the least disturbed).
void run_crowd_bench(int threads, int repeat, std::ostream& out);
/// Plans the crowd `crowd` makes of each seed from `first` to `last` on
/// `threads` threads and prints, per seed, how many reach, the overlap
/// samples (measure_plan), the mean travel time over the straight line's
/// alone, the planning time, and every agent that does not reach its goal
/// (its reason and where it stopped); last, their counts over the seeds.
/// Writes the last seed's plan to `plan_path` unless it is empty.
void run_crowd_seeds(const std::function<Scenario(std::uint64_t)>& crowd, int first, int last,
                     int threads, const std::string& plan_path, std::ostream& out);
/// Times the full-body behavioural planner on the paper's random
/// environments (normal and dense, goals at 6 and 10 steps), the fastest of
/// `repeat` runs per query.
void run_behavior_bench(int repeat, std::ostream& out);

}  // namespace footfall::tools
