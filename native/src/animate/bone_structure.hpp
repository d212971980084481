// Footfall — a humanoid's limbs from the shape of its skeleton, where the
// bone names follow no scheme ("leg_joint_L_1", "Bone.017"): the legs are
// the two chains that descend from where they meet (the hips) to the lowest
// bones, the arms the two that reach farthest to either side from where they
// meet (the chest). Left is left of the facing the feet give (heel to toe).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "footfall/animate/bone_map.hpp"

namespace footfall::animate {

/// Parents by bone name (a later bone of the same name wins).
using Parents = std::map<std::string, std::optional<std::string>>;

/// The bone and its ancestors, nearest first (stopping at a cycle).
std::vector<std::string> ancestors(const std::string& bone, const Parents& parents);

/// side ("left", "right") -> role -> bone, for the roles the shape shows;
/// empty when a bone has no rest geometry or no two legs are found.
std::map<std::string, std::map<std::string, std::string>> limbs_from_shape(const std::vector<RigBone>& bones);

}  // namespace footfall::animate
