#include "footfall/agent_planner.hpp"

#include <stdexcept>

#include "local_goal.hpp"

namespace footfall {
namespace {

/// Searches in a row that may leave the way no shorter before the agent is stuck.
constexpr int kMaxIdleSearches = 3;

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
