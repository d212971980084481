// Footfall — an agent's plan: its status and totals. (Planning agents is the
// crowd driver's, in crowd/crowd_planner.cpp.)
#include "footfall/plan/plan.hpp"

namespace footfall {

const char* to_string(AgentStatus status) {
  return status == AgentStatus::kReached ? "reached" : "partial";
}

double AgentPlan::total_cost() const {
  double sum = 0.0;
  for (const Footstep& step : footsteps) sum += step.cost.total();
  return sum;
}

}  // namespace footfall
