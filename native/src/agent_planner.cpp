#include "footfall/agent_planner.hpp"

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

// The goal of the next search: the agent's goal, or the point
// local_goal_distance toward it, moved back toward the agent until the agent
// could stand there (an intermediate point may fall in or against an obstacle).
Vec2 local_goal(const FootstepPlanner& planner, Vec2 from, Vec2 goal) {
  const double to_goal = distance(from, goal);
  const double reach = planner.params().local_goal_distance;
  if (to_goal <= reach) return goal;
  const double facing = angle_of(goal - from);
  constexpr double kStep = 0.25;  // [m]
  for (double along = reach; along > 0.0; along -= kStep) {
    const Vec2 point = from + (along / to_goal) * (goal - from);
    if (!planner.collides(standing_state(point, facing, planner.character()))) return point;
  }
  return from + (reach / to_goal) * (goal - from);
}

}  // namespace

AgentPlan plan_agent(const AgentSpec& agent, const FootstepPlanner& planner,
                     const RunControl& control) {
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
    const double to_goal = distance(state.com, goal);
    const bool goal_in_reach = to_goal <= params.local_goal_distance;
    const SearchResult search = planner.plan(state, local_goal(planner, state.com, goal));
    ++plan.searches;
    plan.nodes_generated += search.nodes_generated;
    plan.nodes_expanded += search.nodes_expanded;
    plan.footsteps.insert(plan.footsteps.end(), search.footsteps.begin(), search.footsteps.end());
    state = search.end_state;

    if (search.status == Status::kSuccess && goal_in_reach) {
      ++plan.goals_reached;
      if (++goal_index == agent.goals.size()) {
        come_to_rest(planner, state, plan.footsteps);
        plan.status = AgentStatus::kReached;
        break;
      }
      continue;
    }
    // Every other search must bring the agent closer, or it is stuck.
    if (to_goal - distance(state.com, goal) < params.min_progress) {
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
