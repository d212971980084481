// Footfall — how the upper body follows the plan: the body's facing, the
// walking clip's amplitude from each step's speed, and the chest and head
// turning toward the facing ahead before a turn. The model is documented in
// docs/animation.md; the add-on's Apply and the headless writer both use
// this one.
#pragma once

#include "footfall/plan/plan.hpp"

namespace footfall::animate {

constexpr double kLeastSwing = 0.25;  ///< share of the walking clip's amplitude when barely moving
constexpr double kLookAhead = 0.5;    ///< [s] how far ahead the chest and head look
constexpr int kLookSamples = 5;       ///< facings averaged over the look-ahead
constexpr double kMostLook = 1.0471975511965976;  ///< 60 deg: the largest look angle
constexpr double kChestLook = 0.4;    ///< share of the look angle the chest turns by
constexpr double kHeadLook = 0.4;     ///< share the head turns by on top of the chest
constexpr double kTwistEase = 0.15;   ///< [s] the chest's twist turns to a new step's heading over this
constexpr double kMostTwist = 1.0471975511965976;  ///< 60 deg: the largest twist of the chest

/// The body's facing at `t` [rad]: between the feet; in a side step, across
/// the step's direction of travel, on the side the feet point to.
double body_facing(const AgentPlan& plan, double t);

/// The upper body's following of one agent's plan.
class UpperBodyFollower {
 public:
  /// `full_speed`: the speed at which the walking clip plays at its full
  /// amplitude (the character's preferred speed) [m/s].
  UpperBodyFollower(const AgentPlan& plan, double full_speed);
  /// Share of the walking clip's amplitude at `t`, in [kLeastSwing, 1]:
  /// each walking step's speed over `full_speed`, from step middle to step
  /// middle.
  double swing_at(double t) const;
  /// The look angle at `t` [rad, counter-clockwise]: from the body's facing
  /// to its mean facing over the next kLookAhead, within kMostLook, times
  /// the COM's speed over `full_speed` (at most 1): none standing.
  double look_at(double t) const;
  /// The chest's twist at `t` [rad, counter-clockwise]: from the body's
  /// facing (between the feet) to the heading the planner tested the body
  /// at (the step's phi, which may turn ahead of the feet, as at a door the
  /// shoulders turn to pass), reached kTwistEase into each step from the
  /// step's before, within kMostTwist.
  double twist_at(double t) const;

 private:
  const AgentPlan& plan_;
  double full_speed_;
  std::vector<double> swing_times_, swings_;  ///< per walking step: its middle, its share
};

}  // namespace footfall::animate
