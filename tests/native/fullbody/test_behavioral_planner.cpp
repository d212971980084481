// The behavioural path planner on the paper's scenes: the sections and their
// behaviours, zero contacts along them, the mesh as it was, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "footfall/fullbody/behavioral_planner.hpp"
#include "footfall/fullbody/body_check.hpp"
#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/body_sweep.hpp"
#include "footfall/fullbody/step_body_test.hpp"
#include "footfall/plan/section_lookup.hpp"
#include "footfall/planner/planner.hpp"
#include "footfall/scenes/behavior_scenes.hpp"

namespace footfall {
namespace {

// Everything a query needs, for one scene.
struct Planning {
  explicit Planning(const Scenario& s)
      : scenario(s),
        mesh(navmesh_of(s)),
        scene(s.obstacles),
        body(s.character),
        planner(mesh, scene, body, s.planner) {}
  Scenario scenario;
  NavMesh mesh;
  CollisionScene scene;
  BodyModel body;
  BehavioralPlanner planner;
};

std::vector<std::string> behaviors_of(const BehaviorPath& path) {
  std::vector<std::string> names;
  for (const BehaviorSection& s : path.sections) names.push_back(to_string(s.behavior));
  return names;
}

// Every section swept with its own behaviour meets nothing, and the
// sections join end to end.
void expect_collision_free(const Planning& setup, const BehaviorPath& path) {
  for (std::size_t i = 0; i < path.sections.size(); ++i) {
    const BehaviorSection& s = path.sections[i];
    const BodyCollision hit =
        sweep_body(setup.scene, setup.body, s.behavior, s.points, setup.scenario.planner.pose_rate);
    EXPECT_FALSE(hit.hit) << "section " << i << " (" << to_string(s.behavior) << ") meets obstacles["
                          << hit.contact.obstacle << "] at (" << hit.root.x << ", " << hit.root.y
                          << ")";
    if (i > 0) {
      EXPECT_TRUE(path.sections[i - 1].points.back() == s.points.front()) << i;
    }
  }
}

TEST(BehavioralPlanner, DoorBendsAroundTheClutterAndHoldsTheArmsIn) {
  const BehaviorScene scene = door_scene();
  Planning setup(scene.scenario);
  const BehaviorPath path = setup.planner.plan(scene.start, scene.goals[0]);
  ASSERT_EQ(path.status, BehaviorPathStatus::kFound) << path.reason;
  EXPECT_EQ(behaviors_of(path), (std::vector<std::string>{"walk", "arms_in", "walk"}));
  EXPECT_GT(path.point_obstacles, 0);  // the cabinets bend the path
  // The arms-in section spans the door in the wall at x = 0.
  EXPECT_LT(path.sections[1].points.front().x, -0.1);
  EXPECT_GT(path.sections[1].points.back().x, 0.1);
  expect_collision_free(setup, path);
}

TEST(BehavioralPlanner, CorridorTakesArmsInThenWalkThenSideStep) {
  const BehaviorScene scene = corridor_scene();
  Planning setup(scene.scenario);
  const BehaviorPath path = setup.planner.plan(scene.start, scene.goals[0]);
  ASSERT_EQ(path.status, BehaviorPathStatus::kFound) << path.reason;
  EXPECT_EQ(behaviors_of(path),
            (std::vector<std::string>{"walk", "arms_in", "walk", "side_step", "walk"}));
  // The side-step section holds the narrowest part, x from 4.5 to 6.5.
  EXPECT_LT(path.sections[3].points.front().x, 4.5);
  EXPECT_GT(path.sections[3].points.back().x, 6.5);
  expect_collision_free(setup, path);
}

TEST(BehavioralPlanner, AGapNarrowerThanSideSteppingHasNoPath) {
  const BehaviorScene scene = gap_scene();
  Planning setup(scene.scenario);
  const BehaviorPath path = setup.planner.plan(scene.start, scene.goals[0]);
  EXPECT_EQ(path.status, BehaviorPathStatus::kNoPath);
  EXPECT_TRUE(path.sections.empty());
  EXPECT_FALSE(path.reason.empty());
}

TEST(BehavioralPlanner, AnOpenFieldIsOneWalkAlongTheShortestPath) {
  const BehaviorScene scene = open_field_scene();
  Planning setup(scene.scenario);
  const BehaviorPath path = setup.planner.plan(scene.start, scene.goals[0]);
  ASSERT_EQ(path.status, BehaviorPathStatus::kFound);
  ASSERT_EQ(behaviors_of(path), std::vector<std::string>{"walk"});
  EXPECT_NEAR(path.length, distance(scene.start, scene.goals[0]), 1e-9);
  EXPECT_EQ(path.point_obstacles, 0);
}

TEST(BehavioralPlanner, TheMeshAnswersAsBeforeAndQueriesRepeat) {
  for (const std::string name : {"door", "corridor", "random_dense_10"}) {
    const BehaviorScene scene = behavior_scene(name);
    Planning setup(scene.scenario);
    std::vector<PathResult> before;
    for (const Vec2 goal : scene.goals) before.push_back(setup.mesh.find_path({scene.start, goal, 0.2}));
    const std::size_t triangles = setup.mesh.triangle_count();
    int inserted = 0;
    std::vector<BehaviorPath> first;
    for (const Vec2 goal : scene.goals) {
      first.push_back(setup.planner.plan(scene.start, goal));
      inserted += first.back().point_obstacles;
    }
    EXPECT_GT(inserted, 0) << name;
    EXPECT_EQ(setup.mesh.triangle_count(), triangles) << name;
    for (std::size_t g = 0; g < scene.goals.size(); ++g) {
      const PathResult after = setup.mesh.find_path({scene.start, scene.goals[g], 0.2});
      ASSERT_EQ(after.status, before[g].status) << name << " " << g;
      ASSERT_EQ(after.points.size(), before[g].points.size()) << name << " " << g;
      for (std::size_t k = 0; k < after.points.size(); ++k)
        EXPECT_TRUE(after.points[k] == before[g].points[k]) << name << " " << g;
      // Determinism: the same query gives the same sections.
      const BehaviorPath again = setup.planner.plan(scene.start, scene.goals[g]);
      EXPECT_EQ(again.status, first[g].status);
      ASSERT_EQ(again.sections.size(), first[g].sections.size()) << name << " " << g;
      for (std::size_t s = 0; s < again.sections.size(); ++s) {
        EXPECT_EQ(again.sections[s].behavior, first[g].sections[s].behavior);
        EXPECT_EQ(again.sections[s].length, first[g].sections[s].length);
      }
    }
  }
}

TEST(BehavioralPlanner, RandomEnvironmentsGiveCollisionFreeSections) {
  for (const std::string name : {"random_normal_6", "random_normal_10", "random_dense_6",
                                  "random_dense_10"}) {
    const BehaviorScene scene = behavior_scene(name);
    Planning setup(scene.scenario);
    int found = 0, narrower = 0;
    for (const Vec2 goal : scene.goals) {
      const BehaviorPath path = setup.planner.plan(scene.start, goal);
      ASSERT_NE(path.status, BehaviorPathStatus::kTimeLimit) << name;
      if (path.status != BehaviorPathStatus::kFound) continue;
      ++found;
      for (const BehaviorSection& s : path.sections) narrower += s.behavior != Behavior::kWalk;
      expect_collision_free(setup, path);
    }
    EXPECT_GE(found, 90) << name;
    if (name.find("dense") != std::string::npos) {
      EXPECT_GT(narrower, 0) << name;
    }
  }
}

TEST(BehavioralPlanner, TheHorizonCutsTheWay) {
  BehaviorScene scene = open_field_scene();
  scene.scenario.planner.behavior_horizon = 3.0;
  Planning setup(scene.scenario);
  const BehaviorPath path = setup.planner.plan(scene.start, scene.goals[0]);
  EXPECT_EQ(path.status, BehaviorPathStatus::kHorizon);
  EXPECT_NEAR(path.length, 3.0, 1e-9);
}

TEST(BehavioralPlanner, OutOfTimeTheRestIsOneSideStepSection) {
  BehaviorScene scene = corridor_scene();
  scene.scenario.planner.behavior_time_limit = 1e-9;
  Planning setup(scene.scenario);
  const BehaviorPath path = setup.planner.plan(scene.start, scene.goals[0]);
  EXPECT_EQ(path.status, BehaviorPathStatus::kTimeLimit);
  ASSERT_FALSE(path.sections.empty());
  EXPECT_EQ(path.sections.back().behavior, Behavior::kSideStep);
  EXPECT_TRUE(path.sections.back().points.back() == scene.goals[0]);
}

TEST(BehavioralPlanner, ObstaclesAboveTheHeadAreNotInTheWay) {
  // A beam across the way, its underside above the head: walked under.
  Scenario s;
  s.obstacles.push_back(prism({{2, -3}, {2.3, -3}, {2.3, 3}, {2, 3}}, 2.3, 1.9));
  s.agents.push_back({"walker", {0, 0}, 0.0, {{5, 0}}});
  Planning setup(s);
  const BehaviorPath under = setup.planner.plan({0, 0}, {5, 0});
  ASSERT_EQ(under.status, BehaviorPathStatus::kFound);
  EXPECT_EQ(behaviors_of(under), std::vector<std::string>{"walk"});
  EXPECT_NEAR(under.length, 5.0, 1e-9);
  // Lowered below the head, it blocks the way like a wall.
  s.obstacles[0].base = 1.5;
  Planning lowered(s);
  const BehaviorPath around = lowered.planner.plan({0, 0}, {5, 0});
  ASSERT_EQ(around.status, BehaviorPathStatus::kFound);
  EXPECT_GT(around.length, 6.0);
}

}  // namespace
}  // namespace footfall

namespace footfall {
namespace {

// Footsteps on the door scene: every plan lists its sections, each step has
// its section's behaviour; following them (planner.follow_sections), the
// character walks through the door with its arms in and no limb enters an
// obstacle.
TEST(BehavioralFootsteps, TheDoorIsWalkedThroughWithTheArmsIn) {
  BehaviorScene scene = door_scene();
  for (const int follow : {0, 1}) {
    SCOPED_TRACE(follow);
    scene.scenario.planner.follow_sections = follow;
    const Plan plan = plan_scenario(scene.scenario);
    const AgentPlan& agent = plan.agents.front();
    EXPECT_EQ(agent.status, AgentStatus::kReached);
    ASSERT_EQ(agent.sections.size(), 3u);
    EXPECT_EQ(agent.sections[1].behavior, Behavior::kArmsIn);
    const SectionLookup lookup(agent.sections);
    for (const Footstep& step : agent.footsteps) EXPECT_EQ(step.behavior, lookup.of(step));
    if (follow == 0) continue;
    int through = 0;
    for (const Footstep& step : agent.footsteps) {
      if (step.com_start.x < 0.0 && step.com_end.x > 0.0) {
        ++through;
        EXPECT_EQ(step.behavior, Behavior::kArmsIn);
        EXPECT_EQ(step.kind, StepKind::kWalk);
      }
    }
    EXPECT_EQ(through, 1);
    EXPECT_EQ(check_body(plan).penetrations, 0);
  }
}

// The corridor's footsteps, following its sections: arms in along the first
// passage (0.58 m), walking between the knee-high sides (0.45 m; the
// side-step section starts some 0.6 m before the tall sides, where the
// character turns), then turned across the last passage (tall; 0.45 m, and
// 1.5 times the chest's depth, 0.39 m) and stepping sideways; the
// character may stand in passages too narrow to turn in, and no limb enters
// an obstacle. Each section is entered: the character reaches the goal.
class CorridorFootsteps : public ::testing::TestWithParam<double> {};

TEST_P(CorridorFootsteps, TheCorridorIsWalkedArmsInThenWalkingThenSideStepping) {
  const BehaviorScene scene = corridor_scene(GetParam() * CharacterParams{}.chest_depth);
  const Plan plan = plan_scenario(scene.scenario);
  const AgentPlan& agent = plan.agents.front();
  EXPECT_EQ(agent.status, AgentStatus::kReached);
  std::vector<Behavior> inside[3];  // the behaviours of the steps within each passage
  for (const Footstep& step : agent.footsteps) {
    const Vec2 middle = 0.5 * (step.com_start + step.com_end);
    if (std::fabs(middle.y) > 0.3) continue;
    const int passage = middle.x > 0.3 && middle.x < 1.7   ? 0
                        : middle.x > 2.3 && middle.x < 3.5 ? 1
                        : middle.x > 4.8 && middle.x < 6.2 ? 2
                                                           : -1;
    if (passage >= 0) inside[passage].push_back(step.behavior);
  }
  const Behavior expected[3] = {Behavior::kArmsIn, Behavior::kWalk, Behavior::kSideStep};
  for (int p = 0; p < 3; ++p) {
    SCOPED_TRACE(p);
    EXPECT_FALSE(inside[p].empty());
    for (const Behavior behavior : inside[p]) EXPECT_EQ(behavior, expected[p]);
  }
  int lateral = 0;
  for (const Footstep& step : agent.footsteps) lateral += step.kind == StepKind::kSideStep ? 1 : 0;
  EXPECT_GE(lateral, 6);  // 1.4 m in steps of 0.25 m at most
  EXPECT_EQ(check_body(plan).penetrations, 0);
}

INSTANTIATE_TEST_SUITE_P(LastGapOverChestDepth, CorridorFootsteps,
                         ::testing::Values(0.45 / 0.26, 1.5));

// The side-stepping body is centred on its way: from the back of its chest
// to its toes it is 0.33 m wide, and its clearance keeps 2 cm more each
// side. The only door of a room 5 cm wider than that is side-stepped
// through; one 1 cm narrower than the body has no way for it, and the walker
// says so and stands inside.
TEST(BehavioralFootsteps, ADoorNarrowerThanTheSideSteppingBodyIsRefused) {
  const double width =
      2.0 * lateral_extent(BodyModel(CharacterParams{}).motion(Behavior::kSideStep));
  EXPECT_NEAR(width, 0.33, 0.005);
  for (const double door : {width + 0.05, width - 0.01}) {
    SCOPED_TRACE(door);
    const BehaviorScene scene = gap_scene(door);
    const bool passes = door > width;
    Planning setup(scene.scenario);
    EXPECT_EQ(setup.planner.plan(scene.start, scene.goals[0]).status,
              passes ? BehaviorPathStatus::kFound : BehaviorPathStatus::kNoPath);
    const Plan plan = plan_scenario(scene.scenario);
    const AgentPlan& agent = plan.agents.front();
    EXPECT_EQ(agent.status, passes ? AgentStatus::kReached : AgentStatus::kPartial);
    EXPECT_EQ(agent.reason, passes ? "" : "unreachable");
    EXPECT_EQ(agent.narrowest.has_value(), !passes);
    if (!passes) {
      EXPECT_NEAR(agent.narrowest->width, door, 0.02);
    }
    EXPECT_EQ(agent.footsteps.back().com_end.x < 2.0, !passes);
    EXPECT_EQ(check_body(plan).penetrations, 0);
  }
}

// A passage a few millimetres wider than the side-on body and metres deep,
// at any heading: the character squares up to its way and side-steps
// through on it (it stalled at the mouth of one 2.1 m deep before), and no
// limb enters an obstacle.
TEST(BehavioralFootsteps, ADeepPassageBarelyWideEnoughIsSideSteppedThrough) {
  for (const double depth : {2.1, 6.0}) {
    for (const double heading : {0.0, 0.5}) {
      SCOPED_TRACE(std::to_string(depth) + " m deep, heading " + std::to_string(heading));
      Scenario s;
      const double gap = 2.0 * BodyModel(s.character).clearance(Behavior::kSideStep) + 0.004;
      const auto turned = [&](Vec2 p) {
        return Vec2{std::cos(heading) * p.x - std::sin(heading) * p.y, std::sin(heading) * p.x + std::cos(heading) * p.y};
      };
      for (const double side : {1.0, -1.0}) {
        const double near = side * 0.5 * gap, far = side * 20.0;
        s.obstacles.push_back(prism({turned({5.0 - depth / 2, near}), turned({5.0 + depth / 2, near}),
                                     turned({5.0 + depth / 2, far}), turned({5.0 - depth / 2, far})}));
      }
      const Vec2 start = turned({1.0, 0.0}), goal = turned({5.0 + depth / 2 + 3.0, 0.0});
      s.agents.push_back({"walker", start, heading, {goal}});
      const Plan plan = plan_scenario(s);
      const AgentPlan& agent = plan.agents.front();
      EXPECT_EQ(agent.status, AgentStatus::kReached);
      int lateral = 0;
      for (const Footstep& step : agent.footsteps) lateral += step.kind == StepKind::kSideStep ? 1 : 0;
      EXPECT_GE(lateral, static_cast<int>(depth / 0.25));
      EXPECT_EQ(check_body(plan).penetrations, 0);
    }
  }
}

// Seed 128 of the box field: an agent stood side-on, 10 degrees askew, in a
// gap 0.42 m wide between two boxes, where its annotated way was arms-in
// along the gap. A side step straight across its askew facing drifts 5 cm
// toward one box or the other, and neither the tabled pivots nor the steps
// toward its goal leave a body that fits; squared up to the way (across it,
// to side-step along it, or along it, to walk) it steps out.
TEST(BehavioralFootsteps, ABodyAskewInAnArmsInGapSquaresUpToItsWay) {
  const auto box = [](double x0, double y0, double x1, double y1) {
    return prism({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, 1.0);
  };
  const std::vector<Obstacle> boxes{box(-9.17, 29.845, -7.673, 30.887),
                                    box(-9.225, 31.308, -8.393, 32.539)};
  BehaviorSection gap;
  gap.behavior = Behavior::kArmsIn;
  gap.points = {{-8.2, 31.098}, {-9.4, 31.098}};
  gap.length = 1.2;
  const SectionLookup sections({gap});
  const CharacterParams character;
  const BodyModel body(character);
  const CollisionScene scene(boxes);
  const StepBodyTest test(scene, body, 30);
  const ObstacleMap map(boxes);
  const FootstepPlanner planner(character, PlannerParams{}, map, &test);
  FootstepState start = standing_state({-8.888, 31.116}, -1.73, character);
  start.before_first_step = false;
  SearchOptions options;
  options.sections = &sections;
  const SearchResult result = planner.plan(start, {-10.35, 30.78}, {}, options);
  EXPECT_EQ(result.status, Status::kSuccess);
  EXPECT_LT(result.end_state.com.x, -9.3);  // out of the gap
}

// A walking step that passes a waist-high box closely holds the arms in when
// the swinging hands would meet it and the arms held in clear it; otherwise
// (far off, or so close that the arms held in meet it too) it walks. Boxes
// at a range of distances beside one step of the open field's plan.
TEST(BehavioralFootsteps, WalkingStepsHoldTheArmsInWhereTheSwingWouldMeetABox) {
  const BehaviorScene open = open_field_scene();
  const Plan plan = plan_scenario(open.scenario);
  const std::vector<Footstep>& steps = plan.agents.front().footsteps;
  const Footstep walking = steps[steps.size() / 2];
  ASSERT_EQ(walking.kind, StepKind::kWalk);
  const Vec2 along = (1.0 / distance(walking.com_start, walking.com_end)) *
                     (walking.com_end - walking.com_start);
  const Vec2 left = perp(along);
  const Vec2 middle = 0.5 * (walking.com_start + walking.com_end);
  const BodyModel body(open.scenario.character);
  int held = 0;
  for (double gap = 0.1; gap < 0.6; gap += 0.02) {
    SCOPED_TRACE(gap);
    const Vec2 near = middle + gap * left, far = near + 0.5 * left;
    const std::vector<Obstacle> box{prism({near - 0.4 * along, near + 0.4 * along,
                                           far + 0.4 * along, far - 0.4 * along},
                                          0.95)};
    const CollisionScene scene(box);
    const StepBodyTest test(scene, body, 30);
    Footstep arms_in = walking;
    arms_in.behavior = Behavior::kArmsIn;
    const bool holds = test.hits(walking) && !test.hits(arms_in);
    const Behavior expected = holds ? Behavior::kArmsIn : Behavior::kWalk;
    Footstep labelled = walking;
    const FootstepState walking_on = state_after(FootstepState{}, steps[steps.size() / 2 - 1]);
    EXPECT_EQ(WholeBody({nullptr, &test}).passes(labelled, walking_on), holds || !test.hits(walking));
    EXPECT_EQ(labelled.behavior, expected);
    held += expected == Behavior::kArmsIn ? 1 : 0;
  }
  EXPECT_GE(held, 2);
}

}  // namespace
}  // namespace footfall
