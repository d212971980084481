// Planning some agents of a scenario again among the fixed plans of the
// others (replan_agents): the others' plans come back as they were, and the
// agents planned again keep clear of them.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "footfall/crowd/scenario.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/io/scenario_file.hpp"
#include "footfall/plan/metrics.hpp"

namespace footfall {
namespace {

// "across" crosses "along"'s way at (4, 0) when both set off at once.
const std::string kAlong = R"({"name": "along", "position": [0, 0], "goals": [[8, 0]]})";
const std::string kAcross = R"({"name": "across", "position": [4, -4], "goals": [[4, 4]]})";

Scenario scenario_of(const std::string& agents) {
  return parse_scenario(R"({"format": "footfall-scenario", "version": 1, "agents": [)" + agents +
                            "]}",
                        "crossing.json");
}

// The plan of `agent` as a one-agent plan file's text: what must not change.
std::string text_of(const AgentPlan& agent) {
  Plan plan;
  plan.agents = {agent};
  return plan_to_json(plan);
}

TEST(Replan, AnAgentPlannedAgainKeepsClearOfTheFixedPlans) {
  const Scenario both = scenario_of(kAlong + "," + kAcross);
  // Each planned alone: they walk into each other.
  Plan blind = plan_scenario(scenario_of(kAlong));
  blind.agents.push_back(plan_scenario(scenario_of(kAcross)).agents.front());
  ASSERT_GT(measure_plan(blind).overlaps, 0);

  const Plan plan = replan_agents(both, blind, {"along"});
  ASSERT_EQ(plan.agents.size(), 2u);
  EXPECT_EQ(plan.agents[0].name, "along");
  EXPECT_EQ(plan.agents[0].status, AgentStatus::kReached) << plan.agents[0].reason;
  EXPECT_EQ(text_of(plan.agents[1]), text_of(blind.agents[1]));  // kept as it was
  EXPECT_EQ(measure_plan(plan).overlaps, 0);
}

TEST(Replan, AgentsNotNamedNeedAPlanAndNamesNeedAnAgent) {
  const Scenario both = scenario_of(kAlong + "," + kAcross);
  const Plan only_along = plan_scenario(scenario_of(kAlong));
  const auto message = [&](const Plan& fixed, const std::vector<std::string>& names) {
    try {
      replan_agents(both, fixed, names);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(only_along, {"along"}),
            "fixed: has no plan for agent 'across', which is not among the agents to plan");
  EXPECT_EQ(message(only_along, {"across", "nobody\n"}),
            "agents: 'nobody\\n' is not an agent of the scenario");
  EXPECT_EQ(message(only_along, {}), "agents: name at least one agent to plan");
  // Every agent named: nothing is fixed, and the plan is plan_scenario's.
  EXPECT_EQ(plan_to_json(replan_agents(both, Plan{}, {"along", "across"})),
            plan_to_json(plan_scenario(both)));
}

}  // namespace
}  // namespace footfall
