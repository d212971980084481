// Fuzz target: a rig as glTF (a .gltf with its buffer as a data URI, or a
// .glb), read or refused with std::invalid_argument; a rig read has its bones
// detected (no profile) and walks four steps, as `footfall animate` poses it,
// every bone with a finite rotation of unit length at every frame.
// The seed (corpus/fuzz_rig_gltf/humanoid-skeleton.gltf) is the project
// rig's skeleton, skin and a few keys of its walk, without the mesh.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "animate/agent_motion.hpp"
#include "footfall/animate/rig.hpp"
#include "properties.hpp"

namespace {

// Four walking steps at 1.3 m/s, left foot first.
footfall::AgentPlan four_steps() {
  footfall::AgentPlan plan;
  for (int i = 0; i < 4; ++i) {
    footfall::Footstep step;
    step.foot = i % 2 == 0 ? footfall::Foot::kLeft : footfall::Foot::kRight;
    step.start_time = 0.5 * i;
    step.end_time = 0.5 * (i + 1);
    step.foot_position = {0.65 * i + 0.3, i % 2 == 0 ? 0.1 : -0.1};
    step.com_start = {0.65 * i, 0};
    step.com_end = {0.65 * (i + 1), 0};
    plan.footsteps.push_back(step);
  }
  return plan;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const footfall::AgentPlan plan = four_steps();
  static const footfall::CharacterParams character;
  static const footfall::Ground flat;  // the plane z = 0
  static const std::vector<double> times{0.0, 0.25, 0.75, 1.125, 1.625, 2.125};
  try {
    const footfall::Rig rig = footfall::Rig::parse(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.gltf", {});
    footfall::fuzz::require_sound_pose(
        footfall::animate::agent_motion(rig.data(), plan, character, flat, times, 24.0));
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
