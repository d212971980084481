// Footfall — a humanoid rig read from glTF, with its profile (which bone
// plays which role, which animation plays which behaviour), ready to animate
// a crowd (crowd_gltf.hpp). The profile format is docs/rig-profile.md.
#pragma once

#include <map>
#include <memory>
#include <string>

namespace footfall {

/// The behaviours a rig may have a clip for, as a profile's `clips` names them.
inline constexpr const char* kClipBehaviors[] = {"walk", "arms_in", "side_step", "idle"};
/// The clips a rig may have for walking up and down stairs: played where it
/// has them (else the walk plays), never made procedurally.
inline constexpr const char* kStairClips[] = {"stairs_up", "stairs_down"};

/// A rig profile: bone roles, clips and dimensions (docs/rig-profile.md).
/// Any part may be left out: detection (bone_map.hpp) finds the bones it
/// does not name.
struct RigProfile {
  /// Role -> bone: "hips", "spine", "chest", "neck", "head", and per side
  /// "left.thigh", "right.upper_arm"... (upper_arm, forearm, hand, thigh,
  /// shin, foot, toe).
  std::map<std::string, std::string> bones;
  /// Behaviour ("walk", "arms_in", "side_step", "idle", "stairs_up",
  /// "stairs_down") -> animation name; a behaviour left out or null has none.
  std::map<std::string, std::string> clips;
  /// Metres, as the profile gives them (any may be left out).
  std::map<std::string, double> dimensions;
};

/// Parses a profile document. Errors are std::invalid_argument:
/// "SOURCE: FIELD: what is wrong".
RigProfile parse_rig_profile(const std::string& text, const std::string& source = "<profile>");
/// Reads a profile file (errors as parse_rig_profile).
RigProfile load_rig_profile(const std::string& path);
/// The profile of a rig: the file `profile_path`, else (empty) the one
/// beside the rig as the add-on finds it ("robot.glb" -> "robot.json"), else
/// an empty profile (everything detected).
RigProfile rig_profile_for(const std::string& rig_path, const std::string& profile_path = "");

namespace animate {
struct RigData;
}
}  // namespace footfall

namespace tinygltf {
class Model;
}

namespace footfall {

/// A rig read from a .glb or .gltf file: its skeleton, meshes and clips,
/// the roles of its bones, its rest geometry. Cheap to copy (shared, const).
class Rig {
 public:
  /// Reads the rig and maps its bones: the profile's, the others detected
  /// among the joints of its skin. Errors are std::invalid_argument naming
  /// the file and what is wrong (no skin, roles not found with the rig's
  /// bones listed, a bone or clip the profile names that the rig lacks, a
  /// mirrored or sheared transform).
  static Rig load(const std::string& path, const RigProfile& profile);
  /// The same from the bytes of a .glb or a .gltf whose buffers are data
  /// URIs; errors name the rig `name`.
  static Rig parse(const std::string& bytes, const std::string& name, const RigProfile& profile);

  /// The hip joints' height above the ground in the rest pose. [m]
  double hip_height() const;
  /// The rig's file.
  const std::string& path() const;
  /// Behaviour -> where its clip comes from: the animation's name, or
  /// "procedural".
  std::map<std::string, std::string> clip_sources() const;

  const animate::RigData& data() const { return *data_; }

 private:
  static Rig from_model(tinygltf::Model model, const std::string& path, const RigProfile& profile);
  std::shared_ptr<const animate::RigData> data_;
};

}  // namespace footfall
