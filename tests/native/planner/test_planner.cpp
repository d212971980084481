// The footstep planner of section 4 on the scenes, checked by an
// independent collision oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "footfall/fullbody/body_check.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/planner/planner.hpp"
#include "footfall/scenes/scenes.hpp"
#include "oracle/oracle.hpp"

namespace footfall {
namespace {

Scenario one_agent(std::vector<Obstacle> obstacles, Vec2 from, double facing, Vec2 to) {
  Scenario scenario;
  scenario.obstacles = std::move(obstacles);
  scenario.agents.push_back({"a", from, facing, {to}});
  return scenario;
}

// Plans, and checks what every plan must satisfy.
AgentPlan plan_and_check(const Scenario& scenario) {
  const Plan plan = plan_scenario(scenario);
  const AgentPlan& agent = plan.agents.at(0);
  EXPECT_EQ(testing::first_contact(agent, scenario.character, scenario.obstacles), "");
  EXPECT_EQ(check_body(plan).penetrations, 0);
  const CharacterParams& c = scenario.character;
  for (size_t i = 0; i < agent.footsteps.size(); ++i) {
    const Footstep& s = agent.footsteps[i];
    const FootLimits& limits = s.foot == Foot::kLeft ? c.left : c.right;
    if (s.kind == StepKind::kWalk) {
      EXPECT_GE(s.duration(), limits.min_step_duration - 1e-12);
      EXPECT_LE(s.duration(), limits.max_step_duration + 1e-12);
      EXPECT_GE(s.speed, limits.min_speed);
      EXPECT_LE(s.speed, limits.max_speed);
      const double stride = distance(s.com_start, s.com_end);
      EXPECT_GE(stride, limits.min_step_length - 1e-12);
      EXPECT_LE(stride, limits.max_step_length + 1e-12);
      EXPECT_GT(s.alpha, 0.0);
    }
    // The chosen orientation lies in the step's interval.
    EXPECT_NEAR(clamp_orientation(s.foot_orientation, s.orientation_interval, s.foot),
                s.foot_orientation, 1e-9);
    if (i == 0) continue;
    const Footstep& p = agent.footsteps[i - 1];
    // Timed back to back, G1-continuous: same position, same velocity direction.
    EXPECT_DOUBLE_EQ(s.start_time, p.end_time);
    EXPECT_NEAR(distance(s.com_start, p.com_end), 0.0, 1e-12);
    if (length(p.com_velocity_end) > 0 && length(s.com_velocity_start) > 0) {
      EXPECT_NEAR(wrap_angle(angle_of(s.com_velocity_start) - angle_of(p.com_velocity_end)), 0.0,
                  1e-9)
          << i;
    }
    // Walking steps alternate feet.
    if (p.kind == StepKind::kWalk) {
      EXPECT_NE(s.foot, p.foot) << i;
    }
    // A side step sets off from standing, by the foot that did not step last,
    // and keeps the facing.
    if (s.kind == StepKind::kSideStep) {
      EXPECT_EQ(length(p.com_velocity_end), 0.0) << i;
      EXPECT_NE(s.foot, p.foot) << i;
      EXPECT_EQ(s.phi, p.phi) << i;
    }
  }
  return agent;
}

void expect_reached(const AgentPlan& agent, Vec2 goal, const PlannerParams& params = {}) {
  EXPECT_EQ(agent.status, AgentStatus::kReached)
      << agent.reason << " at " << agent.stuck_at.x << ", " << agent.stuck_at.y;
  ASSERT_FALSE(agent.footsteps.empty());
  // Ends standing, within the tolerance plus the coasting of the stop.
  EXPECT_EQ(agent.footsteps.back().kind, StepKind::kStop);
  EXPECT_TRUE(length(agent.footsteps.back().com_velocity_end) == 0.0);
  EXPECT_LT(distance(agent.footsteps.back().com_end, goal), params.goal_tolerance + 0.6);
}

// A boxed-in character with a horizon of a million and no stall limit: the
// search stops at its cap on nodes instead of filling gigabytes.
TEST(Planner, ASearchHoldsABoundedNumberOfNodes) {
  std::vector<Obstacle> walls = wall_with_door(2.0, 0.0, 0.0, 3.0);  // doors of no width
  const std::vector<Obstacle> west = wall_with_door(-2.0, 0.0, 0.0, 3.0);
  walls.insert(walls.end(), west.begin(), west.end());
  walls.push_back(box_obstacle({0.0, 3.0}, {4.4, 0.2}));
  walls.push_back(box_obstacle({0.0, -3.0}, {4.4, 0.2}));
  const ObstacleMap map(walls);
  PlannerParams params;
  params.max_expansions = 1000000;
  params.stall_expansions = 0;
  const FootstepPlanner planner(CharacterParams{}, params, map);
  const SearchResult result = planner.plan(standing_state({0, 0}, 0.0, CharacterParams{}), {8, 0});
  EXPECT_NE(result.status, Status::kSuccess);
  EXPECT_LT(result.nodes_expanded, params.max_expansions);
  EXPECT_LE(result.nodes_generated, 500000 + 100);
}

TEST(Planner, StraightWalkReachesTheGoal) {
  const AgentPlan agent = plan_and_check(one_agent({}, {0, 0}, 0, {10, 0}));
  expect_reached(agent, {10, 0});
  EXPECT_GE(agent.footsteps.size(), 12u);
  // Stays near the straight line.
  for (const Footstep& s : agent.footsteps) EXPECT_LT(std::fabs(s.com_end.y), 0.5);
}

TEST(Planner, TurnsToGoalsBesideAndBehind) {
  for (const Vec2 goal : {Vec2{0, 5}, Vec2{0, -5}, Vec2{-5, 0}, Vec2{-4, 1}}) {
    SCOPED_TRACE(::testing::Message() << "goal " << goal.x << ", " << goal.y);
    const AgentPlan agent = plan_and_check(one_agent({}, {0, 0}, 0, goal));
    expect_reached(agent, goal);
  }
}

TEST(Planner, TurnsWhileWalking) {
  // A walking character whose goal lies behind it turns around.
  const CharacterParams character;
  const ObstacleMap none;
  const FootstepPlanner planner(character, PlannerParams{}, none);
  FootstepState state = standing_state({0, 0}, 0, character);
  state.com_velocity = {1.3, -0.05};
  state.last_foot = Foot::kLeft;
  state.foot_orientation[0] = {0, 0};
  const SearchResult result = planner.plan(state, {-4, 0});
  EXPECT_EQ(result.status, Status::kSuccess);
  EXPECT_LT(distance(result.end_state.com, {-4, 0}), PlannerParams{}.goal_tolerance + 1e-12);
}

TEST(Planner, WalksAroundABox) {
  const Obstacle box = box_obstacle({4, 0}, {1, 1});
  const AgentPlan agent = plan_and_check(one_agent({box}, {0, 0}, 0, {8, 0}));
  expect_reached(agent, {8, 0});
  double widest = 0;
  for (const Footstep& s : agent.footsteps) widest = std::max(widest, std::fabs(s.com_end.y));
  EXPECT_GT(widest, 0.5 + 0.3);  // the torso passed beside the box, not through it
}

TEST(Planner, PassesDoorways) {
  for (const double door : {1.0, 0.7}) {
    SCOPED_TRACE(::testing::Message() << "door " << door);
    const AgentPlan agent = plan_and_check(one_agent(wall_with_door(4.0, door), {0, 0}, 0, {8, 0}));
    expect_reached(agent, {8, 0});
  }
}

TEST(Planner, DemoReachesThroughTheDoorAndAroundTheBox) {
  const Scenario demo = demo_scenario();
  const AgentPlan agent = plan_and_check(demo);
  expect_reached(agent, demo.agents[0].goals[0]);
}

// Standing just below a box's edge (in the 80 m field of 700 boxes of the
// table-1 crowd), its goal 3.5 m on beyond the box: the way hugs the box,
// where there is no room to stand but at 0.25 m ahead. That local goal once
// counted as reached at once, and the agent stood there until it was stuck.
TEST(Planner, AnAgentBesideABoxWalksOn) {
  const Scenario scenario =
      one_agent(box_field(700, 80.0, 7), {13.011, 6.398}, -0.962, {16.2987, 6.5567});
  const AgentPlan agent = plan_and_check(scenario);
  EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.reason;
}

// Issue 4: agent101 of the table-1 crowd stood at the west mouth of a gap
// 0.62 m wide between two boxes 2 m high, the top of a third box 4.5 cm below
// its COM to the west, its goal beyond the gap. Its walking torso is 0.6 m
// wide and its swinging hands 0.62 m: a walk does not pass, and it used to
// side-step through. Now the gap is an arms-in section (wider than the
// shoulders' 0.46 m and the clearance's 2 cm); following its sections, the
// agent walks through with the arms in, and no limb enters a box. (Facing
// 2.2, its forearms already reach into the third box as it stands: the
// scenario's checks of a start are in 2-D.)
TEST(Planner, PassesAGapNarrowerThanTheSwingWithTheArmsIn) {
  const auto box = [](double x0, double y0, double x1, double y1) {
    return prism({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
  };
  const std::vector<Obstacle> boxes = {box(0.676, -22.339, 1.330, -21.467),
                                       box(0.469, -24.242, 1.468, -22.956),
                                       box(-0.550, -23.962, 0.083, -22.698)};
  const Vec2 start{0.719, -22.655}, goal{4.71, -23.05};
  for (const double facing : {0.7, -0.2}) {
    SCOPED_TRACE(facing);
    Scenario scenario = one_agent(boxes, start, facing, goal);
    scenario.planner.follow_sections = 1;
    const Plan plan = plan_scenario(scenario);
    const AgentPlan& agent = plan.agents.front();
    expect_reached(agent, goal);
    ASSERT_FALSE(agent.sections.empty());
    bool arms_in = false;
    for (const BehaviorSection& section : agent.sections)
      arms_in = arms_in || section.behavior == Behavior::kArmsIn;
    EXPECT_TRUE(arms_in);
    // Through the gap (x from 0.68 to 1.33), never with the arms swinging.
    int inside = 0;
    for (const Footstep& s : agent.footsteps) {
      const bool spans = std::min(s.com_start.x, s.com_end.x) < 1.33 &&
                         std::max(s.com_start.x, s.com_end.x) > 0.68 &&
                         std::fabs(0.5 * (s.com_start.y + s.com_end.y) + 22.65) < 0.3;
      if (!spans || s.kind == StepKind::kStop) continue;
      ++inside;
      EXPECT_NE(s.behavior, Behavior::kWalk);
    }
    EXPECT_GT(inside, 0);
    EXPECT_EQ(check_body(plan).penetrations, 0);
  }
}

// Issue 32: agent357 of the box field (seed 29) stood side-on, facing the
// upper wall of a slot 0.45 m wide, 0.16 m short of that wall's end; its goal
// lay round the corner, 52° off its way across. A side step straight across
// (toward the lower wall, 0.17 m from its COM a little on) touched it; one
// aimed at the goal is beyond a side step's skew; no other step fits the
// slot. A side step toward the goal as far as the skew allows clears both.
TEST(Planner, SideStepsOutOfASlotTowardAGoalRoundItsEnd) {
  const auto box = [](double x0, double y0, double x1, double y1) {
    return prism({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, 1.0);
  };
  const std::vector<Obstacle> boxes = {box(-11.886, 4.045, -10.515, 5.036),
                                       box(-10.948, 3.845, -9.575, 5.057),
                                       box(-12.829, 5.482, -11.729, 6.952)};
  const Vec2 goal{-11.31, 5.94};
  const AgentPlan agent = plan_and_check(one_agent(boxes, {-11.887, 5.225}, 1.51, goal));
  expect_reached(agent, goal);
}

TEST(Planner, EnclosedGoalGivesAPartialPlanEndingInStops) {
  // A closed room around the goal: unreachable, though not inside an obstacle.
  const std::vector<Obstacle> room = {
      box_obstacle({6, 2}, {4.2, 0.2}), box_obstacle({6, -2}, {4.2, 0.2}),
      box_obstacle({4, 0}, {0.2, 4.2}), box_obstacle({8, 0}, {0.2, 4.2})};
  Scenario scenario = one_agent(room, {0, 0}, 0, {6, 0});
  scenario.planner.max_expansions = 300;
  const AgentPlan agent = plan_and_check(scenario);
  EXPECT_EQ(agent.status, AgentStatus::kPartial);
  // No way leads there, not even for a disc 1 cm wide: it says so and stands
  // where it is (it walked to the wall and was stuck for 45 s before).
  EXPECT_EQ(agent.reason, "unreachable");
  ASSERT_TRUE(agent.narrowest.has_value());
  EXPECT_EQ(agent.narrowest->width, 0.0);
  EXPECT_EQ(agent.narrowest->at, (Vec2{0, 0}));
  for (const Footstep& step : agent.footsteps) EXPECT_LT(distance(step.com_end, {0, 0}), 0.2);
  EXPECT_LT(agent.end_time(), 5.0);
}

/// The height at which the COM path of `agent` crosses the line x = `x`, for
/// every crossing.
std::vector<double> crossings_of(const AgentPlan& agent, double x) {
  std::vector<double> ys;
  for (const Footstep& s : agent.footsteps) {
    const Vec2 a = s.com_start, b = s.com_end;
    if ((a.x < x) != (b.x < x)) ys.push_back(a.y + (x - a.x) / (b.x - a.x) * (b.y - a.y));
  }
  return ys;
}

TEST(Planner, ThinWallsAreNeverSteppedThrough) {
  // A 5 mm wall right across the way: the route goes round its far end.
  for (const double thickness : {0.005, 0.05}) {
    SCOPED_TRACE(::testing::Message() << "thickness " << thickness);
    Scenario scenario = one_agent({box_obstacle({3, 0}, {thickness, 40})}, {0, 0}, 0, {6, 0});
    scenario.planner.max_expansions = 300;
    const AgentPlan agent = plan_and_check(scenario);
    for (double y : crossings_of(agent, 3.0)) EXPECT_GT(std::fabs(y), 20.0);
  }
}

TEST(Planner, RoutesThroughADistantDoor) {
  // The only way through a 40 m wall is a door 12 m to the side: the straight
  // line's local goals lead into the wall, the navigation mesh's path leads
  // through the door.
  Scenario scenario = one_agent(wall_with_door(3.0, 1.2, 12.0, 20.0), {0, 0}, 0, {6, 0});
  const AgentPlan agent = plan_and_check(scenario);
  EXPECT_EQ(agent.status, AgentStatus::kReached)
      << agent.reason << " at " << agent.stuck_at.x << ", " << agent.stuck_at.y;
  const std::vector<double> ys = crossings_of(agent, 3.0);
  ASSERT_FALSE(ys.empty());
  for (double y : ys) EXPECT_NEAR(y, 12.0, 0.6);
  // Without the mesh, the same agent walks into the wall and stops there.
  const ObstacleMap obstacles(scenario.obstacles);
  const FootstepPlanner planner(scenario.character, scenario.planner, obstacles);
  EXPECT_EQ(plan_agent(scenario.agents[0], planner).status, AgentStatus::kPartial);
}

TEST(Planner, HorizonReturnsThePathToTheMostPromisingNode) {
  const CharacterParams character;
  PlannerParams params;
  params.max_expansions = 4;
  const ObstacleMap none;
  const FootstepPlanner planner(character, params, none);
  const FootstepState start = standing_state({0, 0}, 0, character);
  const SearchResult result = planner.plan(start, {10, 0});
  EXPECT_EQ(result.status, Status::kPartial);
  EXPECT_LE(result.nodes_expanded, 4);
  ASSERT_FALSE(result.footsteps.empty());
  EXPECT_LT(distance(result.end_state.com, {10, 0}), 10.0);
  EXPECT_LT(planner.heuristic(result.end_state, {10, 0}), planner.heuristic(start, {10, 0}));
}

// The goal behind a wall: the search fills the dead end before it, nothing
// nearer the goal, and stops after stall_expansions of that; with none, it
// goes on to the horizon. Both end at the same nearest node.
TEST(Planner, ASearchThatComesNoNearerStops) {
  const CharacterParams character;
  const ObstacleMap wall({box_obstacle({2, 0}, {0.2, 6})});
  PlannerParams params;
  params.stall_expansions = 0;
  const FootstepPlanner patient(character, params, wall);
  params.stall_expansions = 100;
  const FootstepPlanner brief(character, params, wall);
  const FootstepState start = standing_state({0, 0}, 0, character);
  const SearchResult full = patient.plan(start, {4, 0});
  const SearchResult stalled = brief.plan(start, {4, 0});
  EXPECT_EQ(full.nodes_expanded, params.max_expansions);
  EXPECT_LT(stalled.nodes_expanded, params.max_expansions / 2);
  EXPECT_EQ(stalled.status, Status::kPartial);
  EXPECT_NEAR(distance(stalled.end_state.com, full.end_state.com), 0.0, 0.3);
  // One search may stall sooner than the planner's parameter says.
  SearchOptions sooner;
  sooner.stall = 15;
  const SearchResult quick = brief.plan(start, {4, 0}, {}, sooner);
  EXPECT_LT(quick.nodes_expanded, stalled.nodes_expanded);
  EXPECT_EQ(quick.status, Status::kPartial);
  sooner.stall = -1;
  EXPECT_THROW(brief.plan(start, {4, 0}, {}, sooner), std::invalid_argument);
}

TEST(Planner, StandingCharacterWithNowhereToGoWaits) {
  // Boxed in tight: no step is possible, so the best the planner offers is a wait.
  const CharacterParams character;
  // Inside: 0.44 m deep (the torso is 0.3 deep), 0.68 m wide (it is 0.6 wide).
  const std::vector<Obstacle> cell = {
      box_obstacle({0, 0.44}, {1.0, 0.2}), box_obstacle({0, -0.44}, {1.0, 0.2}),
      box_obstacle({0.32, 0}, {0.2, 1.0}), box_obstacle({-0.32, 0}, {0.2, 1.0})};
  const ObstacleMap map(cell);
  const FootstepPlanner planner(character, PlannerParams{}, map);
  const SearchResult result = planner.plan(standing_state({0, 0}, 0, character), {5, 0});
  EXPECT_EQ(result.status, Status::kPartial);
  ASSERT_EQ(result.footsteps.size(), 1u);
  EXPECT_EQ(result.footsteps[0].kind, StepKind::kStop);
}

// At the end of a corridor 0.9 m wide, against its end wall, the goal
// beyond it: nothing gets (much) nearer, so the character stays, unless it
// stands in a keep-out disc (the way another agent waits to take): then it
// goes back out of it to rest.
TEST(Planner, AStandingCharacterLeavesAKeepOutDisc) {
  const CharacterParams character;
  const std::vector<Obstacle> pocket = {box_obstacle({0.6, 0}, {0.2, 3.0}),
                                        box_obstacle({-1.0, 0.55}, {3.0, 0.2}),
                                        box_obstacle({-1.0, -0.55}, {3.0, 0.2})};
  const ObstacleMap map(pocket);
  const FootstepPlanner planner(character, PlannerParams{}, map);
  const FootstepState start = standing_state({0.15, 0}, 0, character);  // 0.35 m from the wall
  SearchOptions options;
  options.keep_out = {{{0.15, 0.0}, 0.5}};
  EXPECT_FALSE(planner.validity().keeps_out(start, options.keep_out));
  // Without the disc it stays at the wall (or gets a shade nearer).
  const SearchResult stays = planner.plan(start, {5, 0});
  EXPECT_GE(stays.end_state.com.x, start.com.x);
  EXPECT_FALSE(planner.validity().keeps_out(stays.end_state, options.keep_out));
  const SearchResult leaves = planner.plan(start, {5, 0}, {}, options);
  EXPECT_EQ(leaves.status, Status::kPartial);
  ASSERT_FALSE(leaves.footsteps.empty());
  const Rest rest = planner.validity().come_to_rest(leaves.end_state);
  ASSERT_TRUE(rest.complete);
  EXPECT_TRUE(planner.validity().keeps_out(rest.state, options.keep_out));
  for (const Footstep& step : leaves.footsteps) EXPECT_FALSE(planner.validity().collides(step));
}

TEST(Planner, ReportsInvalidStartAndGoal) {
  const CharacterParams character;
  const ObstacleMap map({box_obstacle({3, 0}, {1, 1})});
  const FootstepPlanner planner(character, PlannerParams{}, map);
  EXPECT_EQ(planner.plan(standing_state({3, 0}, 0, character), {6, 0}).status,
            Status::kInvalidStart);
  EXPECT_EQ(planner.plan(standing_state({0, 0}, 0, character), {3, 0}).status,
            Status::kInvalidGoal);
}

TEST(Planner, SameInputGivesBitIdenticalPlans) {
  Scenario scenario = demo_scenario();
  scenario.agents.push_back({"second", {0, -3}, 0.3, {{11, -2}, {2, 4}}});
  const std::string first = plan_to_json(plan_scenario(scenario));
  const std::string second = plan_to_json(plan_scenario(scenario));
  EXPECT_EQ(first, second);
}

TEST(Planner, GoalSequencesAreWalkedInOrder) {
  Scenario scenario;
  scenario.agents.push_back({"a", {0, 0}, 0, {{4, 0}, {4, 4}, {0, 4}}});
  const AgentPlan agent = plan_and_check(scenario);
  expect_reached(agent, {0, 4});
  EXPECT_EQ(agent.goals_reached, 3);
  // Intermediate goals are walked through, not stopped at.
  int stops = 0;
  for (const Footstep& s : agent.footsteps) stops += s.kind == StepKind::kStop ? 1 : 0;
  EXPECT_EQ(stops, 2);
}

TEST(Planner, FootOrientationsKeepThePairRule) {
  const Scenario demo = demo_scenario();
  const AgentPlan agent = plan_scenario(demo).agents[0];
  const double max_turn = demo.character.max_foot_turn;
  std::array<double, 2> last{agent.start.facing, agent.start.facing};
  for (const Footstep& s : agent.footsteps) {
    // Outward from the other foot's orientation by 0 to max_foot_turn.
    const double outward = outward_sign(s.foot) *
                           wrap_angle(s.foot_orientation - last[static_cast<int>(other(s.foot))]);
    EXPECT_GE(outward, -1e-9);
    EXPECT_LE(outward, max_turn + 1e-9);
    last[static_cast<int>(s.foot)] = s.foot_orientation;
  }
}

// The closest the circles of two plans come, sampled every 2 ms (negative: they overlap). [m]
double closest_approach(const AgentPlan& a, const AgentPlan& b, const CharacterParams& character) {
  double closest = INFINITY;
  const double end = std::max(a.end_time(), b.end_time());
  for (double t = 0; t <= end; t += 0.002) {
    for (const Circle& x : collision_circles(a, character, t)) {
      for (const Circle& y : collision_circles(b, character, t)) {
        closest = std::min(closest, distance(x.center, y.center) - x.radius - y.radius);
      }
    }
  }
  return closest;
}

/// Another agent's plan, named `name`: standing at `from`, facing its goal
/// `to`, it walks there alone.
AgentPlan walk_alone(const FootstepPlanner& planner, const std::string& name, Vec2 from, Vec2 to) {
  AgentPlan plan;
  plan.name = name;
  plan.start = standing_state(from, angle_of(to - from), planner.character());
  plan.footsteps = planner.plan(plan.start, to).footsteps;
  return plan;
}

TEST(Planner, KeepsClearOfOtherAgentsPlans) {
  const CharacterParams character;
  const ObstacleMap none;
  const FootstepPlanner planner(character, PlannerParams{}, none);
  const AgentPlan first = walk_alone(planner, "first", {0, 0}, {8, 0});
  // Head-on along the same line, and crossing its way at right angles.
  for (const auto& [from, to] :
       {std::pair<Vec2, Vec2>{{8, 0}, {0, 0}}, std::pair<Vec2, Vec2>{{4, -4}, {4, 4}}}) {
    SCOPED_TRACE(::testing::Message() << "from " << from.x << ", " << from.y);
    // Alone, it would walk right through the first.
    AgentPlan second = walk_alone(planner, "second", from, to);
    EXPECT_LT(closest_approach(first, second, character), 0.0);
    // Reading the first's plan, it keeps clear.
    const SearchResult result = planner.plan(second.start, to, {&first});
    EXPECT_EQ(result.status, Status::kSuccess);
    second.footsteps = result.footsteps;
    EXPECT_GE(closest_approach(first, second, character), 0.0);
  }
}

// A rest is where an agent may stand for a while, and where its next search
// starts: it needs room to turn on the spot among the others, or two agents
// resting face to face a few centimetres apart could never step again.
TEST(Planner, ARestLeavesRoomToTurnAmongOtherAgents) {
  const CharacterParams character;
  const ObstacleMap none;
  const FootstepPlanner planner(character, PlannerParams{}, none);
  const FootstepState here = standing_state({0, 0}, 0, character);
  for (const auto& [apart, room] : {std::pair<double, bool>{0.35, false}, {0.8, true}}) {
    SCOPED_TRACE(::testing::Message() << apart << " m apart");
    AgentPlan facing;
    facing.name = "facing";
    facing.start = standing_state({apart, 0}, 3.14159265358979, character);
    EXPECT_EQ(planner.validity().come_to_rest(here, {&facing}).complete, room);
    // Alone, it rests anywhere.
    EXPECT_TRUE(planner.validity().come_to_rest(here).complete);
  }
  // One walking through the spot later in its plan takes the room too.
  const AgentPlan passing = walk_alone(planner, "passing", {-4, 0}, {4, 0});
  EXPECT_FALSE(planner.validity().come_to_rest(here, {&passing}).complete);
}

// Another agent walks across the way and its plan ends where it crosses it.
// Taken to stand there for good, its rest is walked round (the arms held in
// as it passes); taken for a second only (a crowd's rests are provisional:
// the agent plans on), the search goes straight on, and its steps are cut
// before the rest.
TEST(Planner, AWalkingAgentsRestStandsForItsGraceOnly) {
  const CharacterParams character;
  const ObstacleMap none;
  const FootstepPlanner planner(character, PlannerParams{}, none);
  AgentPlan crossing = walk_alone(planner, "crossing", {8, -1.5}, {8, 0});
  FootstepState end = crossing.start;
  for (const Footstep& step : crossing.footsteps) end = state_after(end, step);
  for (const Footstep& step : planner.validity().come_to_rest(end).steps) crossing.footsteps.push_back(step);
  const FootstepState start = standing_state({0, 0}, 0, character);
  const auto widest = [](const SearchResult& result) {
    double y = 0.0;
    for (const Footstep& step : result.footsteps) y = std::max(y, std::fabs(step.com_end.y));
    return y;
  };
  const SearchResult round = planner.plan(start, {12, 0}, {&crossing});
  EXPECT_EQ(round.status, Status::kSuccess);
  EXPECT_GT(widest(round), 0.42);
  SearchOptions options;
  options.rest_grace = 1.0;
  const SearchResult straight = planner.plan(start, {12, 0}, {&crossing}, options);
  EXPECT_EQ(straight.status, Status::kPartial);
  ASSERT_FALSE(straight.footsteps.empty());
  EXPECT_LT(widest(straight), 0.4);
  EXPECT_LT(straight.end_state.com.x, 8.0);
  for (const Footstep& step : straight.footsteps) EXPECT_FALSE(planner.validity().collides(step, {&crossing}));
}

// The crowd searches a blocked agent's wish among only some of the agents
// it sees; when those the search names are all among them, it reuses the
// search instead.
TEST(Planner, NamesTheAgentsThatTurnedDownItsSteps) {
  const CharacterParams character;
  const ObstacleMap none;
  const FootstepPlanner planner(character, PlannerParams{}, none);
  const AgentPlan far = walk_alone(planner, "far", {0, 20}, {8, 20});
  const AgentPlan head_on = walk_alone(planner, "head-on", {8, 0}, {0, 0});
  const FootstepState start = standing_state({0, 0}, 0, character);
  const SearchResult among_both = planner.plan(start, {8, 0}, {&far, &head_on});
  EXPECT_EQ(among_both.refused_by, std::vector<std::size_t>{1});
  const SearchResult among_one = planner.plan(start, {8, 0}, {&head_on});
  EXPECT_EQ(among_one.refused_by, std::vector<std::size_t>{0});
  EXPECT_EQ(among_one.status, among_both.status);
  ASSERT_EQ(among_one.footsteps.size(), among_both.footsteps.size());
  for (std::size_t k = 0; k < among_one.footsteps.size(); ++k)
    EXPECT_EQ(among_one.footsteps[k].com_end, among_both.footsteps[k].com_end);
  EXPECT_TRUE(planner.plan(start, {8, 0}, {&far}).refused_by.empty());
}

TEST(Plan, FeetNeverJump) {
  // The demo, and a walk with stops and restarts along the way (goal behind a wall).
  Scenario stops = one_agent({box_obstacle({3, 0}, {0.2, 3})}, {0, 0}, 0, {6, 0});
  stops.planner.max_expansions = 60;
  Scenario leaving = one_agent({}, {0, 0}, 0, {6, 0});
  leaving.agents[0].leave_at_goal = true;
  for (const Scenario& scenario : {demo_scenario(), stops, leaving}) {
    const AgentPlan agent = plan_scenario(scenario).agents[0];
    std::array<FootPose, 2> last = feet_at(agent, -1.0);
    for (double t = 0; t <= agent.end_time() + 0.01; t += 0.001) {
      const auto feet = feet_at(agent, t);
      for (int f = 0; f < 2; ++f) {
        ASSERT_LT(distance(feet[f].position, last[f].position), 0.02)
            << "foot " << f << " at t = " << t;
        ASSERT_LT(std::fabs(wrap_angle(feet[f].orientation - last[f].orientation)), 0.05) << t;
        ASSERT_GE(feet[f].lift, 0.0);
      }
      last = feet;
    }
    // Planted feet are exactly where their steps put them.
    for (const Footstep& s : agent.footsteps) {
      const auto feet = feet_at(agent, 0.5 * (s.start_time + s.end_time));
      EXPECT_EQ(feet[static_cast<int>(s.foot)].position, s.foot_position);
    }
  }
}

// One that leaves walks on off its last step: meanwhile its other foot swings
// a stride on, past the planted one, and lands as the agent goes; it never
// stands with the COM run beyond both feet.
TEST(Plan, ALeavingAgentWalksOffItsLastStep) {
  Scenario scenario = one_agent({}, {0, 0}, 0, {6, 0});
  scenario.agents[0].leave_at_goal = true;
  const AgentPlan agent = plan_scenario(scenario).agents[0];
  ASSERT_TRUE(agent.leaves);
  const Footstep& last = agent.footsteps.back();
  ASSERT_EQ(last.kind, StepKind::kWalk);
  const int swinging = static_cast<int>(other(last.foot));
  const auto middle = feet_at(agent, 0.5 * (last.start_time + last.end_time));
  EXPECT_FALSE(middle[swinging].planted);
  EXPECT_GT(middle[swinging].lift, 0.0);
  const auto end = feet_at(agent, last.end_time);
  EXPECT_FALSE(end[swinging].planted);
  EXPECT_GT(end[swinging].position.x, last.foot_position.x + 0.3);
  EXPECT_GT(end[swinging].position.x, last.com_end.x);
}

TEST(Planner, LocalGoalInsideAnObstacleIsMovedOut) {
  // The point 10 m ahead falls inside a small box: the walk goes on around it.
  const AgentPlan agent =
      plan_and_check(one_agent({box_obstacle({10, 0}, {0.4, 0.4})}, {0, 0}, 0, {20, 0}));
  expect_reached(agent, {20, 0});
}

TEST(Planner, ALimpOnEitherFootIsAParameterChange) {
  for (FootLimits CharacterParams::*foot : {&CharacterParams::left, &CharacterParams::right}) {
    Scenario scenario = one_agent({}, {0, 0}, 0, {8, 0});
    (scenario.character.*foot).max_speed = 1.0;
    const AgentPlan agent = plan_and_check(scenario);
    expect_reached(agent, {8, 0});
  }
}

TEST(Planner, AnglesStayWrapped) {
  const AgentPlan agent = plan_and_check(one_agent({}, {0, 0}, 1e6, {-3, 6}));
  expect_reached(agent, {-3, 6});
  const double pi = std::acos(-1.0);
  for (const Footstep& s : agent.footsteps) {
    EXPECT_GT(s.phi, -pi - 1e-12);
    EXPECT_LE(s.phi, pi + 1e-12);
    EXPECT_LE(std::fabs(s.foot_orientation), pi + 1e-12);
    EXPECT_LE(std::fabs(s.orientation_interval.inner), pi + 1e-12);
  }
}

TEST(Planner, MisuseIsRefusedNotCrashed) {
  const CharacterParams character;
  const ObstacleMap map({box_obstacle({3, 0}, {1, 1})});
  EXPECT_FALSE(map.overlaps({{NAN, 0}, 0.5}));
  EXPECT_FALSE(map.overlaps({{0, 0}, NAN}));
  const FootstepPlanner planner(character, PlannerParams{}, map);
  FootstepState start = standing_state({0, 0}, 0, character);
  EXPECT_THROW(planner.plan(start, {NAN, 0}), std::invalid_argument);
  start.com.x = INFINITY;
  EXPECT_THROW(planner.plan(start, {5, 0}), std::invalid_argument);
  EXPECT_THROW(plan_agent({"a", {0, 0}, NAN, {{5, 0}}}, planner), std::invalid_argument);
  EXPECT_THROW(plan_agent({"a", {0, 0}, 0, {{1e200, 0}}}, planner), std::invalid_argument);
  PlannerParams params;
  params.goal_tolerance = 2;
  params.local_goal_distance = 1.5;
  try {
    validate(params);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(
                  "planner.goal_tolerance: must be less than local_goal_distance", 0),
              0u);
  }
}

TEST(Plan, EvaluatesFeetAndCirclesOverTime) {
  const AgentPlan agent = plan_scenario(demo_scenario()).agents[0];
  const CharacterParams character;
  const Footstep& step = agent.footsteps[3];
  const double mid = 0.5 * (step.start_time + step.end_time);
  const auto feet = feet_at(agent, mid);
  const FootPose& stance = feet[static_cast<int>(step.foot)];
  EXPECT_TRUE(stance.planted);
  EXPECT_EQ(stance.position, step.foot_position);
  const FootPose& swing = feet[static_cast<int>(other(step.foot))];
  EXPECT_FALSE(swing.planted);
  EXPECT_GT(swing.lift, 0.0);
  EXPECT_EQ(collision_circles(agent, character, mid).size(), 4u);  // torso + one planted foot
  EXPECT_EQ(collision_circles(agent, character, agent.end_time() + 1).size(), 5u);
  // The swing foot lands where the next step plants it.
  const auto landed = feet_at(agent, step.end_time);
  EXPECT_EQ(landed[static_cast<int>(other(step.foot))].position, agent.footsteps[4].foot_position);
}

}  // namespace
}  // namespace footfall
