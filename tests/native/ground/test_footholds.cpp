// Footsteps on ground: every foothold on it, supported, and the rises
// within the character's limits; the way taken where the ground allows it.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "footfall/crowd/scenario.hpp"
#include "footfall/fullbody/body_check.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/io/scenario_file.hpp"
#include "footfall/plan/ground_check.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/ground/foothold.hpp"
#include "footfall/ground/ground.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall {
namespace {

/// The standable level under `p` (the scenes have one at every point).
std::optional<GroundPoint> level_under(const Ground& ground, Vec2 p, const CharacterParams& c) {
  const std::vector<GroundPoint> levels = ground.standable_at(p, c.body_height);
  if (levels.empty()) return std::nullopt;
  return levels.front();
}

/// Checks every footstep of every agent against the ground; returns the
/// highest foothold of each agent.
std::vector<double> expect_on_ground(const Plan& plan, const Ground& ground) {
  const CharacterParams& c = plan.character;
  std::vector<double> highest;
  for (const AgentPlan& agent : plan.agents) {
    SCOPED_TRACE(agent.name);
    double top = -INFINITY;
    std::array<double, 2> feet{};
    for (int f = 0; f < 2; ++f) feet[f] = level_under(ground, agent.start.feet[f], c)->z;
    for (std::size_t k = 0; k < agent.footsteps.size(); ++k) {
      const Footstep& step = agent.footsteps[k];
      const std::optional<GroundPoint> here = level_under(ground, step.foot_position, c);
      if (!here) {
        ADD_FAILURE() << "step " << k << " over no ground";
        break;
      }
      // The body is posed at the foot's height: every step's, waits' too.
      EXPECT_NEAR(step.foot_height, here->z, 1e-9) << "step " << k;
      const Sole sole = sole_of(c, step.foot_position, *here, step.foot_orientation);
      EXPECT_GE(ground.support(sole, 0.02, std::cos(c.max_slope)), c.sole_support) << "step " << k;
      const int planted = static_cast<int>(step.foot);
      const double rise = here->z - feet[1 - planted];
      EXPECT_LE(rise, c.max_step_up + 1e-12) << "step " << k;
      EXPECT_GE(rise, -c.max_step_down - 1e-12) << "step " << k;
      feet[planted] = here->z;
      top = std::max(top, here->z);
    }
    highest.push_back(top);
  }
  return highest;
}

TEST(Footholds, OneClimbsAFlightATreadAStepAndOneComesDown) {
  const Scenario scenario = stairs_scenario(1, 1);
  const Plan plan = plan_scenario(scenario);
  const Ground ground(scenario.ground);
  for (const AgentPlan& agent : plan.agents)
    EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.name << ": " << agent.reason;
  const std::vector<double> highest = expect_on_ground(plan, ground);
  EXPECT_DOUBLE_EQ(highest[0], kRiser * kStairsTreads) << "on the landing";
  // Each tread of the flight held a foot of the one going up.
  for (int k = 0; k < kStairsTreads - 1; ++k) {
    const bool trod = std::any_of(
        plan.agents[0].footsteps.begin(), plan.agents[0].footsteps.end(), [&](const Footstep& s) {
          return s.foot_position.x > kTreadDepth * k && s.foot_position.x < kTreadDepth * (k + 1);
        });
    EXPECT_TRUE(trod) << "tread " << k;
  }
}

TEST(Footholds, ACrowdGoesUpAndDownAFlightEachOnItsTreadsAndClearOfTheOthers) {
  const Scenario scenario = stairs_scenario(6, 6);
  RunControl control;
  control.threads = 2;
  const Plan plan = plan_scenario(scenario, control);
  for (const AgentPlan& agent : plan.agents)
    EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.name << ": " << agent.reason;
  const std::vector<double> highest = expect_on_ground(plan, Ground(scenario.ground));
  for (std::size_t i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(highest[i], kRiser * kStairsTreads);
  EXPECT_EQ(measure_plan(plan).overlaps, 0);
  const GroundCheck check = check_ground(plan);
  EXPECT_GT(check.footholds, 200);
  EXPECT_EQ(check.off_ground + check.unsupported + check.over_rise + check.swing, 0);
  EXPECT_EQ(plan_to_json(plan_scenario(scenario)), plan_to_json(plan)) << "one thread or two";
}

TEST(Footholds, TheGroundCheckFindsAFootOnANosingOrAStepTooHigh) {
  Plan plan = plan_scenario(stairs_scenario(1, 0));
  std::vector<Footstep>& steps = plan.agents[0].footsteps;
  const auto on_flight = std::find_if(steps.begin(), steps.end(), [](const Footstep& s) {
    return s.foot_position.x > kTreadDepth && s.foot_position.x < 2 * kTreadDepth;
  });
  ASSERT_NE(on_flight, steps.end());
  const Footstep kept = *on_flight;
  // Onto the nosing of the tread above.
  on_flight->foot_position.x = 2 * kTreadDepth - 0.02;
  EXPECT_EQ(check_ground(plan).unsupported, 1);
  // Two treads up from the other foot.
  on_flight->foot_position.x = 3.5 * kTreadDepth;
  EXPECT_GE(check_ground(plan).over_rise, 1);
  // Beside the flight.
  *on_flight = kept;
  on_flight->foot_position.y = kStairsWidth;
  EXPECT_EQ(check_ground(plan).off_ground, 1);
}

TEST(Footholds, APlanOnGroundReadsBackWithItsHeightsCostsAndGround) {
  const Scenario scenario = stairs_scenario(1, 0);
  const Plan plan = plan_scenario(scenario);
  const std::string text = plan_to_json(plan);
  const Plan back = parse_plan(text);
  EXPECT_EQ(plan_to_json(back), text);
  ASSERT_EQ(back.ground.size(), scenario.ground.size());
  const std::vector<Footstep>& steps = back.agents[0].footsteps;
  ASSERT_EQ(steps.size(), plan.agents[0].footsteps.size());
  double climbed = 0.0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_EQ(steps[k].foot_height, plan.agents[0].footsteps[k].foot_height);
    EXPECT_EQ(steps[k].cost.terrain, plan.agents[0].footsteps[k].cost.terrain);
    climbed = std::max(climbed, steps[k].foot_height);
  }
  EXPECT_DOUBLE_EQ(climbed, kRiser * kStairsTreads);
  // Up the flight costs some 4.5 times the potential energy of its rise
  // (the step onto the first tread, longer, as a gradient).
  double terrain = 0.0;
  for (const Footstep& step : steps) terrain += step.cost.terrain;
  const double potential = plan.character.mass * 9.81 * kRiser * kStairsTreads;
  EXPECT_GT(terrain, 3.5 * potential);
  EXPECT_LT(terrain, 5.0 * potential);
  // A flat plan's file names no ground, heights or ground costs.
  const std::string flat = plan_to_json(plan_scenario(two_way_hall_scenario(4, 1)));
  for (const char* absent : {"\"ground\"", "foot_height", "\"terrain\"", "max_step_up"})
    EXPECT_EQ(flat.find(absent), std::string::npos) << absent;
}

/// A scenario of `ground` and one agent, as JSON text.
std::string one_on(const std::string& ground, const std::string& position,
                   const std::string& goal) {
  return R"({"format": "footfall-scenario", "version": 1, "ground": )" + ground +
         R"(, "agents": [{"name": "ann", "position": )" + position + R"(, "goals": [)" + goal +
         "]}]}";
}

std::string refusal(const std::string& text) {
  try {
    plan_scenario(parse_scenario(text));
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(Footholds, AgentsAndGoalsOffTheGroundOrItsHeightAreRefused) {
  const std::string floor = R"([{"polygon": [[-5, -5], [5, -5], [5, 5], [-5, 5]], "height": 0.5}])";
  EXPECT_EQ(refusal(one_on(floor, "[0, 0]", "[8, 0]")),
            "<string>: agents[0].goals[0]: over no ground to stand on");
  EXPECT_EQ(refusal(one_on(floor, "[9, 0]", "[2, 0]")),
            "<string>: agents[0].position: over no ground to stand on");
  EXPECT_EQ(refusal(one_on(floor, "[0, 0, 2]", "[2, 0]")),
            "<string>: agents[0].position: no ground to stand on within 0.50 m of its height "
            "2.00 m (the ground there is at 0.50 m)");
  EXPECT_EQ(refusal(R"({"format": "footfall-scenario", "version": 1, "agents": [{"name": "b",
            "position": [0, 0, 0.8], "goals": [[3, 0]]}]})"),
            "<string>: agents[0].position: at a height of 0.80 m, but the scenario has no "
            "ground: its floor is z = 0");
  // Its heel over the floor's edge.
  EXPECT_EQ(refusal(one_on(floor, "[4.998, 0]", "[2, 0]"))
                .rfind("<string>: agents[0].position: the standing agent's left foot is not on "
                       "the ground (",
                       0),
            0u);
  const std::string bridge = R"([{"polygon": [[-5, -5], [5, -5], [5, 5], [-5, 5]], "height": 0},
      {"polygon": [[-1, -5], [1, -5], [1, 5], [-1, 5]], "height": 4.5, "base": 4.3}])";
  EXPECT_EQ(refusal(one_on(bridge, "[-3, 0]", "[3, 0]")), "");  // under the deck
  EXPECT_EQ(refusal(one_on(bridge, "[-3, 0]", "[0, 0]")),
            "<string>: agents[0].goals[0]: 2 levels of ground under it, at 0.00 m and 4.50 m: "
            "give its height, [x, y, z]");
  EXPECT_EQ(refusal(one_on(bridge, "[0, 0]", "[3, 0]")),
            "<string>: agents[0].position: 2 levels of ground under it, at 0.00 m and 4.50 m: "
            "give its height, [x, y, z]");
  EXPECT_EQ(refusal(one_on(R"([{"polygon": [[0, 0], [1, 0], [1, 1], [0, 1]]}])", "[0.5, 0.5]",
                           "[0.5, 0.5]")),
            "<string>: ground[0].height: missing");
}

TEST(Footholds, APlatformTooHighToStepUpIsReachedByTheRampBesideIt) {
  const Scenario scenario = ramp_scenario();
  const Plan plan = plan_scenario(scenario);
  const AgentPlan& walker = plan.agents[0];
  ASSERT_EQ(walker.status, AgentStatus::kReached) << walker.reason;
  expect_on_ground(plan, Ground(scenario.ground));
  // Up by the ramp: it crossed y = 2 before reaching the platform.
  const auto up = std::find_if(walker.footsteps.begin(), walker.footsteps.end(),
                               [](const Footstep& s) {
                                 return s.foot_height > kPlatformHeight - 0.01;
                               });
  ASSERT_NE(up, walker.footsteps.end());
  EXPECT_GT(up->foot_position.y, 1.9);
}

TEST(Footholds, AnObstacleBlocksByItsHeightAboveTheGroundUnderIt) {
  // A beam 2.2 m up over the landing (1.02 m): 1.18 m of headroom there,
  // blocking as a wall would; the body is posed at its height there.
  Scenario scenario = stairs_scenario(1, 0);
  const double top = kTreadDepth * kStairsTreads;
  scenario.obstacles.push_back(
      prism({{top + 2, -kStairsWidth / 2}, {top + 2.3, -kStairsWidth / 2},
             {top + 2.3, kStairsWidth / 2}, {top + 2, kStairsWidth / 2}},
            2.4, 2.2));
  scenario.agents[0].time_limit = 30;
  const Plan plan = plan_scenario(scenario);
  EXPECT_EQ(plan.agents[0].status, AgentStatus::kPartial);
  EXPECT_EQ(check_body(plan).penetrations, 0);
  for (const Footstep& step : plan.agents[0].footsteps) EXPECT_LT(step.foot_position.x, top + 2.3);
  // The same beam over the floor leaves room to walk under it.
  Scenario floor = ramp_scenario();
  floor.obstacles.push_back(prism({{-1, -4}, {-0.7, -4}, {-0.7, 0}, {-1, 0}}, 2.4, 2.2));
  const Plan under = plan_scenario(floor);
  EXPECT_EQ(under.agents[0].status, AgentStatus::kReached) << under.agents[0].reason;
  EXPECT_EQ(check_body(under).penetrations, 0);
}

TEST(Footholds, WalkersCrossAHillWithEveryFootOnItsSlope) {
  const Scenario scenario = hill_scenario();
  const Plan plan = plan_scenario(scenario);
  for (const AgentPlan& agent : plan.agents)
    EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.name << ": " << agent.reason;
  const std::vector<double> highest = expect_on_ground(plan, Ground(scenario.ground));
  EXPECT_GT(highest[0], 2.0) << "over the hill, not round it";
  const GroundCheck check = check_ground(plan);
  EXPECT_GT(check.footholds, 60);
  EXPECT_EQ(check.off_ground + check.unsupported + check.over_rise + check.swing, 0);
}

TEST(Footholds, ASlopeTooSteepIsWalledRoundAndWalkedRound) {
  // A mound 3 m high and 1 m wide (a Gaussian): steeper than max_slope (25
  // degrees) from 0.16 m to 2.3 m from its top, where it is 0.21 m high.
  Scenario scenario;
  scenario.ground.push_back(hill_field(60, 0.3, 3.0, 1.0));
  scenario.agents.push_back({"walker", {-8, 0.2}, 0.0, {{8, 0.2}}});
  const Ground ground(scenario.ground);
  const std::vector<GroundWall> walls =
      ground.walls(0.25, 1.75, std::cos(scenario.character.max_slope));
  double farthest = 0;  // of the walls on the mound, not round the field's rim
  for (const GroundWall& wall : walls)
    if (length(wall.a) < 5) farthest = std::max(farthest, length(wall.a));
  EXPECT_NEAR(farthest, 2.3, 0.3) << "the steep ring is walled round";
  const Plan plan = plan_scenario(scenario);
  ASSERT_EQ(plan.agents[0].status, AgentStatus::kReached) << plan.agents[0].reason;
  const GroundCheck check = check_ground(plan);
  EXPECT_EQ(check.off_ground + check.unsupported + check.over_rise + check.swing, 0);
  for (const Footstep& step : plan.agents[0].footsteps) {
    EXPECT_GT(length(step.foot_position), 2.0);
    EXPECT_LT(step.foot_height, 0.3);
  }
}

}  // namespace
}  // namespace footfall
