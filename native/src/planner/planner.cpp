#include "footfall/planner/planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "model/contact.hpp"
#include "footfall/plan/plan.hpp"
#include "model/footstep_shape.hpp"
#include "util/huge_page_allocator.hpp"
#include "planner/sampled_agents.hpp"

namespace footfall {
namespace {

// Two generated states that fall in the same cell of (COM 4 cm, velocity
// heading 4 degrees, speed 0.1 m/s, standing, last foot) are treated as one:
// the later one is dropped. This keeps the search from re-expanding
// near-identical states.
constexpr double kCellPosition = 0.04;
constexpr double kCellHeading = 4.0 * kPi / 180.0;
constexpr double kCellSpeed = 0.1;
constexpr double kDuplicateTurn = 1e-3;    // [rad] goal-directed turn equal to a tabled one
constexpr double kPivotTurn = 0.25 * kPi;  // [rad] the smaller pivot the search tries
// [m/s] the side steps' speed: with the stop duration (0.5 s), 0.25 m across.
constexpr double kSideStepSpeed = 1.0;

std::uint64_t state_key(Vec2 com, double heading, double speed, bool standing, Foot last_foot) {
  // Clamped before the conversion, so that far-away coordinates stay defined.
  const auto q = [](double v, double cell) {
    return static_cast<std::uint64_t>(
        static_cast<std::int64_t>(std::clamp(std::floor(v / cell), -1e15, 1e15)));
  };
  // Bit 63 set: 0 marks an empty slot of the table below.
  return (q(com.x, kCellPosition) & 0xFFFF) | (q(com.y, kCellPosition) & 0xFFFF) << 16 |
         (q(wrap_angle(heading) + kPi, kCellHeading) & 0x7F) << 32 |
         (q(speed, kCellSpeed) & 0xFF) << 39 | (standing ? 1ull : 0ull) << 47 |
         static_cast<std::uint64_t>(last_foot) << 48 | 1ull << 63;
}

// Open-addressing set of state keys, reused from search to search. Each
// search starts with a table for a typical search's keys (a few hundred) that
// doubles if more come. Sized for the horizon instead, it was 128 KB to zero
// for every full search, and reallocated whenever a blocked agent's shorter
// horizon alternated with the full one. The memory is kept, never handed back.
class KeySet {
 public:
  void clear() {
    used_ = kFirstSize;
    if (slots_.size() < used_) slots_.resize(used_);
    std::fill_n(slots_.begin(), used_, 0);
    size_ = 0;
  }
  // True if `key` was not there yet.
  bool insert(std::uint64_t key) {
    if (2 * (size_ + 1) > used_) grow();
    const size_t mask = used_ - 1;
    for (size_t i = mix(key) & mask;; i = (i + 1) & mask) {
      if (slots_[i] == key) return false;
      if (slots_[i] == 0) {
        slots_[i] = key;
        ++size_;
        return true;
      }
    }
  }

 private:
  static constexpr size_t kFirstSize = 2048;
  static size_t mix(std::uint64_t key) {
    key ^= key >> 33;
    key *= 0xFF51AFD7ED558CCDull;
    return static_cast<size_t>(key ^ (key >> 33));
  }
  void grow() {
    old_.assign(slots_.begin(), slots_.begin() + static_cast<std::ptrdiff_t>(used_));
    used_ *= 2;
    if (slots_.size() < used_) slots_.resize(used_);
    std::fill_n(slots_.begin(), used_, 0);
    size_ = 0;
    for (const std::uint64_t key : old_) {
      if (key != 0) insert(key);
    }
  }
  LargeVector<std::uint64_t> slots_;  ///< The first used_ are the table.
  std::vector<std::uint64_t> old_;    ///< The keys being rehashed.
  size_t used_ = kFirstSize;
  size_t size_ = 0;
};

// A disc that holds the torso throughout the step, grown by `margin`: the
// whole step's COM lies within half the chord plus the sway of the chord's
// midpoint.
Circle sweep_bound(const Footstep& step, const CharacterParams& character, double margin) {
  const double chord = distance(step.com_start, step.com_end);
  const double sway = step.alpha * step.duration() * step.duration() / 4.0;
  return {0.5 * (step.com_start + step.com_end),
          0.5 * chord + sway + 0.5 * character.torso_width + margin};
}

// `others` sampled from time `from` on, for a check outside a search (which
// keeps its own samples for all its steps).
detail::SampledAgents& sampled(const MovingObstacles& others, const CharacterParams& character,
                               double from) {
  thread_local detail::SampledAgents samples;
  samples.reset(others, character, from);
  return samples;
}

// A character standing at a state, checked against other agents' plans from
// the state's time on, with room to turn on the spot, as room_to_turn() asks
// of static obstacles: two agents resting face to face a few centimetres
// apart could never step again, every turn swinging a shoulder into the other.
class StandingCheck {
 public:
  StandingCheck(const FootstepState& state, const CharacterParams& character)
      : com_(state.com),
        mine_{Circle{state.com, 0.5 * character.torso_width},
              Circle{state.feet[0], character.foot_radius},
              Circle{state.feet[1], character.foot_radius}},
        first_(first_contact_instant(state.time)) {
    extent_ = mine_.front().radius + kRestRoom;
    for (const Circle& circle : mine_)
      extent_ = std::max(extent_, distance(circle.center, com_) + circle.radius);
  }

  // True if it touches agent j of `others` (sampled from the state's time).
  bool touches(detail::SampledAgents& others, std::size_t j) const {
    // After its plan ends, the other stands too: the first instant from then
    // on is the last that can differ.
    const long last = std::max(first_, first_contact_instant(others.plan(j).end_time()));
    const double span = static_cast<double>(last - first_) * kContactDt;
    const PlanBounds::From& bounds = others.bounds(j);
    const double near = extent_ + bounds.reach + 0.5 * bounds.top_speed * kContactDt;
    if (squared_distance(bounds.com_box, {com_, com_}) > near * near) return false;
    if (distance(others.at(j, first_).com, com_) > near + bounds.top_speed * span) return false;
    double start_gap = std::numeric_limits<double>::infinity();  // see touching()
    for (long k = first_; k <= last; ++k) {
      const detail::AgentWhere& them = others.at(j, k);
      if (!them.present) break;  // gone for good
      if (distance(them.com, com_) > near) continue;
      const detail::AgentShape& shape = others.shape(j, k);
      const double pad = 0.5 * them.speed * kContactDt;
      if (k != first_ && distance(them.com, com_) - extent_ - shape.extent - pad > 0.0) continue;
      // Room kept from those standing still (the torso disc only).
      const double room = standing_still(0.0, them.speed) ? kRestRoom : 0.0;
      Gap gap;
      for (int i = 0; i < shape.count; ++i)
        for (std::size_t m = 0; m < mine_.size(); ++m) {
          Circle circle = mine_[m];
          if (m == 0) circle.radius += room;
          gap.add(circle, shape.circles[i], pad);
        }
      if (k == first_ && standing_still(0.0, them.speed)) start_gap = gap.outright;
      if (touching(gap, start_gap)) return true;
    }
    return false;
  }

 private:
  Vec2 com_;
  std::array<Circle, 3> mine_;  // the torso disc and the feet
  double extent_ = 0.0;         // how far they reach from the COM, room included
  long first_ = 0;
};

}  // namespace

struct FootstepPlanner::TabledAction {
  detail::StepShape shape;
  std::array<bool, 2> allowed{};  // within each foot's limits
};

// A search node: the state reached and the action that reached it; the step
// itself is rebuilt (bit for bit) when needed.
struct FootstepPlanner::Node {
  FootstepState state;
  double g = 0;
  double h = 0;
  int parent = -1;
  Footstep step;  ///< From the parent's state (none at the root): checked when popped.
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
  KeySet seen;
  detail::SampledAgents others;  // the plans the search avoids
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
                                 const ObstacleMap& obstacles)
    : character_(character), params_(planner), obstacles_(obstacles) {
  validate(character_);
  validate(params_);
  for (const Gait& gait : params_.gaits) {
    for (const double turn : params_.turn_angles) {
      TabledAction action{detail::step_shape(gait.speed, gait.duration, turn, character_), {}};
      action.allowed[0] =
          detail::check_limits(action.shape, character_.left) == StepValidity::kValid;
      action.allowed[1] =
          detail::check_limits(action.shape, character_.right) == StepValidity::kValid;
      if (action.allowed[0] || action.allowed[1]) actions_.push_back(action);
    }
  }
  // A normal step, through the model itself: straight, at the preferred speed
  // and duration, in steady walking (incoming at the same speed), the incoming
  // heading turned outward from phi by the smallest turn angle; by the right
  // foot, or by the left if only it may take such a step (a limp).
  const double turn = *std::min_element(params_.turn_angles.begin(), params_.turn_angles.end());
  StepResult normal;
  for (const Foot foot : {Foot::kRight, Foot::kLeft}) {
    FootstepState walking = standing_state({0.0, 0.0}, 0.0, character_);
    walking.com_velocity = character_.preferred_speed * unit(outward_sign(foot) * turn);
    walking.last_foot = other(foot);
    normal = create_footstep(walking,
                             {StepKind::kWalk, foot, 0.0, character_.preferred_speed,
                              character_.preferred_step_duration},
                             character_);
    if (normal.valid()) break;
  }
  if (!normal.valid()) {
    const bool duration = normal.validity == StepValidity::kDurationOutOfRange;
    throw std::invalid_argument(
        std::string(duration ? "character.preferred_step_duration" : "character.preferred_speed") +
        ": a step at the preferred speed and duration breaks both feet's limits (" +
        to_string(normal.validity) + ")");
  }
  for (const Circle& circle : torso_circles({0.0, 0.0}, 0.0, character_))
    torso_extent_ = std::max(torso_extent_, length(circle.center) + circle.radius);
  expected_step_cost_ = normal.step.cost.total();
  expected_step_length_ = distance(normal.step.com_start, normal.step.com_end);
}

FootstepPlanner::~FootstepPlanner() = default;

double FootstepPlanner::heuristic(const FootstepState& state, Vec2 goal) const {
  const double remaining = std::max(0.0, distance(state.com, goal) - params_.goal_tolerance);
  return expected_step_cost_ * remaining / expected_step_length_;
}

bool FootstepPlanner::collides(const FootstepState& state) const {
  for (const Vec2& foot : state.feet) {
    if (obstacles_.overlaps({foot, character_.foot_radius})) return true;
  }
  for (const Circle& circle : torso_circles(state.com, state.facing, character_)) {
    if (obstacles_.overlaps(circle)) return true;
  }
  return false;
}

bool FootstepPlanner::collides(const Footstep& step, const MovingObstacles& others) const {
  return collides(step, sampled(others, character_, step.start_time), false);
}

bool FootstepPlanner::collides(const Footstep& step, detail::SampledAgents& others,
                               bool from_standing) const {
  // Agents first: in a crowd they turn down most candidate steps.
  return touches_agents(step, others, from_standing) || hits_obstacles(step);
}

bool FootstepPlanner::hits_obstacles(const Footstep& step) const {
  if (obstacles_.overlaps({step.foot_position, character_.foot_radius})) return true;
  // Samples no further apart along the COM path than `spacing`: the path is
  // never longer than speed * time between samples, where the COM speed of a
  // walking step is at most its speed at either end.
  const double top_speed = std::max(length(step.com_velocity_start), length(step.com_velocity_end));
  const double spacing = params_.collision_sample_spacing;
  // The circles are grown by half the spacing, the COM's travel to the
  // nearest sample. A step that does not move the COM (a wait, or a pivot,
  // whose shoulders swing within the room to turn its rest kept) needs none:
  // grown, a pivot by a wall it stands 0.3 m from would never be clear.
  const double pad = top_speed > 0.0 ? 0.5 * spacing : 0.0;
  thread_local std::vector<int> near;
  near.clear();
  obstacles_.gather(sweep_bound(step, character_, pad), near);
  if (near.empty()) return false;
  const int samples =
      std::max(1, static_cast<int>(std::ceil(top_speed * step.duration() / spacing)));
  const double dt = step.duration() / samples;
  // The torso keeps its facing through the step: its circles' offsets from
  // the COM are found once.
  const auto torso = torso_circles({0.0, 0.0}, step.phi, character_, pad);
  for (int i = 0; i <= samples; ++i) {
    const Vec2 com = com_at(step, step.start_time + dt * i).position;
    for (const Circle& offset : torso)
      if (obstacles_.first_overlap({com + offset.center, offset.radius}, near) >= 0) return true;
  }
  return false;
}

bool FootstepPlanner::touches_agents(const Footstep& step, detail::SampledAgents& others,
                                     bool from_standing) const {
  // The contact instants while the step is under way; the one at its end
  // belongs to the next step.
  const long first = first_contact_instant(step.start_time);
  const long last = first_contact_instant(step.end_time) - 1;
  if (others.size() == 0 || last < first) return false;
  // Agents that cannot come near the step at one of its instants are left out
  // before sampling: between the middle instant and the step's ends, a COM
  // moves at most at the top speed of its plan, and its circles reach no
  // farther from it than its plan's circle_reach.
  const long middle = first + (last - first) / 2;
  const double span = static_cast<double>(last - middle) * kContactDt;
  const Circle sweep = sweep_bound(step, character_, 0.0);
  const Circle foot{step.foot_position, character_.foot_radius};
  const double my_reach = std::max(sweep.radius, distance(foot.center, sweep.center) + foot.radius);
  const double my_top_speed =
      std::max(length(step.com_velocity_start), length(step.com_velocity_end));
  const auto may_come_near = [&](std::size_t j) {
    const PlanBounds::From& bounds = others.bounds(j);
    const double pad = 0.5 * (my_top_speed + bounds.top_speed) * kContactDt;
    const double close = my_reach + bounds.reach + pad;
    // Its COM keeps out of a box: far from that, it needs no sample.
    if (squared_distance(bounds.com_box, {sweep.center, sweep.center}) > close * close)
      return false;
    const double reach = close + bounds.top_speed * span;
    const Vec2 d = others.at(j, middle).com - sweep.center;
    return dot(d, d) <= reach * reach;
  };
  // The character at each instant, sampled when first wanted: COM, speed,
  // torso circles, and how far those and the foot reach from the COM.
  struct Instant {
    bool sampled = false;
    Vec2 com;
    double speed = 0.0;
    std::array<Circle, 3> torso;
    double extent = 0.0;
  };
  thread_local std::vector<Instant> mine;
  mine.assign(static_cast<std::size_t>(last - first + 1), Instant{});
  const auto torso_offsets = torso_circles({0.0, 0.0}, step.phi, character_);  // as above
  const auto instant = [&](long k) -> const Instant& {
    Instant& sample = mine[static_cast<std::size_t>(k - first)];
    if (!sample.sampled) {
      const ComSample me = com_at(step, static_cast<double>(k) * kContactDt);
      sample = {true, me.position, length(me.velocity), torso_offsets,
                std::max(torso_extent_, distance(foot.center, me.position) + foot.radius)};
      for (Circle& circle : sample.torso) circle.center = me.position + circle.center;
    }
    return sample;
  };
  // A step from standing that starts on an instant starts where the
  // character stood: it stood still there, whatever speed the step sets off at.
  const bool stood_at_first =
      from_standing && std::fabs(static_cast<double>(first) * kContactDt - step.start_time) < 1e-9;
  // True if the character touches agent j at instant k, if j counts then
  // (up to `counted_until`; its circles reach `reach`); the first instant
  // sets `start_gap` (see touching()), which the later ones need.
  const auto touches_at = [&](std::size_t j, long k, double counted_until, double reach,
                              double& start_gap) {
    const detail::AgentWhere& them = others.at(j, k);
    if (!them.present || static_cast<double>(k) * kContactDt > counted_until) return false;
    const Instant& me = instant(k);
    // Both move between instants: the circles are grown by half the travel.
    const double pad = 0.5 * (me.speed + them.speed) * kContactDt;
    const Vec2 between = me.com - them.com;
    const double near = me.extent + reach + pad;
    if (dot(between, between) > near * near) return false;
    const detail::AgentShape& shape = others.shape(j, k);
    // Too far apart for any pair of circles to come within the padding; at
    // the first instant the gap is still wanted for the exception below.
    const double apart = length(between) - me.extent - shape.extent - pad;
    if (k != first && apart > 0.0) return false;
    Gap gap;  // of the torso: the foot is put down clear of everyone, standing close or not
    for (int i = 0; i < shape.count; ++i) {
      const Circle& theirs = shape.circles[i];
      const Vec2 to_foot = foot.center - theirs.center;
      const double foot_touch = foot.radius + theirs.radius + pad;
      if (dot(to_foot, to_foot) <= foot_touch * foot_touch) return true;
      for (const Circle& circle : me.torso) gap.add(circle, theirs, pad);
    }
    if (k == first && standing_still(stood_at_first ? 0.0 : me.speed, them.speed))
      start_gap = gap.outright;
    return touching(gap, start_gap);
  };
  // After the first instant, the last: a step turned down mostly walks into
  // someone as it ends (the one ahead in a queue). Then those between. (One
  // call in one loop, which the compiler inlines.)
  const auto touches = [&](std::size_t j) {
    const double until = others.counted_until(j), reach = others.bounds(j).reach;
    double start_gap = std::numeric_limits<double>::infinity();
    for (long n = 0; n <= last - first; ++n) {
      const long k = n == 0 ? first : n == 1 ? last : first + n - 1;
      if (touches_at(j, k, until, reach, start_gap)) return true;
    }
    return false;
  };
  // The agent that turned down the last step checked is tried first: a
  // search's candidates, siblings and cousins, mostly run into the same one.
  const std::size_t blocker = others.blocker();
  if (blocker < others.size() && may_come_near(blocker) && touches(blocker)) return true;
  for (std::size_t j = 0; j < others.size(); ++j) {
    if (j != blocker && may_come_near(j) && touches(j)) {
      others.turned_down_by(j);
      return true;
    }
  }
  return false;
}

Rest FootstepPlanner::come_to_rest(const FootstepState& state,
                                   const MovingObstacles& others) const {
  return come_to_rest(state, sampled(others, character_, state.time));
}

Rest FootstepPlanner::come_to_rest(const FootstepState& state,
                                   detail::SampledAgents& others) const {
  Rest rest{{}, state, false};
  const auto stop = [&] {
    double duration = params_.stop_duration;
    for (int attempt = 0; attempt < 4; ++attempt, duration *= 0.5) {
      const StepResult step = stop_step(rest.state, duration, others);
      if (step.valid()) {
        rest.steps.push_back(step.step);
        rest.state = step.state;
        return true;
      }
    }
    return false;
  };
  rest.complete = (rest.state.standing() || stop()) && stop() && stands_clear(rest.state, others);
  return rest;
}

bool FootstepPlanner::stands_clear(const FootstepState& state,
                                   const MovingObstacles& others) const {
  return stands_clear(state, sampled(others, character_, state.time));
}

bool FootstepPlanner::stands_clear(const FootstepState& state,
                                   detail::SampledAgents& others) const {
  const StandingCheck check(state, character_);
  // As in touches_agents: the agent that turned down the last check first.
  const std::size_t blocker = others.blocker();
  if (blocker < others.size() && check.touches(others, blocker)) return false;
  for (std::size_t j = 0; j < others.size(); ++j) {
    if (j != blocker && check.touches(others, j)) {
      others.turned_down_by(j);
      return false;
    }
  }
  return true;
}

std::vector<char> FootstepPlanner::stands_clear_of_each(const FootstepState& state,
                                                        const MovingObstacles& others) const {
  detail::SampledAgents& samples = sampled(others, character_, state.time);
  const StandingCheck check(state, character_);
  std::vector<char> clear(others.size());
  for (std::size_t j = 0; j < others.size(); ++j) clear[j] = !check.touches(samples, j);
  return clear;
}

std::vector<std::size_t> FootstepPlanner::standing_clear(const std::vector<FootstepState>& states,
                                                         const MovingObstacles& others,
                                                         std::size_t at_most) const {
  std::vector<std::size_t> clear;
  if (states.empty()) return clear;
  detail::SampledAgents& samples = sampled(others, character_, states.front().time);
  for (std::size_t k = 0; k < states.size() && clear.size() < at_most; ++k)
    if (stands_clear(states[k], samples)) clear.push_back(k);
  return clear;
}

bool FootstepPlanner::rests_well(const FootstepState& state, detail::SampledAgents& others,
                                 const KeepOut& keep_out) const {
  const Rest rest = come_to_rest(state, others);
  return rest.complete && keeps_out(rest.state, keep_out) && free_to_set_off(rest.state);
}

bool FootstepPlanner::room_to_turn(Vec2 com) const {
  return !obstacles_.overlaps({com, 0.5 * character_.torso_width});
}

bool FootstepPlanner::keeps_out(const FootstepState& rested, const KeepOut& keep_out) const {
  if (keep_out.empty()) return true;
  const auto torso = torso_circles(rested.com, rested.facing, character_);
  const std::array<Circle, 5> mine{Circle{rested.feet[0], character_.foot_radius},
                                   Circle{rested.feet[1], character_.foot_radius}, torso[0],
                                   torso[1], torso[2]};
  double reach = 0.0;  // of the circles from the COM, with a margin for rounding
  for (const Circle& circle : mine)
    reach = std::max(reach, distance(circle.center, rested.com) + circle.radius + 1e-9);
  for (const Circle& disc : keep_out) {
    const Vec2 d = disc.center - rested.com;
    if (dot(d, d) >= (reach + disc.radius) * (reach + disc.radius)) continue;  // far from all
    for (const Circle& circle : mine)
      if (distance(circle.center, disc.center) < circle.radius + disc.radius) return false;
  }
  return true;
}

StepResult FootstepPlanner::stop_step(const FootstepState& state, double duration,
                                      const MovingObstacles& others) const {
  return stop_step(state, duration, sampled(others, character_, state.time));
}

StepResult FootstepPlanner::stop_step(const FootstepState& state, double duration,
                                      detail::SampledAgents& others) const {
  StepResult stop = create_footstep(
      state, {StepKind::kStop, other(state.last_foot), state.facing, 0.0, duration}, character_);
  if (stop.valid() && collides(stop.step, others, state.standing()))
    stop.validity = StepValidity::kCollides;
  return stop;
}

StepResult FootstepPlanner::stop_step(const FootstepState& state,
                                      const MovingObstacles& others) const {
  return stop_step(state, params_.stop_duration, others);
}

StepResult FootstepPlanner::side_step(const FootstepState& standing, double way) const {
  return create_footstep(
      standing,
      {StepKind::kSideStep, other(standing.last_foot), way, kSideStepSpeed, params_.stop_duration},
      character_);
}

template <class Visit>
bool FootstepPlanner::tabled_walks(const FootstepState& state, Foot foot, Visit&& visit) const {
  const detail::Heading heading = detail::heading_of(state);
  const int f = static_cast<int>(foot);
  const double inward = -outward_sign(foot);
  const OrientationInterval reach = reachable_orientations(
      state.foot_orientation[static_cast<int>(other(foot))], other(foot), character_.max_foot_turn);
  for (const TabledAction& action : actions_) {
    if (!action.allowed[f]) continue;
    const double phi = wrap_angle(heading.angle + inward * action.shape.turn);
    if (visit(detail::walk_step(state, foot, heading, action.shape, phi, reach, character_), phi,
              action.shape))
      return true;
  }
  return false;
}

bool FootstepPlanner::free_to_set_off(const FootstepState& rested) const {
  if (!room_to_turn(rested.com)) return false;
  const auto clear = [&](const StepResult& step, double, const detail::StepShape&) {
    return step.valid() && !hits_obstacles(step.step);
  };
  if (tabled_walks(rested, Foot::kLeft, clear) || tabled_walks(rested, Foot::kRight, clear))
    return true;
  // Or a side step, or a pivot toward a way out (the steps' checks pad the
  // torso, so room to turn alone does not promise one).
  const double across = rested.facing + outward_sign(other(rested.last_foot)) * 0.5 * kPi;
  if (clear(side_step(rested, across), 0.0, {})) return true;
  for (const double turn : {kPivotTurn, -kPivotTurn, kMaxPivot, -kMaxPivot}) {
    const StepResult pivot = create_footstep(rested,
                                             {StepKind::kStop, other(rested.last_foot),
                                              rested.facing + turn, 0.0, params_.stop_duration},
                                             character_);
    if (clear(pivot, 0.0, {})) return true;
  }
  return false;
}

// Generates the successors of node `index`: every tabled action and the
// goal-directed one for each foot that may step, and the stop.
void FootstepPlanner::expand(Search& search, int index, Vec2 goal) const {
  const FootstepState state = search.nodes[index].state;
  const double g = search.nodes[index].g;
  const detail::Heading heading = detail::heading_of(state);
  // `speed` and `heading_after` place the state in its cell of the seen-set.
  const auto add = [&](const StepResult& next, double speed, double heading_after) {
    if (!next.valid()) return;
    if (!search.seen.insert(state_key(next.state.com, heading_after, speed,
                                      next.state.standing(), next.step.foot))) {
      return;
    }
    search.push(Node{next.state, g + next.step.cost.total(), heuristic(next.state, goal), index,
                     next.step},
                params_.heuristic_weight);
    ++search.generated;
  };

  const double goal_angle = angle_of(goal - state.com);
  for (const Foot foot : {Foot::kLeft, Foot::kRight}) {
    if (!state.standing() && foot == state.last_foot) continue;
    const double inward = -outward_sign(foot);
    tabled_walks(state, foot,
                 [&](const StepResult& next, double phi, const detail::StepShape& shape) {
                   add(next, shape.speed, phi + inward * shape.turn);
                   return false;
                 });
    const OrientationInterval reach =
        reachable_orientations(state.foot_orientation[static_cast<int>(other(foot))], other(foot),
                               character_.max_foot_turn);
    // The goal-directed phi aims the step's chord at the goal.
    const double goal_turn = inward * wrap_angle(goal_angle - heading.angle);
    if (!(goal_turn > 0.0 && goal_turn < 0.5 * kPi)) continue;
    bool tabled = false;
    for (const double turn : params_.turn_angles)
      tabled = tabled || std::fabs(turn - goal_turn) < kDuplicateTurn;
    if (tabled) continue;
    const FootLimits& limits = foot == Foot::kLeft ? character_.left : character_.right;
    for (const Gait& gait : params_.gaits) {
      const detail::StepShape shape =
          detail::step_shape(gait.speed, gait.duration, goal_turn, character_);
      if (detail::check_limits(shape, limits) != StepValidity::kValid) continue;
      const double phi = wrap_angle(heading.angle + inward * goal_turn);
      add(detail::walk_step(state, foot, heading, shape, phi, reach, character_), gait.speed,
          phi + inward * goal_turn);
    }
  }
  // The stop (a wait when standing), and from standing the pivots.
  const Foot stop_foot = other(state.last_foot);
  for (const double turn : {0.0, kPivotTurn, -kPivotTurn, kMaxPivot, -kMaxPivot}) {
    if (turn != 0.0 && !state.standing()) break;
    const double phi = wrap_angle(state.facing + turn);
    add(create_footstep(state, {StepKind::kStop, stop_foot, phi, 0.0, params_.stop_duration},
                        character_),
        0.0, phi);
  }
  // And the side steps (the foot that stepped last trails): straight across,
  // and toward the goal if it lies within the skew a side step allows (as the
  // goal-directed phi of a walk: a crowd's way through a gap narrower than the
  // shoulders leads to a local goal in sight beyond it).
  if (!state.standing()) return;
  const auto add_side_step = [&](double way) {
    add(side_step(state, way), kSideStepSpeed, state.facing);
  };
  const double across = wrap_angle(state.facing + outward_sign(stop_foot) * 0.5 * kPi);
  add_side_step(across);
  const double skew = std::fabs(wrap_angle(goal_angle - across));
  if (skew > kDuplicateTurn && skew <= kMaxSideStepSkew) add_side_step(goal_angle);
}

SearchResult FootstepPlanner::plan(const FootstepState& start, Vec2 goal,
                                   const MovingObstacles& others,
                                   const SearchOptions& options) const {
  if (options.horizon < 0) throw std::invalid_argument("horizon: must be >= 0");
  if (!(options.rest_grace >= 0.0)) throw std::invalid_argument("rest_grace: must be >= 0");
  if (options.stall < 0) throw std::invalid_argument("stall: must be >= 0");
  const int horizon = options.horizon > 0 ? options.horizon : params_.max_expansions;
  const int stall = options.stall > 0 ? options.stall : params_.stall_expansions;
  const KeepOut& keep_out = options.keep_out;
  if (!in_world(start.com) || !is_finite(start.com_velocity) || !std::isfinite(start.facing) ||
      !in_world(start.feet[0]) || !in_world(start.feet[1]) || !std::isfinite(start.time)) {
    throw std::invalid_argument("start: the state must be finite and within 1e9 m of the origin");
  }
  if (!in_world(goal))
    throw std::invalid_argument("goal: must be finite and within 1e9 m of the origin");
  SearchResult result;
  result.end_state = start;
  if (collides(start)) {
    result.status = Status::kInvalidStart;
    return result;
  }
  if (obstacles_.overlaps({goal, 0.0})) {
    result.status = Status::kInvalidGoal;
    return result;
  }

  // Scratch memory is kept per thread, so that searches do not allocate.
  thread_local Search search;
  search.nodes.clear();
  search.open.clear();
  search.generated = 0;
  search.others.reset(others, character_, start.time);
  search.others.set_rest_grace(options.rest_grace);
  search.seen.clear();
  const detail::Heading start_heading = detail::heading_of(start);
  search.seen.insert(state_key(start.com, start_heading.angle, start_heading.speed,
                               start.standing(), start.last_foot));
  search.push(Node{start, 0.0, heuristic(start, goal), -1, Footstep{}}, params_.heuristic_weight);

  int goal_node = -1;
  std::vector<int> closed;                                   // expanded nodes, the root excluded
  double nearest = std::numeric_limits<double>::infinity();  // the lowest h expanded
  int nearest_at = 0;
  while (!search.open.empty() && result.nodes_expanded < horizon) {
    const int current = search.pop();
    // Collisions are checked lazily, when a node is taken off the open list:
    // most generated nodes are never expanded.
    if (current != 0 && collides(search.nodes[current].step, search.others,
                                 search.nodes[search.nodes[current].parent].state.standing()))
      continue;
    ++result.nodes_expanded;
    // At the goal, and able to come to rest there among the others (whose
    // rests may already stand on it), free to set off again (a local goal is
    // where the next search starts), unless it leaves there.
    if (distance(search.nodes[current].state.com, goal) <= params_.goal_tolerance &&
        (current == 0 || options.leaves ||
         rests_well(search.nodes[current].state, search.others, keep_out))) {
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
  } else {
    // Horizon: the closed node with the best heuristic that the character can
    // still stop from, free to set off where it stops, so that the worst
    // case is a sequence of stop steps and the next search is not trapped.
    result.status = Status::kPartial;
    std::stable_sort(closed.begin(), closed.end(),
                     [&](int a, int b) { return nodes[a].h < nodes[b].h; });
    // A standing character goes only where it gets nearer, unless it stands
    // where it must not stay (another waits to pass there).
    const bool must_move = start.standing() && !keeps_out(start, keep_out);
    for (const int candidate : closed) {
      if ((!start.standing() || must_move || nodes[candidate].h < nodes[0].h) &&
          rests_well(nodes[candidate].state, search.others, keep_out)) {
        end = candidate;
        break;
      }
    }
    // Nothing better than the start: a standing character waits.
    if (end < 0) {
      const StepResult wait =
          start.standing() ? stop_step(start, params_.stop_duration, search.others) : StepResult{};
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
    cut_before_rests(start, search.others, result);
  choose_foot_orientations(result.footsteps, start.foot_orientation, character_);
  result.refused_by = search.others.refusers();
  return result;
}

// The search took walking agents' rests to end after their grace; nothing
// returned may rely on that, so the steps stop before the first that runs
// into one taken for good.
void FootstepPlanner::cut_before_rests(const FootstepState& start, detail::SampledAgents& others,
                                       SearchResult& result) const {
  others.set_rest_grace(std::numeric_limits<double>::infinity());
  FootstepState state = start;
  for (std::size_t k = 0; k < result.footsteps.size(); ++k) {
    const Footstep& step = result.footsteps[k];
    if (touches_agents(step, others, state.standing())) {
      result.footsteps.resize(k);
      result.end_state = state;
      result.status = Status::kPartial;
      return;
    }
    state = state_after(state, step);
  }
}

void choose_foot_orientations(std::vector<Footstep>& steps,
                              const std::array<OrientationInterval, 2>& initial,
                              const CharacterParams& character) {
  // Each step is constrained by the last earlier step of the other foot, its
  // "previous" step (-1: the initial stance of that foot).
  const int n = static_cast<int>(steps.size());
  std::vector<int> previous(n, -1);
  std::array<int, 2> last{-1, -1};
  for (int k = 0; k < n; ++k) {
    previous[k] = last[static_cast<int>(other(steps[k].foot))];
    last[static_cast<int>(steps[k].foot)] = k;
  }
  // Backward: narrow every interval by what its successors can still reach.
  std::vector<OrientationInterval> interval(n);
  for (int k = 0; k < n; ++k) interval[k] = steps[k].orientation_interval;
  for (int k = n - 1; k >= 0; --k) {
    const int p = previous[k];
    if (p < 0) continue;
    const OrientationInterval reach =
        reachable_orientations(interval[k], steps[k].foot, character.max_foot_turn);
    intersect(interval[p], reach, steps[p].foot, &interval[p]);
  }
  // Forward: turn each foot as close to its phi as the chosen previous foot allows.
  for (int k = 0; k < n; ++k) {
    const Foot foot = steps[k].foot;
    const int p = previous[k];
    const OrientationInterval previous_choice =
        p < 0 ? initial[static_cast<int>(other(foot))]
              : OrientationInterval{steps[p].foot_orientation, steps[p].foot_orientation};
    OrientationInterval allowed = interval[k];
    intersect(interval[k],
              reachable_orientations(previous_choice, other(foot), character.max_foot_turn), foot,
              &allowed);
    steps[k].foot_orientation = clamp_orientation(steps[k].phi, allowed, foot);
  }
}

}  // namespace footfall
