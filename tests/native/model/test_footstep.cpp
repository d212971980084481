// The footstep model of section 3, checked against values computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "footfall/model/footstep.hpp"

namespace footfall {
namespace {


// A character walking at `speed` along `heading`, its last step by `last`.
FootstepState walking_state(double heading, double speed, Foot last) {
  FootstepState state = standing_state({1.0, 2.0}, heading, CharacterParams{});
  state.com_velocity = speed * unit(heading);
  state.last_foot = last;
  state.time = 3.0;
  state.before_first_step = false;
  return state;
}

// A standing character that has taken steps (its feet may move at once).
FootstepState stepped_standing(Vec2 position, double facing) {
  FootstepState state = standing_state(position, facing, CharacterParams{});
  state.before_first_step = false;
  return state;
}

// Arc length by Simpson's rule, independent of the closed form.
double numeric_arc_length(double vx0, double alpha, double T) {
  const int n = 2000;
  const double h = T / n;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double t = -T / 2 + i * h;
    const double f = std::hypot(vx0, 2 * alpha * t);
    sum += (i == 0 || i == n ? 1 : (i % 2 ? 4 : 2)) * f;
  }
  return sum * h / 3;
}

TEST(Footstep, WalkStepFollowsEquationOneInTheMirroredLocalFrame) {
  const CharacterParams character;
  const double heading = 0.3, turn = 0.2, v = 1.4, T = 0.55;
  const FootstepState state = walking_state(heading, 1.2, Foot::kRight);
  // A left step turns clockwise: phi is the heading turned inward (right).
  const FootstepAction action{StepKind::kWalk, Foot::kLeft, heading - turn, v, T};
  const StepResult result = create_footstep(state, action, character);
  ASSERT_TRUE(result.valid()) << to_string(result.validity);
  const Footstep& step = result.step;

  const double vx0 = v * std::cos(turn), vy0 = -v * std::sin(turn);
  const double alpha = -vy0 / T;
  EXPECT_NEAR(step.alpha, alpha, 1e-12);
  // Local frame of a left step: +x along phi, +y to the right of travel.
  const Vec2 x = unit(action.phi);
  const Vec2 y = -1.0 * perp(x);
  const Vec2 vertex = state.com + (vx0 * T / 2) * x - (alpha * T * T / 4) * y;
  const Vec2 foot_local{dot(step.foot_position - vertex, x), dot(step.foot_position - vertex, y)};
  EXPECT_NEAR(foot_local.x, 0.0, 1e-12);
  EXPECT_NEAR(foot_local.y, -character.foot_offset, 1e-12);
  // The foot is on the left of the direction of travel.
  EXPECT_GT(cross(x, step.foot_position - state.com), 0.0);
  // Equation 1 at +T/2.
  const Vec2 end = vertex + (vx0 * T / 2) * x + (alpha * T * T / 4) * y;
  EXPECT_NEAR(step.com_end.x, end.x, 1e-12);
  EXPECT_NEAR(step.com_end.y, end.y, 1e-12);
  const Vec2 end_velocity = vx0 * x + (alpha * T) * y;
  EXPECT_NEAR(step.com_velocity_end.x, end_velocity.x, 1e-12);
  EXPECT_NEAR(step.com_velocity_end.y, end_velocity.y, 1e-12);
  // The step starts at the previous velocity (1.2 m/s, not its 1.4): the
  // change of speed spreads over the step, and the velocity is continuous.
  EXPECT_NEAR(angle_of(step.com_velocity_start), heading, 1e-12);
  EXPECT_NEAR(length(step.com_velocity_start), 1.2, 1e-12);
  EXPECT_DOUBLE_EQ(step.start_time, 3.0);
  EXPECT_DOUBLE_EQ(step.end_time, 3.0 + T);
  // The new state.
  EXPECT_EQ(result.state.last_foot, Foot::kLeft);
  EXPECT_EQ(result.state.feet[0], step.foot_position);
  EXPECT_EQ(result.state.com, step.com_end);
  EXPECT_DOUBLE_EQ(result.state.facing, action.phi);
}

TEST(Footstep, CostTermsMatchHandComputation) {
  CharacterParams character;
  character.mass = 80;
  character.energy_rate = 120;
  character.curvature_weight = 0.3;
  character.com_height = 0.95;
  const double heading = -1.0, turn = 0.35, v = 1.1, T = 0.6, v0 = 1.5;
  const FootstepState state = walking_state(heading, v0, Foot::kLeft);
  const StepResult result =
      create_footstep(state, {StepKind::kWalk, Foot::kRight, heading + turn, v, T}, character);
  ASSERT_TRUE(result.valid()) << to_string(result.validity);
  const double vx0 = v * std::cos(turn), alpha = v * std::sin(turn) / T;
  const double theta = std::atan((vx0 * T / 2) / 0.95);
  EXPECT_NEAR(result.step.cost.fixed_rate, 120 * T, 1e-12);
  EXPECT_NEAR(result.step.cost.speed_change,
              80.0 / 2 * std::fabs(v * v - std::pow(v0 * std::cos(2 * theta), 2)), 1e-9);
  EXPECT_NEAR(result.step.cost.curvature, 0.3 * 80 * alpha * numeric_arc_length(vx0, alpha, T),
              1e-9);
  EXPECT_NEAR(
      result.step.cost.total(),
      result.step.cost.fixed_rate + result.step.cost.speed_change + result.step.cost.curvature,
      1e-12);
}

TEST(Footstep, ArcLengthClosedFormMatchesIntegration) {
  for (const double alpha : {0.0, 0.1, 1.0, 5.0}) {
    EXPECT_NEAR(arc_length(1.2, alpha, 0.5), numeric_arc_length(1.2, alpha, 0.5), 1e-9) << alpha;
  }
}

TEST(Footstep, HermiteEvaluationIsTheParabola) {
  const FootstepState state = walking_state(2.0, 1.3, Foot::kLeft);
  const StepResult r =
      create_footstep(state, {StepKind::kWalk, Foot::kRight, 2.5, 1.3, 0.5}, CharacterParams{});
  ASSERT_TRUE(r.valid());
  const Footstep& s = r.step;
  const double T = 0.5, turn = 0.5, vx0 = 1.3 * std::cos(turn), alpha = s.alpha;
  const Vec2 x = unit(s.phi), y = perp(x);  // right step: +y to the left
  const Vec2 vertex = s.com_start + (vx0 * T / 2) * x - (alpha * T * T / 4) * y;
  for (double u = 0; u <= 1.0; u += 0.125) {
    const double t = -T / 2 + u * T;
    const ComSample c = com_at(s, s.start_time + u * T);
    const Vec2 p = vertex + (vx0 * t) * x + (alpha * t * t) * y;
    const Vec2 vel = vx0 * x + (2 * alpha * t) * y;
    EXPECT_NEAR(c.position.x, p.x, 1e-12);
    EXPECT_NEAR(c.position.y, p.y, 1e-12);
    EXPECT_NEAR(c.velocity.x, vel.x, 1e-12);
    EXPECT_NEAR(c.velocity.y, vel.y, 1e-12);
  }
}

TEST(Footstep, RefusesActionsOutsideTheConstraints) {
  const CharacterParams character;
  const FootstepState state = walking_state(0.0, 1.3, Foot::kRight);
  const auto validity = [&](FootstepAction a) {
    return create_footstep(state, a, character).validity;
  };
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kRight, 0.1, 1.3, 0.5}), StepValidity::kWrongFoot);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, -0.1, 1.3, 0.1}),
            StepValidity::kDurationOutOfRange);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, -0.1, 1.3, 0.9}),
            StepValidity::kDurationOutOfRange);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, -0.1, 3.0, 0.5}),
            StepValidity::kSpeedOutOfRange);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, -0.1, 0.1, 0.5}),
            StepValidity::kSpeedOutOfRange);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, -0.1, 0.3, 0.3}),
            StepValidity::kLengthOutOfRange);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, -0.1, 2.4, 0.5}),
            StepValidity::kLengthOutOfRange);
  // A left step cannot turn left: the local parabola would not be positive.
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, 0.0, 1.3, 0.5}), StepValidity::kNotPositive);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, 0.2, 1.3, 0.5}), StepValidity::kNotPositive);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, -0.2, 1.3, 0.5}), StepValidity::kValid);
  EXPECT_EQ(validity({StepKind::kWalk, Foot::kLeft, NAN, 1.3, 0.5}), StepValidity::kNotFinite);
}

TEST(Footstep, PerFootLimitsMakeALimp) {
  CharacterParams limp;
  limp.left.max_speed = 0.8;
  limp.left.max_step_duration = 0.4;
  const FootstepState after_right = walking_state(0.0, 1.0, Foot::kRight);
  const FootstepState after_left = walking_state(0.0, 1.0, Foot::kLeft);
  EXPECT_EQ(
      create_footstep(after_right, {StepKind::kWalk, Foot::kLeft, -0.1, 1.2, 0.35}, limp).validity,
      StepValidity::kSpeedOutOfRange);
  EXPECT_EQ(
      create_footstep(after_right, {StepKind::kWalk, Foot::kLeft, -0.1, 0.7, 0.5}, limp).validity,
      StepValidity::kDurationOutOfRange);
  EXPECT_TRUE(
      create_footstep(after_right, {StepKind::kWalk, Foot::kLeft, -0.1, 0.7, 0.35}, limp).valid());
  EXPECT_TRUE(
      create_footstep(after_left, {StepKind::kWalk, Foot::kRight, 0.1, 1.2, 0.5}, limp).valid());
}

TEST(Footstep, OrientationIntervalFollowsTheIntersectionRule) {
  const CharacterParams character;
  FootstepState state = walking_state(0.05, 1.3, Foot::kRight);
  // The right foot (outward = clockwise) may point from -0.1 (inner) to -0.3 (outer).
  state.foot_orientation[1] = {-0.1, -0.3};
  // Next left: [prev outer, prev inner + pi/2] = [-0.3, -0.1 + pi/2], intersected
  // with [phi, heading] = [-0.05, 0.05].
  StepResult r = create_footstep(state, {StepKind::kWalk, Foot::kLeft, -0.05, 1.3, 0.5}, character);
  ASSERT_TRUE(r.valid());
  EXPECT_NEAR(r.step.orientation_interval.inner, -0.05, 1e-12);
  EXPECT_NEAR(r.step.orientation_interval.outer, 0.05, 1e-12);
  // A right foot turned further out cuts the interval at its outer bound.
  state.foot_orientation[1] = {0.0, -0.02};
  r = create_footstep(state, {StepKind::kWalk, Foot::kLeft, -0.05, 1.3, 0.5}, character);
  ASSERT_TRUE(r.valid());
  EXPECT_NEAR(r.step.orientation_interval.inner, -0.02, 1e-12);
  EXPECT_NEAR(r.step.orientation_interval.outer, 0.05, 1e-12);
  // A right foot turned far left (more than its inner + pi/2 allows) empties it.
  state.foot_orientation[1] = {2.0, 1.9};
  r = create_footstep(state, {StepKind::kWalk, Foot::kLeft, -0.05, 1.3, 0.5}, character);
  EXPECT_EQ(r.validity, StepValidity::kOrientationEmpty);
  // ... and one turned far right does too: the left foot would be pigeon-toed.
  state.foot_orientation[1] = {-2.0, -2.1};
  r = create_footstep(state, {StepKind::kWalk, Foot::kLeft, -0.05, 1.3, 0.5}, character);
  EXPECT_EQ(r.validity, StepValidity::kOrientationEmpty);
}

TEST(Footstep, IntervalsWrapAroundPi) {
  OrientationInterval out;
  // Left foot: [3.0, 3.3] and [-3.1, -2.9] overlap across +-pi.
  ASSERT_TRUE(intersect({3.0, 3.3}, {-3.1, -2.9}, Foot::kLeft, &out));
  EXPECT_NEAR(wrap_angle(out.inner - (2 * kPi - 3.1)), 0.0, 1e-12);
  EXPECT_NEAR(wrap_angle(out.outer - 3.3), 0.0, 1e-12);
  EXPECT_FALSE(intersect({0.0, 0.5}, {1.0, 1.5}, Foot::kLeft, &out));
  EXPECT_NEAR(clamp_orientation(2.0, {0.0, 0.5}, Foot::kLeft), 0.5, 1e-12);
  EXPECT_NEAR(clamp_orientation(-1.0, {0.0, 0.5}, Foot::kLeft), 0.0, 1e-12);
  EXPECT_NEAR(clamp_orientation(-0.2, {0.0, -0.5}, Foot::kRight), -0.2, 1e-12);
}

TEST(Footstep, StartsFromStandingWithEitherFoot) {
  const CharacterParams character;
  const FootstepState standing = standing_state({0, 0}, kPi / 2, character);
  EXPECT_TRUE(standing.standing());
  EXPECT_NEAR(distance(standing.feet[0], standing.feet[1]), 2 * character.foot_offset, 1e-12);
  EXPECT_GT(standing.feet[1].x, standing.feet[0].x);  // facing +y, the right foot is at +x
  for (const Foot foot : {Foot::kLeft, Foot::kRight}) {
    const double phi = kPi / 2 - outward_sign(foot) * 0.1;
    const StepResult r =
        create_footstep(standing, {StepKind::kWalk, foot, phi, 1.0, 0.5}, character);
    ASSERT_TRUE(r.valid()) << to_string(r.validity);
    // From rest, the whole kinetic energy is paid: dE2 = m/2 v^2; the COM
    // sets off from rest.
    EXPECT_NEAR(r.step.cost.speed_change, 0.5 * character.mass * 1.0, 1e-9);
    EXPECT_EQ(length(r.step.com_velocity_start), 0.0);
  }
}

TEST(Footstep, StopBringsTheComToRestBesideTheFeet) {
  const CharacterParams character;
  const FootstepState state = walking_state(0.4, 1.2, Foot::kLeft);
  const StepResult r =
      create_footstep(state, {StepKind::kStop, Foot::kRight, 0.0, 0.0, 0.5}, character);
  ASSERT_TRUE(r.valid());
  const Vec2 rest = state.com + 0.25 * state.com_velocity;
  EXPECT_NEAR(distance(r.step.com_end, rest), 0.0, 1e-12);
  EXPECT_TRUE(r.state.standing());
  EXPECT_EQ(r.step.foot, Foot::kRight);
  EXPECT_NEAR(distance(r.step.foot_position, rest), character.foot_offset, 1e-12);
  const double theta = std::atan(distance(rest, state.com) / character.com_height);
  EXPECT_NEAR(r.step.cost.speed_change,
              0.5 * character.mass * std::pow(1.2 * std::cos(2 * theta), 2), 1e-9);
  EXPECT_DOUBLE_EQ(r.step.cost.curvature, 0.0);
  // The COM decelerates uniformly: half way it has covered three quarters.
  const ComSample mid = com_at(r.step, r.step.start_time + 0.25);
  EXPECT_NEAR(distance(mid.position, state.com), 0.75 * distance(rest, state.com), 1e-12);
  // A stop from standing that keeps the facing is a wait: nothing moves but
  // the stepping foot.
  const StepResult wait =
      create_footstep(r.state, {StepKind::kStop, Foot::kLeft, r.state.facing, 0.0, 0.5}, character);
  ASSERT_TRUE(wait.valid());
  EXPECT_EQ(wait.step.com_end, r.state.com);
  EXPECT_DOUBLE_EQ(wait.step.cost.speed_change, 0.0);
  EXPECT_NEAR(distance(wait.state.feet[0], wait.state.feet[1]), 2 * character.foot_offset, 1e-12);
  // From walking, a stop keeps the facing whatever phi says.
  const StepResult ahead =
      create_footstep(state, {StepKind::kStop, Foot::kRight, 2.0, 0.0, 0.5}, character);
  ASSERT_TRUE(ahead.valid());
  EXPECT_DOUBLE_EQ(ahead.step.phi, state.facing);
}

// A walk sets off along the facing, so a character standing face to face with
// a wall needs to turn on the spot first: a stop from standing with a new
// facing, up to a quarter turn.
TEST(Footstep, APivotTurnsAStandingCharacterOnTheSpot) {
  const CharacterParams character;
  const FootstepState standing = stepped_standing({1.0, 2.0}, 0.0);
  const Foot foot = other(standing.last_foot);
  for (const double turn : {kPi / 4, -kPi / 4, kPi / 2, -kPi / 2}) {
    SCOPED_TRACE(turn);
    const StepResult pivot =
        create_footstep(standing, {StepKind::kStop, foot, turn, 0.0, 0.5}, character);
    ASSERT_TRUE(pivot.valid()) << to_string(pivot.validity);
    EXPECT_EQ(pivot.step.com_end, standing.com);
    EXPECT_TRUE(pivot.state.standing());
    EXPECT_NEAR(pivot.state.facing, turn, 1e-12);
    // The stepping foot lands beside the COM, across the new facing.
    EXPECT_NEAR(distance(pivot.step.foot_position, standing.com), character.foot_offset, 1e-12);
    EXPECT_NEAR(dot(pivot.step.foot_position - standing.com, unit(turn)), 0.0, 1e-12);
    // The pair rule holds: the foot turns no further than the other allows.
    EXPECT_LE(std::fabs(wrap_angle(pivot.step.foot_orientation - 0.0)),
              character.max_foot_turn + 1e-12);
    // Only the fixed rate is paid: nothing speeds up.
    EXPECT_DOUBLE_EQ(pivot.step.cost.speed_change, 0.0);
  }
  // More than a quarter turn at once is refused.
  EXPECT_EQ(create_footstep(standing, {StepKind::kStop, foot, 2.0, 0.0, 0.5}, character).validity,
            StepValidity::kOrientationEmpty);
  // As the first step, a pivot would turn a foot that has had no time to
  // swing; a wait, which moves nothing, may come first.
  const FootstepState first = standing_state({1.0, 2.0}, 0.0, character);
  EXPECT_EQ(create_footstep(first, {StepKind::kStop, foot, 0.5, 0.0, 0.5}, character).validity,
            StepValidity::kNoSwing);
  EXPECT_TRUE(create_footstep(first, {StepKind::kStop, foot, 0.0, 0.0, 0.5}, character).valid());
}

// A walk carries the shoulders across its way; a side step moves the COM
// across the facing, the torso keeping it, so that a gap narrower than the
// shoulders can be passed side-on.
TEST(Footstep, ASideStepMovesAStandingCharacterAcrossItsFacing) {
  const CharacterParams character;
  const FootstepState standing = stepped_standing({1.0, 2.0}, 0.5);
  const Foot foot = other(standing.last_foot);
  const double across = 0.5 + outward_sign(foot) * kPi / 2;
  // Not as the first step: its foot would have had no time to swing.
  EXPECT_EQ(create_footstep(standing_state({1.0, 2.0}, 0.5, character),
                            {StepKind::kSideStep, foot, across, 1.0, 0.5}, character)
                .validity,
            StepValidity::kNoSwing);
  for (const double skew : {0.0, 0.3, -0.3}) {
    SCOPED_TRACE(skew);
    const StepResult side =
        create_footstep(standing, {StepKind::kSideStep, foot, across + skew, 1.0, 0.5}, character);
    ASSERT_TRUE(side.valid()) << to_string(side.validity);
    EXPECT_EQ(side.step.behavior, Behavior::kSideStep);
    // From rest to rest, as far as a stop from 1 m/s over 0.5 s goes: 0.25 m
    // toward phi, fastest half way (0.75 m/s).
    EXPECT_NEAR(distance(side.step.com_end, standing.com + 0.25 * unit(across + skew)), 0.0, 1e-12);
    EXPECT_EQ(length(side.step.com_velocity_start), 0.0);
    EXPECT_EQ(length(side.step.com_velocity_end), 0.0);
    EXPECT_NEAR(length(com_at(side.step, side.step.start_time + 0.25).velocity), 0.75, 1e-12);
    EXPECT_TRUE(side.state.standing());
    EXPECT_DOUBLE_EQ(side.state.facing, 0.5);
    EXPECT_DOUBLE_EQ(side.step.phi, 0.5);  // the torso keeps its facing
    // The stepping foot lands beside the point of rest, across the facing.
    EXPECT_NEAR(
        distance(side.step.foot_position, side.step.com_end + character.foot_offset * unit(across)),
        0.0, 1e-12);
    // It pays for setting off and for stopping.
    const double theta = std::atan(0.25 / character.com_height);
    EXPECT_NEAR(side.step.cost.speed_change,
                0.5 * character.mass * (1.0 + std::pow(std::cos(2 * theta), 2)), 1e-9);
    // A stop from there brings the trailing foot beside the COM.
    const StepResult close =
        create_footstep(side.state, {StepKind::kStop, other(foot), 0.5, 0.0, 0.5}, character);
    ASSERT_TRUE(close.valid());
    EXPECT_NEAR(distance(close.state.feet[0], close.state.feet[1]), 2 * character.foot_offset,
                1e-12);
  }
  const auto validity = [&](const FootstepState& state, const FootstepAction& action) {
    return create_footstep(state, action, character).validity;
  };
  // Too far forward or back of across.
  EXPECT_EQ(validity(standing, {StepKind::kSideStep, foot, across + 0.5, 1.0, 0.5}),
            StepValidity::kOrientationEmpty);
  // The foot that stepped last trails: the feet never drift apart.
  EXPECT_EQ(validity(standing, {StepKind::kSideStep, standing.last_foot, across, 1.0, 0.5}),
            StepValidity::kWrongFoot);
  // The foot's limits hold.
  EXPECT_EQ(validity(standing, {StepKind::kSideStep, foot, across, 3.0, 0.5}),
            StepValidity::kSpeedOutOfRange);
  EXPECT_EQ(validity(standing, {StepKind::kSideStep, foot, across, 0.3, 0.5}),
            StepValidity::kLengthOutOfRange);
  // Only from standing.
  EXPECT_EQ(validity(walking_state(0.0, 1.2, standing.last_foot),
                     {StepKind::kSideStep, foot, across, 1.0, 0.5}),
            StepValidity::kNotStanding);
}

// A walk from standing sets off from rest along the walk's own curve; told
// as a start by the other foot and the rest of the walk, it is the same
// motion, and no foot moves while it bears weight.
TEST(Footstep, AWalkFromStandingSplitsIntoAStartAndTheRestOfTheWalk) {
  const CharacterParams character;
  const FootstepState standing = standing_state({1.0, 2.0}, 0.5, character);
  const StepResult walk =
      create_footstep(standing, {StepKind::kWalk, Foot::kRight, 0.5 + 0.15, 1.3, 0.5}, character);
  ASSERT_TRUE(walk.valid()) << to_string(walk.validity);
  EXPECT_EQ(length(walk.step.com_velocity_start), 0.0);
  const auto [start, rest] = split_set_off(walk.step, standing, 0.25);
  EXPECT_EQ(start.kind, StepKind::kStart);
  EXPECT_EQ(start.foot, Foot::kLeft);
  EXPECT_EQ(start.foot_position, standing.feet[0]);  // planted where it stands
  EXPECT_DOUBLE_EQ(start.end_time, rest.start_time);
  EXPECT_DOUBLE_EQ(rest.start_time, walk.step.start_time + 0.25);
  EXPECT_EQ(rest.foot_position, walk.step.foot_position);
  EXPECT_DOUBLE_EQ(start.phi, walk.step.phi);
  for (int i = 0; i <= 50; ++i) {
    const double t = walk.step.start_time + 0.5 * i / 50.0;
    const ComSample whole = com_at(walk.step, t);
    const ComSample part = com_at(t < rest.start_time ? start : rest, t);
    EXPECT_NEAR(distance(whole.position, part.position), 0.0, 1e-12) << t;
    EXPECT_NEAR(distance(whole.velocity, part.velocity), 0.0, 1e-12) << t;
  }
  EXPECT_NEAR(start.cost.total() + rest.cost.total(), walk.step.cost.total(), 1e-9);
  // Planned on its own, a start is refused.
  EXPECT_EQ(create_footstep(standing, {StepKind::kStart, Foot::kLeft, 0.5, 1.3, 0.25}, character)
                .validity,
            StepValidity::kNotAnAction);
}

// A change of gait spreads over the step: the COM leaves at the speed it came
// in with; top_speed and com_stray still bound what com_at gives.
TEST(Footstep, BoundsHoldAcrossAChangeOfGait) {
  const CharacterParams character;
  for (const double incoming : {0.6, 1.3, 1.6}) {
    for (const double speed : {0.6, 1.3, 1.6}) {
      const FootstepState state = walking_state(0.2, incoming, Foot::kRight);
      const StepResult r = create_footstep(
          state, {StepKind::kWalk, Foot::kLeft, 0.2 - 0.35, speed, 0.5}, character);
      ASSERT_TRUE(r.valid()) << to_string(r.validity);
      const Footstep& step = r.step;
      const Vec2 chord = step.com_end - step.com_start;
      double fastest = 0.0, farthest = 0.0;
      for (int i = 0; i <= 1000; ++i) {
        const ComSample c = com_at(step, step.start_time + 0.5 * i / 1000.0);
        fastest = std::max(fastest, length(c.velocity));
        farthest = std::max(farthest, std::fabs(cross(unit(angle_of(chord)), c.position - step.com_start)));
      }
      EXPECT_LE(fastest, top_speed(step) + 1e-12) << incoming << " to " << speed;
      EXPECT_LE(farthest, com_stray(step) + 1e-12) << incoming << " to " << speed;
      EXPECT_NEAR(length(com_at(step, step.start_time).velocity), incoming, 1e-12);
    }
  }
}

TEST(Footstep, TorsoCirclesSpanTheTorsoWidth) {
  CharacterParams character;
  const auto circles = torso_circles({0, 0}, 0.0, character);
  EXPECT_NEAR(circles[1].center.y + circles[1].radius, character.torso_width / 2, 1e-12);
  EXPECT_NEAR(circles[2].center.y - circles[2].radius, -character.torso_width / 2, 1e-12);
  EXPECT_EQ(circles[0].center, (Vec2{0, 0}));
}

TEST(Params, ValidateNamesTheFieldAndTheLimit) {
  CharacterParams character;
  character.left.max_speed = 0.1;
  try {
    validate(character);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "character.left.max_speed: must be in [0.2, 10], got 0.1");
  }
  PlannerParams planner;
  planner.turn_angles = {0.1, 2.0};
  EXPECT_THROW(validate(planner), std::invalid_argument);
  planner = PlannerParams{};
  planner.max_expansions = 0;
  EXPECT_THROW(validate(planner), std::invalid_argument);
}

}  // namespace
}  // namespace footfall
