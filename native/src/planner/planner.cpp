#include "footfall/planner/planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "model/footstep_shape.hpp"
#include "planner/validity_impl.hpp"
#include "util/huge_page_allocator.hpp"
#include "util/open_hash_map.hpp"

namespace footfall {
namespace {

using planner::detail::kPivotTurn;
using planner::detail::kSideStepSpeed;

// Two generated states that fall in the same cell of (COM 4 cm, velocity
// heading 4 degrees, speed 0.1 m/s, standing, last foot) are treated as one:
// the later one is dropped. This keeps the search from re-expanding
// near-identical states.
constexpr double kCellPosition = 0.04;
constexpr double kCellHeading = 4.0 * kPi / 180.0;
constexpr double kCellSpeed = 0.1;
// A search holds at most this many nodes (about 180 MB), and then stops as at
// its horizon, whatever max_expansions says: a full search of the default
// horizon holds some 50,000.
constexpr std::size_t kMaxSearchNodes = 500000;
constexpr double kDuplicateTurn = 1e-3;    // [rad] goal-directed turn equal to a tabled one

// A number for the level of ground at height `z`: two standable levels over
// one point, more than `headroom` apart, differ in it; ground lower than
// `headroom` (and the floor z = 0) is all level 0. 14 bits.
std::uint64_t level_bucket(double z, double headroom) {
  return static_cast<std::uint64_t>(
             static_cast<std::int64_t>(std::clamp(std::floor(z / headroom), -1e6, 1e6))) &
         0x3FFF;
}

// The level_bucket of the ground under the foot `state` stands on (the one
// its last step did not plant: that one's height is found as its step is checked).
std::uint64_t stance_level(const FootstepState& state, double headroom) {
  return level_bucket(state.foot_heights[1 - static_cast<int>(state.last_foot)], headroom);
}

std::uint64_t state_key(Vec2 com, double heading, double speed, bool standing, Foot last_foot,
                        std::uint64_t level) {
  // Clamped before the conversion, so that far-away coordinates stay defined.
  const auto q = [](double v, double cell) {
    return static_cast<std::uint64_t>(
        static_cast<std::int64_t>(std::clamp(std::floor(v / cell), -1e15, 1e15)));
  };
  // Bit 63 set: 0 marks an empty slot of the table below.
  return (q(com.x, kCellPosition) & 0xFFFF) | (q(com.y, kCellPosition) & 0xFFFF) << 16 |
         (q(wrap_angle(heading) + kPi, kCellHeading) & 0x7F) << 32 |
         (q(speed, kCellSpeed) & 0xFF) << 39 | (standing ? 1ull : 0ull) << 47 |
         static_cast<std::uint64_t>(last_foot) << 48 | level << 49 | 1ull << 63;
}

// True if `step`, taken from `before`, keeps clear of `others`; a walking
// step that would touch one passes if it keeps clear with the arms held in
// (the torso as narrow as the shoulders), and is then labelled arms_in, as
// people squeezing past one another do.
bool passes_others(const ValidityChecker::Impl& checks, Footstep& step,
                   const FootstepState& before, detail::SampledAgents& others) {
  if (!checks.step_touches_agents(step, before, others)) return true;
  if (step.kind != StepKind::kWalk || step.behavior != Behavior::kWalk) return false;
  step.behavior = Behavior::kArmsIn;
  if (!checks.step_touches_agents(step, before, others)) return true;
  step.behavior = Behavior::kWalk;
  return false;
}

// The search took walking agents' rests to end after their grace; nothing
// returned may rely on that, so the steps stop before the first that runs
// into one taken for good.
void cut_before_rests(const ValidityChecker::Impl& checks, const FootstepState& start,
                      detail::SampledAgents& others, SearchResult& result) {
  others.set_rest_grace(std::numeric_limits<double>::infinity());
  FootstepState state = start;
  for (std::size_t k = 0; k < result.footsteps.size(); ++k) {
    const Footstep& step = result.footsteps[k];
    if (checks.step_touches_agents(step, state, others)) {
      result.footsteps.resize(k);
      result.end_state = state;
      result.status = Status::kPartial;
      return;
    }
    state = state_after(state, step);
  }
}

// True if `state` stands with its feet side by side across its facing, as
// standing_state puts them.
bool feet_together(const FootstepState& state, const CharacterParams& character) {
  const FootstepState together = standing_state(state.com, state.facing, character);
  for (int f = 0; f < 2; ++f)
    if (distance(state.feet[f], together.feet[f]) >= 1e-9) return false;
  return true;
}

// Each walk from standing whose foot had no step of the other to swing in
// becomes a start and the rest of the walk (split_set_off): the same motion,
// told so that no foot moves while it bears weight.
void split_set_offs(std::vector<Footstep>& steps, const FootstepState& start) {
  std::vector<Footstep> told;
  told.reserve(steps.size() + 1);
  FootstepState state = start;
  for (const Footstep& step : steps) {
    if (splits_on_set_off(step, state)) {
      for (const Footstep& part : split_set_off(step, state, set_off_lead(step)))
        told.push_back(part);
    } else {
      told.push_back(step);
    }
    state = state_after(state, step);
  }
  steps = std::move(told);
}

}  // namespace

// Named, not anonymous: FootstepPlanner::Search holds one.
namespace planner::detail {

// The state keys a search has seen, kept per thread from search to search.
struct KeyHash {
  std::size_t operator()(std::uint64_t key) const {
    key ^= key >> 33;
    key *= 0xFF51AFD7ED558CCDull;
    return static_cast<std::size_t>(key ^ (key >> 33));
  }
};
using KeySet = util::OpenHashMap<std::uint64_t, util::NoValue, KeyHash, 2048, HugePageAllocator>;

}  // namespace planner::detail

// [m] how much nearer or further land_on_ground tries to plant a foot, in turn
constexpr double kLandingShifts[] = {0.03, 0.06, 0.09, 0.12};
// Climbs kept for one goal before they are found anew (some 4 MB).
constexpr std::size_t kMostClimbs = 100000;

// A search node: the state reached and the action that reached it; the step
// itself is rebuilt (bit for bit) when needed.
struct FootstepPlanner::Node {
  FootstepState state;
  double g = 0;
  double h = 0;
  int parent = -1;
  Footstep step;  ///< From the parent's state (none at the root): checked when popped.
  bool landed = false;  ///< Made by land_on_ground: not moved again.
  bool costed = false;  ///< Its ground's cost is in g (see plan()).
};

struct FootstepPlanner::Search {
  struct OpenEntry {
    double f;
    double h;
    int index;
    // Lowest f first; ties by lowest h, then by creation order (determinism).
    bool operator<(const OpenEntry& o) const {
      if (f != o.f) return f > o.f;
      if (h != o.h) return h > o.h;
      return index > o.index;
    }
  };
  LargeVector<Node> nodes;
  LargeVector<OpenEntry> open;  // a binary heap
  planner::detail::KeySet seen;
  detail::SampledAgents others;  // the plans the search avoids
  std::optional<WholeBody> whole;  // the full-body checks, if any
  bool fine_pivots = false;        // SearchOptions::fine_pivots
  int generated = 0;

  void push(Node node, double weight) {
    const int index = static_cast<int>(nodes.size());
    open.push_back({node.g + weight * node.h, node.h, index});
    std::push_heap(open.begin(), open.end());
    nodes.push_back(std::move(node));
  }
  int pop() {
    std::pop_heap(open.begin(), open.end());
    const int index = open.back().index;
    open.pop_back();
    return index;
  }
};

FootstepPlanner::FootstepPlanner(const CharacterParams& character, const PlannerParams& planner,
                                 const ObstacleMap& obstacles, const StepBodyTest* body,
                                 const Ground* ground)
    : validity_(character, planner, obstacles, ground), body_(body) {
  // A normal step, through the model itself: straight, at the preferred speed
  // and duration, in steady walking (incoming at the same speed), the incoming
  // heading turned outward from phi by the smallest turn angle; by the right
  // foot, or by the left if only it may take such a step (a limp).
  const double turn = *std::min_element(planner.turn_angles.begin(), planner.turn_angles.end());
  StepResult normal;
  for (const Foot foot : {Foot::kRight, Foot::kLeft}) {
    FootstepState walking = standing_state({0.0, 0.0}, 0.0, character);
    walking.com_velocity = character.preferred_speed * unit(outward_sign(foot) * turn);
    walking.last_foot = other(foot);
    normal = create_footstep(walking,
                             {StepKind::kWalk, foot, 0.0, character.preferred_speed,
                              character.preferred_step_duration},
                             character);
    if (normal.valid()) break;
  }
  if (!normal.valid()) {
    const bool duration = normal.validity == StepValidity::kDurationOutOfRange;
    throw std::invalid_argument(
        std::string(duration ? "character.preferred_step_duration" : "character.preferred_speed") +
        ": a step at the preferred speed and duration breaks both feet's limits (" +
        to_string(normal.validity) + ")");
  }
  expected_step_cost_ = normal.step.cost.total();
  expected_step_length_ = distance(normal.step.com_start, normal.step.com_end);
}

FootstepPlanner::~FootstepPlanner() = default;

double FootstepPlanner::heuristic(const FootstepState& state, Vec2 goal) const {
  const double remaining = std::max(0.0, distance(state.com, goal) - params().goal_tolerance);
  // On ground, and the climbs on the way there.
  // From the stance foot's ground (the other one's is found when its step is checked).
  const double z = state.foot_heights[1 - static_cast<int>(state.last_foot)];
  return expected_step_cost_ * remaining / expected_step_length_ + climb_to(state.com, z, goal);
}

double FootstepPlanner::climb_to(Vec2 from, double z, Vec2 goal) const {
  const ValidityChecker::Impl& checks = validity_.impl();
  if (!checks.on_ground()) return 0.0;
  // Found once for each 0.1 m cell of `from` and level, from its middle (the
  // same value whatever found it first, on any thread).
  constexpr double kCell = 0.1;  // [m]
  thread_local std::unordered_map<std::uint64_t, double> climbs;
  thread_local Vec2 climbs_to{std::numeric_limits<double>::quiet_NaN(), 0.0};
  if (!(climbs_to == goal) || climbs.size() > kMostClimbs) {
    climbs.clear();
    climbs_to = goal;
  }
  const auto ix = static_cast<std::int64_t>(std::floor(from.x / kCell));
  const auto iy = static_cast<std::int64_t>(std::floor(from.y / kCell));
  const std::uint64_t level = level_bucket(z, checks.character_.body_height);
  const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(ix)) << 32 |
                             static_cast<std::uint32_t>(iy)) ^
                            level << 50;
  const auto found = climbs.find(key);
  if (found != climbs.end()) return found->second;
  const Vec2 middle{(static_cast<double>(ix) + 0.5) * kCell,
                    (static_cast<double>(iy) + 0.5) * kCell};
  return climbs.emplace(key, checks.climb_cost(middle, z, goal)).first->second;
}

void FootstepPlanner::land_on_ground(Search& search, int index, Vec2 goal) const {
  const Node& node = search.nodes[index];
  if (node.landed || node.step.kind != StepKind::kWalk) return;
  const ValidityChecker::Impl& checks = validity_.impl();
  const int parent = node.parent;
  const FootstepState before = search.nodes[parent].state;
  const Footstep off = node.step;
  // The foot lands half the chord ahead: a speed 2 d / T faster lands it d further.
  for (const double sign : {1.0, -1.0}) {
    for (const double shift : kLandingShifts) {
      const StepResult next = create_footstep(
          before,
          {StepKind::kWalk, off.foot, off.phi, off.speed + sign * 2.0 * shift / off.duration(),
           off.duration()},
          checks.character_);
      Footstep step = next.step;
      if (!next.valid() || (search.whole && !search.whole->label(step)) ||
          checks.off_ground(step, before))
        continue;
      search.push(Node{next.state, search.nodes[parent].g + step.cost.total(),
                       heuristic(next.state, goal), parent, step, true},
                  params().heuristic_weight);
      ++search.generated;
      break;
    }
  }
}

// Generates the successors of node `index`: every tabled action and the
// goal-directed one for each foot that may step, and the stop.
void FootstepPlanner::expand(Search& search, int index, Vec2 goal) const {
  const ValidityChecker::Impl& checks = validity_.impl();
  const CharacterParams& character = checks.character_;
  const PlannerParams& params = checks.params_;
  const FootstepState state = search.nodes[index].state;
  const double g = search.nodes[index].g;
  const detail::Heading heading = detail::heading_of(state);
  // `speed` and `heading_after` place the state in its cell of the seen-set.
  const auto add = [&](const StepResult& next, double speed, double heading_after) {
    if (!next.valid()) return;
    // On a way with narrower sections, each step takes its section's
    // behaviour (the arms in narrow its torso); inside a side-step section
    // only lateral steps, and the stops between them, go.
    Footstep step = next.step;
    if (search.whole && !search.whole->label(step)) return;
    if (!search.seen.insert(state_key(next.state.com, heading_after, speed,
                                      next.state.standing(), next.step.foot,
                                      stance_level(next.state, character.body_height)))
             .second) {
      return;
    }
    search.push(Node{next.state, g + step.cost.total(), heuristic(next.state, goal), index, step},
                params.heuristic_weight);
    ++search.generated;
  };

  const double goal_angle = angle_of(goal - state.com);
  for (const Foot foot : {Foot::kLeft, Foot::kRight}) {
    if (!state.standing() && foot == state.last_foot) continue;
    // Where a search starts standing after its plan's steps, the foot that
    // stepped last sets off only if the other had nothing to swing into: a
    // plan made before may have it swing through that step, and others may
    // have planned against that (a start keeps it planted there).
    if (index == 0 && state.standing() && foot == state.last_foot && !state.before_first_step &&
        !feet_together(state, character))
      continue;
    const double inward = -outward_sign(foot);
    checks.tabled_walks(state, foot,
                 [&](const StepResult& next, double phi, const detail::StepShape& shape) {
                   add(next, shape.speed, phi + inward * shape.turn);
                   return false;
                 });
    const OrientationInterval reach =
        reachable_orientations(state.foot_orientation[static_cast<int>(other(foot))], other(foot),
                               character.max_foot_turn);
    // The goal-directed phi aims the step's chord at the goal.
    const double goal_turn = inward * wrap_angle(goal_angle - heading.angle);
    if (!(goal_turn > 0.0 && goal_turn < 0.5 * kPi)) continue;
    bool tabled = false;
    for (const double turn : params.turn_angles)
      tabled = tabled || std::fabs(turn - goal_turn) < kDuplicateTurn;
    if (tabled) continue;
    const FootLimits& limits = foot == Foot::kLeft ? character.left : character.right;
    for (const Gait& gait : params.gaits) {
      const detail::StepShape shape =
          detail::step_shape(gait.speed, gait.duration, goal_turn, character);
      if (detail::check_limits(shape, limits) != StepValidity::kValid) continue;
      const double phi = wrap_angle(heading.angle + inward * goal_turn);
      add(detail::walk_step(state, foot, heading, shape, phi, reach, character), gait.speed,
          phi + inward * goal_turn);
    }
  }
  // The stop (a wait when standing), and from standing the pivots.
  const Foot stop_foot = other(state.last_foot);
  const auto add_stop = [&](double phi) {
    add(create_footstep(state, {StepKind::kStop, stop_foot, phi, 0.0, params.stop_duration}, character), 0.0,
        phi);
  };
  // Beside a narrower section's way, squared up to it: a passage barely
  // wider than the body takes the body turned square to it (across it to
  // side-step; in an arms-in section along it too, to walk) and on its way
  // to within millimetres, which the tabled pivots and the steps toward the
  // goal reach only by chance. Before the tabled pivots, so that one of
  // those in the same cell of the seen-set gives way to it.
  const SectionLookup* sections = search.whole ? search.whole->sections : nullptr;
  const std::optional<WayLine> way =
      sections && state.standing() ? sections->narrower_way(state.com) : std::nullopt;
  if (way) {
    const auto square_up = [&](double square) {
      const double off = wrap_angle(square - state.facing);
      // The nearer way round.
      const double turn = std::fabs(off) <= 0.5 * kPi ? off : wrap_angle(off - kPi);
      if (std::fabs(turn) > kDuplicateTurn) add_stop(wrap_angle(state.facing + turn));
    };
    const double along = angle_of(way->direction);
    square_up(along + 0.5 * kPi);
    if (way->behavior == Behavior::kArmsIn) square_up(along);
  }
  for (const double turn : {0.0, kPivotTurn, -kPivotTurn, kMaxPivot, -kMaxPivot}) {
    if (turn != 0.0 && !state.standing()) break;
    add_stop(wrap_angle(state.facing + turn));
  }
  if (search.fine_pivots && state.standing())
    for (const double turn : {0.5 * kPivotTurn, -0.5 * kPivotTurn})
      add_stop(wrap_angle(state.facing + turn));
  // And the side steps (the foot that stepped last trails): straight across,
  // and toward the goal as far as the skew a side step allows, when it lies
  // on that side (as the goal-directed phi of a walk: a crowd's way through a
  // gap narrower than the shoulders leads to a local goal in sight beyond it;
  // out of a slot's end, toward a goal round the corner).
  if (!state.standing()) return;
  const auto add_side_step = [&](double direction) {
    add(checks.side_step(state, direction), kSideStepSpeed, state.facing);
  };
  const double across = wrap_angle(state.facing + outward_sign(stop_foot) * 0.5 * kPi);
  add_side_step(across);
  const double skew = wrap_angle(goal_angle - across);
  if (std::fabs(skew) > kDuplicateTurn && std::fabs(skew) < 0.5 * kPi)
    add_side_step(wrap_angle(across + std::clamp(skew, -kMaxSideStepSkew, kMaxSideStepSkew)));
  if (!way) return;
  // The side step that lands on the way, one side step along it (as near as
  // the skew allows).
  const double travel = 0.5 * kSideStepSpeed * params.stop_duration;
  const double aside = cross(way->direction, state.com - way->nearest);
  const double onto = std::sqrt(std::max(0.0, travel * travel - aside * aside));
  const double toward = angle_of(way->nearest + onto * way->direction - state.com);
  if (std::fabs(wrap_angle(toward - across)) > kDuplicateTurn &&
      std::fabs(wrap_angle(toward - goal_angle)) > kDuplicateTurn)
    add_side_step(toward);
}

std::optional<WholeBody> FootstepPlanner::whole_body(const SectionLookup* sections) const {
  if (body_ == nullptr) return std::nullopt;
  return WholeBody{sections, body_};
}

SearchResult FootstepPlanner::plan(const FootstepState& start, Vec2 goal,
                                   const MovingObstacles& others,
                                   const SearchOptions& options) const {
  const ValidityChecker::Impl& checks = validity_.impl();
  const CharacterParams& character = checks.character_;
  const PlannerParams& params = checks.params_;
  if (options.horizon < 0) throw std::invalid_argument("horizon: must be >= 0");
  if (!(options.rest_grace >= 0.0)) throw std::invalid_argument("rest_grace: must be >= 0");
  if (options.stall < 0) throw std::invalid_argument("stall: must be >= 0");
  const int horizon = options.horizon > 0 ? options.horizon : params.max_expansions;
  const int stall = options.stall > 0 ? options.stall : params.stall_expansions;
  const KeepOut& keep_out = options.keep_out;
  if (!in_world(start.com) || !is_finite(start.com_velocity) || !std::isfinite(start.facing) ||
      !in_world(start.feet[0]) || !in_world(start.feet[1]) || !std::isfinite(start.time)) {
    throw std::invalid_argument("start: the state must be finite and within 1e9 m of the origin");
  }
  if (!in_world(goal))
    throw std::invalid_argument("goal: must be finite and within 1e9 m of the origin");
  SearchResult result;
  result.end_state = start;
  const std::optional<WholeBody> following = whole_body(options.sections);
  const WholeBody* whole = following ? &*following : nullptr;
  if (checks.collides(start, whole)) {
    result.status = Status::kInvalidStart;
    return result;
  }
  if (checks.obstacles_.overlaps({goal, 0.0})) {
    result.status = Status::kInvalidGoal;
    return result;
  }

  // Scratch memory is kept per thread, so that searches do not allocate.
  thread_local Search search;
  search.nodes.clear();
  search.open.clear();
  search.generated = 0;
  search.others.reset(others, character, start.time);
  search.others.set_rest_grace(options.rest_grace);
  search.whole = following;
  search.fine_pivots = options.fine_pivots;
  search.seen.clear();
  const detail::Heading start_heading = detail::heading_of(start);
  search.seen.insert(state_key(start.com, start_heading.angle, start_heading.speed,
                               start.standing(), start.last_foot,
                               stance_level(start, checks.character_.body_height)));
  search.push(Node{start, 0.0, heuristic(start, goal), -1, Footstep{}}, params.heuristic_weight);

  int goal_node = -1;
  std::vector<int> closed;                                   // expanded nodes, the root excluded
  double nearest = std::numeric_limits<double>::infinity();  // the lowest h expanded
  int nearest_at = 0;
  while (!search.open.empty() && result.nodes_expanded < horizon &&
         search.nodes.size() < kMaxSearchNodes) {
    const int current = search.pop();
    // Collisions are checked lazily, when a node is taken off the open list:
    // most generated nodes are never expanded. With a body, every step is
    // tested whole, in 3-D, and its shoulders against obstacles only so.
    if (current != 0) {
      Footstep& step = search.nodes[current].step;
      const FootstepState& before = search.nodes[search.nodes[current].parent].state;
      if (const auto foothold = checks.foothold(step, before);
          foothold != FootholdFault::kNone) {
        if (foothold == FootholdFault::kUnsupported)
          land_on_ground(search, current, goal);
        continue;
      }
      checks.place_on_ground(step, before, search.nodes[current].state);
      // The ground's cost is found for the steps taken off the open list
      // only: one that changes is put back at its true cost.
      if (!search.nodes[current].costed) {
        search.nodes[current].costed = true;
        step.cost.terrain = checks.ground_cost(step, before);
        if (step.cost.terrain != 0.0) {
          Node again = search.nodes[current];
          again.g += step.cost.terrain;
          search.push(std::move(again), params.heuristic_weight);
          continue;
        }
      }
      if (!passes_others(checks, step, before, search.others) ||
          checks.hits_obstacles(step, whole != nullptr && whole->shoulders_in_3d()) ||
          (whole != nullptr && !whole->passes(step, before)))
        continue;
    }
    ++result.nodes_expanded;
    // At the goal, and able to come to rest there among the others (whose
    // rests may already stand on it), free to set off again (a local goal is
    // where the next search starts), unless it leaves there.
    if (distance(search.nodes[current].state.com, goal) <= params.goal_tolerance &&
        (current == 0 || options.leaves ||
         checks.rests_well(search.nodes[current].state, search.others, keep_out, whole))) {
      goal_node = current;
      break;
    }
    if (current != 0) closed.push_back(current);
    // Nothing nearer the goal for `stall` nodes: more of them would fill the
    // same dead end (in a queue at a door, most of a search's time).
    if (search.nodes[current].h < nearest) {
      nearest = search.nodes[current].h;
      nearest_at = result.nodes_expanded;
    } else if (stall > 0 && result.nodes_expanded - nearest_at >= stall) {
      break;
    }
    expand(search, current, goal);
  }
  result.nodes_generated = search.generated;

  const auto& nodes = search.nodes;
  int end = goal_node;
  if (goal_node >= 0) {
    result.status = Status::kSuccess;
  } else if (options.reach_or_nothing) {
    result.status = Status::kNoPath;
  } else {
    // Horizon: the closed node with the best heuristic that the character can
    // still stop from, free to set off where it stops, so that the worst
    // case is a sequence of stop steps and the next search is not trapped.
    result.status = Status::kPartial;
    std::stable_sort(closed.begin(), closed.end(),
                     [&](int a, int b) { return nodes[a].h < nodes[b].h; });
    // A standing character goes only where it gets nearer, unless it stands
    // where it must not stay (another waits to pass there).
    const bool must_move = start.standing() && !checks.keeps_out(start, keep_out);
    for (const int candidate : closed) {
      if ((!start.standing() || must_move || nodes[candidate].h < nodes[0].h) &&
          checks.rests_well(nodes[candidate].state, search.others, keep_out, whole)) {
        end = candidate;
        break;
      }
    }
    // Nothing better than the start: a standing character waits.
    if (end < 0) {
      const StepResult wait =
          start.standing() ? checks.stop_step(start, params.stop_duration, search.others,
                                              whole)
                           : StepResult{};
      if (start.standing() && wait.valid()) {
        result.footsteps.push_back(wait.step);
        result.end_state = wait.state;
      } else {
        result.status = Status::kNoPath;
      }
    }
  }
  if (end >= 0) {
    for (int i = end; i > 0; i = nodes[i].parent)
      result.footsteps.push_back(nodes[i].step);
    std::reverse(result.footsteps.begin(), result.footsteps.end());
    result.end_state = nodes[end].state;
  }
  if (options.rest_grace != std::numeric_limits<double>::infinity())
    cut_before_rests(checks, start, search.others, result);

  split_set_offs(result.footsteps, start);
  choose_foot_orientations(result.footsteps, start.foot_orientation, character);
  result.refused_by = search.others.refusers();
  return result;
}

void choose_foot_orientations(std::vector<Footstep>& steps,
                              const std::array<OrientationInterval, 2>& initial,
                              const CharacterParams& character) {
  // Each step is constrained by the last earlier step of the other foot, its
  // "previous" step (-1: the initial stance of that foot). A start keeps its
  // foot as the last earlier step of that foot placed it (`same`).
  const int n = static_cast<int>(steps.size());
  std::vector<int> previous(n, -1), same(n, -1);
  std::array<int, 2> last{-1, -1};
  for (int k = 0; k < n; ++k) {
    previous[k] = last[static_cast<int>(other(steps[k].foot))];
    same[k] = last[static_cast<int>(steps[k].foot)];
    last[static_cast<int>(steps[k].foot)] = k;
  }
  // Backward: narrow every interval by what its successors can still reach.
  std::vector<OrientationInterval> interval(n);
  for (int k = 0; k < n; ++k) interval[k] = steps[k].orientation_interval;
  for (int k = n - 1; k >= 0; --k) {
    if (steps[k].kind == StepKind::kStart && same[k] >= 0)
      intersect(interval[same[k]], interval[k], steps[k].foot, &interval[same[k]]);
    const int p = previous[k];
    if (p < 0) continue;
    const OrientationInterval reach =
        reachable_orientations(interval[k], steps[k].foot, character.max_foot_turn);
    intersect(interval[p], reach, steps[p].foot, &interval[p]);
  }
  // Forward: turn each foot as close to its phi as the chosen previous foot
  // allows. A start keeps its foot as it stands.
  std::array<double, 2> standing{initial[0].inner, initial[1].inner};
  for (int k = 0; k < n; ++k) {
    const Foot foot = steps[k].foot;
    if (steps[k].kind == StepKind::kStart) {
      steps[k].foot_orientation = standing[static_cast<int>(foot)];
      continue;
    }
    const int p = previous[k];
    const OrientationInterval previous_choice =
        p < 0 ? initial[static_cast<int>(other(foot))]
              : OrientationInterval{steps[p].foot_orientation, steps[p].foot_orientation};
    OrientationInterval allowed = interval[k];
    intersect(interval[k],
              reachable_orientations(previous_choice, other(foot), character.max_foot_turn), foot,
              &allowed);
    steps[k].foot_orientation = clamp_orientation(steps[k].phi, allowed, foot);
    standing[static_cast<int>(foot)] = steps[k].foot_orientation;
  }
}

}  // namespace footfall
