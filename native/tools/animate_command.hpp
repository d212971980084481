// footfall animate, and plan's --glb: a plan animated on a rig and written
// as one .glb, without Blender.
#pragma once

#include <ostream>
#include <string>

#include "footfall/plan/plan.hpp"

namespace footfall::tools {

struct AnimateArguments {
  std::string rig;      ///< .glb or .gltf
  std::string profile;  ///< empty: the rig's name with .json beside it, if there is one
  double fps = 24;
};

/// Reads the rig and its profile, animates `plan` and writes `output`
/// (creating its folder); prints what it wrote.
void animate_and_write(const Plan& plan, const AnimateArguments& arguments, const std::string& output,
                       std::ostream& out);

}  // namespace footfall::tools
