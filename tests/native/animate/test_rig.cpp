// Reading rigs and their profiles: the project's rig measured, and every
// refusal naming the file and what is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "animate/rig_data.hpp"
#include "footfall/animate/rig.hpp"
#include "io/json_reader.hpp"

namespace footfall {
namespace {

const std::string kRig = std::string(FOOTFALL_RIGS_DIR) + "/footfall_humanoid.glb";
const std::string kProfile = std::string(FOOTFALL_RIGS_DIR) + "/footfall_humanoid.json";

std::string error_of(const std::string& text) {
  try {
    parse_rig_profile(text, "p.json");
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(RigProfile, RefusalsNameTheField) {
  EXPECT_EQ(error_of("[]"), "p.json: (top level): expected an object, got array");
  EXPECT_EQ(error_of(R"({"format": "footfall-rig-profile", "version": 2})"),
            "p.json: version: unsupported version 2 (this Footfall reads version 1)");
  auto document = detail::parse_json(detail::read_file(kProfile), kProfile);
  document["bones"]["left"]["toes"] = "toe.L";
  EXPECT_EQ(error_of(document.dump()), "p.json: bones.left.toes: unknown field");
  document = detail::parse_json(detail::read_file(kProfile), kProfile);
  document["bones"]["left"]["toe"] = 3;
  EXPECT_EQ(error_of(document.dump()), "p.json: bones.left.toe: expected a bone name (a non-empty string)");
  document = detail::parse_json(detail::read_file(kProfile), kProfile);
  document["clips"]["run"] = "run";
  EXPECT_EQ(error_of(document.dump()),
            "p.json: clips.run: unknown behaviour (one of walk, arms_in, side_step, idle, stairs_up, stairs_down)");
  document = detail::parse_json(detail::read_file(kProfile), kProfile);
  document["dimensions"]["hip_height"] = -1;
  EXPECT_EQ(error_of(document.dump()), "p.json: dimensions.hip_height: expected a positive number of metres");
}

TEST(Rig, TheProjectRigIsMeasuredFromItsBones) {
  const Rig rig = Rig::load(kRig, load_rig_profile(kProfile));
  const auto& data = rig.data();
  const RigProfile profile = load_rig_profile(kProfile);
  EXPECT_NEAR(rig.hip_height(), profile.dimensions.at("hip_height"), 1e-4);
  const double leg = data.legs[0].upper + data.legs[0].lower;
  EXPECT_NEAR(leg, profile.dimensions.at("leg_length"), 1e-4);
  // It faces -Y (Blender's front view), as its profile says.
  EXPECT_NEAR(data.forward_yaw, -M_PI / 2, 1e-6);
  for (const auto& [behavior, source] : rig.clip_sources()) EXPECT_EQ(source, behavior);
  // The heel is behind the ankle, the ball ahead of it.
  EXPECT_GT(data.legs[1].shape.heel_back, 0.03);
  EXPECT_GT(data.legs[1].shape.ball_ahead, 0.1);
}

std::string load_error(const RigProfile& profile, const std::string& path = kRig) {
  try {
    Rig::load(path, profile);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(Rig, WithoutAProfileItsBonesAreDetected) {
  RigProfile none;
  const Rig detected = Rig::load(kRig, none);
  const Rig profiled = Rig::load(kRig, load_rig_profile(kProfile));
  EXPECT_EQ(detected.data().hips, profiled.data().hips);
  for (int side = 0; side < 2; ++side) {
    EXPECT_EQ(detected.data().legs[side].thigh, profiled.data().legs[side].thigh);
    EXPECT_EQ(detected.data().legs[side].toe, profiled.data().legs[side].toe);
    EXPECT_EQ(detected.data().hands[side], profiled.data().hands[side]);
  }
  EXPECT_EQ(detected.clip_sources(), profiled.clip_sources());  // named as the behaviours
}

// The project rig as a .glb with its JSON changed by `change`.
template <typename Change>
std::string changed_rig(Change change) {
  const std::string bytes = detail::read_file(kRig);
  std::uint32_t length;
  std::memcpy(&length, bytes.data() + 12, 4);
  auto document = detail::parse_json(bytes.substr(20, length), kRig);
  change(document);
  std::string text = document.dump();
  text.append((4 - text.size() % 4) % 4, ' ');
  const std::string binary = bytes.substr(20 + length);
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string body = u32(static_cast<std::uint32_t>(text.size())) + "JSON" + text + binary;
  return "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + body.size())) + body;
}

TEST(Rig, BonesWithoutNamesGoByTheirIndexAndAreFoundByShape) {
  // As Khronos' CesiumMan has them: joints without names, one unnamed clip.
  const std::string bytes = changed_rig([](detail::Json& document) {
    for (auto& node : document["nodes"]) node.erase("name");
    auto& animations = document["animations"];
    animations.erase(animations.begin(), animations.begin() + 3);  // the walk is the last
    animations[0].erase("name");
  });
  const Rig rig = Rig::parse(bytes, "unnamed.glb", {});
  const Rig profiled = Rig::load(kRig, load_rig_profile(kProfile));
  EXPECT_EQ(rig.data().hips, profiled.data().hips);
  for (int side = 0; side < 2; ++side) {
    EXPECT_EQ(rig.data().legs[side].toe, profiled.data().legs[side].toe);
    EXPECT_EQ(rig.data().hands[side], profiled.data().hands[side]);
  }
  EXPECT_EQ(rig.data().bone_names[rig.data().hips], "nodes[" + std::to_string(rig.data().hips) + "]");
  // Its only animation is an upper-body clip (its feet keep still): not taken as the walk.
  EXPECT_EQ(rig.clip_sources().at("walk"), "procedural");
}

TEST(Rig, ReadsTheBufferBesideAGltfFileButNoFileFromMemory) {
  const std::string bytes = detail::read_file(kRig);
  std::uint32_t length;
  std::memcpy(&length, bytes.data() + 12, 4);
  auto document = detail::parse_json(bytes.substr(20, length), kRig);
  const auto folder = std::filesystem::temp_directory_path() / ("footfall-gltf-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder / "a-folder");
  std::ofstream(folder / "rig.bin", std::ios::binary) << bytes.substr(20 + length + 8);
  const auto gltf_naming = [&](const std::string& uri) {
    document["buffers"][0]["uri"] = uri;
    const std::string path = (folder / "rig.gltf").string();
    std::ofstream(path) << document.dump();
    return path;
  };
  const RigProfile profile = load_rig_profile(kProfile);
  EXPECT_EQ(Rig::load(gltf_naming("rig.bin"), profile).data().hips, Rig::load(kRig, profile).data().hips);
  const auto refusal = [&](auto read) {
    try {
      read();
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  const std::string text = detail::read_file(gltf_naming("rig.bin"));
  EXPECT_NE(refusal([&] { Rig::parse(text, "memory.gltf", profile); }).find("not a glTF file this Footfall can read"),
            std::string::npos);
  EXPECT_NE(refusal([&] { Rig::load(gltf_naming("a-folder"), profile); }).find("not a glTF file this Footfall can read"),
            std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST(Rig, RefusesAClipWhoseKeyTimeIsNotANumber) {
  // A NaN time passes a sortedness check and would send a lookup past the keys.
  std::string bytes = detail::read_file(kRig);
  std::uint32_t length;
  std::memcpy(&length, bytes.data() + 12, 4);
  const auto document = detail::parse_json(bytes.substr(20, length), kRig);
  const int input = document["animations"][0]["samplers"][0]["input"].get<int>();
  const auto& accessor = document["accessors"][input];
  const auto& view = document["bufferViews"][accessor["bufferView"].get<int>()];
  const std::size_t at = 20 + length + 8 + view.value("byteOffset", 0) + accessor.value("byteOffset", 0) +
                         4 * (accessor["count"].get<std::size_t>() / 2);
  const float nan = std::nanf("");
  std::memcpy(bytes.data() + at, &nan, 4);
  try {
    Rig::parse(bytes, "nan.glb", load_rig_profile(kProfile));
    FAIL() << "a NaN key time was read";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("a key time or value that is not a finite number"), std::string::npos)
        << error.what();
  }
}

TEST(Rig, RefusesBonesAndClipsItLacksAndLegsThatAreNotChains) {
  RigProfile profile = load_rig_profile(kProfile);
  profile.bones["left.foot"] = "Foot_L";
  EXPECT_EQ(load_error(profile), kRig + ": bones.left.foot = 'Foot_L': the rig has no such bone");
  profile = load_rig_profile(kProfile);
  profile.bones["right.shin"] = "thigh.L";
  EXPECT_EQ(load_error(profile), kRig + ": bones.right.shin = 'thigh.L': not a child of the thigh");
  profile = load_rig_profile(kProfile);
  profile.clips["walk"] = "Walk_Cycle";
  EXPECT_EQ(load_error(profile), kRig + ": clips.walk = 'Walk_Cycle': the rig has no such animation (it has: "
                                        "'arms_in', 'idle', 'side_step', 'walk')");
  profile = load_rig_profile(kProfile);
  profile.bones["hips"] = "Hips";
  EXPECT_EQ(load_error(profile), kRig + ": no skin has the bone 'Hips' (bones.hips): the rig needs a skinned mesh "
                                        "on a skeleton");
  EXPECT_NE(load_error(load_rig_profile(kProfile), kProfile).find("not a glTF file this Footfall can read"),
            std::string::npos);
}

}  // namespace
}  // namespace footfall
