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

AgentPlan plan_agent(const AgentSpec& agent, const FootstepPlanner& planner,
                     const RunControl& control) {
  if (agent.goals.empty()) throw std::invalid_argument("agent " + agent.name + ": has no goals");
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
    const Vec2 local_goal =
        goal_in_reach ? goal
                      : state.com + (params.local_goal_distance / to_goal) * (goal - state.com);
    const SearchResult search = planner.plan(state, local_goal);
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
    const bool progressed = to_goal - distance(state.com, goal) >= params.min_progress;
    if (search.status != Status::kSuccess && !progressed) {
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
