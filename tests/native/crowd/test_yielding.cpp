// How the crowd's agents make way (native/src/crowd/crowd_yielding.hpp), on
// small hand-built crowds: a blocked agent's wish, who is asked to keep out of
// it, who must make room and where it steps aside, who gives way, and keeping
// right of oncoming walkers.
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "crowd/crowd_fixture.hpp"
#include "crowd/crowd_walker.hpp"
#include "crowd/crowd_yielding.hpp"
#include "footfall/navmesh/navmesh.hpp"
#include "footfall/planner/planner.hpp"
#include "footfall/scenes/scenes.hpp"
#include "model/contact.hpp"

namespace footfall::crowd {
namespace {

/// A few agents among obstacles.
struct AmongObstacles : CrowdFixture {
  using CrowdFixture::CrowdFixture;

  /// Agent i's steps toward `goal`, searched alone (whoever is in the way).
  std::vector<Footstep> steps_toward(std::size_t i, Vec2 goal) const {
    return planner.plan(walkers[i].state, goal).footsteps;
  }

  /// Gives agent i the plan of its steps toward `goal`.
  void walk(std::size_t i, Vec2 goal) {
    walkers[i].plan.footsteps = steps_toward(i, goal);
    walkers[i].bounds = std::make_shared<const PlanBounds>(walkers[i].plan, planner.character());
  }
};

/// True if a character standing at `state` overlaps no disc of `discs`
/// (its three torso circles and both feet).
bool out_of(const FootstepState& state, const KeepOut& discs, const CharacterParams& character) {
  std::vector<Circle> mine{{state.feet[0], character.foot_radius},
                           {state.feet[1], character.foot_radius}};
  for (const Circle& c : torso_circles(state.com, state.facing, character)) mine.push_back(c);
  for (const Circle& disc : discs)
    for (const Circle& c : mine)
      if (distance(c.center, disc.center) < c.radius + disc.radius) return false;
  return true;
}

/// True if some disc of `discs` covers `point`.
bool covers(const KeepOut& discs, Vec2 point) {
  for (const Circle& disc : discs)
    if (distance(disc.center, point) <= disc.radius) return true;
  return false;
}

/// Agent 0 at the origin on its way east; then agent 1 standing in its way
/// facing it, bound west with more way left; then `more`.
AmongObstacles face_off(std::vector<AgentSpec> more = {}) {
  std::vector<AgentSpec> agents{{"blocked", {0, 0}, 0.0, {{10, 0}}},
                                {"in the way", {1.2, 0}, kPi, {{-12, 0}}}};
  agents.insert(agents.end(), more.begin(), more.end());
  return AmongObstacles(std::move(agents));
}

/// Agent 0's wish in a face_off(), blocked where it stands.
Attempt wish_of_blocked(AmongObstacles& crowd) {
  crowd.walkers[0].blocked = 1;
  Attempt a;
  a.wish = wish_discs(crowd.steps_toward(0, {10, 0}), crowd.planner.character());
  return a;
}

// wish_discs: the first kWishReach of the way is covered, and nothing much beyond it.
TEST(Yielding, WishCoversTheFirstWishReachOfTheWay) {
  const AmongObstacles crowd({{"a", {0, 0}, 0.0, {{8, 0}}}});
  const std::vector<Footstep> steps = crowd.steps_toward(0, {8, 0});
  const CharacterParams& character = crowd.planner.character();
  const KeepOut wish = wish_discs(steps, character);
  ASSERT_FALSE(wish.empty());
  EXPECT_EQ(wish.front().center, steps.front().foot_position);  // the first foot planted
  EXPECT_DOUBLE_EQ(wish.front().radius, character.foot_radius + kWishPad);
  for (const double x : {0.5, 1.0, 1.5, 2.0}) EXPECT_TRUE(covers(wish, {x, 0})) << x;
  for (const Circle& disc : wish) EXPECT_LE(length(disc.center), kWishReach + kBodyLength);
  EXPECT_FALSE(covers(wish, {kWishReach + kBodyLength, 0}));
}

// wish_discs: steps that end within reach add room to rest where they end.
TEST(Yielding, ShortWishEndsWithRoomToRest) {
  const AmongObstacles crowd({{"a", {0, 0}, 0.0, {{1.5, 0}}}});
  const std::vector<Footstep> steps = crowd.steps_toward(0, {1.5, 0});
  ASSERT_LT(distance(steps.back().com_end, {0, 0}), kWishReach);
  const KeepOut wish = wish_discs(steps, crowd.planner.character());
  EXPECT_EQ(wish.back().center, steps.back().com_end);
  EXPECT_DOUBLE_EQ(wish.back().radius, 0.5 * crowd.planner.character().torso_width + kRestRoom);
}

// show_wish: of those resting in the wish, only those that go after the blocked agent are asked.
TEST(Yielding, BlockedAgentAsksThoseInItsWayWithMoreWayLeft) {
  AmongObstacles crowd = face_off({{"ahead of it", {2.4, 0}, kPi, {{3, 0}}},         // less way left
                          {"out of the way", {1.2, 3}, kPi, {{-12, 3}}}});  // more, but aside
  for (Walker& w : crowd.walkers) w.retry_at = 9.0;
  Attempt a = wish_of_blocked(crowd);
  const CharacterParams& character = crowd.planner.character();
  for (const std::size_t j : {1, 2})
    ASSERT_FALSE(out_of(rest_of(crowd.walkers[j]), a.wish, character));
  ASSERT_TRUE(out_of(rest_of(crowd.walkers[3]), a.wish, character));
  const std::size_t discs = a.wish.size();
  std::vector<std::size_t> asked;
  show_wish(crowd.walkers, 0, a, crowd.at(2.0), {1, 2, 3}, asked);
  EXPECT_EQ(crowd.walkers[0].wish.size(), discs);  // it shows its wish
  EXPECT_EQ(asked, std::vector<std::size_t>{1});
  EXPECT_EQ(crowd.walkers[1].yielding_to, std::vector<std::size_t>{0});
  EXPECT_DOUBLE_EQ(crowd.walkers[1].retry_at, 2.0);  // it searches again at once
  EXPECT_DOUBLE_EQ(crowd.walkers[1].news_at, 2.0);
  for (const std::size_t j : {2, 3}) {
    EXPECT_TRUE(crowd.walkers[j].yielding_to.empty()) << j;
    EXPECT_DOUBLE_EQ(crowd.walkers[j].retry_at, 9.0) << j;
  }
}

// show_wish: one that gives way goes after all, so it is asked even with less way left.
TEST(Yielding, OneThatGivesWayIsAskedWhateverItsWay) {
  AmongObstacles crowd = face_off();
  crowd.walkers[1].way = 1.0;  // less than agent 0's 10 m
  Attempt a = wish_of_blocked(crowd), again = a;  // show_wish takes the attempt's wish
  Snapshot now = crowd.at(0.0);
  std::vector<std::size_t> asked;
  show_wish(crowd.walkers, 0, a, now, {1}, asked);
  EXPECT_TRUE(asked.empty());
  now.giving_way[1] = 1;
  show_wish(crowd.walkers, 0, again, now, {1}, asked);
  EXPECT_EQ(asked, std::vector<std::size_t>{1});
}

// show_wish: a dormant agent asked is woken, and no one is asked twice.
TEST(Yielding, AskedAgentIsWokenAndAskedOnce) {
  AmongObstacles crowd = face_off();
  crowd.walkers[1].dormant = true;
  Attempt a = wish_of_blocked(crowd), again = a;
  std::vector<std::size_t> asked;
  show_wish(crowd.walkers, 0, a, crowd.at(1.0), {1}, asked);
  EXPECT_FALSE(crowd.walkers[1].dormant);
  show_wish(crowd.walkers, 0, again, crowd.at(1.5), {1}, asked);
  EXPECT_EQ(asked, std::vector<std::size_t>{1});
  EXPECT_EQ(crowd.walkers[1].yielding_to, std::vector<std::size_t>{0});
}

// show_wish: an agent no longer blocked withdraws its wish and asks no one.
TEST(Yielding, WishIsWithdrawnOnceNotBlocked) {
  AmongObstacles crowd = face_off();
  Walker& w = crowd.walkers[0];
  w.wish = wish_discs(crowd.steps_toward(0, {10, 0}), crowd.planner.character());
  w.wish_makes_room = true;
  w.blocked = 0;
  Attempt a;
  a.wish = w.wish;
  std::vector<std::size_t> asked;
  show_wish(crowd.walkers, 0, a, crowd.at(0.0), {1}, asked);
  EXPECT_FALSE(wishing(w));
  EXPECT_FALSE(w.wish_makes_room);
  EXPECT_TRUE(asked.empty());
  EXPECT_TRUE(crowd.walkers[1].yielding_to.empty());
}

// must_make_room: only in the wish of one bound against it, or of a wish that makes room.
TEST(Yielding, MustMakeRoomInTheWishOfOneBoundAgainstIt) {
  // Agent 2 stands in the wish too but is bound the same way (a queue);
  // agent 3 is bound against it but stands out of its wish.
  AmongObstacles crowd = face_off({{"queued", {1.2, 0}, 0.0, {{12, 0}}},
                          {"aside", {1.2, 3}, kPi, {{-12, 3}}}});
  crowd.walkers[0].wish = wish_discs(crowd.steps_toward(0, {10, 0}), crowd.planner.character());
  for (std::size_t j = 1; j < 4; ++j) crowd.walkers[j].yielding_to = {0};
  const Snapshot now = crowd.at(0.0);
  EXPECT_TRUE(must_make_room(crowd.walkers, 1, now, crowd.planner));
  EXPECT_FALSE(must_make_room(crowd.walkers, 2, now, crowd.planner));
  EXPECT_FALSE(must_make_room(crowd.walkers, 3, now, crowd.planner));
  crowd.walkers[0].wish_makes_room = true;  // then those in it make room whichever way bound
  EXPECT_TRUE(must_make_room(crowd.walkers, 2, now, crowd.planner));
  EXPECT_FALSE(must_make_room(crowd.walkers, 3, now, crowd.planner));
  crowd.walkers[1].yielding_to.clear();  // not asked: nothing to make room for
  EXPECT_FALSE(must_make_room(crowd.walkers, 1, now, crowd.planner));
}

// step_aside: the one asked steps to a place nearby whose rest keeps out of the wish.
TEST(Yielding, OneAskedStepsAsideOutOfTheWish) {
  AmongObstacles crowd = face_off();
  const KeepOut wish = wish_discs(crowd.steps_toward(0, {10, 0}), crowd.planner.character());
  const Walker& asked = crowd.walkers[1];
  ASSERT_FALSE(out_of(asked.state, wish, crowd.planner.character()));
  SearchOptions options;
  options.keep_out = wish;
  options.horizon = kBlockedHorizon;
  const auto aside = step_aside(asked.state, wish, {obstacle_of(crowd.walkers[0])}, crowd.planner,
                                nullptr, options);
  ASSERT_TRUE(aside.has_value());
  ASSERT_FALSE(aside->footsteps.empty());
  // Where its steps leave it, and where the stops after them bring it to rest.
  FootstepState rest = aside->end_state;
  for (int stop = rest.standing() ? 1 : 2; stop > 0; --stop)
    rest = create_footstep(rest, {StepKind::kStop, Foot::kLeft, rest.facing, 0.0, 0.5},
                           crowd.planner.character())
               .state;
  EXPECT_TRUE(out_of(rest, wish, crowd.planner.character()));
  EXPECT_LE(distance(rest.com, asked.state.com), 2.25 + 1.0);  // the nearest rings
  EXPECT_GT(distance(rest.com, crowd.walkers[0].state.com), 0.6);  // not into the one it yields to
}

// step_aside: boxed in by walls, with no room aside, it finds nothing.
TEST(Yielding, NoStepAsideWhenBoxedIn) {
  const std::vector<Obstacle> walls{
      box_obstacle({0, 0.7}, {1.6, 0.2}), box_obstacle({0, -0.7}, {1.6, 0.2}),
      box_obstacle({0.7, 0}, {0.2, 1.6}), box_obstacle({-0.7, 0}, {0.2, 1.6})};
  NavMesh mesh({-5, -5}, {5, 5});
  for (const Obstacle& wall : walls) mesh.add_polygon(wall.polygon);
  const AmongObstacles crowd({{"boxed", {0, 0}, 0.0, {{3, 0}}}}, walls);
  const KeepOut here{{{0, 0}, 0.5}};
  SearchOptions options;
  options.keep_out = here;
  options.horizon = kBlockedHorizon;
  EXPECT_FALSE(
      step_aside(crowd.walkers[0].state, here, {}, crowd.planner, &mesh, options).has_value());
  // Without the walls it finds a way out of the disc.
  const AmongObstacles open({{"free", {0, 0}, 0.0, {{3, 0}}}});
  EXPECT_TRUE(
      step_aside(open.walkers[0].state, here, {}, open.planner, nullptr, options).has_value());
}

// gives_way: only one blocked kGiveWayBlocked times, out of patience, near one bound against it.
TEST(Yielding, GivesWayOnlyWhenStalledFacingOneBoundAgainstIt) {
  const auto gives = [](Vec2 other_at, Vec2 other_goal, int blocked, double improved_at) {
    AmongObstacles crowd({{"stalled", {0, 0}, 0.0, {{10, 0}}}, {"other", other_at, kPi, {other_goal}}});
    Walker& w = crowd.walkers[0];
    w.blocked = blocked;
    w.state.time = 10.0;
    w.improved_at = improved_at;
    return gives_way(crowd.walkers, 0, crowd.at(10.0));
  };
  EXPECT_TRUE(gives({1.5, 0}, {-10, 0}, kGiveWayBlocked, 0.0));
  EXPECT_FALSE(gives({1.5, 0}, {-10, 0}, kGiveWayBlocked - 1, 0.0));  // not blocked long enough
  EXPECT_FALSE(gives({1.5, 0}, {-10, 0}, kGiveWayBlocked, 10.0 - 0.5 * kJamPatience));  // patient
  EXPECT_FALSE(gives({1.5, 0}, {10, 1}, kGiveWayBlocked, 0.0));     // bound the same way
  EXPECT_FALSE(gives({kJamDistance + 0.5, 0}, {-10, 0}, kGiveWayBlocked, 0.0));  // too far
}

/// Agent 0 at the origin bound east, agent 1 walking west from (8, 0) toward
/// `its_goal` (its plan heads west whatever its goal), seen by agent 0.
struct Oncoming {
  AmongObstacles crowd;
  Snapshot now;
  Oncoming(Vec2 its_goal, std::vector<Obstacle> obstacles = {})
      : crowd({{"east", {0, 0}, 0.0, {{20, 0}}}, {"west", {8, 0}, kPi, {its_goal}}},
              std::move(obstacles)) {
    crowd.walk(1, {-20, 0});
    now = crowd.at(2.0);
  }
  LocalGoal aim(LocalGoal target, const std::vector<std::size_t>& seen) const {
    return keep_right(crowd.walkers, 0, target, seen, now, crowd.planner, nullptr);
  }
};

// keep_right: seeing one walking against it, bound that way, it moves its local goal 3 m right.
TEST(Yielding, KeepsRightOfOneWalkingAgainstIt) {
  const Oncoming scene({-20, 0});
  ASSERT_LT(com_at(scene.crowd.walkers[1].plan, scene.now.t).velocity.x, -kOncomingSpeed);
  const LocalGoal moved = scene.aim({{10, 0}, false}, {1});
  EXPECT_NEAR(moved.point.x, 10.0, 1e-9);
  EXPECT_NEAR(moved.point.y, -kKeepRightShift, 1e-9);  // right of east is -y
  EXPECT_FALSE(moved.is_goal);
}

// keep_right: the goal itself, one not seen, or one stepping back (bound our way) change nothing.
TEST(Yielding, KeepsItsLocalGoalOtherwise) {
  const Oncoming scene({-20, 0});
  const LocalGoal goal = scene.aim({{10, 0}, true}, {1});
  EXPECT_TRUE(goal.is_goal);
  EXPECT_EQ(goal.point, (Vec2{10, 0}));
  EXPECT_EQ(scene.aim({{10, 0}, false}, {}).point, (Vec2{10, 0}));
  const Oncoming stepping_back({20, 0});  // walks west, bound east
  EXPECT_EQ(stepping_back.aim({{10, 0}, false}, {1}).point, (Vec2{10, 0}));
}

// keep_right: where 3 m to the right is blocked, it shifts less, to where it could stand.
TEST(Yielding, KeepsRightLessWhereTheFullShiftIsBlocked) {
  const Oncoming scene({-20, 0}, {box_obstacle({10, -3}, {1, 1})});
  const LocalGoal moved = scene.aim({{10, 0}, false}, {1});
  EXPECT_NEAR(moved.point.x, 10.0, 1e-9);
  EXPECT_NEAR(moved.point.y, -2.0, 1e-9);  // 2.5 m is at the box's edge
}

}  // namespace
}  // namespace footfall::crowd
