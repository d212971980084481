// Footfall — an animated crowd as one binary glTF, without Blender: every
// agent of a plan animated on a rig (docs/animation.md) and written with
// tinygltf.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "footfall/animate/rig.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {

/// A rig may stand this share taller or shorter than the character an agent
/// was planned with (its centre of mass about 5 % above the hip joints).
constexpr double kRigSizeTolerance = 0.1;

struct CrowdGltfOptions {
  double fps = 24;  ///< keys per second [1, 240]
};

/// What was written.
struct CrowdGltfSummary {
  int agents = 0;
  int frames = 0;              ///< keys per channel
  std::uintmax_t bytes = 0;    ///< the file's size
  /// Behaviour -> the clip that plays it: an animation's name, or "procedural".
  std::map<std::string, std::string> clips;
};

/// Animates every agent of `plan` on `rig` and writes one .glb to `path`
/// (atomically: a failure leaves no file). Per agent: a node named after it
/// holding a copy of the rig's nodes, a skin of its own over the rig's shared
/// meshes, and one animation named after it; an agent that leaves is scaled
/// to nothing after it has left. std::invalid_argument names the agent when
/// the rig is not the size it was planned with, or the fps is out of range,
/// and refuses a plan on ground (its "ground"), which it cannot animate yet.
CrowdGltfSummary write_crowd_gltf(const Plan& plan, const Rig& rig, const std::string& path,
                                  const CrowdGltfOptions& options = {});

}  // namespace footfall
