#include "footfall/agent_planner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace footfall {
namespace {

// Appends a stop step, halving its duration while it would run into an
// obstacle (the COM still coasts while it decelerates). Returns false when even
// the shortest stop collides.
bool append_stop(const FootstepPlanner& planner, FootstepState& state,
                 std::vector<Footstep>& steps) {
  double duration = planner.params().stop_duration;
  for (int attempt = 0; attempt < 4; ++attempt, duration *= 0.5) {
    const StepResult stop = planner.stop_step(state, duration);
    if (stop.valid()) {
      steps.push_back(stop.step);
      state = stop.state;
      return true;
    }
  }
  return false;
}

// Brings the character to rest with its feet side by side: one stop to
// decelerate, a second one to close the feet.
void come_to_rest(const FootstepPlanner& planner, FootstepState& state,
                  std::vector<Footstep>& steps) {
  if (!state.standing() && !append_stop(planner, state, steps)) return;
  append_stop(planner, state, steps);
}

}  // namespace

const char* to_string(AgentStatus status) {
  return status == AgentStatus::kReached ? "reached" : "partial";
}

double AgentPlan::total_cost() const {
  double sum = 0.0;
  for (const Footstep& step : footsteps) sum += step.cost.total();
  return sum;
}

double AgentPlan::end_time() const { return footsteps.empty() ? 0.0 : footsteps.back().end_time; }

namespace {

/// The way only places local goals; its arcs need not be fine. [m]
constexpr double kRouteArcTolerance = 0.05;
/// Searches in a row that may leave the way no shorter before the agent is stuck.
constexpr int kMaxIdleSearches = 3;
/// A local goal out of sight is looked for this much nearer, each time. [1]
constexpr double kSightBackOff = 0.6;
/// ...down to this far along the way, past a corner or not. [m]
constexpr double kMinAhead = 1.5;
/// A roomier way is taken if it is at most this much longer than the
/// tightest: kRoomyDetour times, plus kRoomyExtra.
constexpr double kRoomyDetour = 1.25;
constexpr double kRoomyExtra = 2.0;  // [m]
/// Room beside the shoulders, where there is room, for the body's sway. [m]
constexpr double kSwayMargin = 0.25;

/// The way from `from` toward `goal`, and its length.
struct Way {
  std::vector<Vec2> points;
  double length = 0.0;
};

/// The way on the navigation mesh: the roomiest of three that is not much
/// longer than the tightest (at most kRoomyDetour times plus kRoomyExtra):
/// room to walk upright with a margin for the sway, just upright (half the
/// torso width), or only to side-step (the torso circle), as through a gap
/// narrower than the shoulders. With no way at all, the straight line, along
/// which the local search finds what it can.
Way way_toward(const NavMesh* mesh, const CharacterParams& character, Vec2 from, Vec2 goal) {
  Way way{{from, goal}, distance(from, goal)};
  if (mesh == nullptr) return way;
  const double upright = 0.5 * character.torso_width;
  PathResult tight = mesh->find_path({from, goal, character.torso_radius, kRouteArcTolerance});
  if (tight.status != PathStatus::kFound) return way;
  for (double radius : {upright + kSwayMargin, upright}) {
    PathResult roomy = mesh->find_path({from, goal, radius, kRouteArcTolerance});
    if (roomy.status == PathStatus::kFound &&
        roomy.length <= kRoomyDetour * tight.length + kRoomyExtra)
      return {std::move(roomy.points), roomy.length};
  }
  return {std::move(tight.points), tight.length};
}

/// The point `along` metres along `points` (clamped to its ends).
Vec2 point_along(const std::vector<Vec2>& points, double along) {
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const double piece = distance(points[k], points[k + 1]);
    if (along <= piece && piece > 0.0) return points[k] + (along / piece) * (points[k + 1] - points[k]);
    along -= piece;
  }
  return points.back();
}

/// True if the agent at `from` sees `to`: a straight line with room for the
/// torso circle joins them. A short-horizon search cannot go round a wall to
/// reach a point behind it.
bool in_sight(const NavMesh* mesh, const CharacterParams& character, Vec2 from, Vec2 to) {
  if (mesh == nullptr) return true;
  const PathResult path = mesh->find_path({from, to, character.torso_radius, kRouteArcTolerance});
  return path.status == PathStatus::kFound && path.points.size() == 2;
}

/// Where the next search aims: the goal if the way to it is within
/// local_goal_distance and in sight; else the farthest point of the way
/// within that distance that is in sight (looking nearer by steps of
/// kSightBackOff, down to kMinAhead), moved back along the way until the
/// agent could stand there (a point may fall in or against an obstacle).
struct LocalGoal {
  Vec2 point;
  bool is_goal = false;
};

LocalGoal local_goal(const FootstepPlanner& planner, const NavMesh* mesh, const Way& way) {
  const Vec2 from = way.points.front();
  double reach = std::min(planner.params().local_goal_distance, way.length);
  while (reach > kMinAhead && !in_sight(mesh, planner.character(), from, point_along(way.points, reach)))
    reach = std::max(kMinAhead, kSightBackOff * reach);
  if (way.length <= reach) return {way.points.back(), true};
  constexpr double kStep = 0.25;  // [m]
  for (double along = reach; along > 0.0; along -= kStep) {
    const Vec2 point = point_along(way.points, along);
    const Vec2 ahead = point_along(way.points, along + kStep);
    const double facing = angle_of(ahead - point);
    if (!planner.collides(standing_state(point, facing, planner.character()))) return {point, false};
  }
  return {point_along(way.points, reach), false};
}

}  // namespace

AgentPlan plan_agent(const AgentSpec& agent, const FootstepPlanner& planner,
                     const NavMesh* mesh, const RunControl& control) {
  if (agent.goals.empty()) throw std::invalid_argument("agent " + agent.name + ": has no goals");
  if (!in_world(agent.position) || !std::isfinite(agent.facing)) {
    throw std::invalid_argument("agent " + agent.name +
                                ": position and facing must be finite, within 1e9 m");
  }
  for (const Vec2& goal : agent.goals) {
    if (!in_world(goal))
      throw std::invalid_argument("agent " + agent.name + ": goals must be finite, within 1e9 m");
  }
  const PlannerParams& params = planner.params();
  AgentPlan plan;
  plan.name = agent.name;
  plan.start = standing_state(agent.position, agent.facing, planner.character());
  FootstepState state = plan.start;
  size_t goal_index = 0;
  int idle_searches = 0;
  while (true) {
    if (control.cancelled()) {
      plan.reason = "cancelled";
      break;
    }
    if (state.time >= params.max_time) {
      plan.reason = "time limit";
      break;
    }
    const Vec2 goal = agent.goals[goal_index];
    const Way way = way_toward(mesh, planner.character(), state.com, goal);
    const LocalGoal target = local_goal(planner, mesh, way);
    const SearchResult search = planner.plan(state, target.point);
    ++plan.searches;
    plan.nodes_generated += search.nodes_generated;
    plan.nodes_expanded += search.nodes_expanded;
    plan.footsteps.insert(plan.footsteps.end(), search.footsteps.begin(), search.footsteps.end());
    state = search.end_state;

    if (search.status == Status::kSuccess && target.is_goal) {
      ++plan.goals_reached;
      if (++goal_index == agent.goals.size()) {
        come_to_rest(planner, state, plan.footsteps);
        plan.status = AgentStatus::kReached;
        break;
      }
      continue;
    }
    // Searches must keep shortening the way to the goal, or the agent is
    // stuck (a few may only turn the agent round, against a wall say).
    const double left = way_toward(mesh, planner.character(), state.com, goal).length;
    idle_searches = way.length - left < params.min_progress ? idle_searches + 1 : 0;
    if (idle_searches == kMaxIdleSearches) {
      come_to_rest(planner, state, plan.footsteps);
      plan.reason = "stuck";
      break;
    }
  }
  plan.stuck_at = state.com;
  choose_foot_orientations(plan.footsteps, plan.start.foot_orientation, planner.character());
  return plan;
}

}  // namespace footfall
