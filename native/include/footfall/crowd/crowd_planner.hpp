// Footfall — agents' whole walks: repeated short-horizon searches toward each
// of their goals in turn, among each other's plans, until the last goal is
// reached, the agent is stuck, or the time limit passes (crowd_planner.cpp).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "footfall/model/footstep.hpp"
#include "footfall/navmesh/navmesh.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/planner/planner.hpp"

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
  /// Its annotated way from `position` through every goal (the full-body
  /// planner's sections, joined end to end; plan_scenario plans it). Where it
  /// has a section other than walk, the agent follows it: its way is the
  /// annotated one, and its steps take their sections' behaviours.
  std::vector<BehaviorSection> sections{};
  /// Its own character (a scenario's per-agent `character`); null: the
  /// planner's. Its plan keeps it (AgentPlan::character).
  std::shared_ptr<const CharacterParams> character{};
  /// Its time budget, (0, kMaxTimeLimit]; 0: time_limit_of()'s default. [s]
  double time_limit = 0;
  /// It stands where it is until this time, then sets off; its time budget
  /// starts then. [s] [0, kMaxTimeLimit]
  double start_delay = 0;
  /// It stands this long at each goal but the last before it walks on. [s]
  /// [0, kMaxTimeLimit]
  double goal_wait = 0;
  /// The facing it turns to on the spot at its last goal, where it has the
  /// room (not for one that leaves there). [rad]
  std::optional<double> end_facing{};
  /// Per goal, the facing it turns to on the spot once it stands there (then
  /// it waits goal_wait and walks on), where it has the room: one per goal,
  /// null for none, or empty. The last goal's may be end_facing instead. [rad]
  std::vector<std::optional<double>> goal_facings{};
  /// Its body's size, as a share of the character's (`character` is made
  /// from scaled() of the scenario's; its plan keeps it, AgentPlan::scale).
  /// [kLeastScale, kMostScale]
  double scale = 1;
  /// The height it stands at, where its position gives one ([x, y, z]): it
  /// stands on the ground within kHeightReach of it. [m]
  std::optional<double> height{};
  /// Per goal, the height given with it, or none; empty: none given. [m]
  std::vector<std::optional<double>> goal_heights{};
};

/// How near the ground an agent's or goal's given height must be. [m]
constexpr double kHeightReach = 0.5;

/// What is wrong with an agent's facings at its goals: the field
/// ("end_facing", "goal_facings" or "goal_facings[k]") and the problem; none.
std::optional<std::pair<std::string, std::string>> facings_problem(const AgentSpec& agent);

/// The facing `agent` turns to at its goal number `goal`: its goal_facings',
/// or its end_facing at its last goal; none: it stands as it arrives.
std::optional<double> goal_facing(const AgentSpec& agent, std::size_t goal);

/// The simulated time an agent may walk: its own time_limit, else the
/// planner's max_time or four times its route's walking time at the
/// preferred speed (straight lines through its goals), whichever is longer,
/// up to kMaxTimeLimit. [s]
double time_limit_of(const AgentSpec& agent, const CharacterParams& character,
                     const PlannerParams& planner);

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
/// Each plan lists its agent's sections, and each step its behaviour.
/// Deterministic, whatever `control.threads`.
/// Every agent walks with the planner's character: none may have its own.
std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const FootstepPlanner& planner, const NavMesh* mesh = nullptr,
                                   const RunControl& control = {});

/// The full-body planner's sections for agents[agent] of plan_agents from
/// `from` through its goals from `first_goal` on, as far as there is a way.
/// Asked for a stuck agent, which the crowd may have pushed off its
/// annotated way, into a gap it walks through only with the arms in or
/// side-stepping.
using Annotator = std::function<std::vector<BehaviorSection>(std::size_t agent, Vec2 from,
                                                              std::size_t first_goal)>;

/// The same with a planner per agent: agent i searches with planners[i],
/// made for its own character (plan_scenario makes one per character), and
/// every check of one agent's body against another's takes each one's own.
/// The planners' PlannerParams are the first one's. Where `fixed` (empty, or
/// one per agent) gives agent i a plan, the agent keeps that plan as it is:
/// the others plan among it as among an agent that has finished planning
/// (it walks its plan, asked to make room by none), and its plan comes back
/// unchanged. With `annotate`, a stuck agent's second chance (the roomiest
/// way) also follows its way annotated anew from where it stands.
std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const std::vector<const FootstepPlanner*>& planners,
                                   const NavMesh* mesh = nullptr, const RunControl& control = {},
                                   const std::vector<const AgentPlan*>& fixed = {},
                                   const Annotator& annotate = {});

class LayeredNavigation;

/// plan_agents on ground with levels above one another: each agent finds its
/// ways on the mesh of the layer it stands on, to where its way crosses to
/// another, and its footsteps take it across. No ways are annotated (the
/// full-body planner does not yet find ways between levels).
std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const std::vector<const FootstepPlanner*>& planners,
                                   const LayeredNavigation& navigation,
                                   const RunControl& control = {},
                                   const std::vector<const AgentPlan*>& fixed = {});

/// One agent's walk alone (plan_agents with no one else).
AgentPlan plan_agent(const AgentSpec& agent, const FootstepPlanner& planner,
                     const NavMesh* mesh = nullptr, const RunControl& control = {});

}  // namespace footfall
