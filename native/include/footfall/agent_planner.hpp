// Footfall — agents' whole walks: repeated short-horizon searches toward each
// of their goals in turn, among each other's plans, until the last goal is
// reached, the agent is stuck, or the time limit passes (crowd.cpp).
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "footfall/footstep.hpp"
#include "footfall/navmesh.hpp"
#include "footfall/planner.hpp"

namespace footfall {

/// An agent to plan: where it stands and where it goes.
struct AgentSpec {
  std::string name;         ///< Unique name.
  Vec2 position;            ///< Standing position of the COM. [m]
  double facing = 0;        ///< Initial facing. [rad]
  std::vector<Vec2> goals;  ///< Goals, visited in order. [m] [non-empty]
  /// Walks through its last goal and leaves the scene there, as SteerSuite's
  /// agents do, instead of coming to rest on it.
  bool leave_at_goal = false;
};

/// How an agent's plan ended.
enum class AgentStatus {
  kReached,  ///< Every goal was reached; the agent stands at the last one.
  kPartial,  ///< The walk ended early; `AgentPlan::reason` says why.
};
/// "reached" or "partial".
const char* to_string(AgentStatus status);

/// Lets a caller follow and stop a long run.
struct RunControl {
  /// Called with the fraction done, in [0, 1], at most a few times a second.
  std::function<void(double)> progress;
  /// When set and true, the run stops at the next tick and reports kCancelled.
  const std::atomic<bool>* cancel = nullptr;
  /// Threads the searches of one tick run on; the plans do not depend on it. [1, 64]
  int threads = 1;
  /// When set, the seconds spent in footstep searches (each agent's way, its
  /// local goal, the search and the cut to a rest) are added to it, summed
  /// over threads: the planner's own time, beside the run's wall time.
  double* search_seconds = nullptr;
  /// True if the caller asked to stop.
  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

/// The plan of one agent: its start and its timed footsteps.
struct AgentPlan {
  std::string name;                            ///< The agent's name.
  AgentStatus status = AgentStatus::kPartial;  ///< Reached or partial.
  /// Empty when reached; otherwise "stuck", "time limit" or "cancelled".
  std::string reason;
  Vec2 stuck_at;                    ///< Where the agent stopped, when partial. [m]
  FootstepState start;              ///< Standing start state.
  std::vector<Footstep> footsteps;  ///< The timed footsteps, in order.
  int goals_reached = 0;            ///< Goals reached, in order.
  /// The agent walked through its last goal and is gone after its last step
  /// (present_at): no one can meet it there.
  bool leaves = false;
  int searches = 0;               ///< Footstep searches run.
  long long nodes_generated = 0;  ///< Summed over the searches.
  long long nodes_expanded = 0;   ///< Summed over the searches.

  /// Sum of the step costs. [J]
  double total_cost() const;
  /// Time at the end of the last step. [s] (Inline: crowd checks ask it
  /// at every sample.)
  double end_time() const { return footsteps.empty() ? 0.0 : footsteps.back().end_time; }
};

/// False once an agent that leaves has taken its last step.
inline bool present_at(const AgentPlan& plan, double t) {
  return !plan.leaves || t <= plan.end_time();
}

/// Plans `agents` together, each walking through its goals in turn. Each
/// agent's way to its goal is its path on `mesh` (with room to walk upright,
/// else to side-step; the straight line without a mesh or a path), and each
/// search aims at a local goal up to local_goal_distance along it, in sight.
/// Agents plan among the plans of the agents they see (within 30 m, in front
/// of the torso, with a clear line of sight), which they keep clear of as
/// moving obstacles, and replan 1 s before their plan runs out (0.1 s after a
/// search that gave nothing to commit); a 20 Hz tick decides who replans when. Waiting is a valid
/// answer; a blocked agent asks those with more way left that stand in its
/// way to step out of it (yielding, docs/footstep-model.md). A reached last goal
/// ends in a stop step, or for an agent that leaves at it, in the step that
/// reaches it; an agent whose way has not shortened by min_progress
/// for 15 s is stuck: it waits until an agent near it moves, then tries
/// again, and one still waiting when no one else walks on is "stuck"; the
/// walk also ends at max_time ("time limit") or on cancel ("cancelled").
/// Deterministic, whatever `control.threads`.
std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const FootstepPlanner& planner, const NavMesh* mesh = nullptr,
                                   const RunControl& control = {});

/// One agent's walk alone (plan_agents with no one else).
AgentPlan plan_agent(const AgentSpec& agent, const FootstepPlanner& planner,
                     const NavMesh* mesh = nullptr, const RunControl& control = {});

}  // namespace footfall
