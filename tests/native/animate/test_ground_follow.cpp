// The animation follows the ground: planted soles on their footholds and
// along their slopes, swinging feet clear of every nosing, the body riding up
// a flight and leaning into the climb.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "footfall/animate/ground_follow.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall::animate {
namespace {

constexpr FootExtent kSoleFoot{0.065, 0.195, 0.10};  // the planner's sole
constexpr double kRate = 100.0;                // samples a second

/// The highest ground under a foot's 9 x 3 samples, heel to toe (the heel
/// rounded: half as wide).
double highest_under(const Ground& ground, const FootOnGround& foot) {
  const Vec2 along = unit(foot.heading), across = perp(along);
  double highest = -INFINITY;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec2 p = footfall::ground(foot.sole) +
                     (-kSoleFoot.heel_back + (kSoleFoot.heel_back + kSoleFoot.toe_ahead) * i / 8.0) * along +
                     ((i == 0 ? 0.5 : 1.0) * kSoleFoot.width * (j / 2.0 - 0.5)) * across;
      for (const GroundPoint& level : ground.levels_at(p))
        if (level.z < foot.sole.z + 0.5) highest = std::max(highest, level.z);
    }
  return highest;
}

TEST(GroundFollow, UpAndDownAFlightEverySoleIsOnItsTreadOrClearOfEveryNosing) {
  const Plan plan = plan_scenario(stairs_scenario(2, 2));
  const Ground ground(plan.ground);
  for (const AgentPlan& agent : plan.agents) {
    SCOPED_TRACE(agent.name);
    ASSERT_EQ(agent.status, AgentStatus::kReached);
    const GroundFollower follower(agent, plan.character, ground, kSoleFoot);
    double most_lean = 0, least_lean = 0;
    const int samples = static_cast<int>(agent.end_time() * kRate);
    for (int i = 0; i <= samples; ++i) {
      const double t = i / kRate;
      const std::array<FootPose, 2> feet = feet_at(agent, t);
      for (int side = 0; side < 2; ++side) {
        const FootOnGround foot = follower.foot(feet[side]);
        if (feet[side].planted) {
          EXPECT_NEAR(foot.sole.z, ground.standing_on(feet[side].position, 1.8)->z, 1e-12) << t;
        }
        // No part of the foot under the ground it is over (a toe in a riser).
        EXPECT_GE(foot.sole.z, highest_under(ground, foot) - 0.01) << "t " << t << " side " << side;
        // A swing leaves one foothold and lands on the other without a jump.
        const FootPose& pose = feet[side];
        if (!pose.planted && (pose.swing_phase < 0.01 || pose.swing_phase > 0.99)) {
          const Vec2 end = pose.swing_phase < 0.5 ? pose.swing_from : pose.swing_to;
          EXPECT_NEAR(foot.sole.z, ground.standing_on(end, 1.8)->z, 0.01) << t;
        }
      }
      const double lean = follower.lean(t);
      most_lean = std::max(most_lean, lean);
      least_lean = std::min(least_lean, lean);
    }
    // The body ends on its last foothold's level, up on the landing or down on the floor.
    const bool up = agent.name.rfind("up", 0) == 0;
    EXPECT_NEAR(follower.body_height(feet_at(agent, agent.end_time())), up ? 1.02 : 0.0, 1e-9);
    if (up) {
      EXPECT_GT(most_lean, 0.1);  // leaning into the climb
    } else {
      EXPECT_LT(least_lean, -0.05);
      EXPECT_LE(most_lean, 1e-9);
    }
  }
}

TEST(GroundFollow, OnAHillEachPlantedSoleLiesAlongTheSlopeUnderIt) {
  const Plan plan = plan_scenario(hill_scenario());
  const Ground ground(plan.ground);
  int tilted = 0;
  for (const AgentPlan& agent : plan.agents) {
    const GroundFollower follower(agent, plan.character, ground, kSoleFoot);
    for (double t = 0; t <= agent.end_time(); t += 0.05) {
      for (const FootPose& pose : feet_at(agent, t)) {
        if (!pose.planted) continue;
        const FootOnGround foot = follower.foot(pose);
        const GroundPoint under = *ground.standing_on(pose.position, 1.8);
        EXPECT_NEAR(foot.sole.z, under.z, 1e-12);
        EXPECT_NEAR(dot(foot.normal, under.normal), 1.0, 1e-12);
        tilted += under.normal.z < 0.99 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(tilted, 20);
}

TEST(GroundFollow, WithoutGroundTheFeetAreThePlansAndTheBodyOnTheFloor) {
  Scenario scenario = stairs_scenario(1, 0);
  scenario.ground.clear();
  for (AgentSpec& agent : scenario.agents) agent.goal_heights.clear();
  const Plan plan = plan_scenario(scenario);
  const Ground ground;
  const AgentPlan& agent = plan.agents.front();
  const GroundFollower follower(agent, plan.character, ground, kSoleFoot);
  for (double t = 0; t <= agent.end_time(); t += 0.05) {
    const std::array<FootPose, 2> feet = feet_at(agent, t);
    for (const FootPose& pose : feet) {
      const FootOnGround foot = follower.foot(pose);
      EXPECT_EQ(foot.sole.x, pose.position.x);
      EXPECT_EQ(foot.sole.y, pose.position.y);
      EXPECT_EQ(foot.sole.z, pose.lift);
      EXPECT_EQ(foot.heading, pose.orientation);
    }
    EXPECT_EQ(follower.body_height(feet), 0.0);
    EXPECT_EQ(follower.lean(t), 0.0);
  }
}

}  // namespace
}  // namespace footfall::animate
