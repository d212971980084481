// Measuring plans: our five-circle overlaps and SteerBench's figures.
#include <gtest/gtest.h>

#include "footfall/plan/metrics.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall {
namespace {

TEST(Metrics, AValidWalkHasNoOverlapsAndSteerBenchFigures) {
  const Plan plan = plan_scenario(demo_scenario());
  const PlanMetrics metrics = measure_plan(plan);
  ASSERT_EQ(metrics.agents.size(), plan.agents.size());
  double time = 0, energy = 0, acceleration = 0;
  for (const AgentMetrics& agent : metrics.agents) {
    EXPECT_TRUE(agent.reached) << agent.name;
    EXPECT_EQ(agent.overlaps, 0) << agent.name;
    EXPECT_EQ(agent.collision_episodes, 0) << agent.name;
    time += agent.time;
    energy += agent.energy;
    acceleration += agent.acceleration;
  }
  const double count = static_cast<double>(metrics.agents.size());
  const AgentMetrics& m = metrics.agents[0];  // "walker"
  EXPECT_TRUE(m.reached);
  EXPECT_EQ(m.overlaps, 0);
  EXPECT_EQ(m.collision_episodes, 0);
  EXPECT_DOUBLE_EQ(m.time, plan.agents[0].end_time());
  EXPECT_DOUBLE_EQ(m.effort, plan.agents[0].total_cost());
  EXPECT_GT(m.path_length, 11.0);  // start to goal is 11.0 m; the walk sways and detours
  EXPECT_LT(m.path_length, 13.0);
  // Energy: half the squared speed per sample, walking at 0.8 to 1.7 m/s.
  const double samples = m.time * metrics.rate;
  EXPECT_GT(m.energy, 0.5 * 0.8 * 0.8 * samples * 0.8);
  EXPECT_LT(m.energy, 0.5 * 1.7 * 1.7 * samples);
  EXPECT_GT(m.acceleration, 0.0);
  EXPECT_DOUBLE_EQ(metrics.composite01, 50.0 * 0 + time / count + energy / count);
  EXPECT_DOUBLE_EQ(metrics.composite02, metrics.composite01 + acceleration / count);
}

TEST(Metrics, AgentsWalkingThroughEachOtherCollide) {
  // Head-on, on one line, each planned alone: they walk through each other.
  Scenario scenario;
  scenario.agents.push_back({"a", {0, 0}, 0, {{8, 0}}});
  scenario.agents.push_back({"b", {8, 0}, 3.14159265358979, {{0, 0}}});
  const ObstacleMap obstacles(scenario.obstacles);
  const FootstepPlanner planner(scenario.character, scenario.planner, obstacles);
  Plan plan;
  plan.character = scenario.character;
  for (const AgentSpec& agent : scenario.agents) plan.agents.push_back(plan_agent(agent, planner));
  const PlanMetrics metrics = measure_plan(plan);
  for (const AgentMetrics& m : metrics.agents) {
    EXPECT_GE(m.collision_episodes, 1) << m.name;
    EXPECT_GT(m.overlaps, 0) << m.name;
  }
  EXPECT_EQ(metrics.overlaps, metrics.agents[0].overlaps + metrics.agents[1].overlaps);
  EXPECT_NEAR(
      metrics.composite01,
      50.0 * (metrics.agents[0].collision_episodes + metrics.agents[1].collision_episodes) / 2 +
          (metrics.agents[0].time + metrics.agents[1].time) / 2 +
          (metrics.agents[0].energy + metrics.agents[1].energy) / 2,
      1e-9);
}

TEST(Metrics, AnObstacleOnThePathIsOneEpisode) {
  // Planned in the open, measured with a post in the way.
  Scenario open;
  open.agents.push_back({"a", {0, 0}, 0, {{8, 0}}});
  Plan plan = plan_scenario(open);
  plan.obstacles.push_back(box_obstacle({4, 0}, {0.1, 0.1}));
  const AgentMetrics m = measure_plan(plan).agents[0];
  EXPECT_EQ(m.collision_episodes, 1);
  EXPECT_GT(m.overlaps, 0);
}

TEST(Metrics, PlanFilesKeepTheirObstacles) {
  const Plan plan = plan_scenario(demo_scenario());
  const Plan read = parse_plan(plan_to_json(plan));
  ASSERT_EQ(read.obstacles.size(), plan.obstacles.size());
  EXPECT_EQ(read.obstacles[2].polygon[1], plan.obstacles[2].polygon[1]);
  EXPECT_THROW(measure_plan(plan, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace footfall
