// Footfall — finding a humanoid's bones by name and hierarchy, whatever the
// naming scheme, and by the skeleton's shape where names say nothing
// (docs/rig-profile.md, "Detection"). The add-on's Import Rig and the core's
// rig reader both use it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "footfall/model/geometry3.hpp"

namespace footfall {

/// A bone of a rig: its name, its parent's (none at a root), and where
/// known its rest head and tail in the world (Z up). [m]
struct RigBone {
  std::string name;
  std::optional<std::string> parent;
  std::optional<Vec3> head;
  std::optional<Vec3> tail;
};

/// What detection found: role -> bone ("hips", "spine", "chest", "neck",
/// "head", "left.thigh", ...), and the roles it could not find, in the order
/// left limbs, right limbs (upper_arm, forearm, hand, thigh, shin, foot, toe),
/// then the trunk.
struct BoneDetection {
  std::map<std::string, std::string> roles;
  std::vector<std::string> missing;
};

/// Maps the bones to roles. Roles in `given` are taken as they are, and the
/// trunk is found from the limbs given as well as from those found. Limbs are
/// found by name (a side marker and a base name among synonyms), else from
/// the skeleton's shape when every bone has its rest head and tail; the hips
/// where both legs meet, the chest where both arms meet, the spine the first
/// bone from the hips toward the chest, the neck and head by name or as the
/// chain that rises from the chest.
BoneDetection detect_bones(const std::vector<RigBone>& bones,
                           const std::map<std::string, std::string>& given = {});

/// (side, base name) of a bone name: side "left", "right" or "" for the
/// trunk; the base lower case without separators ("mixamorig:LeftForeArm" ->
/// ("left", "forearm")).
std::pair<std::string, std::string> split_side(const std::string& name);

}  // namespace footfall
