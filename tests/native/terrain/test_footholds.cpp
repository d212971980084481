// Footsteps on ground: every foothold on it, supported, and the rises
// within the character's limits; the way taken where the ground allows it.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "footfall/crowd/scenario.hpp"
#include "footfall/terrain/ground.hpp"
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
      const Sole sole{{step.foot_position.x, step.foot_position.y, here->z}, here->normal,
                      step.foot_orientation, c.sole_length, c.sole_width};
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

}  // namespace
}  // namespace footfall
