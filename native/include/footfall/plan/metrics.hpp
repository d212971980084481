// Footfall — measuring a plan: our own figures, and SteerBench's, computed
// SteerBench's way from the plan sampled at a fixed rate.
#pragma once

#include <string>
#include <vector>

#include "footfall/plan/plan.hpp"

namespace footfall {

/// The figures of one agent.
struct AgentMetrics {
  std::string name;        ///< The agent.
  bool reached = false;    ///< Every goal reached.
  double time = 0;         ///< Time to the end of its plan (to the goal when reached). [s]
  double path_length = 0;  ///< Length of the COM path, over the samples. [m]
  double effort = 0;       ///< Sum of the step costs. [J]
  /// Samples at which one of its five circles overlaps an obstacle or a
  /// circle of another agent (our collision model; zero for a valid plan).
  /// For an agent whose sections hold one narrower than walk, its shoulder
  /// circles are not counted against obstacles: the full-body check tests
  /// the shoulders and arms there in 3-D.
  int overlaps = 0;
  int collision_episodes = 0;  ///< SteerBench: times it starts to overlap (torso discs).
  double energy = 0;           ///< SteerBench: sum over samples of |dpos/dt|^2 / 2.
  double acceleration = 0;     ///< SteerBench: sum over samples of |dv| / dt.
};

/// The figures of a whole plan.
struct PlanMetrics {
  std::vector<AgentMetrics> agents;  ///< In the plan's order.
  double rate = 20;                  ///< Samples per second. [Hz]
  double composite01 = 0;            ///< 50 * mean collision episodes + mean time + mean energy.
  double composite02 = 0;            ///< composite01 + mean acceleration.
  int overlaps = 0;                  ///< Sum of the agents' five-circle overlaps.
};

/// SteerBench's collision model: a torso disc of this radius. [m]
constexpr double kSteerBenchRadius = 0.15;
/// SteerBench counts an overlap deeper than this. [m]
constexpr double kSteerBenchPenetration = 0.001;

/// Measures `plan` sampled at `rate` [Hz] (0, 1000] from time 0 to the end of the
/// longest agent plan; an agent past the end of its plan stands where it ended.
/// Throws std::invalid_argument for a rate out of range or a plan that ends
/// after kMaxPlanTime.
PlanMetrics measure_plan(const Plan& plan, double rate = 20.0);

}  // namespace footfall
