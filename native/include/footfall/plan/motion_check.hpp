// Footfall — how well a plan moves, by its own evaluation: whether the COM's
// velocity is continuous from step to step and within the character's top
// speed, and whether every stance foot stays where it is planted.
#pragma once

#include "footfall/plan/plan.hpp"

namespace footfall {

/// The worst of each fault over one agent's plan.
struct MotionCheck {
  /// Largest change of the COM velocity across a step boundary (standing
  /// counts as zero before the first step). [m/s]
  double velocity_jump = 0;
  double top_speed = 0;  ///< Fastest COM, sampled. [m/s]
  /// Farthest a stance foot is from where its step plants it, or turned from
  /// how it stood at the step's first instant (a turn counts as the travel of
  /// a point 0.1 m from the ankle; a foot not on the ground at least 1 um),
  /// while the step is under way (sampled, ends included). [m]
  double stance_slide = 0;
  int worst_jump_step = -1;   ///< The step after the largest jump.
  int worst_slide_step = -1;  ///< The step whose stance foot strays farthest.
};

/// Checks `plan` at `rate` samples a second within every step. Throws
/// std::invalid_argument for a rate outside (0, 10000] Hz.
MotionCheck check_motion(const AgentPlan& plan, double rate = 500.0);

}  // namespace footfall
