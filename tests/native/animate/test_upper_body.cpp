// The upper body follows the plan: the walking clip's amplitude from each
// step's speed, the chest and head looking into a turn before the body turns.
#include <gtest/gtest.h>

#include <cmath>

#include "footfall/animate/upper_body.hpp"
#include "plan/action_plan.hpp"

namespace footfall::animate {
namespace {

constexpr double kTurn = 0.3;  // [rad] per step of the turn by the foot that can turn that way
constexpr double kSway = 0.05;  // [rad] the facing's sway between the feet, walking straight

struct Stride {
  double bend = 0;     ///< [rad] turned by the step
  double speed = 1.3;  ///< [m/s]
};

// Alternating walks from the left foot, from standing facing +x, each aimed
// a little inward of the way the COM goes (as a straight walk's are) and
// turned by its stride's bend (a left step turns right, a right one left).
AgentPlan walk_plan(const std::vector<Stride>& strides) {
  const CharacterParams character;
  AgentPlan plan;
  plan.start = standing_state({0.0, 0.0}, 0.0, character);
  FootstepState state = plan.start;
  for (std::size_t i = 0; i < strides.size(); ++i) {
    const Foot foot = i % 2 == 0 ? Foot::kLeft : Foot::kRight;
    const double heading = state.standing() ? 0.0 : std::atan2(state.com_velocity.y, state.com_velocity.x);
    const double phi = heading - outward_sign(foot) * 0.02 + strides[i].bend;
    const StepResult r = create_footstep(state, {StepKind::kWalk, foot, phi, strides[i].speed, 0.5}, character);
    EXPECT_TRUE(r.valid()) << "step " << i << ": " << to_string(r.validity);
    plan.footsteps.push_back(r.step);
    state = r.state;
  }
  return plan;
}

// `straight` steps, `turning` steps of which those by the foot that can turn
// that way turn by `turn`, `straight` again.
AgentPlan turning_plan(int straight, int turning, double turn) {
  std::vector<Stride> strides(2 * straight + turning);
  const int turning_foot = turn > 0 ? 1 : 0;  // the right foot turns left
  for (int i = straight; i < straight + turning; ++i)
    if (i % 2 == turning_foot) strides[i].bend = turn;
  return walk_plan(strides);
}

double chord_speed(const Footstep& s) { return length(s.com_end - s.com_start) / (s.end_time - s.start_time); }
double middle(const Footstep& s) { return 0.5 * (s.start_time + s.end_time); }

TEST(UpperBody, SwingFollowsEachStepsSpeed) {
  const AgentPlan plan = walk_plan({{0, 1.3}, {0, 1.3}, {0, 1.3}, {0, 0.6}, {0, 0.6}, {0, 0.6}});
  const UpperBodyFollower follower(plan, 1.3);
  const auto& steps = plan.footsteps;
  const double slow = chord_speed(steps[5]) / 1.3;
  ASSERT_LT(slow, 0.6);
  EXPECT_NEAR(follower.swing_at(middle(steps[5])), slow, 1e-12);
  EXPECT_NEAR(follower.swing_at(middle(steps[1])), std::min(chord_speed(steps[1]) / 1.3, 1.0), 1e-12);
  // From step middle to step middle, and held past the last.
  const double between = 0.5 * (middle(steps[2]) + middle(steps[3]));
  EXPECT_NEAR(follower.swing_at(between), 0.5 * (chord_speed(steps[2]) + chord_speed(steps[3])) / 1.3, 1e-12);
  EXPECT_NEAR(follower.swing_at(plan.end_time() + 5.0), slow, 1e-12);
  // Never less than kLeastSwing: a character whose full speed is far above.
  EXPECT_EQ(UpperBodyFollower(plan, 10.0).swing_at(middle(steps[5])), kLeastSwing);
}

TEST(UpperBody, LooksIntoATurnBeforeTheBodyTurns) {
  for (const double turn : {kTurn, -kTurn}) {
    const AgentPlan plan = turning_plan(6, 4, turn);
    const UpperBodyFollower follower(plan, 1.3);
    double turns = 0;  // when the body starts turning
    while (turns < plan.end_time() && std::abs(body_facing(plan, turns)) < kSway) turns += 0.01;
    ASSERT_GT(turns, 2.0);
    // Walking straight, well before: looking ahead, but for the sway.
    for (double t = 0.5; t < turns - kLookAhead; t += 0.05) EXPECT_LT(std::abs(follower.look_at(t)), kSway);
    // A quarter of a second before the body turns, the look is well into the turn.
    const double look = follower.look_at(turns - 0.25);
    EXPECT_GT(look * turn, 0.2 * kTurn * std::abs(turn)) << "turn " << turn;
    // At most the turn still ahead, and never past kMostLook.
    EXPECT_LT(std::abs(look), 2 * kTurn);
    for (double t = 0; t < plan.end_time(); t += 0.05) EXPECT_LE(std::abs(follower.look_at(t)), kMostLook);
    // Straight again after the turn: ahead once more.
    EXPECT_LT(std::abs(follower.look_at(plan.end_time() - 0.1)), kSway);
  }
}

// Standing, the body turns whole in its pivots, as the planner tests it:
// the chest and head do not turn ahead of them (in a door frame the arms
// would swing into it). Waiting facing +x, then two pivots toward +y.
TEST(UpperBody, AStandingBodyDoesNotLookAheadOfItsPivots) {
  const AgentPlan plan = plan_of({{StepKind::kStop, Foot::kLeft, 0.0, 0.0, 0.5},
                                  {StepKind::kStop, Foot::kRight, 0.0, 0.0, 0.5},
                                  {StepKind::kStop, Foot::kLeft, 0.25 * kPi, 0.0, 0.5},
                                  {StepKind::kStop, Foot::kRight, 0.5 * kPi, 0.0, 0.5}});
  ASSERT_GT(body_facing(plan, plan.end_time()), 0.7);  // turned, the feet by 45 degrees a pivot
  const UpperBodyFollower follower(plan, 1.3);
  for (double t = 0; t <= plan.end_time(); t += 0.05) EXPECT_EQ(follower.look_at(t), 0.0) << t;
}

TEST(UpperBody, LookIsBoundedInASharpTurn) {
  const AgentPlan plan = turning_plan(4, 8, 0.6);
  const UpperBodyFollower follower(plan, 1.3);
  double most = 0;
  for (double t = 0; t < plan.end_time(); t += 0.02) most = std::max(most, std::abs(follower.look_at(t)));
  EXPECT_GT(most, 0.3);
  EXPECT_LE(most, kMostLook);
}

TEST(UpperBody, FacesAcrossTheWayInASideStep) {
  // Standing facing +x, the right foot steps to the right: the body faces +x,
  // across its travel toward -y.
  const AgentPlan plan = plan_of({{StepKind::kStop, Foot::kLeft, 0.0, 0.0, 0.5},
                                  {StepKind::kSideStep, Foot::kRight, -1.5707963267948966, 0.6, 0.6}});
  const Footstep& side = plan.footsteps[1];
  ASSERT_EQ(side.kind, StepKind::kSideStep);
  const double travel = std::atan2(side.com_end.y - side.com_start.y, side.com_end.x - side.com_start.x);
  EXPECT_NEAR(std::cos(body_facing(plan, middle(side)) - travel), 0.0, 1e-9);
  EXPECT_NEAR(body_facing(plan, middle(side)), 0.0, 0.2);
}

}  // namespace
}  // namespace footfall::animate
