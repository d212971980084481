// The body model: the built-in motions' sizes and the clearances c1 < c2 < c3.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"
#include "footfall/scenes/behavior_scenes.hpp"

namespace footfall {
namespace {

double top_of(const BehaviorMotion& motion) {
  double top = 0;
  for (const BodyPose& pose : motion.poses)
    for (const Capsule& c : pose) top = std::max({top, c.a.z + c.radius, c.b.z + c.radius});
  return top;
}

TEST(BodyModel, BuiltInMotionsHaveTheCharactersMeasures) {
  CharacterParams c;
  const BehaviorMotion walk = builtin_motion(Behavior::kWalk, c);
  const BehaviorMotion arms_in = builtin_motion(Behavior::kArmsIn, c);
  const BehaviorMotion side = builtin_motion(Behavior::kSideStep, c);
  EXPECT_NEAR(lateral_extent(walk), 0.5 * c.arm_swing_width, 1e-9);  // the swing's widest
  EXPECT_NEAR(lateral_extent(arms_in), 0.5 * c.shoulder_width, 1e-9);
  // Turned across the way and centred on it, the body reaches from the back
  // of its chest to its toes, 0.2 m ahead of the ankles: the knees, kept in
  // by the swinging hip rising, and the hands reach less far.
  EXPECT_NEAR(2.0 * lateral_extent(side), 0.5 * c.chest_depth + 0.75 * 0.152 * c.body_height, 1e-9);
  for (const auto* m : {&walk, &arms_in, &side}) {
    EXPECT_NEAR(top_of(*m), c.body_height, 1e-9);
    EXPECT_EQ(m->poses.size(), static_cast<std::size_t>(kBuiltinPhases));
  }
  EXPECT_DOUBLE_EQ(walk.speed, c.preferred_speed);
  EXPECT_DOUBLE_EQ(side.speed, c.side_step_speed);
}

TEST(BodyModel, TheMotionsFollowTheSizes) {
  CharacterParams c;
  c.body_height = 1.5;
  c.arm_swing_width = 0.8;
  const BodyModel body(c);
  EXPECT_NEAR(top_of(body.motion(Behavior::kWalk)), 1.5, 1e-9);
  EXPECT_NEAR(body.clearance(Behavior::kWalk), 0.42, 1e-9);  // 0.4 and the margin
}

TEST(BodyModel, ClearancesRiseFromSideStepToWalk) {
  const BodyModel body{CharacterParams{}};
  EXPECT_LT(body.clearance(Behavior::kSideStep), body.clearance(Behavior::kArmsIn));
  EXPECT_LT(body.clearance(Behavior::kArmsIn), body.clearance(Behavior::kWalk));
}

TEST(BodyModel, OverridesWinAndMustKeepTheOrder) {
  CharacterParams c;
  c.arms_in_clearance = 0.27;
  EXPECT_DOUBLE_EQ(BodyModel(c).clearance(Behavior::kArmsIn), 0.27);
  c.arms_in_clearance = 0.5;  // wider than walking's
  try {
    BodyModel{c};
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("side_step < arms_in < walk"), std::string::npos)
        << e.what();
  }
}

TEST(BodyModel, PosesAreCyclicAndInterpolated) {
  const BodyModel body{CharacterParams{}};
  const double cycle = body.motion(Behavior::kWalk).cycle_duration;
  BodyPose a, b, mid;
  body.pose_at(Behavior::kWalk, 0.1, a);
  body.pose_at(Behavior::kWalk, 0.1 + 3 * cycle, b);
  for (int limb = 0; limb < kLimbCount; ++limb) EXPECT_NEAR(length(a[limb].a - b[limb].a), 0, 1e-9);
  const auto& samples = body.motion(Behavior::kWalk).poses;
  body.pose_at(Behavior::kWalk, 0.5 * cycle / static_cast<double>(samples.size()), mid);
  const int hand = static_cast<int>(Limb::kForearmLeft);
  const Vec3 halfway = 0.5 * (samples[0][hand].b + samples[1][hand].b);
  EXPECT_NEAR(length(mid[hand].b - halfway), 0, 1e-9);
}

TEST(BodyModel, SampledMotionsAreChecked) {
  CharacterParams c;
  BehaviorMotion motion = builtin_motion(Behavior::kWalk, c);
  motion.poses[3][static_cast<int>(Limb::kHead)].radius = 0;
  c.motions[static_cast<int>(Behavior::kWalk)] = motion;
  try {
    BodyModel{c};
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "character.behaviors.walk.poses[3].head: radius must be in (0, 1] m");
  }
}

// A standing body (stops, waits, pivots) keeps its feet together and its arms
// hanging: turning on the spot between knee-high sides 0.45 m apart, the
// walking body with a leg lifted mid-stride would kick them.
TEST(BodyModel, AStandingBodyHasItsFeetTogetherAndItsArmsHanging) {
  const BodyModel body(CharacterParams{});
  for (const Behavior behavior : {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep}) {
    SCOPED_TRACE(to_string(behavior));
    const BodyPose& pose = body.standing(behavior);
    const auto at = [&](Limb limb) { return pose[static_cast<int>(limb)]; };
    for (const Limb foot : {Limb::kFootLeft, Limb::kFootRight}) {
      EXPECT_NEAR(at(foot).a.z, at(foot).radius, 1e-12);
      EXPECT_NEAR(at(foot).b.z, at(foot).radius, 1e-12);
    }
    for (const Limb limb : {Limb::kThighLeft, Limb::kShinLeft, Limb::kUpperArmRight,
                            Limb::kForearmRight}) {
      EXPECT_NEAR(at(limb).a.x, at(limb).b.x, 1e-12);
      EXPECT_NEAR(at(limb).a.y, at(limb).b.y, 1e-12);
    }
  }
  const BehaviorScene scene = corridor_scene();
  const CollisionScene obstacles(scene.scenario.obstacles);
  for (double facing = 0.0; facing < 2.0 * kPi; facing += 0.25) {
    const GroundPlacement between_knee_high_sides{{3.2, 0.0}, facing};
    EXPECT_FALSE(obstacles.test(body.standing(Behavior::kWalk), between_knee_high_sides))
        << facing;
  }
}

}  // namespace
}  // namespace footfall
