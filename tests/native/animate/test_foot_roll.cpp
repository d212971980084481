// Heel-toe roll: the foot turns about the point it rests on, and rolls only
// where the body walks over it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// A sole on the ground, seen from the side: vertices every centimetre from
// the heel to 3 cm behind the toe joint (0.135 ahead) skinned to the foot,
// and one 5 mm up at the heel; from 1 cm ahead of the joint to the tip, to
// the toe; and one under the joint, skinned `under_joint` to the foot.
std::vector<SoleVertex> sole(double under_joint) {
  std::vector<SoleVertex> skin{{-0.065, 0.005, 1.0, 0.0}};
  for (int k = 0; k <= 17; ++k) skin.push_back({-0.065 + 0.01 * k, 0.0, 1.0, 0.0});
  for (int k = 1; k <= 6; ++k) skin.push_back({kFoot.ball_ahead + 0.01 * k, 0.0, 0.0, 1.0});
  skin.push_back({kFoot.ball_ahead, 0.0, under_joint, 1.0 - under_joint});
  return skin;
}

TEST(FootRoll, TheHeelRisesNoFurtherThanLetsTheSkinUnderTheBallSlide) {
  // A vertex under the joint, skinned 0.4 to the foot, slides back
  // 0.4 x 0.025 m x sin(pitch) as the heel rises: 4 mm at 23.6 degrees.
  const double limit = steepest_toe_off(kFoot, sole(0.4));
  EXPECT_NEAR(limit, std::asin(kSoleSlide / (0.4 * kFoot.ball_height)), kToeOff / 120);
  EXPECT_LE(0.4 * kFoot.ball_height * std::sin(limit), kSoleSlide);
  FootShape shape = kFoot;
  shape.toe_off_limit = limit;
  const FootRoller roller(walking_plan(), 1.3);
  EXPECT_NEAR(roller.at(1.0 - 1e-9, 1, true, shape).pitch, -limit, 1e-6);
  EXPECT_NEAR(roller.at(1.0 + 1e-9, 1, false, shape).pitch, -limit, 1e-6);  // and swings from there
  // Skinned wholly to the toe, the skin under the joint stays put; wholly to
  // the foot, it slides 2.5 cm x sin(pitch), 4 mm at 9 degrees, while it has
  // risen only 0.3 mm: still touching.
  EXPECT_EQ(steepest_toe_off(kFoot, sole(0.0)), kToeOff);
  EXPECT_LT(steepest_toe_off(kFoot, sole(1.0)), limit);
  // Without a mesh: the full toe-off.
  EXPECT_EQ(steepest_toe_off(kFoot, {}), kToeOff);
}

}  // namespace
}  // namespace footfall::animate
