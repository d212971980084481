// Footfall — the crowd driver. Agents plan their footsteps toward local goals
// on their ways (local_goal.hpp), each among the plans of the agents it sees,
// replanning a little before its plan runs out. A fixed tick decides who
// replans when; the output is every agent's continuous footstep plan.
//
// No overlaps: every plan ends with the agent coming to rest (a provisional
// rest, replaced when the agent replans; an agent that leaves at its last goal
// is gone after it instead), and a new plan is committed only if it keeps
// clear of every other agent's plan, rest included, seen or not; otherwise
// the agent waits where its rest leaves it. Every committed plan was checked
// against everyone's rest, so waiting is always clear.
//
// Yielding: a blocked agent shows the agents after it (in the order of way
// left) that rest in its way where it would go; they rest out of it. In a
// face-off, where no one can rest ahead, those in the way of one bound
// against them step aside to the nearest room (must_make_room()). One stalled
// there, with one bound against it near, goes last (gives_way()). One stuck
// (stuck()) sleeps until one near it moves (wake_near()).
//
// Determinism: the searches of one tick read a snapshot (every plan as it
// stood when the tick began) and may run on several threads; their results are
// committed one agent after another in the agents' order, each checked against
// the plans as they then stand. So the plans do not depend on the number of
// threads or their timing. The check against a plan no commit of the tick has
// changed yet gives what it gave against the snapshot, so it is made on the
// threads too, with the search (propose()); only plans changed earlier in the
// tick are checked in order (refusal()).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "agent_grid.hpp"
#include "contact.hpp"
#include "footfall/agent_planner.hpp"
#include "footfall/plan.hpp"
#include "local_goal.hpp"
#include "trial.hpp"
#include "workers.hpp"

namespace footfall {
namespace {

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
/// a torso's width (0.6 m): with 1.5 m, those walking near a wall, the ones
/// most in the way, never kept right, and a hall 8 m wide jammed for 3 seeds
/// of 8 (of 30 seeds, 26 now reach 200 of 200).
constexpr double kKeepRightAhead = 30.0;  ///< [m]
constexpr double kKeepRightBand = 2.0;    ///< [m]
constexpr double kOncomingSpeed = 0.8;    ///< [m/s]
constexpr double kKeepRightShift = 3.0;   ///< [m]
constexpr double kKeepRightRoom = 0.5;    ///< [m]

void check_agent(const AgentSpec& agent) {
  if (agent.goals.empty()) throw std::invalid_argument("agent " + agent.name + ": has no goals");
  if (!in_world(agent.position) || !std::isfinite(agent.facing)) {
    throw std::invalid_argument("agent " + agent.name +
                                ": position and facing must be finite, within 1e9 m");
  }
  for (const Vec2& goal : agent.goals) {
    if (!in_world(goal))
      throw std::invalid_argument("agent " + agent.name + ": goals must be finite, within 1e9 m");
  }
}

/// A way measured on the navigation mesh, from where to which goal.
struct KnownWay {
  Vec2 from, goal;
  Way way;
};

/// The way from `from` to `goal`: one of `known` if it starts and ends there
/// (the mesh does not change while the agents plan, so it would come out the
/// same), else measured anew.
Way way_toward(const std::vector<KnownWay>& known, const NavMesh* mesh,
               const CharacterParams& character, Vec2 from, Vec2 goal, bool roomy) {
  for (const KnownWay& k : known)
    if (k.from == from && k.goal == goal) return k.way;
  return way_toward(mesh, character, from, goal, roomy);
}

/// One agent as the driver keeps it.
struct Walker {
  const AgentSpec* spec = nullptr;
  AgentPlan plan;        ///< Its steps, ending with `resting` provisional rest steps.
  PlanBounds bounds;     ///< Of `plan`, rebuilt whenever it changes.
  /// Of `plan`, those its commit check took; dropped whenever it changes.
  detail::PlanSamples samples;
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
  /// It goes after every other (gives_way(), as the tick began).
  bool giving_way = false;
  /// Stuck (stuck()): it stands where its plan ends and replans no more,
  /// until one near it moves on or asks it to make room (wake()).
  bool dormant = false;
  /// Its ways to the current goal are the roomiest there are: it was stuck
  /// once on the usual ones (take_roomy_ways()).
  bool roomy = false;
  bool done = false;
};

/// True if walker `w`, searching from `state`, has gained way within
/// kJamPatience (its search in a jam may stop early).
bool patient(const Walker& w, const FootstepState& state) {
  return state.time - w.improved_at < kJamPatience;
}

/// True if agent `a` goes before agent `b` where their ways cross: one that
/// gives way goes after one that does not; then the one with less way left,
/// then the earlier in the scenario.
bool goes_first(const std::vector<Walker>& walkers, std::size_t a, std::size_t b) {
  const Walker &first = walkers[a], &second = walkers[b];
  if (first.giving_way != second.giving_way) return second.giving_way;
  return first.way < second.way || (first.way == second.way && a < b);
}

/// True if steps that reach the walker's current goal end its walk there.
bool leaves_now(const Walker& w, bool reached) {
  return reached && w.spec->leave_at_goal && w.goal + 1 == w.spec->goals.size();
}

/// What one search gave, before it is committed.
struct Attempt {
  std::vector<Footstep> steps;
  FootstepState end;
  Rest rest;             ///< After the steps, among the agents the search saw.
  bool reached = false;  ///< The steps reach the current goal itself.
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
  /// of them (among boxes, measuring ways took a ninth of the planning).
  std::vector<KnownWay> ways;
};

/// Where every agent is at a tick's time t, and whether it is still there.
/// The tick's commits change plans only from t on (a due agent's plan runs
/// to t or beyond before it searches), so this holds for the whole tick.
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
};

/// The snapshot at time t of the agents whose plans `walks` read (one each,
/// kept from tick to tick: the step under way is found from the last tick's),
/// with their bounds from `bounds_from` on.
Snapshot snapshot(const std::vector<Walker>& walkers, std::vector<PlanWalk>& walks, double t,
                  double bounds_from, Workers& workers) {
  Snapshot s{t,
             std::vector<Vec2>(walkers.size()),
             std::vector<char>(walkers.size()),
             {},
             bounds_from,
             std::vector<PlanBounds::From>(walkers.size())};
  // Shared out among the threads in parts of kPart agents: otherwise the
  // largest step of a tick outside its searches (the 500 among boxes).
  constexpr std::size_t kPart = 64;
  workers.run((walkers.size() + kPart - 1) / kPart, [&](std::size_t part) {
    for (std::size_t j = part * kPart; j < std::min(walkers.size(), (part + 1) * kPart); ++j) {
      s.com[j] = walks[j].com_at(t).position;
      s.present[j] = present_at(walkers[j].plan, t);
      s.bounds[j] = walkers[j].bounds.from(bounds_from);
    }
  });
  s.grid = AgentGrid(s.com, kGridCell);
  return s;
}

/// The agents that agent `i` sees at the snapshot's time (within
/// kViewDistance, in front of its torso, and with a clear line of sight),
/// those it has noticed, and those whose wishes it keeps out of.
std::vector<std::size_t> seen_by(const std::vector<Walker>& walkers, std::size_t i,
                                 const Snapshot& now, const NavMesh* mesh) {
  const Vec2 eye = now.com[i];
  const Vec2 ahead = unit(facing_at(walkers[i].plan, now.t));
  std::vector<std::size_t> seen;
  std::vector<Vec2> where;
  std::vector<std::size_t> around;
  now.grid.around(eye, kViewDistance, around);
  for (const std::size_t j : around) {
    if (j == i || !now.present[j]) continue;
    const Vec2 d = now.com[j] - eye;
    if (dot(d, d) > kViewDistance * kViewDistance || dot(d, ahead) <= 0.0) continue;
    seen.push_back(j);
    where.push_back(now.com[j]);
  }
  if (mesh != nullptr) {
    const std::vector<char> in_sight = mesh->lines_of_sight(eye, where);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < seen.size(); ++k)
      if (in_sight[k]) seen[kept++] = seen[k];
    seen.resize(kept);
  }
  for (const auto* known : {&walkers[i].noticed, &walkers[i].yielding_to})
    for (const std::size_t j : *known)
      if (now.present[j] && std::find(seen.begin(), seen.end(), j) == seen.end()) seen.push_back(j);
  return seen;
}

/// Cuts the attempt's steps back to the last state from which the agent
/// comes to rest among `others`, outside `keep_out`, free to set off again
/// unless the steps reach the goal (none left: it waits), and keeps that
/// rest. Committed plans
/// are checked with the agent standing after its rest, so the rest must be
/// complete; and the next search starts there, so it must be able to set
/// off: a rest in a door frame, facing a post, can leave every step blocked.
void cut_to_rest(const FootstepPlanner& planner, const FootstepState& start,
                 const MovingObstacles& others, const KeepOut& keep_out, Attempt& a) {
  std::vector<FootstepState> states{start};
  for (const Footstep& step : a.steps) states.push_back(state_after(states.back(), step));
  std::size_t keep = a.steps.size();
  for (; keep > 0; --keep) {
    a.rest = planner.come_to_rest(states[keep], others);
    const bool at_goal = a.reached && keep == a.steps.size();
    if (a.rest.complete && planner.keeps_out(a.rest.state, keep_out) &&
        (at_goal || planner.free_to_set_off(a.rest.state)))
      break;
  }
  if (keep == a.steps.size()) return;
  a.steps.resize(keep);
  a.end = states[keep];
  a.reached = false;
}

/// True while agent `w` shows a wish.
bool wishing(const Walker& w) { return !w.wish.empty(); }

/// Agent `w`'s plan, as others keep clear of it.
MovingObstacle obstacle_of(const Walker& w) { return {&w.plan, &w.bounds, &w.samples}; }

/// The plans of agents `which`.
MovingObstacles plans_of(const std::vector<Walker>& walkers,
                         const std::vector<std::size_t>& which) {
  MovingObstacles plans;
  plans.reserve(which.size());
  for (const std::size_t j : which) plans.push_back(obstacle_of(walkers[j]));
  return plans;
}

/// What a wish along `steps` keeps others out of, until its COM is
/// kWishReach from where it set off: the torso circles every kContactDt and
/// the planted feet, grown by kWishPad (room to pass); and where the steps
/// end, if within reach, room to rest.
KeepOut wish_discs(const std::vector<Footstep>& steps, const CharacterParams& character) {
  KeepOut discs;
  const Vec2 from = steps.front().com_start;
  for (const Footstep& step : steps) {
    discs.push_back({step.foot_position, character.foot_radius + kWishPad});
    for (long k = first_contact_instant(step.start_time);
         static_cast<double>(k) * kContactDt <= step.end_time; ++k) {
      const Vec2 com = com_at(step, static_cast<double>(k) * kContactDt).position;
      if (distance(com, from) > kWishReach) return discs;
      for (Circle circle : torso_circles(com, step.phi, character)) {
        circle.radius += kWishPad;
        discs.push_back(circle);
      }
    }
  }
  discs.push_back({steps.back().com_end, 0.5 * character.torso_width + kRestRoom});
  return discs;
}

/// Keeps only the attempt's leading pivots, if it has any: a character that
/// starts with its back to where it is going has not seen who is there (it
/// sees only in front of its torso), so it turns first and plans the rest
/// once it looks that way (later, having walked, it has looked around).
/// Otherwise every plan it made walked into agents it never saw, refused one
/// after another until it counted as stuck.
void turn_first(const FootstepState& start, Attempt& a) {
  FootstepState state = start;
  std::size_t pivots = 0;
  bool turns = false;
  for (; pivots < a.steps.size() && a.steps[pivots].kind == StepKind::kStop; ++pivots) {
    turns = turns || a.steps[pivots].phi != state.facing;
    state = state_after(state, a.steps[pivots]);
  }
  if (!turns || pivots == a.steps.size()) return;
  a.steps.resize(pivots);
  a.end = state;
  a.reached = false;
}

/// Where walker `w`, at `at`, is bound: the way to its current goal (its last
/// once it has reached them all).
Vec2 bound_of(const Walker& w, Vec2 at) {
  return w.spec->goals[std::min(w.goal, w.spec->goals.size() - 1)] - at;
}

/// True if agent i gives way to all: blocked kGiveWayBlocked searches in a
/// row, its patience run out (its way has not shortened for kJamPatience),
/// with one bound against it (their goals more than 90 degrees apart) within
/// kJamDistance. In a knot (agents bound every way in a gap between boxes,
/// all waiting) the one that goes first may have nowhere to go that the
/// others can make room for; it then goes last, and the next one's wish is
/// kept clear instead. In a queue, all bound one way, the order stands.
bool gives_way(const std::vector<Walker>& walkers, std::size_t i, const Snapshot& now) {
  const Walker& w = walkers[i];
  if (w.done || w.dormant || w.blocked < kGiveWayBlocked || patient(w, w.state)) return false;
  const Vec2 bound = bound_of(w, now.com[i]);
  std::vector<std::size_t> around;
  now.grid.around(now.com[i], kJamDistance, around);
  for (const std::size_t j : around) {
    if (j == i || walkers[j].done || walkers[j].dormant || !now.present[j] ||
        distance(now.com[j], now.com[i]) > kJamDistance)
      continue;
    if (dot(bound_of(walkers[j], now.com[j]), bound) < 0.0) return true;
  }
  return false;
}

/// The local goal moved to the right of the line from agent i to it (by
/// kKeepRightShift, else by less, 0.5 m at the least, where it could stand
/// with room all along the way there), if one it sees walks the other way
/// ahead near that line and it has room round it; `target` otherwise. Lanes
/// form before two blocks of agents meet: in a hall 8 m wide, two hundred
/// walking both ways stood wall to wall in the middle without it.
LocalGoal keep_right(const std::vector<Walker>& walkers, std::size_t i, LocalGoal target,
                     const std::vector<std::size_t>& seen, const Snapshot& now,
                     const FootstepPlanner& planner, const NavMesh* mesh) {
  const Vec2 from = walkers[i].state.com, to = target.point - from;
  if (target.is_goal || length(to) < 1e-6) return target;
  const Vec2 ahead = unit(angle_of(to));
  const bool oncoming = std::any_of(seen.begin(), seen.end(), [&](std::size_t j) {
    const Vec2 d = now.com[j] - from;
    const double along = dot(d, ahead);
    if (along <= 0.0 || along > kKeepRightAhead || std::fabs(cross(ahead, d)) > kKeepRightBand)
      return false;
    // Walking this way, and bound this way too: not one stepping back to
    // make room (near a door, all bound the same way).
    const Vec2 bound = bound_of(walkers[j], now.com[j]);
    return dot(com_at(walkers[j].plan, now.t).velocity, ahead) < -kOncomingSpeed &&
           dot(bound, ahead) < -0.5 * length(bound);
  });
  if (!oncoming || (mesh != nullptr && mesh->clearance(from) < kKeepRightRoom)) return target;
  for (double shift = kKeepRightShift; shift >= 0.5; shift -= 0.5) {
    const Vec2 point = target.point - shift * perp(ahead);
    if (planner.room_to_turn(point) &&
        !planner.collides(standing_state(point, angle_of(to), planner.character())) &&
        (mesh == nullptr ||
         mesh->clearance_between(from, point, kKeepRightRoom) >= kKeepRightRoom))
      return {point, false};
  }
  return target;
}

/// True if `step` neither moves the COM nor turns the torso from `facing`.
bool still(const Footstep& step, double facing) {
  return step.kind == StepKind::kStop && step.phi == facing &&
         length(step.com_velocity_start) == 0.0 && length(step.com_velocity_end) == 0.0;
}

/// The nearest places round `state` (in rings 0.75 m apart, up to 2.25 m)
/// where the agent could stand out of `keep_out`, clear of the obstacles and
/// of the plans of `others`, nearest first (of those on one ring, the one
/// with the most room round it, from the others where they are now); at most
/// kAsideTries of them.
std::vector<Vec2> room_aside(const FootstepState& state, const KeepOut& keep_out,
                             const MovingObstacles& others, const FootstepPlanner& planner,
                             const NavMesh* mesh) {
  constexpr int kDirections = 16, kRings = 3;
  constexpr double kRingStep = 0.75;  // [m]
  const double half_torso = 0.5 * planner.character().torso_width;
  std::vector<Vec2> now;
  for (const MovingObstacle& other : others) now.push_back(com_at(*other.plan, state.time).position);
  struct Place {
    FootstepState standing;
    double ring, room;
  };
  std::vector<Place> places;
  for (int r = 1; r <= kRings; ++r) {
    const double ring = kRingStep * r;
    for (int k = 0; k < kDirections; ++k) {
      const Vec2 point = state.com + ring * unit(2.0 * kPi * k / kDirections);
      double room = std::numeric_limits<double>::infinity();
      for (const Vec2 where : now) room = std::min(room, distance(where, point));
      if (room < planner.character().torso_width) continue;  // another stands there now
      FootstepState there = standing_state(point, state.facing, planner.character());
      there.time = state.time;
      if (!planner.room_to_turn(point) || !planner.keeps_out(there, keep_out) ||
          planner.collides(there) ||
          (mesh != nullptr && mesh->clearance_between(state.com, point, half_torso) < half_torso))
        continue;
      places.push_back({there, ring, room});
    }
  }
  std::stable_sort(places.begin(), places.end(), [](const Place& a, const Place& b) {
    return a.ring < b.ring || (a.ring == b.ring && a.room > b.room);
  });
  std::vector<FootstepState> states;
  for (const Place& place : places) states.push_back(place.standing);
  std::vector<Vec2> clear;
  for (const std::size_t k : planner.standing_clear(states, others, kAsideTries))
    clear.push_back(states[k].com);
  return clear;
}

/// Steps to the nearest place that room_aside() offers and a search of
/// `options` reaches (the nearest may be behind the very agents it makes
/// room for); none if no such search succeeds.
std::optional<SearchResult> step_aside(const FootstepState& state, const KeepOut& keep_out,
                                       const MovingObstacles& others,
                                       const FootstepPlanner& planner, const NavMesh* mesh,
                                       const SearchOptions& options) {
  for (const Vec2 place : room_aside(state, keep_out, others, planner, mesh)) {
    SearchResult result = planner.plan(state, place, others, options);
    if (result.status == Status::kSuccess && !result.footsteps.empty()) return result;
  }
  return std::nullopt;
}

/// True if agent i stands in the wish of one it yields to that is bound
/// against it (their goals more than 90 degrees apart), or whose wish makes
/// room for such a one. Among agents bound the same way (a queue at a door)
/// a wish passes once those ahead move on.
bool must_make_room(const std::vector<Walker>& walkers, std::size_t i, const Snapshot& now,
                    const FootstepPlanner& planner) {
  const Walker& w = walkers[i];
  const Vec2 bound = bound_of(w, w.state.com);
  return std::any_of(w.yielding_to.begin(), w.yielding_to.end(), [&](std::size_t j) {
    return (walkers[j].wish_makes_room || dot(bound_of(walkers[j], now.com[j]), bound) < 0.0) &&
           !planner.keeps_out(w.state, walkers[j].wish);
  });
}

/// Agent i's next search: toward its local goal, among the plans of the
/// agents it sees (`seen`), resting out of the wishes of those it yields to.
/// When it stands blocked after a search that gained nothing, with one that
/// goes after it near, also its wish: the same search among only those it
/// sees that go first.
Attempt search(const std::vector<Walker>& walkers, std::size_t i, const FootstepPlanner& planner,
               const NavMesh* mesh, const std::vector<std::size_t>& seen, const Snapshot& now) {
  const Walker& w = walkers[i];
  const Vec2 goal = w.spec->goals[w.goal];
  const Way way = way_toward(w.ways, mesh, planner.character(), w.state.com, goal, w.roomy);
  const LocalGoal target =
      keep_right(walkers, i, local_goal(planner, mesh, way), seen, now, planner, mesh);
  // One that leaves at this goal needs no room to rest there.
  const bool leaves = leaves_now(w, target.is_goal);
  KeepOut keep_out;
  for (const std::size_t j : w.yielding_to)
    keep_out.insert(keep_out.end(), walkers[j].wish.begin(), walkers[j].wish.end());
  const MovingObstacles others = plans_of(walkers, seen);
  // An agent in a jam looks less far ahead, and a blocked one less deep:
  // there the full search finds no more than waiting, or than a few nodes
  // find, at the most cost. One held up by obstacles alone needs it all (a
  // side-on way through a narrow gap is long).
  bool jammed = false;
  for (const std::size_t j : seen)
    jammed = jammed || distance(now.com[j], w.state.com) <= kJamDistance;
  const SearchOptions options{leaves, keep_out, w.blocked >= 1 && jammed ? kBlockedHorizon : 0,
                              kRestGrace, jammed && patient(w, w.state) ? kJamStall : 0};
  SearchResult result = planner.plan(w.state, target.point, others, options);
  const bool moves = std::any_of(result.footsteps.begin(), result.footsteps.end(),
                                 [&](const Footstep& step) { return !still(step, w.state.facing); });
  SearchOptions short_search = options;
  short_search.horizon = kBlockedHorizon;
  // Standing where it must make room, with nowhere to go but aside.
  bool boxed_in = false;
  if (!moves && w.state.standing() && must_make_room(walkers, i, now, planner)) {
    // In a face-off (two blocks of a counterflow, a knot among boxes) no one
    // gains on its own way, and waiting only stands in the way: it makes
    // room, stepping aside out of the wishes it yields to.
    boxed_in = true;
    if (auto aside = step_aside(w.state, keep_out, others, planner, mesh, short_search)) {
      result = std::move(*aside);
      boxed_in = false;
    }
  }
  Attempt a;
  a.from = w.state;
  a.steps = result.footsteps;
  a.end = result.footsteps.empty() ? w.state : result.end_state;
  a.reached = result.status == Status::kSuccess && target.is_goal;
  if (w.plan.footsteps.empty() && dot(unit(w.state.facing), target.point - w.state.com) < 0.0)
    turn_first(w.state, a);
  if (!leaves_now(w, a.reached)) cut_to_rest(planner, w.state, others, keep_out, a);
  a.ways.push_back({w.state.com, goal, way});
  if (!a.reached) {
    Way left = way_toward(w.ways, mesh, planner.character(), a.end.com, goal, w.roomy);
    a.way_left = left.length;
    a.ways.push_back({a.end.com, goal, std::move(left)});
  }
  a.way_from = way.length;
  a.nodes_generated = result.nodes_generated;
  a.nodes_expanded = result.nodes_expanded;
  a.searched = true;
  const double min_progress = planner.params().min_progress;
  // Those it sees that go first; a wish is worth a search only if one that
  // goes after it stands near enough to be in its way.
  std::vector<std::size_t> first;
  bool asks_someone = false;
  for (const std::size_t j : seen) {
    if (goes_first(walkers, j, i))
      first.push_back(j);
    else
      asks_someone = asks_someone || distance(now.com[j], now.com[i]) <= kWishReach + kBodyLength;
  }
  if (asks_someone && w.blocked > 0 && w.state.standing() && !a.reached &&
      a.way_left > way.length - min_progress) {
    // Out of the wishes it yields to too: a wish may be the way out of
    // another's, which those behind it make room for first. If only those
    // that go first turned anything down, the search among them alone would
    // find what this one found.
    // Boxed in where it must make room: its wish is the way aside that those
    // behind it (who go after it) would leave it, and they make room too.
    if (boxed_in) {
      const MovingObstacles ahead = plans_of(walkers, first);
      if (const auto aside = step_aside(w.state, keep_out, ahead, planner, mesh, short_search)) {
        a.wish = wish_discs(aside->footsteps, planner.character());
        a.wish_makes_room = true;
        return a;
      }
    }
    const bool same = std::all_of(result.refused_by.begin(), result.refused_by.end(),
                                  [&](std::size_t k) { return goes_first(walkers, seen[k], i); });
    const SearchResult wish =
        same ? result : planner.plan(w.state, target.point, plans_of(walkers, first), options);
    const Vec2 from = w.state.com, to = wish.end_state.com;
    const bool gains = distance(to, target.point) < distance(from, target.point) - min_progress;
    const bool leaves_a_wish =
        !planner.keeps_out(w.state, keep_out) && distance(to, from) > min_progress;
    if (gains || leaves_a_wish) a.wish = wish_discs(wish.footsteps, planner.character());
  }
  return a;
}

/// Every other agent within kCheckDistance of agent `i` at the snapshot's
/// time, seen or not.
std::vector<std::size_t> near(std::size_t i, const Snapshot& now) {
  std::vector<std::size_t> around, out;
  now.grid.around(now.com[i], kCheckDistance, around);
  for (const std::size_t j : around) {
    if (j != i && now.present[j] && distance(now.com[j], now.com[i]) <= kCheckDistance)
      out.push_back(j);
  }
  return out;
}

/// Lets the agent's provisional rest happen (it is no longer provisional),
/// and if it would then stand before time `t`, has it stand until `t` (in
/// waits of kMaxWait at most: one woken after long stuck waits many): the
/// next steps start now, not in the past.
void rest_until(Walker& w, const FootstepPlanner& planner, double t) {
  if (w.resting > 0) {
    w.state = w.rested;
    w.resting = 0;
  }
  bool waited = false;
  while (w.state.time < t) {
    const StepResult wait = planner.stop_step(w.state, std::min(t - w.state.time, kMaxWait));
    if (!wait.valid()) break;
    w.plan.footsteps.push_back(wait.step);
    w.state = wait.state;
    waited = true;
  }
  if (waited) {
    w.bounds = PlanBounds(w.plan, planner.character());
    w.samples = {};
  }
}

/// Wakes a dormant (stuck) agent: it replans from the next tick on, with
/// kStuckAfter again to gain way.
void wake(Walker& w, double t) {
  w.dormant = false;
  w.plan.reason.clear();
  w.retry_at = t;
  w.improved_at = t;
}

/// Wakes the dormant agents within kFreezeRadius of agent `i`, which has
/// just committed steps that move: what held them may have moved on.
void wake_near(std::vector<Walker>& walkers, std::size_t i, const Snapshot& now) {
  std::vector<std::size_t> around;
  now.grid.around(now.com[i], kFreezeRadius, around);
  for (const std::size_t j : around)
    if (walkers[j].dormant && distance(now.com[j], now.com[i]) <= kFreezeRadius)
      wake(walkers[j], now.t);
}

/// Notes the way left, and when it last shortened by min_progress.
void progress(Walker& w, double way_left, const FootstepPlanner& planner) {
  if (w.first_way == 0.0) w.first_way = way_left;
  if (way_left < w.best_way - planner.params().min_progress) {
    w.best_way = way_left;
    w.improved_at = w.state.time;
  }
}

/// True if agent `i` is stuck: its way has not shortened by min_progress for
/// kStuckAfter, and neither has that of any agent within kQueueDistance. One
/// waiting behind others that move is queueing (at a crowded exit, for
/// longer than kStuckAfter), not stuck; a deadlock does not move at all. One
/// that has just reached its goal there counts as moving: it may have stood
/// in the way until then.
bool stuck(const std::vector<Walker>& walkers, std::size_t i) {
  const Walker& w = walkers[i];
  const double since = w.state.time - kStuckAfter;
  if (w.improved_at >= since) return false;
  for (std::size_t j = 0; j < walkers.size(); ++j) {
    const Walker& other = walkers[j];
    if (j != i && other.improved_at >= since &&
        distance(other.state.com, w.state.com) <= kQueueDistance)
      return false;
  }
  return true;
}

/// A stuck agent (stuck()) tries once more, for another kStuckAfter, on the
/// roomiest way there is (way_toward()). The tightest way, with room only to
/// side-step, passes any gap the torso's circle fits through, but the
/// footsteps need more (their checks pad the torso, and it turns at the
/// corners): among boxes, agents stood for good where their ways led into
/// slots 0.37 m wide. Its next search is news (nothing_new()).
void take_roomy_ways(Walker& w, double t) {
  w.roomy = true;
  w.ways.clear();
  // Its way is measured anew: a way round may be longer than the one it
  // was stuck on, and still gain.
  w.best_way = std::numeric_limits<double>::infinity();
  w.improved_at = w.state.time;
  w.news_at = t;
}

/// True if `plan` stands still from time `from` on.
bool still_from(const AgentPlan& plan, double from) {
  const double facing = facing_at(plan, from);
  for (auto step = plan.footsteps.rbegin(); step != plan.footsteps.rend() && step->end_time > from;
       ++step) {
    if (!still(*step, facing)) return false;
  }
  return true;
}

/// True if the two states stand (or walk) the same way at the same place.
bool same_stance(const FootstepState& a, const FootstepState& b) {
  return distance(a.com, b.com) <= kSamePlace && a.facing == b.facing &&
         a.standing() == b.standing();
}

/// True if a search by agent i now would see what its last one saw, which
/// gained nothing: it committed nothing but waiting then (a pivot gains no
/// way, but looks elsewhere), it would start as its last search did (a
/// search from a walk that found nothing leaves the agent standing where its
/// rest brought it, with new steps open to it) and search as deep (its
/// patience has not run out since), no one asked it to make room
/// nor was noticed since, and everyone within kFreezeRadius (or gone from
/// there) has neither committed since nor moved from then on. In a jam most
/// agents wait behind others that wait; their searches would cost the most.
bool nothing_new(const std::vector<Walker>& walkers, std::size_t i, const Snapshot& now) {
  const Walker& w = walkers[i];
  if (w.blocked == 0 || w.news_at >= w.searched_at || w.committed_at >= w.searched_at ||
      !same_stance(w.searched_from, w.state) || patient(w, w.searched_from) != patient(w, w.state))
    return false;
  std::vector<std::size_t> around;
  now.grid.around(now.com[i], kFreezeRadius, around);
  for (const std::size_t j : around) {
    if (j == i || distance(now.com[j], now.com[i]) > kFreezeRadius) continue;
    if (walkers[j].committed_at >= w.searched_at || !still_from(walkers[j].plan, w.searched_at))
      return false;
  }
  return true;
}

/// The state agent `w` stands in after its plan.
const FootstepState& rest_of(const Walker& w) { return w.resting > 0 ? w.rested : w.state; }

/// An attempt as it would stand in its agent's plan, and what the commit
/// check finds against each agent near as the tick began. Made for every
/// due agent at once (on the workers): in the agents' order, only the plans
/// committed before it in the same tick need checking again (refusal()).
struct Proposal {
  std::vector<Footstep> steps;     ///< The attempt's steps, then (unless it leaves) its rest.
  FootstepState rested;            ///< Where they leave the agent.
  bool leaving = false;            ///< It walks on through its last goal.
  detail::Trial trial;             ///< The plan with them in place of the old rest.
  bool new_place = false;          ///< It rests somewhere new: it needs room there.
  std::vector<std::size_t> close;  ///< The agents near (near()).
  std::vector<char> hits;          ///< Per close: the trial touches its plan.
  std::vector<char> no_room;       ///< Per close: no room to rest beside it (new_place).
};

/// The trial that agent i's attempt makes, and its check against the plans
/// of the agents `close` as they stand now.
Proposal propose(const std::vector<Walker>& walkers, std::size_t i, const Attempt& a,
                 const FootstepPlanner& planner, std::vector<std::size_t> close,
                 const Snapshot& now) {
  const Walker& w = walkers[i];
  Proposal p;
  p.close = std::move(close);
  p.steps = a.steps;
  p.rested = a.end;
  // One that leaves at its last goal walks on through it; the others come to rest.
  p.leaving = leaves_now(w, a.reached);
  if (!p.leaving) {
    p.steps.insert(p.steps.end(), a.rest.steps.begin(), a.rest.steps.end());
    p.rested = a.rest.state;
  }
  if (a.steps.empty()) return p;
  AgentPlan plan;
  plan.leaves = p.leaving;
  plan.start = w.plan.start;
  const std::size_t kept = w.plan.footsteps.size() - w.resting;
  plan.footsteps.assign(w.plan.footsteps.begin(), w.plan.footsteps.begin() + kept);
  plan.footsteps.insert(plan.footsteps.end(), p.steps.begin(), p.steps.end());
  // During the last kept step the free foot swings toward the next step's
  // foot (feet_at): that step's circles change with the new steps too.
  const double from = kept > 0 ? plan.footsteps[kept - 1].start_time : a.steps.front().start_time;
  p.trial = detail::Trial(std::move(plan), from, planner.character());
  // A new place to rest needs room among everyone, seen or not.
  p.new_place = !p.leaving && distance(p.rested.com, rest_of(w).com) > kSamePlace;
  const bool bounded = p.trial.from() >= now.bounds_from;
  for (const std::size_t j : p.close)
    p.hits.push_back(!(bounded && p.trial.apart(now.bounds[j])) &&
                     p.trial.touches(walkers[j].plan, walkers[j].bounds, &walkers[j].samples));
  p.no_room.assign(p.close.size(), 0);
  if (p.new_place) {
    const std::vector<char> clear = planner.stands_clear_of_each(p.rested, plans_of(walkers, p.close));
    for (std::size_t c = 0; c < clear.size(); ++c) p.no_room[c] = !clear[c];
  }
  return p;
}

/// The index in p.close of the agent the trial is refused for: the first it
/// touches, else (resting somewhere new) the first it has no room beside;
/// -1 if none. The plans of agents `changed` this tick are checked anew.
int refusal(const std::vector<Walker>& walkers, Proposal& p, const std::vector<char>& changed,
            const FootstepPlanner& planner) {
  if (p.trial.plan().footsteps.empty()) return -1;
  for (std::size_t c = 0; c < p.close.size(); ++c) {
    const Walker& other = walkers[p.close[c]];
    if (changed[p.close[c]] ? p.trial.touches(other.plan, other.bounds, &other.samples) : p.hits[c])
      return static_cast<int>(c);
  }
  if (!p.new_place) return -1;
  for (std::size_t c = 0; c < p.close.size(); ++c) {
    if (changed[p.close[c]] ? !planner.stands_clear(p.rested, {obstacle_of(walkers[p.close[c]])})
                            : p.no_room[c])
      return static_cast<int>(c);
  }
  return -1;
}

/// Adds the attempt's steps and a provisional rest after them to agent i's
/// plan, in place of its old rest, unless the proposal was refused (for
/// p.close[refused]); then the old rest happens and the agent waits there.
/// Then goals reached and progress.
void commit(std::vector<Walker>& walkers, std::size_t i, const Attempt& a, Proposal& p, int refused,
            const FootstepPlanner& planner, double t) {
  Walker& w = walkers[i];
  if (a.searched) {
    ++w.plan.searches;
    w.plan.nodes_generated += a.nodes_generated;
    w.plan.nodes_expanded += a.nodes_expanded;
  }
  if (refused >= 0) {
    if (std::find(w.noticed.begin(), w.noticed.end(), p.close[refused]) == w.noticed.end())
      w.noticed.push_back(p.close[refused]);
    w.news_at = t;
  }
  if (a.steps.empty() || refused >= 0) {
    rest_until(w, planner, t);
    w.retry_at = t + kRetryAfter * (1 << std::min(w.failures++, kMaxBackoff));
    if (!(a.reached && a.steps.empty())) {  // at the goal already, or waiting
      progress(w, w.best_way, planner);
      return;
    }
  } else {
    // Waiting on where it stands is no news to the others.
    if (!std::all_of(p.steps.begin(), p.steps.end(),
                     [&](const Footstep& step) { return still(step, w.state.facing); }))
      w.committed_at = t;
    w.failures = 0;
    // Those noticed stay in mind while they are near.
    const Vec2 here = com_at(w.plan, t).position;
    w.noticed.erase(std::remove_if(w.noticed.begin(), w.noticed.end(),
                                   [&](std::size_t j) {
                                     return distance(com_at(walkers[j].plan, t).position, here) >
                                            kNoticeDistance;
                                   }),
                    w.noticed.end());
    w.samples = p.trial.take_samples();
    w.plan.footsteps = std::move(p.trial.plan().footsteps);
    w.bounds = std::move(p.trial.bounds());
    w.resting = p.steps.size() - a.steps.size();
    w.state = a.end;
    w.rested = p.rested;
  }
  if (!a.reached) {
    progress(w, a.way_left, planner);
    return;
  }
  ++w.plan.goals_reached;
  if (++w.goal == w.spec->goals.size()) {
    w.plan.status = AgentStatus::kReached;
    w.plan.leaves = w.spec->leave_at_goal;
    w.samples = {};  // taken before it could leave at its goal
    w.done = true;
    return;
  }
  w.first_way = 0.0;
  w.best_way = std::numeric_limits<double>::infinity();
  w.improved_at = w.state.time;
  w.roomy = false;
}

/// Shows agent i's wish, if its attempt found one and it is still blocked,
/// to the agents `near` that go after it and rest in it: they keep out of it,
/// searching again at the next tick. Otherwise withdraws it.
void show_wish(std::vector<Walker>& walkers, std::size_t i, Attempt& a,
               const FootstepPlanner& planner, double t, const std::vector<std::size_t>& near) {
  Walker& w = walkers[i];
  if (w.done || w.blocked == 0 || a.wish.empty()) {
    w.wish.clear();
    w.wish_makes_room = false;
    return;
  }
  w.wish = std::move(a.wish);
  w.wish_makes_room = a.wish_makes_room;
  for (const std::size_t j : near) {
    Walker& other = walkers[j];
    if (other.done || goes_first(walkers, j, i) || planner.keeps_out(rest_of(other), w.wish))
      continue;
    if (std::find(other.yielding_to.begin(), other.yielding_to.end(), i) != other.yielding_to.end())
      continue;  // asked before
    if (other.dormant) wake(other, t);
    other.yielding_to.push_back(i);
    other.retry_at = std::min(other.retry_at, t);
    other.news_at = t;
  }
}

/// How far the walker is: its goals reached, and the way to the current one.
double progress_of(const Walker& w) {
  if (w.done) return 1.0;
  double current = 0.0;
  if (w.first_way > 0.0 && std::isfinite(w.best_way))
    current = std::clamp(1.0 - w.best_way / w.first_way, 0.0, 1.0);
  return (static_cast<double>(w.goal) + current) / static_cast<double>(w.spec->goals.size());
}

}  // namespace

std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const FootstepPlanner& planner, const NavMesh* mesh,
                                   const RunControl& control) {
  for (const AgentSpec& agent : agents) check_agent(agent);
  if (control.threads < 1 || control.threads > 64)
    throw std::invalid_argument("threads must be between 1 and 64");
  std::vector<Walker> walkers(agents.size());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    Walker& w = walkers[i];
    w.spec = &agents[i];
    w.plan.name = agents[i].name;
    w.plan.start = standing_state(agents[i].position, agents[i].facing, planner.character());
    w.state = w.plan.start;
    w.bounds = PlanBounds(w.plan, planner.character());
  }
  std::vector<PlanWalk> walks;
  for (const Walker& w : walkers) walks.emplace_back(w.plan);
  Workers workers(control.threads);
  double reported = 0.0;
  auto last_report = std::chrono::steady_clock::now();
  for (long tick = 0;; ++tick) {
    const double t = static_cast<double>(tick) * kTick;
    std::vector<std::size_t> due;
    bool active = false;
    for (std::size_t i = 0; i < walkers.size(); ++i) {
      if (walkers[i].done || walkers[i].dormant) continue;
      active = true;
      if (walkers[i].state.time - t <= kReplanLead && t >= walkers[i].retry_at) due.push_back(i);
    }
    if (!active) break;
    const bool cancelled = control.cancelled();
    if (cancelled || t > planner.params().max_time) {
      for (Walker& w : walkers)
        if (!w.done && !w.dormant) w.plan.reason = cancelled ? "cancelled" : "time limit";
      break;
    }
    if (due.empty()) continue;
    // A plan that has run into its rest starts again from where that leaves it.
    for (std::size_t i : due)
      if (walkers[i].state.time < t) rest_until(walkers[i], planner, t);
    // The tick's trials differ from their agents' plans from the start of
    // the last step each keeps on (propose()).
    double trials_from = kForever;
    for (const std::size_t i : due) {
      const Walker& w = walkers[i];
      const std::size_t kept = w.plan.footsteps.size() - w.resting;
      const double from = kept > 0 ? w.plan.footsteps[kept - 1].start_time : w.state.time;
      trials_from = std::min(trials_from, from);
    }
    const Snapshot at_tick = snapshot(walkers, walks, t, trials_from, workers);
    for (std::size_t i = 0; i < walkers.size(); ++i)
      walkers[i].giving_way = gives_way(walkers, i, at_tick);
    std::vector<Attempt> attempts(due.size());
    std::vector<char> idle(due.size());
    for (std::size_t k = 0; k < due.size(); ++k) idle[k] = nothing_new(walkers, due[k], at_tick);
    // The dearest-looking jobs start first (those that search, by what their
    // last ones took), so that threads finish the tick together; results go
    // by index, so the order changes nothing else.
    std::vector<std::size_t> order(due.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    const auto cost = [&](std::size_t k) { return idle[k] ? 0.0 : walkers[due[k]].last_cost; };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
    std::vector<double> seconds(due.size()), job_seconds(due.size());
    std::vector<Proposal> proposals(due.size());
    workers.run(due.size(), [&](std::size_t job) {
      const std::size_t k = order[job], i = due[k];
      const auto begin = std::chrono::steady_clock::now();
      if (!idle[k]) {
        attempts[k] =
            search(walkers, i, planner, mesh, seen_by(walkers, i, at_tick, mesh), at_tick);
        seconds[k] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      }
      proposals[k] = propose(walkers, i, attempts[k], planner, near(i, at_tick), at_tick);
      job_seconds[k] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    });
    for (std::size_t k = 0; k < due.size(); ++k)
      if (!idle[k]) walkers[due[k]].last_cost = job_seconds[k];
    if (control.search_seconds != nullptr)
      for (const double s : seconds) *control.search_seconds += s;
    // Plans changed in this tick so far (by a commit, or a wait).
    std::vector<char> changed(walkers.size(), 0);
    for (std::size_t k = 0; k < due.size(); ++k) {
      const std::size_t i = due[k];
      Walker& w = walkers[i];
      // Those it yielded to and that no longer wish are let go.
      w.yielding_to.erase(std::remove_if(w.yielding_to.begin(), w.yielding_to.end(),
                                         [&](std::size_t r) { return !wishing(walkers[r]); }),
                          w.yielding_to.end());
      const Attempt& a = attempts[k];
      const int refused = refusal(walkers, proposals[k], changed, planner);
      commit(walkers, i, a, proposals[k], refused, planner, t);
      changed[i] = 1;
      if (w.committed_at == t) wake_near(walkers, i, at_tick);
      if (a.searched) {
        w.ways = std::move(attempts[k].ways);
        w.searched_at = t;
        w.searched_from = a.from;
        w.way = a.way_from;
        const bool gained = a.reached || a.way_left <= a.way_from - planner.params().min_progress;
        w.blocked = w.failures == 0 && gained ? 0 : w.blocked + 1;
      }
      show_wish(walkers, i, attempts[k], planner, t, proposals[k].close);
      if (!w.done && stuck(walkers, i)) {
        if (!w.roomy) {
          take_roomy_ways(w, t);
        } else {
          w.plan.reason = "stuck";
          w.dormant = true;
        }
      }
    }
    const auto now = std::chrono::steady_clock::now();
    if (control.progress &&
        std::chrono::duration<double>(now - last_report).count() >= kProgressInterval) {
      double sum = 0.0;
      for (const Walker& w : walkers) sum += progress_of(w);
      reported = std::max(reported, sum / static_cast<double>(walkers.size()));
      control.progress(reported);
      last_report = now;
    }
  }
  if (control.progress && !control.cancelled()) control.progress(1.0);
  std::vector<AgentPlan> plans;
  for (Walker& w : walkers) {
    w.plan.stuck_at = w.resting > 0 ? w.rested.com : w.state.com;
    choose_foot_orientations(w.plan.footsteps, w.plan.start.foot_orientation, planner.character());
    plans.push_back(std::move(w.plan));
  }
  return plans;
}

AgentPlan plan_agent(const AgentSpec& agent, const FootstepPlanner& planner, const NavMesh* mesh,
                     const RunControl& control) {
  return plan_agents({agent}, planner, mesh, control).front();
}

}  // namespace footfall
