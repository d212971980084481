#include "footfall/footstep.hpp"

#include <algorithm>
#include <cmath>

namespace footfall {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kIntervalTolerance = 1e-9;  // [rad] bounds this close still meet

const FootLimits& limits_of(const CharacterParams& character, Foot foot) {
  return foot == Foot::kLeft ? character.left : character.right;
}

Vec2 normalized(Vec2 v) {
  const double len = length(v);
  return {v.x / len, v.y / len};
}

// dE2 of equation 4: the work to reach the desired speed after heel strike
// dissipated the momentum along the new leg.
double speed_change_cost(double mass, double desired_speed, double incoming_speed, double theta) {
  const double kept = incoming_speed * std::cos(2.0 * theta);
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
  const FootLimits& limits = limits_of(character, foot);
  const double T = action.duration;
  if (T < limits.min_step_duration || T > limits.max_step_duration) {
    return invalid(StepValidity::kDurationOutOfRange);
  }
  if (action.speed < limits.min_speed || action.speed > limits.max_speed) {
    return invalid(StepValidity::kSpeedOutOfRange);
  }
  const double s = outward_sign(foot);
  // Local parabola frame: +x along phi, +y away from the stance foot.
  const Vec2 x_axis = unit(action.phi);
  const Vec2 y_axis = -s * perp(x_axis);
  // The previous velocity direction (the facing when standing), rescaled.
  const Vec2 direction = state.standing() ? unit(state.facing) : normalized(state.com_velocity);
  const double vx0 = action.speed * dot(direction, x_axis);
  const double vy0 = action.speed * dot(direction, y_axis);
  // Incoming velocity at t = -T/2 is (vx0, -alpha T): alpha > 0 needs vy0 < 0.
  if (!(vy0 < 0.0)) return invalid(StepValidity::kNotPositive);
  const double alpha = -vy0 / T;
  const double chord = vx0 * T;
  if (chord < limits.min_step_length || chord > limits.max_step_length) {
    return invalid(StepValidity::kLengthOutOfRange);
  }

  // Orientation interval: [phi, incoming velocity] within reach of the other foot.
  const OrientationInterval trajectory{action.phi, action.phi + s * std::atan2(-vy0, vx0)};
  const OrientationInterval reach = reachable_orientations(
      state.foot_orientation[static_cast<int>(other(foot))], other(foot), character.max_foot_turn);
  OrientationInterval interval;
  if (!intersect(reach, trajectory, foot, &interval)) {
    return invalid(StepValidity::kOrientationEmpty);
  }

  // Equation 1 at t = +-T/2, back in world space. The chord lies along +x.
  const double half = 0.5 * T;
  const Vec2 vertex = state.com - (-vx0 * half) * x_axis - (alpha * half * half) * y_axis;
  StepResult result;
  Footstep& step = result.step;
  step.foot = foot;
  step.kind = StepKind::kWalk;
  step.start_time = state.time;
  step.end_time = state.time + T;
  step.foot_position = vertex - character.foot_offset * y_axis;
  step.orientation_interval = interval;
  step.foot_orientation = clamp_orientation(action.phi, interval, foot);
  step.com_start = state.com;
  step.com_end = state.com + chord * x_axis;
  step.com_velocity_start = vx0 * x_axis + vy0 * y_axis;
  step.com_velocity_end = vx0 * x_axis + (alpha * T) * y_axis;
  step.phi = action.phi;
  step.speed = action.speed;
  step.alpha = alpha;
  const double theta = std::atan2(vx0 * half, character.com_height);
  const double incoming_speed = length(state.com_velocity);
  step.cost.fixed_rate = character.energy_rate * T;
  step.cost.speed_change = speed_change_cost(character.mass, action.speed, incoming_speed, theta);
  step.cost.curvature =
      character.curvature_weight * character.mass * alpha * arc_length(vx0, alpha, T);

  FootstepState& next = result.state;
  next = state;
  next.com = step.com_end;
  next.com_velocity = step.com_velocity_end;
  next.last_foot = foot;
  next.feet[static_cast<int>(foot)] = step.foot_position;
  next.foot_orientation[static_cast<int>(foot)] = interval;
  next.facing = action.phi;
  next.time = step.end_time;
  return result;
}

// The stop action: the COM decelerates uniformly to rest, and the stepping foot
// lands beside the point of rest, at the stance offset, turned to the facing.
StepResult create_stop(const FootstepState& state, const FootstepAction& action,
                       const CharacterParams& character) {
  const Foot foot = other(state.last_foot);
  const double T = action.duration;
  if (!(T > 0.0)) return invalid(StepValidity::kDurationOutOfRange);
  const Vec2 rest = state.com + (0.5 * T) * state.com_velocity;
  const double s = outward_sign(foot);
  const OrientationInterval reach = reachable_orientations(
      state.foot_orientation[static_cast<int>(other(foot))], other(foot), character.max_foot_turn);
  const double orientation = clamp_orientation(state.facing, reach, foot);

  StepResult result;
  Footstep& step = result.step;
  step.foot = foot;
  step.kind = StepKind::kStop;
  step.start_time = state.time;
  step.end_time = state.time + T;
  step.foot_position = rest + (s * character.foot_offset) * perp(unit(state.facing));
  step.orientation_interval = {orientation, orientation};
  step.foot_orientation = orientation;
  step.com_start = state.com;
  step.com_end = rest;
  step.com_velocity_start = state.com_velocity;
  step.com_velocity_end = {0.0, 0.0};
  step.phi = state.facing;
  const double theta = std::atan2(distance(rest, state.com), character.com_height);
  step.cost.fixed_rate = character.energy_rate * T;
  step.cost.speed_change = speed_change_cost(character.mass, 0.0, length(state.com_velocity), theta);

  FootstepState& next = result.state;
  next = state;
  next.com = rest;
  next.com_velocity = {0.0, 0.0};
  next.last_foot = foot;
  next.feet[static_cast<int>(foot)] = step.foot_position;
  next.foot_orientation[static_cast<int>(foot)] = step.orientation_interval;
  // The planted foot must stay within reach of the fixed stop orientation.
  OrientationInterval& stance = next.foot_orientation[static_cast<int>(other(foot))];
  intersect(stance, reachable_orientations(step.orientation_interval, foot, character.max_foot_turn),
            other(foot), &stance);
  next.time = step.end_time;
  return result;
}

}  // namespace

const char* to_string(Foot foot) { return foot == Foot::kLeft ? "left" : "right"; }

const char* to_string(StepKind kind) { return kind == StepKind::kWalk ? "walk" : "stop"; }

const char* to_string(Behavior behavior) {
  switch (behavior) {
    case Behavior::kWalk: return "walk";
    case Behavior::kArmsIn: return "arms_in";
    case Behavior::kSideStep: return "side_step";
  }
  return "walk";
}

const char* to_string(StepValidity validity) {
  switch (validity) {
    case StepValidity::kValid: return "valid";
    case StepValidity::kWrongFoot: return "a walking character must alternate feet";
    case StepValidity::kDurationOutOfRange: return "step duration out of range";
    case StepValidity::kSpeedOutOfRange: return "speed out of range";
    case StepValidity::kLengthOutOfRange: return "step length out of range";
    case StepValidity::kNotPositive: return "local parabola not positive";
    case StepValidity::kOrientationEmpty: return "empty foot-orientation interval";
    case StepValidity::kNotFinite: return "non-finite input";
    case StepValidity::kCollides: return "runs into an obstacle";
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
    *out = {a.inner + s * lo, a.inner + s * hi};
    return true;
  }
  return false;
}

double clamp_orientation(double angle, const OrientationInterval& interval, Foot foot) {
  const double s = outward_sign(foot);
  const double u = s * wrap_angle(angle - interval.inner);
  if (u >= 0.0 && u <= width(interval, foot)) return interval.inner + s * u;
  const double to_inner = std::fabs(wrap_angle(angle - interval.inner));
  const double to_outer = std::fabs(wrap_angle(angle - interval.outer));
  return to_inner <= to_outer ? interval.inner : interval.outer;
}

FootstepState standing_state(Vec2 position, double facing, const CharacterParams& character) {
  FootstepState state;
  state.com = position;
  state.facing = facing;
  const Vec2 left = perp(unit(facing));
  state.feet[static_cast<int>(Foot::kLeft)] = position + character.foot_offset * left;
  state.feet[static_cast<int>(Foot::kRight)] = position - character.foot_offset * left;
  state.foot_orientation[0] = state.foot_orientation[1] = {facing, facing};
  return state;
}

StepResult create_footstep(const FootstepState& state, const FootstepAction& action,
                           const CharacterParams& character) {
  if (!std::isfinite(action.phi) || !std::isfinite(action.speed) ||
      !std::isfinite(action.duration) || !is_finite(state.com) || !is_finite(state.com_velocity)) {
    return invalid(StepValidity::kNotFinite);
  }
  return action.kind == StepKind::kStop ? create_stop(state, action, character)
                                        : create_walk(state, action, character);
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

std::array<Circle, 3> torso_circles(Vec2 com, double facing, const CharacterParams& character,
                                    double pad) {
  const Vec2 left = perp(unit(facing));
  const double shoulder = 0.5 * character.torso_width - character.shoulder_radius;
  return {Circle{com, character.torso_radius + pad},
          Circle{com + shoulder * left, character.shoulder_radius + pad},
          Circle{com - shoulder * left, character.shoulder_radius + pad}};
}

}  // namespace footfall
