// Rig profiles, read field by field as the add-on's core/rig_profile.py reads
// them (with partial=True: what a profile leaves out is detected).
#include <filesystem>
#include <stdexcept>

#include "footfall/animate/rig.hpp"
#include "io/json_reader.hpp"

namespace footfall {

namespace {

using detail::child;
using detail::fail;
using detail::Json;

constexpr const char* kDimensions[] = {"hip_height", "leg_length", "shoulder_width", "foot_length"};

void read_bone(const Json& parent, const std::string& path, const std::string& role, const std::string& key,
               RigProfile& profile) {
  const auto value = parent.find(key);
  if (value == parent.end()) return;  // left to detection
  if (!value->is_string() || value->get_ref<const std::string&>().empty())
    fail(child(path, key), "expected a bone name (a non-empty string)");
  profile.bones[role] = value->get<std::string>();
}

RigProfile read_profile(const Json& root) {
  detail::expect_header(root, "footfall-rig-profile", 1);
  detail::expect_object(root, "", {"format", "version", "rig", "facing", "bones", "clips", "dimensions"});
  RigProfile profile;
  if (const auto bones = root.find("bones"); bones != root.end()) {
    detail::expect_object(*bones, "bones", {"hips", "spine", "chest", "neck", "head", "left", "right"});
    for (const char* role : {"hips", "spine", "chest", "neck", "head"}) read_bone(*bones, "bones", role, role, profile);
    for (const char* side : {"left", "right"}) {
      const auto limb = bones->find(side);
      if (limb == bones->end()) continue;
      const std::string path = child("bones", side);
      detail::expect_object(*limb, path, {"upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe"});
      for (const char* role : {"upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe"})
        read_bone(*limb, path, std::string(side) + "." + role, role, profile);
    }
  }
  if (const auto clips = root.find("clips"); clips != root.end()) {
    if (!clips->is_object()) fail("clips", "expected an object, got " + detail::type_name(*clips));
    for (auto it = clips->begin(); it != clips->end(); ++it) {
      bool known = false;
      for (const char* behavior : kClipBehaviors) known = known || it.key() == behavior;
      for (const char* behavior : kStairClips) known = known || it.key() == behavior;
      if (!known)
        fail(child("clips", it.key()),
             "unknown behaviour (one of walk, arms_in, side_step, idle, stairs_up, stairs_down)");
      if (it->is_null()) continue;
      if (!it->is_string() || it->get_ref<const std::string&>().empty())
        fail(child("clips", it.key()), "expected a clip name or null");
      profile.clips[it.key()] = it->get<std::string>();
    }
  }
  if (const auto dimensions = root.find("dimensions"); dimensions != root.end()) {
    detail::expect_object(*dimensions, "dimensions",
                          {kDimensions[0], kDimensions[1], kDimensions[2], kDimensions[3]});
    for (auto it = dimensions->begin(); it != dimensions->end(); ++it) {
      const std::string path = child("dimensions", it.key());
      const double value = detail::number(*it, path);
      if (value <= 0) fail(path, "expected a positive number of metres");
      profile.dimensions[it.key()] = value;
    }
  }
  return profile;
}

}  // namespace

RigProfile parse_rig_profile(const std::string& text, const std::string& source) {
  const Json root = detail::parse_json(text, source);
  try {
    return read_profile(root);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
}

RigProfile load_rig_profile(const std::string& path) {
  return parse_rig_profile(detail::read_file(path), path);
}

RigProfile rig_profile_for(const std::string& rig_path, const std::string& profile_path) {
  if (!profile_path.empty()) return load_rig_profile(profile_path);
  std::filesystem::path beside(rig_path);
  beside.replace_extension(".json");
  std::error_code error;
  return std::filesystem::is_regular_file(beside, error) ? load_rig_profile(beside.string()) : RigProfile{};
}

}  // namespace footfall
