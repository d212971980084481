#include "footfall/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>
#include <stdexcept>
#include <string>
#include <unordered_set>

namespace footfall {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Two generated states that fall in the same cell of (COM 4 cm, velocity
// heading 4 degrees, speed 0.1 m/s, last foot) are treated as one: the later
// one is dropped. This keeps the search from re-expanding near-identical states.
constexpr double kCellPosition = 0.04;
constexpr double kCellHeading = 4.0 * kPi / 180.0;
constexpr double kCellSpeed = 0.1;
constexpr double kDuplicateTurn = 1e-3;  // [rad] goal-directed phi equal to a fixed one

struct Node {
  FootstepState state;
  Footstep step;  // the step that led here (unused at the root)
  double g = 0;
  double h = 0;
  int parent = -1;
};

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

std::uint64_t state_key(const FootstepState& s) {
  const auto q = [](double v, double cell) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / cell)) & 0xFFFF);
  };
  const double speed = length(s.com_velocity);
  const double heading = speed > 0.0 ? angle_of(s.com_velocity) : s.facing;
  return q(s.com.x, kCellPosition) | q(s.com.y, kCellPosition) << 16 |
         (q(heading + kPi, kCellHeading) & 0x7F) << 32 | (q(speed, kCellSpeed) & 0xFF) << 39 |
         (s.standing() ? 1ull : 0ull) << 47 | static_cast<std::uint64_t>(s.last_foot) << 48;
}

}  // namespace

FootstepPlanner::FootstepPlanner(const CharacterParams& character, const PlannerParams& planner,
                                 const ObstacleMap& obstacles)
    : character_(character), params_(planner), obstacles_(obstacles) {
  validate(character_);
  validate(params_);
  // A normal step, through the model itself: straight, at the preferred speed
  // and duration, in steady walking (incoming at the same speed), the incoming
  // heading turned outward from phi by the smallest turn angle.
  const double turn = *std::min_element(params_.turn_angles.begin(), params_.turn_angles.end());
  FootstepState walking = standing_state({0.0, 0.0}, 0.0, character_);
  walking.com_velocity = character_.preferred_speed * unit(-turn);
  walking.last_foot = Foot::kLeft;
  const StepResult normal = create_footstep(
      walking,
      {StepKind::kWalk, Foot::kRight, 0.0, character_.preferred_speed,
       character_.preferred_step_duration},
      character_);
  if (!normal.valid()) {
    throw std::invalid_argument(
        std::string("character.preferred_speed: a step at the preferred speed and duration is "
                    "invalid: ") +
        to_string(normal.validity));
  }
  expected_step_cost_ = normal.step.cost.total();
  expected_step_length_ = distance(normal.step.com_start, normal.step.com_end);
}

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

bool FootstepPlanner::collides(const Footstep& step) const {
  if (obstacles_.overlaps({step.foot_position, character_.foot_radius})) return true;
  const double spacing = params_.collision_sample_spacing;
  const double pad = 0.5 * spacing;
  // The whole step's COM lies within half the chord plus the sway of the chord
  // midpoint; one query of that disc clears most steps at once.
  const double chord = distance(step.com_start, step.com_end);
  const double sway = step.alpha * step.duration() * step.duration() / 4.0;
  const Circle bound{0.5 * (step.com_start + step.com_end),
                     0.5 * chord + sway + 0.5 * character_.torso_width + pad};
  if (!obstacles_.overlaps(bound)) return false;
  // Samples no further apart along the COM path than `spacing`: the path is
  // never longer than speed * time between samples, where the COM speed of a
  // walking step is at most its speed at either end.
  const double top_speed = std::max(length(step.com_velocity_start), length(step.com_velocity_end));
  const int samples = std::max(1, static_cast<int>(std::ceil(top_speed * step.duration() / spacing)));
  for (int i = 0; i <= samples; ++i) {
    const double t = step.start_time + step.duration() * i / samples;
    for (const Circle& circle : torso_circles(com_at(step, t).position, step.phi, character_, pad)) {
      if (obstacles_.overlaps(circle)) return true;
    }
  }
  return false;
}

StepResult FootstepPlanner::stop_step(const FootstepState& state, double duration) const {
  StepResult stop = create_footstep(
      state, {StepKind::kStop, other(state.last_foot), state.facing, 0.0, duration}, character_);
  if (stop.valid() && collides(stop.step)) stop.validity = StepValidity::kCollides;
  return stop;
}

StepResult FootstepPlanner::stop_step(const FootstepState& state) const {
  return stop_step(state, params_.stop_duration);
}

SearchResult FootstepPlanner::plan(const FootstepState& start, Vec2 goal) const {
  SearchResult result;
  result.end_state = start;
  if (collides(start)) {
    result.status = Status::kInvalidStart;
    return result;
  }
  for (int i = 0; i < static_cast<int>(obstacles_.obstacles().size()); ++i) {
    if (obstacles_.contains(i, goal)) {
      result.status = Status::kInvalidGoal;
      return result;
    }
  }

  std::vector<Node> nodes;
  nodes.reserve(static_cast<size_t>(params_.max_expansions) * 8 + 1);
  std::priority_queue<OpenEntry> open;
  std::unordered_set<std::uint64_t> seen;
  nodes.push_back({start, Footstep{}, 0.0, heuristic(start, goal), -1});
  open.push({params_.heuristic_weight * nodes[0].h, nodes[0].h, 0});
  seen.insert(state_key(start));

  int goal_node = -1;
  std::vector<int> closed;  // expanded nodes, the root excluded
  std::vector<FootstepAction> actions;
  while (!open.empty() && result.nodes_expanded < params_.max_expansions) {
    const int current = open.top().index;
    open.pop();
    // Collisions are checked lazily, when a node is taken off the open list:
    // most generated nodes are never expanded.
    if (current != 0 && collides(nodes[current].step)) continue;
    ++result.nodes_expanded;
    const FootstepState state = nodes[current].state;
    if (distance(state.com, goal) <= params_.goal_tolerance) {
      goal_node = current;
      break;
    }
    if (current != 0) closed.push_back(current);

    // Discretised actions: each gait with each turn, plus the goal-directed phi.
    actions.clear();
    const Vec2 heading = state.standing() ? unit(state.facing) : state.com_velocity;
    const double heading_angle = angle_of(heading);
    const double goal_angle = angle_of(goal - state.com);
    const std::array<Foot, 2> both{Foot::kLeft, Foot::kRight};
    for (const Foot foot : both) {
      if (!state.standing() && foot == state.last_foot) continue;
      const double inward = -outward_sign(foot);
      const double goal_turn = inward * wrap_angle(goal_angle - heading_angle);
      bool goal_turn_is_new = goal_turn > 0.0 && goal_turn < 0.5 * kPi;
      for (const double turn : params_.turn_angles) {
        if (std::fabs(turn - goal_turn) < kDuplicateTurn) goal_turn_is_new = false;
      }
      for (const Gait& gait : params_.gaits) {
        for (const double turn : params_.turn_angles) {
          actions.push_back({StepKind::kWalk, foot, heading_angle + inward * turn, gait.speed,
                             gait.duration});
        }
        if (goal_turn_is_new) {
          actions.push_back({StepKind::kWalk, foot, goal_angle, gait.speed, gait.duration});
        }
      }
    }
    actions.push_back({StepKind::kStop, other(state.last_foot), state.facing, 0.0, params_.stop_duration});

    for (const FootstepAction& action : actions) {
      StepResult next = create_footstep(state, action, character_);
      if (!next.valid()) continue;
      if (!seen.insert(state_key(next.state)).second) continue;
      const double g = nodes[current].g + next.step.cost.total();
      const double h = heuristic(next.state, goal);
      nodes.push_back({next.state, next.step, g, h, current});
      open.push({g + params_.heuristic_weight * h, h, static_cast<int>(nodes.size()) - 1});
      ++result.nodes_generated;
    }
  }

  int end = goal_node;
  if (goal_node >= 0) {
    result.status = Status::kSuccess;
  } else {
    // Horizon: the closed node with the best heuristic that the character can
    // still stop from, so that the worst case is a sequence of stop steps.
    result.status = Status::kPartial;
    std::stable_sort(closed.begin(), closed.end(),
                     [&](int a, int b) { return nodes[a].h < nodes[b].h; });
    for (const int candidate : closed) {
      if (!start.standing() || nodes[candidate].h < nodes[0].h) {
        if (stop_step(nodes[candidate].state).valid()) {
          end = candidate;
          break;
        }
      }
    }
    // Nothing better than the start: a standing character waits.
    if (end < 0) {
      const StepResult wait = start.standing() ? stop_step(start) : StepResult{};
      if (start.standing() && wait.valid()) {
        result.footsteps.push_back(wait.step);
        result.end_state = wait.state;
      } else {
        result.status = Status::kNoPath;
      }
    }
  }
  if (end >= 0) {
    for (int i = end; i > 0; i = nodes[i].parent) result.footsteps.push_back(nodes[i].step);
    std::reverse(result.footsteps.begin(), result.footsteps.end());
    result.end_state = nodes[end].state;
  }
  choose_foot_orientations(result.footsteps, start.foot_orientation, character_);
  return result;
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
    intersect(interval[k], reachable_orientations(previous_choice, other(foot), character.max_foot_turn),
              foot, &allowed);
    steps[k].foot_orientation = clamp_orientation(steps[k].phi, allowed, foot);
  }
}

}  // namespace footfall
