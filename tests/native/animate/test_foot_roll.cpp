// Heel-toe roll: the foot turns about the point it rests on, and rolls only
// where the body walks over it.
#include <gtest/gtest.h>

#include <cmath>

#include "footfall/animate/foot_roll.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall::animate {
namespace {

const FootShape kFoot{0.085, 0.065, 0.135, 0.025};

double distance(double dx, double dz) { return std::hypot(dx, dz); }

TEST(FootRoll, TurningOnTheHeelKeepsTheAnkleAsFarFromIt) {
  const FootRoll r = roll_at_pitch(kFoot, 0.25);
  // The heel's contact is (-heel_back, 0) from the point under the ankle.
  EXPECT_NEAR(distance(r.forward + kFoot.heel_back, kFoot.ankle_height + r.up),
              distance(kFoot.heel_back, kFoot.ankle_height), 1e-12);
  EXPECT_GT(r.up, 0.0);
}

TEST(FootRoll, TurningOnTheBallKeepsTheAnkleAsFarFromIt) {
  const FootRoll r = roll_at_pitch(kFoot, -0.5);
  EXPECT_NEAR(distance(r.forward - kFoot.ball_ahead, kFoot.ankle_height + r.up - kFoot.ball_height),
              distance(kFoot.ball_ahead, kFoot.ankle_height - kFoot.ball_height), 1e-12);
  EXPECT_GT(r.forward, 0.0);  // the ankle rises and comes forward over the ball
}

// Four walking steps at 1.3 m/s, left foot first.
AgentPlan walking_plan() {
  AgentPlan plan;
  for (int i = 0; i < 4; ++i) {
    Footstep step;
    step.foot = i % 2 == 0 ? Foot::kLeft : Foot::kRight;
    step.start_time = 0.5 * i;
    step.end_time = 0.5 * (i + 1);
    step.com_start = {0.65 * i, 0};
    step.com_end = {0.65 * (i + 1), 0};
    plan.footsteps.push_back(step);
  }
  return plan;
}

TEST(FootRoll, AStanceStrikesOnTheHeelGoesFlatAndLeavesOnTheBall) {
  const AgentPlan plan = walking_plan();
  const FootRoller roller(plan, 1.3);
  const int right = 1;  // the second step's stance
  EXPECT_NEAR(roller.at(0.5, right, true, kFoot).pitch, kHeelStrike, 1e-12);
  EXPECT_EQ(roller.at(0.5 + 0.5 * 0.3, right, true, kFoot).pitch, 0.0);
  EXPECT_NEAR(roller.at(1.0 - 1e-9, right, true, kFoot).pitch, -kToeOff, 1e-6);
  // The first stance set off from standing: no heel strike, but a toe-off.
  EXPECT_EQ(roller.at(0.0, 0, true, kFoot).pitch, 0.0);
  EXPECT_LT(roller.at(0.5 - 1e-9, 0, true, kFoot).pitch, 0.0);
  // The last: no toe-off, the agent stops there.
  EXPECT_EQ(roller.at(2.0 - 1e-9, right, true, kFoot).pitch, 0.0);
}

TEST(FootRoll, SideStepsStayFlat) {
  AgentPlan plan = walking_plan();
  for (Footstep& step : plan.footsteps) step.kind = StepKind::kSideStep;
  const FootRoller roller(plan, 1.3);
  for (double t = 0; t < 2.0; t += 0.05) {
    EXPECT_EQ(roller.at(t, 0, true, kFoot).pitch, 0.0) << t;
    EXPECT_EQ(roller.at(t, 1, false, kFoot).pitch, 0.0) << t;
  }
}

}  // namespace
}  // namespace footfall::animate
