// Agents with characters of their own (a scenario's agents[i].character):
// each walks with its own limits, and bodies meet as each one's size.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "footfall/crowd/scenario.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/io/scenario_file.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {
namespace {

// Two tall agents and a small one, with the small one's overrides twice
// (agents with the same overrides share one character), in a 2.4 m corridor
// where the small one meets a tall one head on.
const std::string kScenario = R"({
  "format": "footfall-scenario", "version": 1,
  "obstacles": [{"polygon": [[-1, 1.2], [9, 1.2], [9, 1.6], [-1, 1.6]]},
                {"polygon": [[-1, -1.6], [9, -1.6], [9, -1.2], [-1, -1.2]]}],
  "agents": [
    {"name": "tall", "position": [0, 0.4], "goals": [[8, 0.4]]},
    {"name": "small", "position": [8, 0.3], "goals": [[0, 0.3]],
     "character": {"com_height": 0.7, "max_step_length": 0.5, "torso_width": 0.4,
                   "torso_radius": 0.1, "foot_radius": 0.05, "preferred_speed": 0.85}},
    {"name": "small twin", "position": [0, -0.6], "goals": [[8, -0.6]],
     "character": {"foot_radius": 0.05, "com_height": 0.7, "max_step_length": 0.5,
                   "torso_width": 0.4, "torso_radius": 0.1, "preferred_speed": 0.85}}
  ]
})";

// `text` with the first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

double longest_chord(const AgentPlan& plan) {
  double longest = 0.0;
  for (const Footstep& step : plan.footsteps)
    longest = std::max(longest, distance(step.com_start, step.com_end));
  return longest;
}

TEST(AgentCharacters, EachAgentWalksWithItsOwnLimitsAndBody) {
  const Scenario scenario = parse_scenario(kScenario, "three.json");
  ASSERT_TRUE(scenario.agents[1].character);
  EXPECT_EQ(scenario.agents[1].character, scenario.agents[2].character);  // one planner for both
  EXPECT_DOUBLE_EQ(scenario.agents[1].character->mass, scenario.character.mass);  // the rest inherited
  const Plan plan = plan_scenario(scenario);
  for (const AgentPlan& agent : plan.agents)
    EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.name << ": " << agent.reason;
  EXPECT_FALSE(plan.agents[0].character);
  ASSERT_TRUE(plan.agents[1].character);
  EXPECT_DOUBLE_EQ(plan.agents[1].character->com_height, 0.7);
  EXPECT_LE(longest_chord(plan.agents[1]), 0.5 + 1e-9);
  EXPECT_LE(longest_chord(plan.agents[2]), 0.5 + 1e-9);
  EXPECT_GT(longest_chord(plan.agents[0]), 0.5);
  // Its body is its own: the small torso's circles, wherever it is measured.
  const std::vector<Circle> small = collision_circles(plan.agents[1], plan.character, 0.0);
  const std::vector<Circle> tall = collision_circles(plan.agents[0], plan.character, 0.0);
  EXPECT_DOUBLE_EQ(small[0].radius, 0.1);
  EXPECT_DOUBLE_EQ(tall[0].radius, plan.character.torso_radius);
  EXPECT_EQ(measure_plan(plan).overlaps, 0);
}

TEST(AgentCharacters, ThePlanFileKeepsThem) {
  const Plan plan = plan_scenario(parse_scenario(kScenario, "three.json"));
  const std::string text = plan_to_json(plan);
  const Plan read = parse_plan(text, "plan.json");
  EXPECT_FALSE(read.agents[0].character);
  ASSERT_TRUE(read.agents[1].character);
  EXPECT_EQ(read.agents[1].character, read.agents[2].character);
  EXPECT_DOUBLE_EQ(read.agents[1].character->torso_width, 0.4);
  EXPECT_DOUBLE_EQ(read.agents[1].character->left.max_speed, plan.character.left.max_speed);
  EXPECT_EQ(plan_to_json(read), text);
}

TEST(AgentCharacters, ABadOneIsNamedByItsAgent) {
  try {
    parse_scenario(replaced(kScenario, "\"max_step_length\": 0.5", "\"max_step_length\": -1"),
                   "three.json");
    FAIL() << "a negative step length was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("three.json: agents[1].character."), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(parse_scenario(replaced(kScenario, "\"com_height\"", "\"height\""), "three.json"),
               std::invalid_argument);
  try {  // a preferred step longer than its longest
    parse_scenario(replaced(kScenario, "\"preferred_speed\": 0.85", "\"preferred_speed\": 1.3"),
                   "three.json");
    FAIL() << "a preferred step beyond the limits was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("three.json: agents[1].character.preferred_speed"),
              std::string::npos)
        << error.what();
  }
}

// Time budgets: an agent's own, or max_time stretched to its route.
TEST(AgentTimeLimits, AnAgentWalksItsRouteOrItsOwnBudget) {
  const Scenario scenario = parse_scenario(R"({
    "format": "footfall-scenario", "version": 1,
    "agents": [{"name": "far", "position": [0, 0], "goals": [[15, 0], [15, 15]]},
               {"name": "hurried", "position": [0, 3], "goals": [[30, 3]], "time_limit": 6}],
    "planner": {"max_time": 10}
  })", "two.json");
  // 30 m at the preferred 1.3 m/s is 23 s: four times that, not max_time's 10 s.
  EXPECT_NEAR(time_limit_of(scenario.agents[0], scenario.character, scenario.planner),
              4 * 30 / scenario.character.preferred_speed, 1e-9);
  EXPECT_DOUBLE_EQ(time_limit_of(scenario.agents[1], scenario.character, scenario.planner), 6.0);
  const Plan plan = plan_scenario(scenario);
  EXPECT_EQ(plan.agents[0].status, AgentStatus::kReached) << plan.agents[0].reason;
  EXPECT_GT(plan.agents[0].end_time(), 10.0);
  EXPECT_EQ(plan.agents[1].status, AgentStatus::kPartial);
  EXPECT_EQ(plan.agents[1].reason, "time limit");
  // What it had committed by then (a search's reach at most), and its rest.
  EXPECT_LT(plan.agents[1].end_time(), 6.0 + scenario.planner.local_goal_distance /
                                                 scenario.character.preferred_speed +
                                             scenario.planner.stop_duration);
  EXPECT_LT(com_at(plan.agents[1], plan.agents[1].end_time()).position.x, 29.0);
  try {
    parse_scenario(R"({"format": "footfall-scenario", "version": 1,
      "agents": [{"position": [0, 0], "goals": [[1, 0]], "time_limit": -1}]})", "bad.json");
    FAIL() << "a negative time limit was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("bad.json: agents[0].time_limit: must be in (0, 100000] s"),
              std::string::npos) << error.what();
  }
}

TEST(AgentTimeLimits, ADelayedAgentStandsUntilItsStart) {
  const Scenario scenario = parse_scenario(R"({
    "format": "footfall-scenario", "version": 1,
    "agents": [{"name": "late", "position": [0, 0], "goals": [[6, 0]], "start_delay": 3,
                "time_limit": 4},
               {"name": "early", "position": [0, 3], "goals": [[6, 3]]}]
  })", "two.json");
  const Plan plan = plan_scenario(scenario);
  const AgentPlan& late = plan.agents[0];
  // Its budget starts with it: 4 s of walking after 3 s of standing.
  EXPECT_EQ(late.status, AgentStatus::kReached) << late.reason;
  for (const Footstep& step : late.footsteps) {
    if (step.start_time < 3.0) {
      EXPECT_EQ(distance(step.com_start, step.com_end), 0.0) << step.start_time;
    }
  }
  EXPECT_GE(late.end_time(), 3.0 + 6.0 / scenario.character.preferred_speed);
  EXPECT_LT(plan.agents[1].end_time(), late.end_time() - 2.0);
}

TEST(AgentTimeLimits, AnAgentWaitsAtEachGoalButTheLast) {
  const std::string text = R"({
    "format": "footfall-scenario", "version": 1,
    "agents": [{"name": "a", "position": [0, 0], "goals": [[4, 0], [4, 4]], "goal_wait": 20}]
  })";
  const Plan plan = plan_scenario(parse_scenario(text, "one.json"));
  const AgentPlan& a = plan.agents[0];
  EXPECT_EQ(a.status, AgentStatus::kReached) << a.reason;
  // It stands still at the first goal for the wait, at one stretch.
  double longest = 0.0, since = 0.0;
  Vec2 where{0, 0};
  for (const Footstep& step : a.footsteps) {
    if (distance(step.com_start, step.com_end) > 0.0) {
      since = step.end_time;
    } else if (step.end_time - since > longest) {
      longest = step.end_time - since;
      where = step.com_end;
    }
  }
  EXPECT_GE(longest, 20.0);
  EXPECT_LT(distance(where, {4, 0}), 0.5);
}

TEST(AgentCharacters, OnePlannerForAllRefusesAgentsOfTheirOwn) {
  const Scenario scenario = parse_scenario(kScenario, "three.json");
  const ObstacleMap obstacles(scenario.obstacles);
  const FootstepPlanner planner(scenario.character, scenario.planner, obstacles);
  EXPECT_THROW(plan_agents(scenario.agents, planner), std::invalid_argument);
}

}  // namespace
}  // namespace footfall
