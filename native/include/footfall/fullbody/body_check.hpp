// Footfall — the full-body check of a plan: each agent's body, in each
// step's behaviour and phase, swept along its planned COM path against the
// scene's obstacles in 3-D.
#pragma once

#include <vector>

#include "footfall/plan/plan.hpp"

namespace footfall {

/// A limb reaching deeper than this into an obstacle counts as a
/// penetration (a limb touching one is not). [m]
constexpr double kPenetrationTolerance = 0.001;

/// One agent's figures.
struct AgentBodyCheck {
  long long poses = 0;   ///< Body poses tested.
  int penetrations = 0;  ///< Poses with a limb deeper than kPenetrationTolerance.
  double deepest = 0;    ///< The deepest reach of a limb into an obstacle. [m]
};

/// The whole plan's.
struct BodyCheck {
  std::vector<AgentBodyCheck> agents;  ///< In the plan's order.
  long long poses = 0;
  int penetrations = 0;
  double deepest = 0;  ///< [m]
};

/// Checks `plan` at `pose_rate` poses per second [1, 1000] of each agent's
/// plan (its body from plan.character, placed as pose_during places it;
/// before the first step and after the last, as at their ends). Throws
/// std::invalid_argument for a rate out of range, bad obstacles or a bad
/// character.
BodyCheck check_body(const Plan& plan, double pose_rate = 30.0);

}  // namespace footfall
