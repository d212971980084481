// Footfall — a plan's footholds checked against its ground (footfall
// metrics): every foot on it, held, within the step limits, its swing clear.
#pragma once

#include <array>

#include "footfall/ground/ground.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {

/// A plan's footholds by foothold_fault (ground/foothold.hpp), each at its
/// chosen orientation.
struct GroundCheck {
  long footholds = 0;    ///< Every footstep of every agent; 0 without ground.
  /// kOffGround: no standable level, or too steep; or the plan's foot_height
  /// over 2 cm from the ground there.
  long off_ground = 0;
  long unsupported = 0;  ///< kUnsupported: too little of the sole held.
  long over_rise = 0;    ///< kRise: a step up or down over the limits.
  long swing = 0;        ///< kSwing: a swinging foot through the ground.
};

/// Checks `plan`'s footholds on its ground (none without ground).
GroundCheck check_ground(const Plan& plan);

/// The ground's height under each foot of `agent`'s start, indexed by Foot:
/// the standable level there nearest its first footstep's foot_height (a
/// plan's footsteps carry their heights, its start does not), else the
/// lowest; 0 where there is none. [m]
std::array<double, 2> start_foot_heights(const Ground& ground, const AgentPlan& agent,
                                         const CharacterParams& character);

}  // namespace footfall
