// Footfall — what the crowd driver (crowd_planner.cpp) keeps of each agent, what one
// of its searches gives, and where everyone is at a tick; the constants that
// tune the driver's rules, and the small questions every part of it asks.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "behavior/local_goal.hpp"
#include "crowd/congestion.hpp"
#include "footfall/crowd/crowd_planner.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/plan/plan_samples.hpp"
#include "footfall/planner/planner.hpp"
#include "plan/agent_grid.hpp"

namespace footfall::crowd {

constexpr double kTick = 0.05;       ///< The scheduling tick (20 Hz). [s]
constexpr double kReplanLead = 1.0;  ///< An agent replans when this little of its plan is left. [s]
constexpr double kViewDistance = 30.0;  ///< Agents farther away are not seen. [m]
/// An agent whose way has not shortened by min_progress for this long, nor
/// that of any agent within kQueueDistance, is stuck. [s]
constexpr double kStuckAfter = 15.0;
constexpr double kQueueDistance = 4.0;     ///< [m]
constexpr double kProgressInterval = 0.2;  ///< Between progress reports. [s]
/// A new plan is checked against the agents this near now; none farther can
/// reach it within a plan's few seconds. [m]
constexpr double kCheckDistance = 40.0;
/// Nodes a blocked agent's search expands at most (after a search that
/// gained nothing), when one it sees stands within kJamDistance.
constexpr int kBlockedHorizon = 100;
/// Places aside an agent making room tries to reach, nearest first.
constexpr std::size_t kAsideTries = 4;
constexpr double kJamDistance = 3.0;  ///< [m]
/// Nodes the search of an agent with someone it sees within kJamDistance
/// expands without one nearer its goal before it stops (the planner's
/// stall_expansions, 300, is for one held up by obstacles): in a jam, a way
/// forward shows within a few nodes or is not there yet.
constexpr int kJamStall = 15;
/// An agent whose way has not shortened by min_progress for this long
/// searches as if alone again, for a way out that a short search misses. [s]
constexpr double kJamPatience = 5.0;
/// Searches in a row without progress after which an impatient agent gives
/// way to all (gives_way()).
constexpr int kGiveWayBlocked = 6;
/// Longer ago than any time: "never". [s]
constexpr double kForever = std::numeric_limits<double>::infinity();
/// A blocked agent searches again only if something within this changed. [m]
constexpr double kFreezeRadius = 5.0;
/// The side of the cells the snapshot buckets agents in (at least; larger
/// where they are spread thin), about the nearest of the distances asked
/// about. [m]
constexpr double kGridCell = 5.0;
/// Steps that ended this long before a tick are past every check and
/// search (none reaches back more than a few seconds; settle()). [s]
constexpr double kSettledAge = 10.0;
/// How often plans are settled (every second), and the fewest steps worth it.
constexpr long kSettleTicks = 20;
constexpr std::size_t kSettleAtLeast = 8;
/// Rests closer than this are the same place. [m]
constexpr double kSamePlace = 0.01;
/// Noticed agents are kept in mind while they are this near. [m]
constexpr double kNoticeDistance = 3.0;
/// Searches take walking agents to stand where their plans end for this
/// long only: they will plan on (SearchOptions::rest_grace). [s]
constexpr double kRestGrace = 1.0;
/// Longest single wait step. [s]
constexpr double kMaxWait = 5.0;
/// An agent whose search found nothing it could commit tries again this much
/// later, not at every tick: a blocked agent's searches would cost the most;
/// after each further failure in a row it waits twice as long, up to
/// kRetryAfter * 2^kMaxBackoff (someone queueing at an exit need not look
/// for a way out ten times a second). [s]
constexpr double kRetryAfter = 0.1;
constexpr int kMaxBackoff = 3;
/// How far along its wish a blocked agent asks others to make room. [m]
constexpr double kWishReach = 2.5;
/// About as far as an agent's circles reach from its COM. [m]
constexpr double kBodyLength = 1.0;
/// Room to pass that the others leave beside a wish (more than a search's
/// padding between samples). [m]
constexpr double kWishPad = 0.05;
/// Keeping right in counterflow (keep_right()): an agent with kKeepRightRoom
/// round it that sees one walking the other way (at kOncomingSpeed or faster
/// against the line to its local goal, and bound that way) within
/// kKeepRightAhead ahead and kKeepRightBand beside that line moves its local
/// goal up to kKeepRightShift to its right, where there is kKeepRightRoom all
/// along the way there (not through a door). The room is a little less than
/// a torso's width (0.6 m), so that those walking near a wall, the ones most
/// in the way, keep right too.
constexpr double kKeepRightAhead = 30.0;  ///< [m]
constexpr double kKeepRightBand = 2.0;    ///< [m]
constexpr double kOncomingSpeed = 0.8;    ///< [m/s]
constexpr double kKeepRightShift = 3.0;   ///< [m]
constexpr double kKeepRightRoom = 0.5;    ///< [m]

/// A way measured on the navigation mesh, from where to which goal.
struct KnownWay {
  Vec2 from, goal;
  Way way;
};

/// One agent as the driver keeps it.
struct Walker {
  const AgentSpec* spec = nullptr;
  /// Its planner, made for its character.
  const FootstepPlanner* planner = nullptr;
  /// It plans from this time on (its start delay), and no more past the
  /// deadline ("time limit"). [s]
  double start_at = 0.0;
  double deadline = 0.0;
  /// Its sections (spec->sections), for its searches.
  std::shared_ptr<const SectionLookup> sections;
  /// Per goal, the annotated way to it from the goal before (or the start),
  /// which it follows; empty when it does not follow its sections
  /// (planner.follow_sections 0, or a way of walk alone).
  std::vector<std::vector<Vec2>> guides;
  AgentPlan plan;  ///< Its steps, ending with `resting` provisional rest steps.
  /// Counts the changes of `plan` (its steps, or whether it leaves): a check
  /// made against one version holds while it stands.
  std::uint64_t version = 0;
  /// Of `plan`, rebuilt whenever it changes. Bounds and samples are never
  /// changed in place, only replaced: the views of the walkers that a tick's
  /// searches read share them.
  std::shared_ptr<const PlanBounds> bounds;
  /// Of `plan`, those its commit check took (none: null); dropped whenever
  /// it changes.
  std::shared_ptr<const PlanSamples> samples;
  FootstepState state;   ///< Where the next search starts: before the rest.
  FootstepState rested;  ///< After the rest.
  std::size_t resting = 0;
  std::size_t goal = 0;
  double retry_at = 0.0;            ///< No search before this time. [s]
  int failures = 0;                 ///< Searches in a row that gave nothing to commit.
  int blocked = 0;                  ///< Searches in a row that committed no progress.
  double searched_at = -kForever;   ///< Tick of its last search. [s]
  FootstepState searched_from;      ///< Where its last search started.
  double committed_at = -kForever;  ///< Tick its plan last changed by a commit. [s]
  /// Tick it was last asked to make room, or noticed an agent. [s]
  double news_at = -kForever;
  /// Seconds its last search and check took: a guess at the next one's cost
  /// (only the order in which a tick's jobs start depends on it).
  double last_cost = 0.0;
  double first_way = 0.0;  ///< Way to the current goal when it was first measured. [m]
  double best_way = std::numeric_limits<double>::infinity();  ///< Shortest way left so far. [m]
  double improved_at = 0.0;  ///< Plan time when best_way last shortened by min_progress. [s]
  /// Where its plan last stood with room to walk upright: stuck in a tight
  /// place, it backs out toward there (the way it came in, which its steps
  /// passed).
  std::optional<Vec2> roomy_at;
  /// Agents a plan of this one's was refused for touching (or for resting
  /// too close to), while they stay within kNoticeDistance: seen or not, its
  /// searches avoid them (it has bumped into them). Without them, an agent
  /// that does not see who is in its way finds the same refused plan again
  /// at every retry.
  std::vector<std::size_t> noticed;
  /// Way left from `state`, at its last search: who goes first. [m]
  double way = std::numeric_limits<double>::infinity();
  /// While blocked, its wish: the first kWishReach of the way it would take
  /// if the agents that go after it made room, as the circles it sweeps
  /// (wish_discs; empty: none). Those resting there are asked to keep out.
  KeepOut wish;
  /// Its wish is the way out of the wishes of others (must_make_room()):
  /// those in it make room too, whichever way they are bound.
  bool wish_makes_room = false;
  /// Agents whose wishes this one was asked to keep out of.
  std::vector<std::size_t> yielding_to;
  /// The ways its last search measured (Attempt::ways).
  std::vector<KnownWay> ways;
  /// Stuck (stuck()): it stands where its plan ends and replans no more,
  /// until one near it moves on or asks it to make room (wake()).
  bool dormant = false;
  /// Its ways to the current goal are the roomiest there are: it was stuck
  /// once on the usual ones (try_again()).
  bool roomy = false;
  /// Times it counted as stuck on its way to the current goal: after the
  /// third it sleeps (plan_agents()).
  int stuck_times = 0;
  bool done = false;

  /// The sections its searches, rests and waits follow (none when it does
  /// not follow them). Stuck once, it leaves the annotated way for the
  /// roomiest, but its steps keep their sections' behaviours: it may stand
  /// in a passage it could not walk with its arms swinging.
  const SectionLookup* following() const { return guides.empty() ? nullptr : sections.get(); }
};

/// True if walker `w`, searching from `state`, has gained way within
/// kJamPatience (its search in a jam may stop early).
inline bool patient(const Walker& w, const FootstepState& state) {
  return state.time - w.improved_at < kJamPatience;
}

/// True if steps that reach the walker's current goal end its walk there.
inline bool leaves_now(const Walker& w, bool reached) {
  return reached && w.spec->leave_at_goal && w.goal + 1 == w.spec->goals.size();
}

/// What one search gave, before it is committed.
struct Attempt {
  std::vector<Footstep> steps;
  FootstepState end;
  Rest rest;             ///< After the steps, among the agents the search saw.
  bool reached = false;  ///< The steps reach the current goal itself.
  bool turned = false;   ///< Its rest ends turning to the goal's facing (goal_facing).
  double way_left = 0.0;
  double way_from = 0.0;  ///< Way left at the start. [m]
  /// The agent's wish (Walker::wish), when it is blocked; empty otherwise.
  KeepOut wish;
  bool wish_makes_room = false;  ///< Walker::wish_makes_room.
  int nodes_generated = 0, nodes_expanded = 0;
  bool searched = false;
  FootstepState from;  ///< Where the search started.
  /// The ways it measured, from where it started and, unless the steps reach
  /// the goal, from their end: the agent's next search mostly starts at one
  /// of them, and takes its way from there instead of measuring it anew.
  std::vector<KnownWay> ways;
};

/// Where every agent is at a tick's time t, and whether it is still there,
/// as their plans stood when the tick's searches were set going: the
/// commits of the tick before, made while they run, change plans from that
/// tick's time on (a due agent's plan runs to it or beyond before it
/// searches), so those agents' places are up to a tick old.
struct Snapshot {
  double t = 0.0;
  std::vector<Vec2> com;
  std::vector<char> present;
  AgentGrid grid;  ///< com, for the agents near one (present or not).
  /// Every plan's bounds from `bounds_from` on, read in a row by the commit
  /// checks of the tick's trials from that time on (Trial::apart()), rather
  /// than from each plan's own bounds. [s]
  double bounds_from = 0.0;
  std::vector<PlanBounds::From> bounds;
  /// Per agent: it goes after every other (gives_way()).
  std::vector<char> giving_way;
  /// Per layer of ground (one but on levels above one another), where the
  /// present agents on it are thick (none without a mesh).
  std::vector<CrowdDensity> crowds;
  /// Per agent, the height of the ground it stands on (ground_at), and the
  /// body's height: agents on levels apart by that much never meet.
  std::vector<double> ground;
  double headroom = 0.0;

  /// The agents but `i` within `radius` of agent `i` (and some further) on
  /// its level: grid.around, less those on levels apart from it.
  void around(std::size_t i, double radius, std::vector<std::size_t>& out) const {
    grid.around(com[i], radius, out);
    out.erase(std::remove_if(out.begin(), out.end(),
                             [&](std::size_t j) {
                               return j == i || levels_apart(ground[j], ground[i], headroom);
                             }),
              out.end());
  }
};

/// True if agent `a` goes before agent `b` where their ways cross: one that
/// gives way (as of `now`) goes after one that does not; then the one with
/// less way left, then the earlier in the scenario.
inline bool goes_first(const std::vector<Walker>& walkers, const Snapshot& now, std::size_t a,
                       std::size_t b) {
  if (now.giving_way[a] != now.giving_way[b]) return now.giving_way[b] != 0;
  const Walker &first = walkers[a], &second = walkers[b];
  return first.way < second.way || (first.way == second.way && a < b);
}

/// True while agent `w` shows a wish.
inline bool wishing(const Walker& w) { return !w.wish.empty(); }

/// Agent `w`'s plan, as others keep clear of it.
inline MovingObstacle obstacle_of(const Walker& w) {
  return {&w.plan, w.bounds.get(), w.samples.get()};
}

/// The plans of agents `which`.
inline MovingObstacles plans_of(const std::vector<Walker>& walkers,
                                const std::vector<std::size_t>& which) {
  MovingObstacles plans;
  plans.reserve(which.size());
  for (const std::size_t j : which) plans.push_back(obstacle_of(walkers[j]));
  return plans;
}

/// Where walker `w`, at `at`, is bound: the way to its current goal (its last
/// once it has reached them all).
inline Vec2 bound_of(const Walker& w, Vec2 at) {
  return w.spec->goals[std::min(w.goal, w.spec->goals.size() - 1)] - at;
}

/// True if `step` neither moves the COM nor turns the torso from `facing`.
inline bool still(const Footstep& step, double facing) {
  return step.kind == StepKind::kStop && step.phi == facing &&
         length(step.com_velocity_start) == 0.0 && length(step.com_velocity_end) == 0.0;
}

/// The state agent `w` stands in after its plan.
inline const FootstepState& rest_of(const Walker& w) { return w.resting > 0 ? w.rested : w.state; }

/// Wakes a dormant (stuck) agent: it replans from the next tick on, with
/// kStuckAfter again to gain way.
inline void wake(Walker& w, double t) {
  w.dormant = false;
  w.plan.reason.clear();
  w.retry_at = t;
  w.improved_at = t;
}

}  // namespace footfall::crowd
