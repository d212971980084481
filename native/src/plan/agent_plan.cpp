// Footfall — an agent's plan: its status and totals. (Planning agents is the
// crowd driver's, in crowd/crowd_planner.cpp.)
#include "footfall/plan/plan.hpp"

#include <cstdio>

namespace footfall {

const char* to_string(AgentStatus status) {
  return status == AgentStatus::kReached ? "reached" : "partial";
}

std::string unreachable_text(const Narrowest& narrowest) {
  const std::string head = "cannot reach its goal: ";
  if (narrowest.width <= 0.0) return head + "no way leads there";
  const char* moving = narrowest.behavior == Behavior::kWalk     ? "walking"
                       : narrowest.behavior == Behavior::kArmsIn ? "with its arms in"
                                                                 : "side-stepping";
  char text[160];
  std::snprintf(text, sizeof text,
                "the way at (%.2f, %.2f) is %.2f m wide, its body needs %.2f m %s", narrowest.at.x,
                narrowest.at.y, narrowest.width, narrowest.needs, moving);
  return head + text;
}

std::string short_of_goal_text(const AgentPlan& agent) {
  if (agent.narrowest) return unreachable_text(*agent.narrowest);
  const char* why = agent.reason == "time limit" ? "its time limit ran out"
                    : agent.reason == "stuck"    ? "no step it could take led on"
                    : agent.reason == "cancelled" ? "planning was cancelled"
                                                  : agent.reason.c_str();
  char at[80];
  std::snprintf(at, sizeof at, "stands at (%.2f, %.2f) short of its goal: ", agent.stuck_at.x,
                agent.stuck_at.y);
  return at + std::string(why);
}

double AgentPlan::total_cost() const {
  double sum = 0.0;
  for (const Footstep& step : footsteps) sum += step.cost.total();
  return sum;
}

}  // namespace footfall
