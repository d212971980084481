// check_motion measures what an animator sees of a plan: velocity jumps at
// step boundaries, and stance feet that move.
#include <gtest/gtest.h>

#include <cmath>

#include "footfall/model/footstep.hpp"
#include "footfall/plan/motion_check.hpp"
#include "plan/action_plan.hpp"

namespace footfall {
namespace {

TEST(MotionCheck, FindsAJumpAndAFootThatSlides) {
  // A first walk from standing, told as one step (no start before it): its
  // foot, with no step before it to swing in, moves in a lead-in at the start
  // of its stance. Written as an older planner wrote it, it also sets off at
  // full speed.
  AgentPlan plan = plan_of({{StepKind::kWalk, Foot::kLeft, -0.04, 1.3, 0.5},
                            {StepKind::kWalk, Foot::kRight, 0.0, 1.3, 0.5},
                            {StepKind::kWalk, Foot::kLeft, -0.04, 1.3, 0.5}});
  MotionCheck check = check_motion(plan);
  EXPECT_LT(check.velocity_jump, 1e-9);
  EXPECT_GT(check.stance_slide, 0.3);  // the first stride
  EXPECT_EQ(check.worst_slide_step, 0);
  plan.footsteps[0].com_velocity_start = {1.3, 0.0};
  check = check_motion(plan);
  EXPECT_NEAR(check.velocity_jump, 1.3, 1e-12);
  EXPECT_EQ(check.worst_jump_step, 0);
  EXPECT_THROW(check_motion(plan, 0.0), std::invalid_argument);
}

TEST(MotionCheck, AStartedWalkMovesSmoothly) {
  // After a wait by the left foot the right swings in while it stands, and
  // a first walk split into a start moves no stance foot either.
  const AgentPlan waited = plan_of({{StepKind::kStop, Foot::kLeft, 0.0, 0.0, 0.5},
                                    {StepKind::kWalk, Foot::kRight, 0.04, 1.3, 0.5},
                                    {StepKind::kWalk, Foot::kLeft, 0.0, 1.3, 0.5}});
  AgentPlan started = plan_of({{StepKind::kWalk, Foot::kLeft, -0.04, 1.3, 0.5},
                               {StepKind::kWalk, Foot::kRight, 0.0, 1.3, 0.5}});
  const auto parts = split_set_off(started.footsteps[0], started.start, kSetOffSwing);
  started.footsteps.erase(started.footsteps.begin());
  started.footsteps.insert(started.footsteps.begin(), parts.begin(), parts.end());
  for (const AgentPlan* plan : {&waited, static_cast<const AgentPlan*>(&started)}) {
    const MotionCheck check = check_motion(*plan);
    EXPECT_LT(check.stance_slide, 1e-9);
    EXPECT_LT(check.velocity_jump, 1e-9);
    EXPECT_LE(check.top_speed, 1.8);  // setting off from rest: above 1.3 midway
  }
  // A start's foot stays as it was put down whatever orientation the start
  // records (a crowd chooses them again once its plan is complete; checks
  // made before must see the same feet).
  started.footsteps[0].foot_orientation += 0.3;
  EXPECT_LT(check_motion(started).stance_slide, 1e-9);
  EXPECT_TRUE(feet_at(started, 0.1)[static_cast<int>(started.footsteps[0].foot)].planted);
}

// A first wait whose foot orientation the post-process chose a bit off the
// standing one's (a crowd's box field, seed 190) keeps that foot planted: it
// was swung in a lead-in, a slide of 1e-6 m in check_motion. A turn of a
// millionth of a radian is a pivot and swings it.
TEST(MotionCheck, AFootTurnedByARoundingErrorStaysPlanted) {
  AgentPlan waited = plan_of({{StepKind::kStop, Foot::kLeft, 0.0, 0.0, 0.5},
                              {StepKind::kWalk, Foot::kRight, 0.04, 1.3, 0.5}});
  double& turned = waited.footsteps[0].foot_orientation;
  const double standing = turned;
  turned = std::nextafter(standing, 1.0);
  EXPECT_TRUE(feet_at(waited, 0.05)[0].planted);
  EXPECT_LT(check_motion(waited).stance_slide, 1e-9);
  turned = standing + 1e-6;
  EXPECT_FALSE(feet_at(waited, 0.05)[0].planted);
}

}  // namespace
}  // namespace footfall
