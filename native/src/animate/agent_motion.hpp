// Footfall — one agent's motion on a rig, frame by frame: the hips on the
// planned COM path, the legs reaching the planned feet (an analytic two-bone
// IK with a knee pole) as they roll heel to toe, the upper body playing each
// section's clip (docs/animation.md).
#pragma once

#include <vector>

#include "animate/rig_data.hpp"
#include "footfall/ground/ground.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall::animate {

/// The local transforms of the nodes the motion moves, per frame.
struct AgentMotion {
  std::vector<int> nodes;                ///< rig node indices
  std::vector<std::vector<Trs>> frames;  ///< [node][frame]
};

/// The motion of `plan`'s agent at `times` [s] (frames at `fps`, from 0),
/// with `character` (the agent's), on `ground` (the plan's): after its last
/// step it holds its last pose.
AgentMotion agent_motion(const RigData& rig, const AgentPlan& plan, const CharacterParams& character,
                         const Ground& ground, const std::vector<double>& times, double fps);

}  // namespace footfall::animate
