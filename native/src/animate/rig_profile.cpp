// Rig profiles, read field by field as the add-on's core/rig_profile.py reads
// them (a complete profile: the core does not detect bones yet).
#include <filesystem>
#include <stdexcept>

#include "footfall/animate/rig.hpp"
#include "io/json_reader.hpp"
#include "util/quoted.hpp"

namespace footfall {

namespace {

using detail::child;
using detail::fail;
using detail::Json;

constexpr const char* kBehaviors[] = {"walk", "arms_in", "side_step", "idle"};
constexpr const char* kDimensions[] = {"hip_height", "leg_length", "shoulder_width", "foot_length"};

std::string bone_name(const Json& parent, const std::string& path, const char* role) {
  const Json& value = detail::require(parent, path, role);
  const std::string where = child(path, role);
  if (!value.is_string() || value.get_ref<const std::string&>().empty())
    fail(where, "expected a bone name (a non-empty string)");
  return value.get<std::string>();
}

RigProfile read_profile(const Json& root) {
  detail::expect_header(root, "footfall-rig-profile", 1);
  detail::expect_object(root, "", {"format", "version", "rig", "facing", "bones", "clips", "dimensions"});
  RigProfile profile;
  const Json& bones = detail::require(root, "", "bones");
  detail::expect_object(bones, "bones", {"hips", "spine", "chest", "neck", "head", "left", "right"});
  profile.hips = bone_name(bones, "bones", "hips");
  profile.spine = bone_name(bones, "bones", "spine");
  profile.chest = bone_name(bones, "bones", "chest");
  profile.neck = bone_name(bones, "bones", "neck");
  profile.head = bone_name(bones, "bones", "head");
  const char* sides[] = {"left", "right"};
  for (int s = 0; s < 2; ++s) {
    const std::string path = child("bones", sides[s]);
    const Json& limb = detail::require(bones, "bones", sides[s]);
    detail::expect_object(limb, path, {"upper_arm", "forearm", "hand", "thigh", "shin", "foot", "toe"});
    RigProfile::Limb& out = profile.sides[s];
    out.upper_arm = bone_name(limb, path, "upper_arm");
    out.forearm = bone_name(limb, path, "forearm");
    out.hand = bone_name(limb, path, "hand");
    out.thigh = bone_name(limb, path, "thigh");
    out.shin = bone_name(limb, path, "shin");
    out.foot = bone_name(limb, path, "foot");
    out.toe = bone_name(limb, path, "toe");
  }
  if (const auto clips = root.find("clips"); clips != root.end()) {
    if (!clips->is_object()) fail("clips", "expected an object, got " + detail::type_name(*clips));
    for (auto it = clips->begin(); it != clips->end(); ++it) {
      bool known = false;
      for (const char* behavior : kBehaviors) known = known || it.key() == behavior;
      if (!known)
        fail(child("clips", it.key()), "unknown behaviour (one of walk, arms_in, side_step, idle)");
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

std::string profile_beside(const std::string& rig_path) {
  std::filesystem::path beside(rig_path);
  beside.replace_extension(".json");
  std::error_code error;
  if (!std::filesystem::is_regular_file(beside, error))
    throw std::invalid_argument(detail::user_text(rig_path) + ": no rig profile beside it (" +
                                detail::user_text(beside.string()) +
                                "); give one (docs/rig-profile.md)");
  return beside.string();
}

}  // namespace footfall
