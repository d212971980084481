// Crossings: agents bound every way where narrow streets meet.
#include <gtest/gtest.h>

#include "footfall/crowd/scenario.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall {
namespace {

TEST(Crossings, AWaitCycleOfFourAgentsResolves) {
  // Two streets 1.2 m wide cross: room for one at a time where they meet.
  // Four agents 3 m from the middle, one in each arm, each bound straight
  // across: each stands in the way of the one on its left, a wait cycle
  // unless one goes first.
  Scenario scenario;
  const double half = 0.6;
  for (const Vec2 corner : {Vec2{1, 1}, Vec2{-1, 1}, Vec2{-1, -1}, Vec2{1, -1}})
    scenario.obstacles.push_back(
        box_obstacle({corner.x * (half + 4.0), corner.y * (half + 4.0)}, {8.0, 8.0}, 2.5));
  const Vec2 arms[] = {{-1, 0}, {0, -1}, {1, 0}, {0, 1}};
  for (int k = 0; k < 4; ++k) {
    AgentSpec agent{"arm" + std::to_string(k), 3.0 * arms[k], 0.0, {{-7.0 * arms[k]}}};
    agent.facing = angle_of(-1.0 * arms[k]);
    agent.leave_at_goal = true;
    scenario.agents.push_back(agent);
  }
  const Plan plan = plan_scenario(scenario);
  EXPECT_EQ(measure_plan(plan).overlaps, 0);
  for (const AgentPlan& agent : plan.agents) {
    EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.name;
    // 10 m alone take some 8 s; three wait for the crossing to clear.
    EXPECT_LT(agent.end_time(), 25.0) << agent.name;
  }
}

}  // namespace
}  // namespace footfall
