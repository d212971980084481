// Private: the parts of a walking step that depend only on the action relative
// to the incoming velocity (speed, duration, turn), so that the planner can
// compute them once per action instead of once per node. create_footstep and
// the planner build every walking step through walk_step below.
#pragma once

#include "footfall/model/footstep.hpp"

namespace footfall::detail {

/// A walking step in its local parabola frame.
struct StepShape {
  double speed = 0;       ///< Desired speed v. [m/s]
  double duration = 0;    ///< T. [s]
  double turn = 0;        ///< Inward angle from the incoming velocity to phi. [rad]
  double cos_turn = 1;    ///< cos(turn)
  double sin_turn = 0;    ///< sin(turn)
  double vx0 = 0;         ///< Local velocity along phi. [m/s]
  double alpha = 0;       ///< Equation 1's coefficient. [m/s^2]
  double chord = 0;       ///< COM travel, vx0 T. [m]
  double cos_2theta = 1;  ///< cos(2 theta), theta the leg angle at heel strike.
  double fixed_rate = 0;  ///< dE1. [J]
  double curvature = 0;   ///< dE3. [J]
};

/// The shape of a step at `speed` for `duration`, turned by `turn` (which
/// must lie in (0, pi) for a positive parabola).
StepShape step_shape(double speed, double duration, double turn, const CharacterParams& character);

/// Why `shape` breaks `limits`, or kValid.
StepValidity check_limits(const StepShape& shape, const FootLimits& limits);

/// The direction a state moves in: its velocity, or its facing when standing.
struct Heading {
  Vec2 direction;    ///< Unit vector.
  double angle = 0;  ///< [rad]
  double speed = 0;  ///< Incoming speed, 0 when standing. [m/s]
};
/// The heading of `state`.
Heading heading_of(const FootstepState& state);

/// The walking step of `foot` with `shape` from `state`, its parabola turned
/// to `phi` (= heading.angle + inward * turn); `reach` is what the other foot
/// allows (reachable_orientations). Checks only the orientation interval.
StepResult walk_step(const FootstepState& state, Foot foot, const Heading& heading,
                     const StepShape& shape, double phi, const OrientationInterval& reach,
                     const CharacterParams& character);

}  // namespace footfall::detail
