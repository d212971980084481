#include "footfall/model/footstep.hpp"

#include <algorithm>
#include <cmath>

#include "model/footstep_shape.hpp"

namespace footfall {

FootstepState state_after(const FootstepState& state, const Footstep& step) {
  FootstepState next = state;
  next.com = step.com_end;
  next.com_velocity = step.com_velocity_end;
  next.last_foot = step.foot;
  next.feet[static_cast<int>(step.foot)] = step.foot_position;
  next.foot_heights[static_cast<int>(step.foot)] = step.foot_height;
  next.foot_orientation[static_cast<int>(step.foot)] = step.orientation_interval;
  next.facing = step.phi;
  next.time = step.end_time;
  next.before_first_step = false;
  return next;
}

namespace {

constexpr double kIntervalTolerance = 1e-9;  // [rad] bounds this close still meet

const FootLimits& limits_of(const CharacterParams& character, Foot foot) {
  return foot == Foot::kLeft ? character.left : character.right;
}

// cos(2 theta) from tan(theta), theta the leg's angle from vertical.
double cos_double_angle(double tan_theta) {
  return (1.0 - tan_theta * tan_theta) / (1.0 + tan_theta * tan_theta);
}

// dE2 of equation 4: the work to reach the desired speed after heel strike
// dissipated the momentum along the new leg.
double speed_change_cost(double mass, double desired_speed, double incoming_speed,
                         double cos_2theta) {
  const double kept = incoming_speed * cos_2theta;
  return 0.5 * mass * std::fabs(desired_speed * desired_speed - kept * kept);
}

StepResult invalid(StepValidity why) {
  StepResult result;
  result.validity = why;
  return result;
}

StepResult create_walk(const FootstepState& state, const FootstepAction& action,
                       const CharacterParams& character) {
  const Foot foot = action.foot;
  if (!state.standing() && foot == state.last_foot) return invalid(StepValidity::kWrongFoot);
  const detail::Heading heading = detail::heading_of(state);
  // phi lies inward of the incoming velocity: clockwise for a left step.
  const double turn = -outward_sign(foot) * wrap_angle(action.phi - heading.angle);
  const detail::StepShape shape =
      detail::step_shape(action.speed, action.duration, turn, character);
  const StepValidity limits = detail::check_limits(shape, limits_of(character, foot));
  if (limits != StepValidity::kValid) return invalid(limits);
  const OrientationInterval reach = reachable_orientations(
      state.foot_orientation[static_cast<int>(other(foot))], other(foot), character.max_foot_turn);
  return detail::walk_step(state, foot, heading, shape, wrap_angle(action.phi), reach, character);
}

// A step that plants `foot` beside the point where the COM, setting off at
// `velocity`, comes to rest after decelerating uniformly for `T`, at the stance
// offset across `facing` and turned to it as far as the other foot allows.
// Its cost is dE1 and the energy of removing the momentum.
StepResult rest_step(const FootstepState& state, Foot foot, Vec2 velocity, double facing, double T,
                     StepKind kind, const CharacterParams& character) {
  const Vec2 rest = state.com + (0.5 * T) * velocity;
  const double s = outward_sign(foot);
  const OrientationInterval reach = reachable_orientations(
      state.foot_orientation[static_cast<int>(other(foot))], other(foot), character.max_foot_turn);
  const double orientation = clamp_orientation(facing, reach, foot);

  StepResult result;
  Footstep& step = result.step;
  step.foot = foot;
  step.kind = kind;
  step.start_time = state.time;
  step.end_time = state.time + T;
  step.foot_position = rest + (s * character.foot_offset) * perp(unit(facing));
  step.orientation_interval = {orientation, orientation};
  step.foot_orientation = orientation;
  step.com_start = state.com;
  step.com_end = rest;
  step.com_velocity_start = velocity;
  step.com_velocity_end = {0.0, 0.0};
  step.phi = facing;
  const double tan_theta = distance(rest, state.com) / character.com_height;
  step.cost.fixed_rate = character.energy_rate * T;
  step.cost.speed_change =
      speed_change_cost(character.mass, 0.0, length(velocity), cos_double_angle(tan_theta));

  result.state = state_after(state, step);
  // The planted foot must stay within reach of the fixed orientation.
  OrientationInterval& stance = result.state.foot_orientation[static_cast<int>(other(foot))];
  intersect(stance,
            reachable_orientations(step.orientation_interval, foot, character.max_foot_turn),
            other(foot), &stance);
  return result;
}

// The stop action: the COM decelerates uniformly to rest, and the stepping foot
// lands beside the point of rest, at the stance offset, turned to the facing.
// From standing, the facing may change (a pivot): a walk sets off along the
// facing, so without pivots a character standing face to face with a wall or
// another could never step away.
StepResult create_stop(const FootstepState& state, const FootstepAction& action,
                       const CharacterParams& character) {
  const double T = action.duration;
  if (!(T > 0.0)) return invalid(StepValidity::kDurationOutOfRange);
  if (!std::isfinite(action.phi)) return invalid(StepValidity::kNotFinite);
  const double facing = state.standing() ? wrap_angle(action.phi) : state.facing;
  if (std::fabs(wrap_angle(facing - state.facing)) > kMaxPivot + 1e-12)
    return invalid(StepValidity::kOrientationEmpty);
  StepResult result = rest_step(state, other(state.last_foot), state.com_velocity, facing, T,
                                StepKind::kStop, character);
  const Foot foot = result.step.foot;
  const bool moves = distance(result.step.foot_position, state.feet[static_cast<int>(foot)]) > 1e-9 ||
                     result.step.foot_orientation != state.foot_orientation[static_cast<int>(foot)].inner;
  if (state.before_first_step && moves) return invalid(StepValidity::kNoSwing);
  return result;
}

// The side step: from standing, the COM moves toward phi, across the facing
// on the stepping foot's side (give or take kMaxSideStepSkew), `speed T / 2`
// as a stop from that speed would, but setting off from rest and coming to
// rest (no velocity jump), the torso keeping its facing. A walk carries the
// shoulders across its way, so without it a character could never pass a gap
// narrower than its shoulders (the way on the navigation mesh may lead
// through one).
StepResult create_side_step(const FootstepState& state, const FootstepAction& action,
                            const CharacterParams& character) {
  if (!state.standing()) return invalid(StepValidity::kNotStanding);
  // The trailing foot stepped last, so it stands beside the COM (or the feet
  // would drift apart over side steps one way).
  if (action.foot == state.last_foot) return invalid(StepValidity::kWrongFoot);
  if (state.before_first_step) return invalid(StepValidity::kNoSwing);
  const FootLimits& limits = limits_of(character, action.foot);
  const double T = action.duration;
  if (T < limits.min_step_duration || T > limits.max_step_duration)
    return invalid(StepValidity::kDurationOutOfRange);
  if (action.speed < limits.min_speed || action.speed > limits.max_speed)
    return invalid(StepValidity::kSpeedOutOfRange);
  const double travel = 0.5 * action.speed * T;
  if (travel < limits.min_step_length || travel > limits.max_step_length)
    return invalid(StepValidity::kLengthOutOfRange);
  const double across = state.facing + outward_sign(action.foot) * 0.5 * kPi;
  if (std::fabs(wrap_angle(action.phi - across)) > kMaxSideStepSkew + 1e-12)
    return invalid(StepValidity::kOrientationEmpty);
  const Vec2 velocity = action.speed * unit(action.phi);
  StepResult result =
      rest_step(state, action.foot, velocity, state.facing, T, StepKind::kSideStep, character);
  Footstep& step = result.step;
  step.com_velocity_start = {0.0, 0.0};
  step.behavior = Behavior::kSideStep;
  step.speed = action.speed;
  // Setting off from rest pays the whole kinetic energy, as a walk does.
  step.cost.speed_change += speed_change_cost(character.mass, action.speed, 0.0, 1.0);
  return result;
}

}  // namespace

namespace detail {

StepShape step_shape(double speed, double duration, double turn, const CharacterParams& character) {
  StepShape shape;
  shape.speed = speed;
  shape.duration = duration;
  shape.turn = turn;
  shape.cos_turn = std::cos(turn);
  shape.sin_turn = std::sin(turn);
  // Incoming local velocity (vx0, vy0) = v (cos turn, -sin turn) = (vx0, -alpha T).
  shape.vx0 = speed * shape.cos_turn;
  shape.alpha = speed * shape.sin_turn / duration;
  shape.chord = shape.vx0 * duration;
  shape.cos_2theta = cos_double_angle(0.5 * shape.chord / character.com_height);
  shape.fixed_rate = character.energy_rate * duration;
  shape.curvature = character.curvature_weight * character.mass * shape.alpha *
                    arc_length(shape.vx0, shape.alpha, duration);
  return shape;
}

StepValidity check_limits(const StepShape& shape, const FootLimits& limits) {
  if (shape.duration < limits.min_step_duration || shape.duration > limits.max_step_duration) {
    return StepValidity::kDurationOutOfRange;
  }
  if (shape.speed < limits.min_speed || shape.speed > limits.max_speed)
    return StepValidity::kSpeedOutOfRange;
  // alpha > 0: the incoming velocity points toward the stance foot.
  if (!(shape.alpha > 0.0)) return StepValidity::kNotPositive;
  if (shape.chord < limits.min_step_length || shape.chord > limits.max_step_length) {
    return StepValidity::kLengthOutOfRange;
  }
  return StepValidity::kValid;
}

Heading heading_of(const FootstepState& state) {
  Heading heading;
  if (state.standing()) {
    heading.angle = state.facing;
    heading.direction = unit(state.facing);
  } else {
    heading.speed = length(state.com_velocity);
    heading.direction = (1.0 / heading.speed) * state.com_velocity;
    heading.angle = angle_of(state.com_velocity);
  }
  return heading;
}

StepResult walk_step(const FootstepState& state, Foot foot, const Heading& heading,
                     const StepShape& shape, double phi, const OrientationInterval& reach,
                     const CharacterParams& character) {
  const double s = outward_sign(foot);
  // Orientation interval: [phi, incoming velocity] within reach of the other foot.
  OrientationInterval interval;
  if (!intersect(reach, {phi, phi + s * shape.turn}, foot, &interval)) {
    return invalid(StepValidity::kOrientationEmpty);
  }
  // Local parabola frame: +x along phi, +y away from the stance foot.
  const Vec2 x_axis =
      shape.cos_turn * heading.direction - (s * shape.sin_turn) * perp(heading.direction);
  const Vec2 y_axis = -s * perp(x_axis);
  // Equation 1 at t = +-T/2, back in world space. The chord lies along +x.
  const double T = shape.duration;
  const double half = 0.5 * T;
  const Vec2 vertex =
      state.com + (shape.vx0 * half) * x_axis - (shape.alpha * half * half) * y_axis;
  StepResult result;
  Footstep& step = result.step;
  step.foot = foot;
  step.kind = StepKind::kWalk;
  step.start_time = state.time;
  step.end_time = state.time + T;
  step.foot_position = vertex - character.foot_offset * y_axis;
  step.orientation_interval = interval;
  step.foot_orientation = interval.inner;  // phi, or as near as the other foot allows
  step.com_start = state.com;
  step.com_end = state.com + shape.chord * x_axis;
  // It sets off at the velocity it comes in with: from rest when standing,
  // and a change of gait spreads over the step.
  step.com_velocity_start = state.com_velocity;
  step.com_velocity_end = shape.vx0 * x_axis + (shape.alpha * T) * y_axis;
  step.phi = phi;
  step.speed = shape.speed;
  step.alpha = shape.alpha;
  step.cost.fixed_rate = shape.fixed_rate;
  step.cost.speed_change =
      speed_change_cost(character.mass, shape.speed, heading.speed, shape.cos_2theta);
  step.cost.curvature = shape.curvature;

  result.state = state_after(state, step);
  return result;
}

}  // namespace detail

const char* to_string(Foot foot) { return foot == Foot::kLeft ? "left" : "right"; }

double terrain_cost(double mass, double run, double rise) {
  constexpr double kSteepest = 0.45;  // the polynomial's measured range
  constexpr double kStairFactor = 4.5;
  constexpr double kGravity = 9.81;  // [m/s^2]
  // Minetti et al. 2002, J Appl Physiol 93:1039, walking: C(i) in J/(kg m).
  const auto minetti = [](double i) {
    return (((((280.5 * i - 58.7) * i - 76.8) * i + 51.9) * i + 19.6) * i) + 2.5;
  };
  const double stairs = kStairFactor * mass * kGravity * rise;
  if (!(run > 0.0)) return std::max(0.0, stairs);
  const double gradient = std::clamp(rise / run, -kSteepest, kSteepest);
  const double slope = mass * run * (minetti(gradient) - minetti(0.0));
  return rise > kSteepest * run ? std::max(slope, stairs) : slope;
}

const char* to_string(StepKind kind) {
  switch (kind) {
    case StepKind::kWalk:
      return "walk";
    case StepKind::kStop:
      return "stop";
    case StepKind::kSideStep:
      return "side_step";
    case StepKind::kStart:
      return "start";
  }
  return "walk";
}

const char* to_string(Behavior behavior) {
  switch (behavior) {
    case Behavior::kWalk:
      return "walk";
    case Behavior::kArmsIn:
      return "arms_in";
    case Behavior::kSideStep:
      return "side_step";
  }
  return "walk";
}

const char* to_string(StepValidity validity) {
  switch (validity) {
    case StepValidity::kValid:
      return "valid";
    case StepValidity::kWrongFoot:
      return "a walking or side-stepping character must alternate feet";
    case StepValidity::kNotStanding:
      return "a side step sets off from standing";
    case StepValidity::kNotAnAction:
      return "a start is the beginning of a walk from standing, not an action of its own";
    case StepValidity::kNoSwing:
      return "the first step cannot move its foot: it has had no time to swing";
    case StepValidity::kDurationOutOfRange:
      return "step duration out of range";
    case StepValidity::kSpeedOutOfRange:
      return "speed out of range";
    case StepValidity::kLengthOutOfRange:
      return "step length out of range";
    case StepValidity::kNotPositive:
      return "local parabola not positive";
    case StepValidity::kOrientationEmpty:
      return "empty foot-orientation interval";
    case StepValidity::kNotFinite:
      return "non-finite input";
    case StepValidity::kCollides:
      return "runs into an obstacle";
  }
  return "invalid";
}

double width(const OrientationInterval& interval, Foot foot) {
  return outward_sign(foot) * (interval.outer - interval.inner);
}

OrientationInterval reachable_orientations(const OrientationInterval& interval, Foot foot,
                                           double max_foot_turn) {
  const double reach = width(interval, foot) + max_foot_turn;
  return {interval.outer, interval.outer + outward_sign(other(foot)) * reach};
}

bool intersect(const OrientationInterval& a, const OrientationInterval& b, Foot foot,
               OrientationInterval* out) {
  // Outward coordinates measured from a.inner: a is [0, wa], b is [b0, b0 + wb]
  // up to a whole turn.
  const double s = outward_sign(foot);
  const double wa = width(a, foot);
  const double wb = width(b, foot);
  const double b0 = s * wrap_angle(b.inner - a.inner);
  for (const double shift : {0.0, -2.0 * kPi, 2.0 * kPi}) {
    double lo = std::max(0.0, b0 + shift);
    double hi = std::min(wa, b0 + shift + wb);
    if (hi < lo - kIntervalTolerance) continue;
    if (hi < lo) lo = hi = 0.5 * (lo + hi);
    const double inner = wrap_angle(a.inner + s * lo);  // bounds never drift by whole turns
    *out = {inner, inner + s * (hi - lo)};
    return true;
  }
  return false;
}

double clamp_orientation(double angle, const OrientationInterval& interval, Foot foot) {
  const double s = outward_sign(foot);
  const double u = s * wrap_angle(angle - interval.inner);
  if (u >= 0.0 && u <= width(interval, foot)) return wrap_angle(interval.inner + s * u);
  const double to_inner = std::fabs(wrap_angle(angle - interval.inner));
  const double to_outer = std::fabs(wrap_angle(angle - interval.outer));
  return wrap_angle(to_inner <= to_outer ? interval.inner : interval.outer);
}

FootstepState standing_state(Vec2 position, double facing, const CharacterParams& character) {
  FootstepState state;
  state.com = position;
  facing = wrap_angle(facing);
  state.facing = facing;
  const Vec2 left = perp(unit(facing));
  state.feet[static_cast<int>(Foot::kLeft)] = position + character.foot_offset * left;
  state.feet[static_cast<int>(Foot::kRight)] = position - character.foot_offset * left;
  state.foot_orientation[0] = state.foot_orientation[1] = {facing, facing};
  state.before_first_step = true;
  return state;
}

StepResult create_footstep(const FootstepState& state, const FootstepAction& action,
                           const CharacterParams& character) {
  if (!std::isfinite(action.phi) || !std::isfinite(action.speed) ||
      !std::isfinite(action.duration) || !is_finite(state.com) || !is_finite(state.com_velocity)) {
    return invalid(StepValidity::kNotFinite);
  }
  switch (action.kind) {
    case StepKind::kStop:
      return create_stop(state, action, character);
    case StepKind::kSideStep:
      return create_side_step(state, action, character);
    case StepKind::kStart:
      return invalid(StepValidity::kNotAnAction);
    case StepKind::kWalk:
      break;
  }
  return create_walk(state, action, character);
}

double arc_length(double vx0, double alpha, double duration) {
  // Length of (vx0 t, alpha t^2) over [-T/2, T/2], in closed form.
  const double half = 0.5 * duration;
  if (vx0 <= 0.0) return 2.0 * alpha * half * half;
  const double a = 2.0 * alpha / vx0;
  if (a * half < 1e-9) return vx0 * duration;
  return vx0 * (half * std::sqrt(1.0 + a * a * half * half) + std::asinh(a * half) / a);
}

ComSample com_at(const Footstep& step, double t) {
  const double T = step.duration();
  const double u = T > 0.0 ? std::clamp((t - step.start_time) / T, 0.0, 1.0) : 1.0;
  const double u2 = u * u, u3 = u2 * u;
  // Cubic Hermite basis and its derivative.
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
               h11 = u3 - u2;
  const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -6 * u2 + 6 * u,
               d11 = 3 * u2 - 2 * u;
  const Vec2 p0 = step.com_start, p1 = step.com_end;
  const Vec2 m0 = T * step.com_velocity_start, m1 = T * step.com_velocity_end;
  ComSample sample;
  sample.position = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
  sample.velocity = T > 0.0 ? (1.0 / T) * (d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1) : Vec2{};
  return sample;
}

bool splits_on_set_off(const Footstep& walk, const FootstepState& before) {
  const bool swung_in = !before.before_first_step && before.last_foot != walk.foot;
  return walk.kind == StepKind::kWalk && before.standing() && !swung_in;
}

double set_off_lead(const Footstep& walk) { return std::min(kSetOffSwing, 0.5 * walk.duration()); }

std::array<Footstep, 2> split_set_off(const Footstep& walk, const FootstepState& before,
                                      double lead) {
  // The walk's own COM curve, cut at the end of the start: a cubic Hermite
  // is exact on any part of itself, so the two steps trace it as one.
  const double at = walk.start_time + lead;
  const ComSample cut = com_at(walk, at);
  Footstep start = walk;
  start.kind = StepKind::kStart;
  start.foot = other(walk.foot);
  start.end_time = at;
  start.foot_position = before.feet[static_cast<int>(start.foot)];
  start.foot_height = before.foot_heights[static_cast<int>(start.foot)];
  start.orientation_interval = before.foot_orientation[static_cast<int>(start.foot)];
  start.foot_orientation = start.orientation_interval.inner;
  start.com_end = cut.position;
  start.com_velocity_end = cut.velocity;
  start.alpha = 0.0;
  // Setting off pays the kinetic energy; the time is shared.
  const double share = lead / walk.duration();
  start.cost = {walk.cost.fixed_rate * share, walk.cost.speed_change, 0.0};
  Footstep rest = walk;
  rest.start_time = at;
  rest.com_start = cut.position;
  rest.com_velocity_start = cut.velocity;
  rest.cost = {walk.cost.fixed_rate - start.cost.fixed_rate, 0.0, walk.cost.curvature};
  return {start, rest};
}

double top_speed(const Footstep& step) {
  // The Hermite's Bezier control velocities: v0, 3 chord / T - v0 - v1, v1.
  const double T = step.duration();
  double top = std::max(length(step.com_velocity_start), length(step.com_velocity_end));
  if (T > 0.0) {
    const Vec2 middle = (3.0 / T) * (step.com_end - step.com_start) - step.com_velocity_start -
                        step.com_velocity_end;
    top = std::max(top, length(middle));
  }
  return top;
}

double com_stray(const Footstep& step) {
  // The curve lies in the hull of its Bezier control points p0, p0 + m0 / 3,
  // p1 - m1 / 3, p1: how far the inner two stray from the chord, across it or
  // beyond its ends.
  const double T = step.duration();
  const Vec2 chord = step.com_end - step.com_start;
  const double span = length(chord);
  const Vec2 along = span > 0.0 ? (1.0 / span) * chord : Vec2{1.0, 0.0};
  double stray = 0.0;
  for (const Vec2 offset : {(T / 3.0) * step.com_velocity_start,
                            chord - (T / 3.0) * step.com_velocity_end}) {
    const double x = dot(offset, along);
    stray = std::max({stray, std::fabs(cross(along, offset)), -x, x - span});
  }
  return stray;
}

std::array<Circle, 3> torso_circles(Vec2 com, double facing, const CharacterParams& character,
                                    double pad, Behavior behavior) {
  const Vec2 left = perp(unit(facing));
  // With the arms in, the shoulders are the body's outside; never wider than
  // the walking torso (the bounds of a plan's reach assume that width).
  const double width = behavior == Behavior::kArmsIn
                           ? std::min(character.torso_width, character.shoulder_width)
                           : character.torso_width;
  const double shoulder = std::max(0.0, 0.5 * width - character.shoulder_radius);
  return {Circle{com, character.torso_radius + pad},
          Circle{com + shoulder * left, character.shoulder_radius + pad},
          Circle{com - shoulder * left, character.shoulder_radius + pad}};
}

}  // namespace footfall
