// A street under a footbridge (bridge_scenario): ground with two levels over
// the street, each walked as its own, joined where the deck meets the banks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "footfall/crowd/scenario.hpp"
#include "footfall/plan/ground_check.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall {
namespace {

void expect_reached_clear_and_on_ground(const Plan& plan) {
  for (const AgentPlan& agent : plan.agents) {
    EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.name;
  }
  EXPECT_EQ(measure_plan(plan).overlaps, 0);
  const GroundCheck ground = check_ground(plan);
  EXPECT_GT(ground.footholds, 0);
  EXPECT_EQ(ground.off_ground + ground.unsupported + ground.over_rise + ground.swing, 0);
}

TEST(Bridge, ThoseUnderTheDeckWalkAsIfNoOneCrossedAbove) {
  constexpr int kUnder = 4, kOver = 4;
  const Plan alone = plan_scenario(bridge_scenario(kUnder, 0));
  const Plan both = plan_scenario(bridge_scenario(kUnder, kOver));
  expect_reached_clear_and_on_ground(both);
  for (int i = 0; i < kUnder; ++i) {
    const auto& mine = alone.agents[i].footsteps;
    const auto& theirs = both.agents[i].footsteps;
    ASSERT_EQ(mine.size(), theirs.size()) << alone.agents[i].name;
    for (std::size_t k = 0; k < mine.size(); ++k) {
      EXPECT_EQ(mine[k].foot_position, theirs[k].foot_position);
      EXPECT_EQ(mine[k].start_time, theirs[k].start_time);
      EXPECT_EQ(mine[k].foot_height, 0.0);
    }
  }
  // They did meet in plan: one crossed over one walking under it.
  double closest = INFINITY;
  for (double t = 0; t < 20; t += 0.05)
    for (int i = 0; i < kUnder; ++i)
      for (int j = kUnder; j < kUnder + kOver; ++j)
        closest = std::min(closest, distance(com_at(both.agents[i], t).position,
                                             com_at(both.agents[j], t).position));
  EXPECT_LT(closest, 0.5);
  // Those crossing stay at the banks' and the deck's height all the way.
  for (int j = kUnder; j < kUnder + kOver; ++j)
    for (const Footstep& step : both.agents[j].footsteps)
      EXPECT_DOUBLE_EQ(step.foot_height, kBridgeHeight) << both.agents[j].name;
}

TEST(Bridge, AWalkerClimbsFromTheStreetToTheDeckByTheFlightAndOneComesDown) {
  Scenario scenario = bridge_scenario(0, 0);
  scenario.agents.push_back({"climber", {-10, 0}, 0.0, {{0, 0}}});
  scenario.agents.back().goal_heights = {kBridgeHeight};
  scenario.agents.push_back({"descender", {0, 1}, 0.5 * kPi, {{2, -1}}});
  scenario.agents.back().height = kBridgeHeight;
  const Plan plan = plan_scenario(scenario);
  expect_reached_clear_and_on_ground(plan);
  for (const AgentPlan& agent : plan.agents) {
    const auto& steps = agent.footsteps;
    EXPECT_TRUE(std::any_of(steps.begin(), steps.end(), [](const Footstep& s) {
      return s.foot_position.x > 6 && s.foot_position.x < 8 && s.foot_position.y > 4.5;
    })) << agent.name << " not by the flight";
  }
  EXPECT_DOUBLE_EQ(plan.agents[0].footsteps.back().foot_height, kBridgeHeight);
  EXPECT_DOUBLE_EQ(plan.agents[1].footsteps.back().foot_height, 0.0);
}

}  // namespace
}  // namespace footfall
