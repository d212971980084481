// Footfall — the crowd driver. Agents plan their footsteps toward local goals
// on their ways (local_goal.hpp), each among the plans of the agents it sees,
// replanning a little before its plan runs out. A fixed tick decides who
// replans when; the output is every agent's continuous footstep plan.
//
// No overlaps: every plan ends with the agent coming to rest (a provisional
// rest, replaced when the agent replans; an agent that leaves at its last goal
// is gone after it instead), and a new plan is committed only if it keeps
// clear of every other agent's plan, rest included, seen or not
// (crowd_commit.hpp); otherwise the agent waits where its rest leaves it.
// Every committed plan was checked against everyone's rest, so waiting is
// always clear.
//
// Making way: blocked agents ask those after them to rest out of their way
// (crowd_yielding.hpp). One stuck (stuck()) sleeps until one near it moves
// (wake_near()).
//
// Threads and determinism: a tick's searches read a view, a copy of the
// walkers as they stood when the tick's searches were set going, before the
// commits of the tick before. Those commits are made while this tick's
// searches run, and the next tick's searches fill the threads while this
// tick's last ones finish: agents see others' new plans a tick (50 ms) later
// than had each tick waited for the last. A tick's results are committed a
// tick later, one agent after another in the agents' order, each checked
// against the plans as they then stand. The check against a plan unchanged
// since the view gives what it gave against the view, so it is made on the
// threads, with the search (propose()); only plans changed since are checked
// again, in order (refusal(), by each plan's version). Nothing a search reads
// depends on the number of threads or their timing, nor then do the plans.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "behavior/local_goal.hpp"
#include "crowd/crowd_commit.hpp"
#include "crowd/crowd_walker.hpp"
#include "crowd/crowd_ways.hpp"
#include "crowd/crowd_yielding.hpp"
#include "footfall/crowd/crowd_planner.hpp"
#include "footfall/plan/plan.hpp"
#include "plan/agent_grid.hpp"
#include "util/workers.hpp"

namespace footfall {

using namespace crowd;

namespace {

void check_agent(const AgentSpec& agent) {
  if (agent.goals.empty()) throw std::invalid_argument("agent " + agent.name + ": has no goals");
  if (!(agent.time_limit >= 0.0 && agent.time_limit <= kMaxTimeLimit))
    throw std::invalid_argument("agent " + agent.name + ": time_limit must be in [0, 100000] s");
  if (!(agent.start_delay >= 0.0 && agent.start_delay <= kMaxTimeLimit))
    throw std::invalid_argument("agent " + agent.name + ": start_delay must be in [0, 100000] s");
  if (!(agent.goal_wait >= 0.0 && agent.goal_wait <= kMaxTimeLimit))
    throw std::invalid_argument("agent " + agent.name + ": goal_wait must be in [0, 100000] s");
  if (!in_scale_range(agent.scale))
    throw std::invalid_argument("agent " + agent.name + ": scale " + kScaleRange);
  if (const auto problem = facings_problem(agent))
    throw std::invalid_argument("agent " + agent.name + ": " + problem->first + " " + problem->second);
  if (!in_world(agent.position) || !std::isfinite(agent.facing)) {
    throw std::invalid_argument("agent " + agent.name +
                                ": position and facing must be finite, within 1e9 m");
  }
  for (const Vec2& goal : agent.goals) {
    if (!in_world(goal))
      throw std::invalid_argument("agent " + agent.name + ": goals must be finite, within 1e9 m");
  }
}

/// An agent's annotated way from its goal `first` on (`sections`), split at
/// its goals (the sections end each leg exactly at its goal); the legs
/// before `first` are empty.
std::vector<std::vector<Vec2>> guides_of(const AgentSpec& agent,
                                         const std::vector<BehaviorSection>& sections,
                                         std::size_t first) {
  std::vector<std::vector<Vec2>> guides(agent.goals.size());
  std::size_t leg = first;
  for (const BehaviorSection& section : sections) {
    for (const Vec2 p : section.points) {
      if (leg >= guides.size()) break;
      if (guides[leg].empty() || !(guides[leg].back() == p)) guides[leg].push_back(p);
      if (p == agent.goals[leg]) {
        ++leg;
        if (leg < guides.size()) guides[leg].push_back(p);
      }
    }
  }
  return guides;
}

/// Gives stuck walker w (agent i) its way annotated anew from where it
/// stands (`annotate`), to follow from now on: where it is narrower than
/// walk, or on its third chance, whatever it is. Its steps so far keep their
/// sections: the lookup holds both.
void annotate_anew(Walker& w, std::size_t i, const Annotator& annotate,
                   const PlannerParams& params) {
  std::vector<BehaviorSection> fresh = annotate(i, w.state.com, w.goal);
  const bool narrower = std::any_of(fresh.begin(), fresh.end(), [](const BehaviorSection& s) {
    return s.behavior != Behavior::kWalk;
  });
  if (params.follow_sections == 1 && (narrower || w.stuck_times > 1))
    w.guides = guides_of(*w.spec, fresh, w.goal);
  std::vector<BehaviorSection> both = w.sections->sections();
  both.insert(both.end(), fresh.begin(), fresh.end());
  w.sections = std::make_shared<const SectionLookup>(std::move(both));
}

/// Near a narrower section (walking with the arms in, side-stepping) a search
/// aims no farther than kNarrowAim along the way, the middle of the passage
/// (the annotated way keeps to it): a passage a few centimetres wider than
/// the body is entered square and centred, which steps aimed at a goal 10 m
/// on do not find. "Near": within kNarrowAhead along the way. [m]
constexpr double kNarrowAim = 1.5;
constexpr double kNarrowAhead = 3.0;

LocalGoal aim_of(const Walker& w, const FootstepPlanner& planner, const NavMesh* mesh,
                 const Way& way) {
  if (w.guides.empty() || w.roomy) return local_goal(planner, mesh, way);
  bool narrow = false;
  const Way ahead = way_start(way, kNarrowAhead);
  for (std::size_t k = 1; k < ahead.points.size() && !narrow; ++k) {
    const Vec2 a = ahead.points[k - 1], b = ahead.points[k];
    const int samples = 1 + static_cast<int>(distance(a, b) / 0.25);
    for (int s = 0; s <= samples && !narrow; ++s)
      narrow = w.sections->at(a + (static_cast<double>(s) / samples) * (b - a)) != Behavior::kWalk;
  }
  if (!narrow || way.length <= kNarrowAim) return local_goal(planner, mesh, way);
  LocalGoal target = local_goal(planner, mesh, way_start(way, kNarrowAim));
  target.is_goal = false;
  return target;
}

/// The snapshot at time t of the agents whose plans `walks` read (one each,
/// kept from tick to tick: the step under way is found from the last tick's),
/// with their bounds from `bounds_from` on, who gives way, and where they are
/// thick (on `crowd_grids`, one per layer of `ways`, if any), each agent
/// counted on the layer it stands on.
Snapshot snapshot(const std::vector<Walker>& walkers, std::vector<PlanWalk>& walks, double t,
                  double bounds_from, const std::vector<CrowdGrid>& crowd_grids,
                  const CrowdWays& ways) {
  Snapshot s{t,
             std::vector<Vec2>(walkers.size()),
             std::vector<char>(walkers.size()),
             {},
             bounds_from,
             std::vector<PlanBounds::From>(walkers.size()),
             std::vector<char>(walkers.size()),
             {},
             std::vector<double>(walkers.size()),
             walkers.empty() ? 0.0 : walkers.front().planner->character().body_height};
  for (std::size_t j = 0; j < walkers.size(); ++j) {
    s.com[j] = walks[j].com_at(t).position;
    s.ground[j] = ground_at(walkers[j].plan, t);
    s.present[j] = present_at(walkers[j].plan, t);
    s.bounds[j] = walkers[j].bounds->from(bounds_from);
  }
  s.grid = AgentGrid(s.com, kGridCell);
  std::vector<const Way*> going(walkers.size(), nullptr);
  for (std::size_t j = 0; j < walkers.size(); ++j)
    if (!walkers[j].done && !walkers[j].ways.empty()) going[j] = &walkers[j].ways.front().way;
  std::vector<int> layer_of(walkers.size(), 0);
  if (crowd_grids.size() > 1)
    for (std::size_t j = 0; j < walkers.size(); ++j)
      layer_of[j] = ways.layered->layer_under(s.com[j], s.ground[j]);
  for (std::size_t layer = 0; layer < crowd_grids.size(); ++layer) {
    std::vector<char> on = s.present;
    for (std::size_t j = 0; j < walkers.size(); ++j)
      on[j] = on[j] && layer_of[j] == static_cast<int>(layer);
    s.crowds.emplace_back(crowd_grids[layer], s.com, on, going);
  }
  for (std::size_t j = 0; j < walkers.size(); ++j) s.giving_way[j] = gives_way(walkers, j, s);
  return s;
}

/// The agents that agent `i` sees at the snapshot's time (within
/// kViewDistance, in front of its torso, and with a clear line of sight),
/// those it has noticed, and those whose wishes it keeps out of.
std::vector<std::size_t> seen_by(const std::vector<Walker>& walkers, std::size_t i,
                                 const Snapshot& now, const CrowdWays& ways) {
  const NavMesh* mesh = ways.mesh_at(walkers[i].state);
  const Vec2 eye = now.com[i];
  const Vec2 ahead = unit(facing_at(walkers[i].plan, now.t));
  std::vector<std::size_t> seen;
  std::vector<Vec2> where;
  std::vector<std::size_t> around;
  now.around(i, kViewDistance, around);
  for (const std::size_t j : around) {
    if (!now.present[j]) continue;
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
/// comes to rest among `others`, outside the search's keep-out, free to set
/// off again unless the steps reach the goal (none left: it waits), and
/// keeps that rest, all checked as the search (`options`) checks its steps.
/// Committed plans are checked with the agent standing after its rest, so the rest must be
/// complete; and the next search starts there, so it must be able to set
/// off: a rest in a door frame, facing a post, can leave every step blocked.
void cut_to_rest(const FootstepPlanner& planner, const FootstepState& start,
                 const MovingObstacles& others, const SearchOptions& options, Attempt& a) {
  const std::optional<WholeBody> following = planner.whole_body(options.sections);
  const WholeBody* whole = following ? &*following : nullptr;
  std::vector<FootstepState> states{start};
  for (const Footstep& step : a.steps) states.push_back(state_after(states.back(), step));
  std::size_t keep = a.steps.size();
  for (; keep > 0; --keep) {
    // A start and the walk it begins are one step of the search: not parted.
    if (a.steps[keep - 1].kind == StepKind::kStart) continue;
    a.rest = planner.validity().come_to_rest(states[keep], others, whole);
    const bool at_goal = a.reached && keep == a.steps.size();
    if (a.rest.complete && planner.validity().keeps_out(a.rest.state, options.keep_out) &&
        (at_goal || planner.validity().free_to_set_off(a.rest.state, whole)))
      break;
  }
  if (keep == a.steps.size()) return;
  a.steps.resize(keep);
  a.end = states[keep];
  a.reached = false;
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

/// Agent i's next search: toward its local goal, among the plans of the
/// agents it sees (`seen`), resting out of the wishes of those it yields to.
/// When it stands blocked after a search that gained nothing, with one that
/// goes after it near, also its wish: the same search among only those it
/// sees that go first.
Attempt search(const std::vector<Walker>& walkers, std::size_t i, const FootstepPlanner& planner,
               const CrowdWays& ways, const std::vector<std::size_t>& seen, const Snapshot& now) {
  const Walker& w = walkers[i];
  const Vec2 goal = w.spec->goals[w.goal];
  const NavMesh* mesh = ways.mesh_at(w.state);
  const LayerWay on = way_on(w, ways, planner.character(), w.state, seen, now);
  const Way& way = on.way;
  // Near where its way crosses to another layer, it aims past the crossing:
  // the footsteps take it across (each layer's mesh is walled there).
  const LocalGoal aim =
      on.across && polyline_length(way.points) <= planner.params().local_goal_distance
          ? LocalGoal{*on.across, false}
          : aim_of(w, planner, mesh, way);
  const LocalGoal target = keep_right(walkers, i, aim, seen, now, planner, mesh);
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
  const SearchOptions options{leaves,
                              keep_out,
                              w.blocked >= 1 && jammed ? kBlockedHorizon : 0,
                              kRestGrace,
                              jammed && patient(w, w.state) ? kJamStall : 0,
                              w.following(),
                              w.roomy};
  SearchResult result = planner.plan(w.state, target.point, others, options);
  const bool moves =
      std::any_of(result.footsteps.begin(), result.footsteps.end(),
                  [&](const Footstep& step) { return !still(step, w.state.facing); });
  SearchOptions short_search = options;
  short_search.horizon = kBlockedHorizon;
  // Standing where it must make room, with nowhere to go but aside.
  bool boxed_in = false, steps_aside = false;
  if (!moves && w.state.standing() && must_make_room(walkers, i, now, planner)) {
    // In a face-off (two blocks of a counterflow, a knot among boxes) no one
    // gains on its own way, and waiting only stands in the way: it makes
    // room, stepping aside out of the wishes it yields to.
    boxed_in = true;
    if (auto aside = step_aside(w.state, keep_out, others, planner, mesh, short_search)) {
      result = std::move(*aside);
      boxed_in = false;
      steps_aside = true;
    }
  }
  Attempt a;
  a.from = w.state;
  a.steps = result.footsteps;
  a.end = result.footsteps.empty() ? w.state : result.end_state;
  // Aside, it reached the place it makes room at, not its goal.
  a.reached = result.status == Status::kSuccess && target.is_goal && !steps_aside;
  if (w.plan.footsteps.empty() && dot(unit(w.state.facing), target.point - w.state.com) < 0.0)
    turn_first(w.state, a);
  if (!leaves_now(w, a.reached)) cut_to_rest(planner, w.state, others, options, a);
  const std::optional<double> facing = goal_facing(*w.spec, w.goal);
  if (a.reached && a.rest.complete && facing && !leaves_now(w, a.reached)) {
    // At a goal it turns to face as asked, as far as it has room to.
    const std::optional<WholeBody> following = planner.whole_body(options.sections);
    Rest turn = planner.validity().turn_to(a.rest.state, *facing, others, following ? &*following : nullptr);
    a.rest.steps.insert(a.rest.steps.end(), turn.steps.begin(), turn.steps.end());
    a.rest.state = turn.state;
    a.turned = true;
  }
  // Ways to where they cross to another layer are not kept: they lead
  // elsewhere than the goal they would be found by.
  if (!on.across) a.ways.push_back({w.state.com, goal, way});
  if (!a.reached) {
    LayerWay left = way_on(w, ways, planner.character(), a.end, seen, now);
    a.way_left = left.way.length;
    if (!left.across) a.ways.push_back({a.end.com, goal, std::move(left.way)});
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
    if (goes_first(walkers, now, j, i))
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
    // Where it stands cramped (in a gap between boxes) the way on may be
    // many nodes deep (a side step takes some 140), which a blocked search's
    // short horizon or stall cuts off: the wish, which settles who makes room
    // for whom, is searched in full there.
    const bool tight = cramped(mesh, planner.character(), w.state.com);
    SearchOptions wish_options = options;
    if (tight) wish_options.horizon = wish_options.stall = 0;
    const bool same =
        !tight && std::all_of(result.refused_by.begin(), result.refused_by.end(),
                              [&](std::size_t k) { return goes_first(walkers, now, seen[k], i); });
    const SearchResult wish =
        same ? result : planner.plan(w.state, target.point, plans_of(walkers, first), wish_options);
    const Vec2 from = w.state.com, to = wish.end_state.com;
    const bool gains = distance(to, target.point) < distance(from, target.point) - min_progress;
    const bool leaves_a_wish =
        !planner.validity().keeps_out(w.state, keep_out) && distance(to, from) > min_progress;
    if (gains || leaves_a_wish) a.wish = wish_discs(wish.footsteps, planner.character());
  }
  return a;
}

/// Every other agent within kCheckDistance of agent `i` at the snapshot's
/// time, seen or not.
std::vector<std::size_t> near(std::size_t i, const Snapshot& now) {
  std::vector<std::size_t> around, out;
  now.around(i, kCheckDistance, around);
  for (const std::size_t j : around) {
    if (now.present[j] && distance(now.com[j], now.com[i]) <= kCheckDistance)
      out.push_back(j);
  }
  return out;
}

/// Wakes the dormant agents within kFreezeRadius of agent `i`, which has
/// just committed steps that move: what held them may have moved on. Those
/// woken go into `woken`.
void wake_near(std::vector<Walker>& walkers, std::size_t i, const Snapshot& now,
               std::vector<std::size_t>& woken) {
  std::vector<std::size_t> around;
  now.around(i, kFreezeRadius, around);
  for (const std::size_t j : around) {
    if (walkers[j].dormant && distance(now.com[j], now.com[i]) <= kFreezeRadius) {
      wake(walkers[j], now.t);
      woken.push_back(j);
    }
  }
}

/// Where and when an agent leaves at its goal (the end of its last step).
struct Departure {
  double time;  ///< [s]
  Vec2 at;
};

/// Wakes the dormant agents within kFreezeRadius of where one of
/// `departures` left by time `t`, and forgets those departures: what held
/// them may have gone. wake_near() wakes them when one near moves, but one
/// that leaves moves last before it goes. Those woken go into `woken`.
void wake_where_gone(std::vector<Walker>& walkers, std::vector<Departure>& departures, double t,
                     std::vector<std::size_t>& woken) {
  const auto gone = std::stable_partition(departures.begin(), departures.end(),
                                          [t](const Departure& d) { return d.time > t; });
  for (auto d = gone; d != departures.end(); ++d) {
    for (std::size_t j = 0; j < walkers.size(); ++j) {
      if (walkers[j].dormant && distance(walkers[j].state.com, d->at) <= kFreezeRadius) {
        wake(walkers[j], t);
        woken.push_back(j);
      }
    }
  }
  departures.erase(gone, departures.end());
}

/// Keeps the last place its committed steps `a` stand with room to walk
/// upright (Walker::roomy_at).
void note_roomy_place(Walker& w, const Attempt& a, const CrowdWays& ways) {
  const NavMesh* mesh = ways.mesh_at(a.end);
  if (mesh == nullptr) return;
  const double upright = 0.5 * w.planner->character().torso_width;
  for (auto step = a.steps.rbegin(); step != a.steps.rend(); ++step) {
    if (mesh->clearance(step->com_end) >= upright) {
      w.roomy_at = step->com_end;
      return;
    }
  }
}

/// True if agent `i` is stuck: its way has not shortened by min_progress for
/// kStuckAfter, and neither has that of any agent within kQueueDistance
/// bound the same way as it (its goal less than 90 degrees round). One
/// waiting behind others that move is queueing (at a crowded exit, for
/// longer than kStuckAfter), not stuck; a deadlock does not move at all. In
/// a knot of crossing streams some always shuffle on, bound elsewhere: they
/// are no queue it waits in. One that has just reached its goal there
/// counts as moving: it may have stood in the way until then.
bool stuck(const std::vector<Walker>& walkers, std::size_t i) {
  const Walker& w = walkers[i];
  const double since = w.state.time - kStuckAfter;
  if (w.improved_at >= since) return false;
  const Vec2 bound = bound_of(w, w.state.com);
  for (std::size_t j = 0; j < walkers.size(); ++j) {
    const Walker& other = walkers[j];
    if (j != i && other.improved_at >= since &&
        distance(other.state.com, w.state.com) <= kQueueDistance &&
        dot(bound_of(other, other.state.com), bound) > 0.0)
      return false;
  }
  return true;
}

/// A stuck agent (stuck()) tries again, for another kStuckAfter: its way
/// is measured anew (a way round may be longer than the one it was stuck
/// on, and still gain), and its next search is news (nothing_new()).
/// `roomy`: on the roomiest way there is (way_toward()). The tightest way,
/// with room only to side-step, passes any gap the torso's circle fits
/// through, but the footsteps need more (their checks pad the torso, and it
/// turns at the corners): a slot a little wider than the torso's circle may
/// let no step through.
void try_again(Walker& w, double t, bool roomy) {
  w.roomy = roomy;
  w.ways.clear();
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
  now.around(i, kFreezeRadius, around);
  for (const std::size_t j : around) {
    if (distance(now.com[j], now.com[i]) > kFreezeRadius) continue;
    if (walkers[j].committed_at >= w.searched_at || !still_from(walkers[j].plan, w.searched_at))
      return false;
  }
  return true;
}

/// Walker `w` keeps `plan` whole (plan_agents' `fixed`): done from the
/// start, standing where the plan ends once it has walked it.
void hold_fixed(Walker& w, const AgentPlan& plan) {
  const std::shared_ptr<const CharacterParams> character = w.plan.character;
  w.plan = plan;
  w.plan.character = character;  // the run's, as for every walker
  FootstepState end = w.plan.start;
  for (const Footstep& step : w.plan.footsteps) end = state_after(end, step);
  w.state = w.rested = end;
  w.bounds = std::make_shared<const PlanBounds>(w.plan, w.planner->character());
  w.goal = w.spec->goals.size();
  w.improved_at = end.time;  // moving until then, as one that arrived then
  w.done = true;
}

/// How far the walker is: its goals reached, and the way to the current one.
double progress_of(const Walker& w) {
  if (w.done) return 1.0;
  double current = 0.0;
  if (w.first_way > 0.0 && std::isfinite(w.best_way))
    current = std::clamp(1.0 - w.best_way / w.first_way, 0.0, 1.0);
  return (static_cast<double>(w.goal) + current) / static_cast<double>(w.spec->goals.size());
}

/// Moves the first steps of walker w's plan that no check or search reaches
/// any more, those kSettledAge before `t`, to `settled`: every copy of a
/// plan (the views, each trial) then holds only what is still checked. Its
/// bounds follow; `walk`, which reads its plan, starts over. False if too
/// few would go to be worth it (kSettleAtLeast).
bool settle(Walker& w, PlanWalk& walk, std::vector<Footstep>& settled, double t) {
  const std::size_t count = droppable_steps(w.plan, t - kSettledAge);
  if (count < kSettleAtLeast) return false;
  drop_steps(w.plan, count, settled);
  w.plan.footsteps.shrink_to_fit();
  w.bounds = std::make_shared<const PlanBounds>(w.plan, w.planner->character());
  walk = PlanWalk(w.plan);
  return true;
}

/// One tick's searches and checks, run on the workers, committed a tick later.
struct TickJobs {
  double t = 0.0;
  std::vector<std::size_t> due;  ///< The agents that replan, in their order.
  Snapshot at;
  std::vector<char> idle;           ///< Per due: nothing_new(), no search.
  std::vector<std::size_t> order;   ///< The jobs' order: indices into `due`.
  std::vector<Attempt> attempts;    ///< Per due.
  std::vector<Proposal> proposals;  ///< Per due.
  std::vector<double> seconds;      ///< Per due: the search's time. [s]
  std::vector<double> job_seconds;  ///< Per due: the search's and check's. [s]
  std::uint64_t batch = 0;          ///< Its batch on the workers.
};

}  // namespace

std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const FootstepPlanner& planner, const NavMesh* mesh,
                                   const RunControl& control) {
  for (std::size_t i = 0; i < agents.size(); ++i) {
    if (agents[i].character)
      throw std::invalid_argument(
          "agents[" + std::to_string(i) +
          "].character: one planner plans every agent with its character; give a planner per agent");
  }
  return plan_agents(agents, std::vector<const FootstepPlanner*>(agents.size(), &planner), mesh,
                     control);
}

namespace {

// plan_agents, finding ways on `ways`.
std::vector<AgentPlan> plan_on(const std::vector<AgentSpec>& agents,
                               const std::vector<const FootstepPlanner*>& planners,
                               const CrowdWays& ways, const RunControl& control,
                               const std::vector<const AgentPlan*>& fixed,
                               const Annotator& annotate) {
  if (planners.size() != agents.size() ||
      std::find(planners.begin(), planners.end(), nullptr) != planners.end())
    throw std::invalid_argument("plan_agents: give one planner per agent");
  if (!fixed.empty() && fixed.size() != agents.size())
    throw std::invalid_argument("plan_agents: give no fixed plans or one (or null) per agent");
  const auto is_fixed = [&](std::size_t i) { return !fixed.empty() && fixed[i] != nullptr; };
  for (const AgentSpec& agent : agents) check_agent(agent);
  if (control.threads < 1 || control.threads > 64)
    throw std::invalid_argument("threads must be between 1 and 64");
  if (agents.empty()) return {};
  const PlannerParams& params = planners.front()->params();
  std::vector<Walker> walkers(agents.size());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    Walker& w = walkers[i];
    w.spec = &agents[i];
    w.planner = planners[i];
    w.sections = std::make_shared<const SectionLookup>(agents[i].sections);
    if (params.follow_sections == 1 && w.sections->any_narrower())
      w.guides = guides_of(agents[i], agents[i].sections, 0);
    w.plan.name = agents[i].name;
    // Every plan carries its character while the crowd plans (the others
    // check against it), its planner's: not owned, it outlives the run.
    w.plan.character = std::shared_ptr<const CharacterParams>(std::shared_ptr<void>(),
                                                              &w.planner->character());
    w.plan.start =
        w.planner->validity().standing(agents[i].position, agents[i].facing, agents[i].height);
    w.state = w.plan.start;
    w.bounds = std::make_shared<const PlanBounds>(w.plan, w.planner->character());
    w.start_at = agents[i].start_delay;
    w.deadline = w.start_at + time_limit_of(agents[i], w.planner->character(), params);
    if (is_fixed(i)) hold_fixed(w, *fixed[i]);
  }
  std::vector<PlanWalk> walks;
  for (const Walker& w : walkers) walks.emplace_back(w.plan);
  // The steps settled (settle()), and where each plan started before them.
  std::vector<std::vector<Footstep>> settled(walkers.size());
  std::vector<FootstepState> first_states;
  for (const Walker& w : walkers) first_states.push_back(w.plan.start);
  std::vector<CrowdGrid> crowd_grids;  // one per layer
  const double sway = sway_room(planners.front()->character());
  if (ways.layered != nullptr)
    for (int layer = 0; layer < ways.layered->layers(); ++layer)
      crowd_grids.emplace_back(ways.layered->mesh(layer), sway);
  else if (ways.mesh != nullptr)
    crowd_grids.emplace_back(*ways.mesh, sway);
  // Two views (see the top of this file), one per tick in flight; each is
  // brought up to date from the walkers changed since it last was. Bounds
  // and samples are shared with the walkers, not copied.
  std::array<std::vector<Walker>, 2> views{walkers, walkers};
  std::array<std::uint64_t, 2> synced{0, 0};
  std::uint64_t epoch = 1;
  std::vector<std::uint64_t> changed_at(walkers.size(), 0);
  const auto touch = [&](std::size_t i) { changed_at[i] = epoch; };
  std::vector<char> in_flight(walkers.size(), 0);
  std::vector<Departure> departures;  // still to come (wake_where_gone())
  std::unique_ptr<TickJobs> pending, current;
  Workers workers(control.threads);  // after what its jobs read: it ends first
  // The tick's results, committed in the agents' order against the walkers
  // as they now stand.
  const auto commit_tick = [&](TickJobs& jobs) {
    workers.finish(jobs.batch);
    const double t = jobs.t;
    for (std::size_t k = 0; k < jobs.due.size(); ++k) {
      if (!jobs.idle[k]) walkers[jobs.due[k]].last_cost = jobs.job_seconds[k];
      if (control.search_seconds != nullptr) *control.search_seconds += jobs.seconds[k];
    }
    std::vector<std::size_t> others;  // changed by a commit besides its own agent
    for (std::size_t k = 0; k < jobs.due.size(); ++k) {
      const std::size_t i = jobs.due[k];
      Walker& w = walkers[i];
      in_flight[i] = 0;
      touch(i);
      // Those it yielded to and that no longer wish are let go.
      w.yielding_to.erase(std::remove_if(w.yielding_to.begin(), w.yielding_to.end(),
                                         [&](std::size_t r) { return !wishing(walkers[r]); }),
                          w.yielding_to.end());
      const Attempt& a = jobs.attempts[k];
      const int refused = refusal(walkers, jobs.proposals[k], *w.planner);
      commit(walkers, i, a, jobs.proposals[k], refused, *w.planner, t);
      if (w.done && w.plan.leaves && !w.plan.footsteps.empty())
        departures.push_back({w.plan.footsteps.back().end_time, w.plan.footsteps.back().com_end});
      others.clear();
      if (w.committed_at == t) {
        wake_near(walkers, i, jobs.at, others);
        note_roomy_place(w, a, ways);
      }
      if (a.searched) {
        w.ways = std::move(jobs.attempts[k].ways);
        w.searched_at = t;
        w.searched_from = a.from;
        w.way = a.way_from;
        const bool gained = a.reached || a.way_left <= a.way_from - params.min_progress;
        w.blocked = w.failures == 0 && gained ? 0 : w.blocked + 1;
      }
      show_wish(walkers, i, jobs.attempts[k], jobs.at, jobs.proposals[k].close, others);
      for (const std::size_t j : others) touch(j);
      if (!w.done && stuck(walkers, i)) {
        // Its second chance on the roomiest way, its third on its way
        // annotated anew from where it stands (annotate_anew()).
        ++w.stuck_times;
        if (w.stuck_times == 1) {
          try_again(w, t, true);
          if (annotate) annotate_anew(w, i, annotate, params);
        } else if (w.stuck_times == 2 && annotate) {
          try_again(w, t, false);
          annotate_anew(w, i, annotate, params);
        } else {
          w.plan.reason = "stuck";
          w.dormant = true;
        }
      }
    }
  };
  double reported = 0.0;
  auto last_report = std::chrono::steady_clock::now();
  for (long tick = 0;; ++tick) {
    const double t = static_cast<double>(tick) * kTick;
    std::vector<std::size_t> due;
    std::vector<std::size_t> woken;
    wake_where_gone(walkers, departures, t, woken);
    for (const std::size_t j : woken) touch(j);
    // Not those in flight: their commits replace their plans with the view's.
    if (tick % kSettleTicks == 0)
      for (std::size_t i = 0; i < walkers.size(); ++i)
        if (!in_flight[i] && settle(walkers[i], walks[i], settled[i], t)) touch(i);
    bool active = !departures.empty();
    for (std::size_t i = 0; i < walkers.size(); ++i) {
      if (walkers[i].done || walkers[i].dormant) continue;
      if (!in_flight[i] && t > walkers[i].deadline) {  // it stands where its plan ends
        walkers[i].plan.reason = "time limit";
        walkers[i].done = true;
        touch(i);
        continue;
      }
      active = true;
      if (!in_flight[i] && walkers[i].state.time - t <= kReplanLead && t >= walkers[i].retry_at &&
          t >= walkers[i].start_at)
        due.push_back(i);
    }
    if (!active) break;  // none in flight either
    const bool cancelled = control.cancelled();
    if (cancelled) {
      if (pending) commit_tick(*pending);
      for (Walker& w : walkers)
        if (!w.done && !w.dormant) w.plan.reason = "cancelled";
      break;
    }
    if (!due.empty()) {
      current = std::make_unique<TickJobs>();
      TickJobs& jobs = *current;
      jobs.t = t;
      jobs.due = std::move(due);
      // A plan that has run into its rest starts again from where that leaves it.
      for (const std::size_t i : jobs.due) {
        if (walkers[i].state.time < t) {
          rest_until(walkers[i], *walkers[i].planner, t);
          touch(i);
        }
        in_flight[i] = 1;
      }
      // The tick's trials differ from their agents' plans from the start of
      // the last step each keeps on (propose()).
      double trials_from = kForever;
      for (const std::size_t i : jobs.due) {
        const Walker& w = walkers[i];
        const std::size_t kept = w.plan.footsteps.size() - w.resting;
        const double from = kept > 0 ? w.plan.footsteps[kept - 1].start_time : w.state.time;
        trials_from = std::min(trials_from, from);
      }
      jobs.at = snapshot(walkers, walks, t, trials_from, crowd_grids, ways);
      const std::size_t n = jobs.due.size();
      jobs.idle.resize(n);
      for (std::size_t k = 0; k < n; ++k) jobs.idle[k] = nothing_new(walkers, jobs.due[k], jobs.at);
      std::vector<Walker>& view = views[static_cast<std::size_t>(tick % 2)];
      std::uint64_t& view_synced = synced[static_cast<std::size_t>(tick % 2)];
      for (std::size_t j = 0; j < walkers.size(); ++j)
        // A fresh copy: one assigned over the old would keep its longer plan's room.
        if (changed_at[j] > view_synced) view[j] = Walker(walkers[j]);
      view_synced = epoch++;
      // The dearest-looking jobs start first (those that search, by what
      // their last ones took), so that threads finish together; results go
      // by index, so the order changes nothing else.
      jobs.order.resize(n);
      for (std::size_t k = 0; k < n; ++k) jobs.order[k] = k;
      const auto cost = [&](std::size_t k) {
        return jobs.idle[k] ? 0.0 : walkers[jobs.due[k]].last_cost;
      };
      std::stable_sort(jobs.order.begin(), jobs.order.end(),
                       [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
      jobs.attempts.resize(n);
      jobs.proposals.resize(n);
      jobs.seconds.assign(n, 0.0);
      jobs.job_seconds.assign(n, 0.0);
      jobs.batch = workers.launch(n, [&jobs, &view, &ways](std::size_t job) {
        const std::size_t k = jobs.order[job], i = jobs.due[k];
        const FootstepPlanner& planner = *view[i].planner;
        const auto begin = std::chrono::steady_clock::now();
        if (!jobs.idle[k]) {
          jobs.attempts[k] =
              search(view, i, planner, ways, seen_by(view, i, jobs.at, ways), jobs.at);
          jobs.seconds[k] =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        }
        jobs.proposals[k] = propose(view, i, jobs.attempts[k], planner, near(i, jobs.at), jobs.at);
        jobs.job_seconds[k] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      });
    }
    if (pending) commit_tick(*pending);
    pending = std::move(current);
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
  for (std::size_t i = 0; i < walkers.size(); ++i) {
    if (is_fixed(i)) {
      plans.push_back(*fixed[i]);
      continue;
    }
    Walker& w = walkers[i];
    w.plan.start = first_states[i];
    settled[i].insert(settled[i].end(), w.plan.footsteps.begin(), w.plan.footsteps.end());
    w.plan.footsteps = std::move(settled[i]);
    w.plan.stuck_at = w.resting > 0 ? w.rested.com : w.state.com;
    choose_foot_orientations(w.plan.footsteps, w.plan.start.foot_orientation,
                             w.planner->character());
    // Without the full-body test the steps take their sections' behaviours
    // (those a search gave the arms in keep them: the others were checked
    // against that narrower torso). With it every step keeps the posture it
    // was tested in: sections added later (annotate_anew()) would turn a wait
    // side-on, its limbs where none was tested.
    if (!w.planner->tests_body())
      for (Footstep& step : w.plan.footsteps)
        if (step.behavior != Behavior::kArmsIn)
          step.behavior = std::max(step.behavior, w.sections->of(step));
    w.plan.sections = w.sections->sections();
    w.plan.character = w.spec->character;
    w.plan.scale = w.spec->scale;
    plans.push_back(std::move(w.plan));
  }
  return plans;
}

}  // namespace

std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const std::vector<const FootstepPlanner*>& planners,
                                   const NavMesh* mesh, const RunControl& control,
                                   const std::vector<const AgentPlan*>& fixed,
                                   const Annotator& annotate) {
  return plan_on(agents, planners, CrowdWays{mesh, nullptr}, control, fixed, annotate);
}

std::vector<AgentPlan> plan_agents(const std::vector<AgentSpec>& agents,
                                   const std::vector<const FootstepPlanner*>& planners,
                                   const LayeredNavigation& navigation, const RunControl& control,
                                   const std::vector<const AgentPlan*>& fixed) {
  return plan_on(agents, planners, CrowdWays{nullptr, &navigation}, control, fixed, {});
}

std::optional<std::pair<std::string, std::string>> facings_problem(const AgentSpec& agent) {
  if (agent.end_facing && !std::isfinite(*agent.end_facing)) return std::pair{"end_facing", "must be finite"};
  const std::vector<std::optional<double>>& facings = agent.goal_facings;
  if (facings.empty()) return std::nullopt;
  if (facings.size() != agent.goals.size())
    return std::pair{"goal_facings", "needs one facing (or null) per goal: " + std::to_string(agent.goals.size()) +
                                         " goals, " + std::to_string(facings.size()) + " facings"};
  for (std::size_t k = 0; k < facings.size(); ++k)
    if (facings[k] && !std::isfinite(*facings[k]))
      return std::pair{"goal_facings[" + std::to_string(k) + "]", std::string("must be finite")};
  if (agent.end_facing && facings.back())
    return std::pair{"end_facing", "and goal_facings[" + std::to_string(facings.size() - 1) +
                                       "] both give the last goal's facing: give one"};
  return std::nullopt;
}

std::optional<double> goal_facing(const AgentSpec& agent, std::size_t goal) {
  if (goal < agent.goal_facings.size() && agent.goal_facings[goal]) return agent.goal_facings[goal];
  return goal + 1 == agent.goals.size() ? agent.end_facing : std::nullopt;
}

double time_limit_of(const AgentSpec& agent, const CharacterParams& character,
                     const PlannerParams& planner) {
  if (agent.time_limit > 0.0) return agent.time_limit;
  double route = 0.0;
  Vec2 from = agent.position;
  for (const Vec2 goal : agent.goals) {
    route += distance(from, goal);
    from = goal;
  }
  constexpr double kRouteSlack = 4.0;  // detours, queues and waits
  return std::min(kMaxTimeLimit,
                  std::max(planner.max_time, kRouteSlack * route / character.preferred_speed));
}

AgentPlan plan_agent(const AgentSpec& agent, const FootstepPlanner& planner, const NavMesh* mesh,
                     const RunControl& control) {
  return plan_agents({agent}, planner, mesh, control).front();
}

}  // namespace footfall
