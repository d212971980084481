// The crowd driver: agents that see each other keep clear of each other's
// plans, waiting when they must; the plans do not depend on the thread count.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "footfall/metrics.hpp"
#include "footfall/plan.hpp"
#include "footfall/plan_io.hpp"
#include "footfall/steersuite.hpp"

namespace footfall {
namespace {

const std::string kCases = FOOTFALL_STEERSUITE_DIR;

/// Plans `scenario` and checks that every agent reached its goals with no
/// overlap under the five-circle model and no SteerBench collision episode.
Plan plan_clear_of_each_other(const Scenario& scenario, int threads = 1) {
  RunControl control;
  control.threads = threads;
  const Plan plan = plan_scenario(scenario, control);
  const PlanMetrics metrics = measure_plan(plan);
  EXPECT_EQ(metrics.overlaps, 0);
  for (std::size_t i = 0; i < plan.agents.size(); ++i) {
    EXPECT_EQ(plan.agents[i].status, AgentStatus::kReached)
        << plan.agents[i].name << ": " << plan.agents[i].reason;
    EXPECT_EQ(metrics.agents[i].collision_episodes, 0) << plan.agents[i].name;
  }
  return plan;
}

/// True if the agent stops (waits or slows to a halt) before its last stops.
bool waits_on_the_way(const AgentPlan& agent) {
  const auto& steps = agent.footsteps;
  for (std::size_t i = 1; i + 2 < steps.size(); ++i)
    if (steps[i].kind == StepKind::kStop && steps[i - 1].kind == StepKind::kWalk) return true;
  return false;
}

TEST(Crowd, HeadOnAgentsPassEachOther) {
  // The same two agents walk through each other when each is planned alone
  // (Metrics.AgentsWalkingThroughEachOtherCollide).
  Scenario scenario;
  scenario.agents.push_back({"a", {0, 0}, 0, {{8, 0}}});
  scenario.agents.push_back({"b", {8, 0}, 3.14159265358979, {{0, 0}}});
  plan_clear_of_each_other(scenario);
}

TEST(Crowd, DoorwayTwoWayBothPassAndOneWaits) {
  const Plan plan = plan_clear_of_each_other(load_steersuite(kCases + "/doorway-two-way.xml"));
  EXPECT_TRUE(waits_on_the_way(plan.agents[0]) || waits_on_the_way(plan.agents[1]));
}

TEST(Crowd, SmallSteerSuiteCasesWalkClearOfEachOther) {
  for (const char* name : {"3-squeeze", "circle-20", "crossing-1", "crossing-2", "crossing-3",
                           "fan-out", "oncoming-1", "oncoming-2", "overtake", "squeeze",
                           "surprise-1", "simple-wall"}) {
    SCOPED_TRACE(name);
    plan_clear_of_each_other(load_steersuite(kCases + "/" + name + ".xml"));
  }
}

TEST(Crowd, ThreadsDoNotChangeThePlan) {
  const Scenario circle = load_steersuite(kCases + "/circle-20.xml");
  EXPECT_EQ(plan_to_json(plan_clear_of_each_other(circle, 1)),
            plan_to_json(plan_clear_of_each_other(circle, 2)));
}

}  // namespace
}  // namespace footfall
