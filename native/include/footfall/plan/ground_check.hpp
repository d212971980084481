// Footfall — a plan's footholds checked against its ground (footfall
// metrics): every foot on it, held, within the step limits, its swing clear.
#pragma once

#include "footfall/plan/plan.hpp"

namespace footfall {

/// A plan's footholds by foothold_fault (ground/foothold.hpp), each at its
/// chosen orientation.
struct GroundCheck {
  long footholds = 0;    ///< Every footstep of every agent; 0 without ground.
  long off_ground = 0;   ///< kOffGround: no standable level, or too steep.
  long unsupported = 0;  ///< kUnsupported: too little of the sole held.
  long over_rise = 0;    ///< kRise: a step up or down over the limits.
  long swing = 0;        ///< kSwing: a swinging foot through the ground.
};

/// Checks `plan`'s footholds on its ground (none without ground).
GroundCheck check_ground(const Plan& plan);

}  // namespace footfall
