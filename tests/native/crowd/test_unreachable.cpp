// An agent whose body no way leads to its goal says so at once, walks to
// the nearest place before the narrowest point where it stands clear, and
// stands there.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "footfall/crowd/scenario.hpp"
#include "footfall/fullbody/body_check.hpp"
#include "footfall/fullbody/body_model.hpp"
#include "footfall/io/plan_file.hpp"

namespace footfall {
namespace {

// A corridor 2 m wide along x, walls at y = +-1, shut at its ends
// (x = -1 and 12), crossed at x = 5-5.3 by two
// boxes that leave a slot 0.25 m wide from y = 0.175 to 0.425: too narrow
// for anyone side-stepping. The walker sets off at (1, 0) for (10, 0).
constexpr double kSlot = 0.25;
const Vec2 kSlotMiddle{5.15, 0.3};

Scenario slot_scenario(std::vector<Vec2> goals) {
  Scenario s;
  s.obstacles.push_back(prism({{-1, 1}, {12, 1}, {12, 1.3}, {-1, 1.3}}));
  s.obstacles.push_back(prism({{-1, -1.3}, {12, -1.3}, {12, -1}, {-1, -1}}));
  s.obstacles.push_back(prism({{-1.3, -1.3}, {-1, -1.3}, {-1, 1.3}, {-1.3, 1.3}}));
  s.obstacles.push_back(prism({{12, -1.3}, {12.3, -1.3}, {12.3, 1.3}, {12, 1.3}}));
  const double low = kSlotMiddle.y - kSlot / 2, high = kSlotMiddle.y + kSlot / 2;
  s.obstacles.push_back(prism({{5, -1}, {5.3, -1}, {5.3, low}, {5, low}}));
  s.obstacles.push_back(prism({{5, high}, {5.3, high}, {5.3, 1}, {5, 1}}));
  s.agents.push_back({"walker", {1, 0}, 0.0, std::move(goals)});
  return s;
}

// How far the centre of mass travels. [m]
double walked(const AgentPlan& agent) {
  double sum = 0.0;
  for (const Footstep& step : agent.footsteps) sum += distance(step.com_start, step.com_end);
  return sum;
}

TEST(Unreachable, AWalkerBeforeASlotTooNarrowSaysWhereAndStandsCalm) {
  const Scenario scenario = slot_scenario({{10, 0}});
  const Plan plan = plan_scenario(scenario);
  const AgentPlan& agent = plan.agents.front();
  EXPECT_EQ(agent.status, AgentStatus::kPartial);
  EXPECT_EQ(agent.reason, "unreachable");
  EXPECT_EQ(agent.goals_reached, 0);
  ASSERT_TRUE(agent.narrowest.has_value());
  const Narrowest& narrowest = *agent.narrowest;
  EXPECT_LT(distance(narrowest.at, kSlotMiddle), 0.03);
  EXPECT_NEAR(narrowest.width, kSlot, 0.005);
  const double side_step = BodyModel(scenario.character).clearance(Behavior::kSideStep);
  EXPECT_DOUBLE_EQ(narrowest.needs, 2.0 * side_step);
  EXPECT_EQ(narrowest.behavior, Behavior::kSideStep);
  // It walks up to the slot and stands, clear of it: no pacing.
  EXPECT_LT(walked(agent), 4.0);
  EXPECT_GT(agent.stuck_at.x, 3.0);
  EXPECT_LT(agent.stuck_at.x, 5.0 - side_step);
  for (const Footstep& step : agent.footsteps) EXPECT_NE(step.kind, StepKind::kSideStep);
  EXPECT_EQ(check_body(plan).penetrations, 0);
  // Its goal in the plan's scenario stays as given.
  EXPECT_EQ(scenario.agents.front().goals, (std::vector<Vec2>{{10, 0}}));
  EXPECT_EQ(unreachable_text(narrowest).rfind("cannot reach its goal: the way at (5.", 0), 0u)
      << unreachable_text(narrowest);
}

TEST(Unreachable, TheNarrowestPointSurvivesThePlanFileToTheBit) {
  const Plan plan = plan_scenario(slot_scenario({{10, 0}}));
  const std::string text = plan_to_json(plan);
  const Plan read = parse_plan(text);
  const AgentPlan& agent = read.agents.front();
  ASSERT_TRUE(agent.narrowest.has_value());
  EXPECT_EQ(agent.narrowest->at, plan.agents.front().narrowest->at);
  EXPECT_EQ(agent.narrowest->width, plan.agents.front().narrowest->width);
  EXPECT_EQ(agent.narrowest->needs, plan.agents.front().narrowest->needs);
  EXPECT_EQ(agent.narrowest->behavior, Behavior::kSideStep);
  EXPECT_EQ(plan_to_json(read), text);
  EXPECT_NE(text.find("\"narrowest\":{\"at\":["), std::string::npos);
}

// Goals before the one it cannot reach are visited; those after it are not.
TEST(Unreachable, AGoalPastTheSlotEndsTheWalkThere) {
  const Plan plan = plan_scenario(slot_scenario({{3, 0.5}, {10, 0}, {1, -0.5}}));
  const AgentPlan& agent = plan.agents.front();
  EXPECT_EQ(agent.reason, "unreachable");
  EXPECT_EQ(agent.goals_reached, 1);
  EXPECT_LT(agent.stuck_at.x, 5.0);
  EXPECT_GT(agent.stuck_at.x, 3.0);
  EXPECT_EQ(check_body(plan).penetrations, 0);
}

// Two slots in a row, 0.30 m wide at x = 3-3.3, then the 0.25 m one: the
// first stops the walker, and it is the one named; it stands before it.
TEST(Unreachable, OfTwoSlotsTooNarrowTheFirstIsNamed) {
  Scenario s = slot_scenario({{10, 0}});
  s.obstacles.push_back(prism({{3, -1}, {3.3, -1}, {3.3, -0.45}, {3, -0.45}}));
  s.obstacles.push_back(prism({{3, -0.15}, {3.3, -0.15}, {3.3, 1}, {3, 1}}));
  const Plan plan = plan_scenario(s);
  const AgentPlan& agent = plan.agents.front();
  EXPECT_EQ(agent.reason, "unreachable");
  ASSERT_TRUE(agent.narrowest.has_value());
  EXPECT_LT(distance(agent.narrowest->at, {3.15, -0.3}), 0.03);
  EXPECT_NEAR(agent.narrowest->width, 0.30, 0.005);
  EXPECT_LT(agent.stuck_at.x, 3.0);
  EXPECT_LT(walked(agent), 2.5);
  EXPECT_EQ(check_body(plan).penetrations, 0);
}

// A goal walled in all round: no way leads there at all. The agent stands
// where it is, and the narrowest point is there, 0 wide.
TEST(Unreachable, AGoalWalledInAllRoundLeavesTheAgentWhereItStands) {
  Scenario s = slot_scenario({{10, 0}});
  s.obstacles[4] = prism({{5, -1}, {5.3, -1}, {5.3, 1}, {5, 1}});  // shuts the slot
  const Plan plan = plan_scenario(s);
  const AgentPlan& agent = plan.agents.front();
  EXPECT_EQ(agent.reason, "unreachable");
  ASSERT_TRUE(agent.narrowest.has_value());
  EXPECT_EQ(agent.narrowest->width, 0.0);
  EXPECT_EQ(agent.narrowest->at, (Vec2{1, 0}));
  EXPECT_LT(walked(agent), 0.3);
  EXPECT_EQ(unreachable_text(*agent.narrowest), "cannot reach its goal: no way leads there");
}

// Where every agent reaches, nothing is said.
TEST(Unreachable, AWideEnoughSlotIsPassed) {
  Scenario s = slot_scenario({{10, 0}});
  s.obstacles[5] = prism({{5, 0.95}, {5.3, 0.95}, {5.3, 1}, {5, 1}});  // opens the slot to 0.78 m
  const Plan plan = plan_scenario(s);
  EXPECT_EQ(plan.agents.front().status, AgentStatus::kReached);
  EXPECT_FALSE(plan.agents.front().narrowest.has_value());
  EXPECT_EQ(plan_to_json(plan).find("narrowest"), std::string::npos);
}

}  // namespace
}  // namespace footfall
