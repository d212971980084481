// The full-body test of single footsteps: where the body stands over a step.
#include <gtest/gtest.h>

#include <algorithm>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"
#include "footfall/fullbody/step_body_test.hpp"
#include "footfall/model/footstep.hpp"
#include "footfall/planner/planner.hpp"

namespace footfall {
namespace {

/// How far the pose's legs reach behind its root (along -x). [m]
double legs_behind(const BodyPose& pose) {
  double behind = 0.0;
  for (std::size_t c = static_cast<std::size_t>(Limb::kThighLeft); c < pose.size(); ++c)
    behind = std::max({behind, pose[c].radius - pose[c].a.x, pose[c].radius - pose[c].b.x});
  return behind;
}

/// The first step of a walk from standing at the origin, facing +x, to 3 m
/// ahead: its start.
Footstep first_step(const CharacterParams& character) {
  const std::vector<Obstacle> none;
  const ObstacleMap map(none);
  const FootstepPlanner planner(character, PlannerParams{}, map);
  const SearchResult walk = planner.plan(standing_state({0.0, 0.0}, 0.0, character), {3.0, 0.0});
  EXPECT_EQ(walk.status, Status::kSuccess);
  return walk.footsteps.at(0);
}

// A walk from standing starts with the standing pose's legs, as its feet
// do; the motion's mid-stride pose at its start would reach a foot a stride
// behind, into a kerb the character stands with its back to. (Its arms
// swing with the motion from the start, as the animation swings them.)
TEST(StepBodyTest, AWalkFromStandingStartsFromTheStandingPose) {
  const CharacterParams character;
  const BodyModel body(character);
  const Footstep from_standing = first_step(character);
  ASSERT_EQ(from_standing.kind, StepKind::kStart);
  ASSERT_EQ(from_standing.com_velocity_start, (Vec2{0.0, 0.0}));
  Footstep mid_stride = from_standing;
  mid_stride.com_velocity_start = {1.2, 0.0};

  BodyPose pose;
  GroundPlacement placement;
  pose_during(body, from_standing, from_standing.start_time, pose, placement);
  const double standing_reach = legs_behind(body.standing(Behavior::kWalk));
  EXPECT_DOUBLE_EQ(legs_behind(pose), standing_reach);
  pose_during(body, mid_stride, mid_stride.start_time, pose, placement);
  const double stride_reach = legs_behind(pose);
  ASSERT_GT(stride_reach, standing_reach + 0.1);
  // Both end in the motion's pose.
  BodyPose end_from_standing, end_mid_stride;
  pose_during(body, from_standing, from_standing.end_time, end_from_standing, placement);
  pose_during(body, mid_stride, mid_stride.end_time, end_mid_stride, placement);
  EXPECT_DOUBLE_EQ(legs_behind(end_from_standing), legs_behind(end_mid_stride));

  // A kerb across, behind the character, between the two reaches, below
  // the hands.
  const double wall = -0.5 * (standing_reach + stride_reach);
  const std::vector<Obstacle> obstacles{
      prism({{wall - 0.5, -2.0}, {wall, -2.0}, {wall, 2.0}, {wall - 0.5, 2.0}}, 0.3)};
  const CollisionScene scene(obstacles);
  const StepBodyTest test(scene, body, 30);
  EXPECT_FALSE(test.hits(from_standing));
  EXPECT_TRUE(test.hits(mid_stride));
}

}  // namespace
}  // namespace footfall
