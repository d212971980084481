// Footfall — limb names.
#include "footfall/model/body.hpp"

namespace footfall {

const char* to_string(Limb limb) {
  static const char* const kNames[kLimbCount] = {
      "head",         "shoulders",     "torso",      "pelvis",      "upper_arm_left",
      "upper_arm_right", "forearm_left", "forearm_right", "thigh_left", "thigh_right",
      "shin_left",    "shin_right",    "foot_left",  "foot_right"};
  const int index = static_cast<int>(limb);
  return index >= 0 && index < kLimbCount ? kNames[index] : "?";
}

}  // namespace footfall
