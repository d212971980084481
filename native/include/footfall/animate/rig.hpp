// Footfall — a humanoid rig read from glTF, with its profile (which bone
// plays which role, which animation plays which behaviour), ready to animate
// a crowd (crowd_gltf.hpp). The profile format is docs/rig-profile.md.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>

namespace footfall {

/// A rig profile: bone roles, clips and dimensions (docs/rig-profile.md).
struct RigProfile {
  struct Limb {
    std::string upper_arm, forearm, hand, thigh, shin, foot, toe;
  };
  std::string hips, spine, chest, neck, head;
  std::array<Limb, 2> sides;  ///< left, right
  /// Behaviour ("walk", "arms_in", "side_step", "idle") -> animation name;
  /// a behaviour left out or null has none.
  std::map<std::string, std::string> clips;
  /// Metres, as the profile gives them (any may be left out).
  std::map<std::string, double> dimensions;
};

/// Parses a profile document. Errors are std::invalid_argument:
/// "SOURCE: FIELD: what is wrong".
RigProfile parse_rig_profile(const std::string& text, const std::string& source = "<profile>");
/// Reads a profile file (errors as parse_rig_profile).
RigProfile load_rig_profile(const std::string& path);
/// The profile beside a rig, as the add-on finds it ("robot.glb" ->
/// "robot.json"); std::invalid_argument if there is none.
std::string profile_beside(const std::string& rig_path);

namespace animate {
struct RigData;
}

/// A rig read from a .glb or .gltf file: its skeleton, meshes and clips,
/// the roles of its bones, its rest geometry. Cheap to copy (shared, const).
class Rig {
 public:
  /// Reads the rig and maps its bones by `profile`. Errors are
  /// std::invalid_argument naming the file and what is wrong (no skin, a
  /// bone or clip the profile names that the rig lacks, a mirrored or sheared
  /// transform).
  static Rig load(const std::string& path, const RigProfile& profile);

  /// The hip joints' height above the ground in the rest pose. [m]
  double hip_height() const;
  /// The rig's file.
  const std::string& path() const;
  /// Behaviour -> where its clip comes from: the animation's name, or
  /// "procedural".
  std::map<std::string, std::string> clip_sources() const;

  const animate::RigData& data() const { return *data_; }

 private:
  std::shared_ptr<const animate::RigData> data_;
};

}  // namespace footfall
