// Fuzz target: a rig profile (JSON), read or refused with
// std::invalid_argument; a profile read is applied to the project rig's
// skeleton (the rig target's seed), whose bones it may name wrongly (refused
// too) or rightly, and a rig made is posed at one instant, every bone with a
// finite rotation of unit length.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "animate/agent_motion.hpp"
#include "footfall/animate/rig.hpp"
#include "properties.hpp"

namespace {

std::string skeleton() {
  std::ifstream in(FOOTFALL_FUZZ_CORPUS "/fuzz_rig_gltf/humanoid-skeleton.gltf", std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string rig_text = skeleton();
  static const footfall::AgentPlan standing;
  static const footfall::CharacterParams character;
  static const footfall::Ground flat;  // the plane z = 0
  static const std::vector<double> times{0.0};
  try {
    const footfall::RigProfile profile = footfall::parse_rig_profile(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    const footfall::Rig rig = footfall::Rig::parse(rig_text, "rig.gltf", profile);
    footfall::fuzz::require_sound_pose(
        footfall::animate::agent_motion(rig.data(), standing, character, flat, times, 24.0));
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
