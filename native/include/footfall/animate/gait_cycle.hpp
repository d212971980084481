// Footfall — a clip's gait cycle found from its motion: how many cycles it
// holds and where in the cycle the right heel strikes. The add-on's
// core/clip_cycle.py (a rig's actions in Blender) and the headless rig reader
// (a glTF animation) both use it.
#pragma once

#include <string>
#include <vector>

namespace footfall::animate {

/// `cycles` gait cycles over the clip; the right heel strikes at `strike`
/// (a fraction of a cycle); `source` says what showed it: "feet", "hands"
/// or "convention".
struct GaitCycle {
  int cycles = 1;
  double strike = 0.25;  ///< where the procedural clips put it (the left arm forward)
  std::string source = "convention";
};

/// The cycle of a clip sampled evenly over its range (its end left out):
/// `feet` the right foot's lead over the left along the rig's facing,
/// `hands` the left hand's lead over the right, `leg_length` in the same
/// units. The right heel strikes where the right foot leads most; a clip
/// whose feet keep still (less than 5 % of the leg's length apart) is timed
/// by its hands, which swing against the legs; up to four cycles (the
/// strongest harmonic).
GaitCycle find_gait_cycle(const std::vector<double>& feet, const std::vector<double>& hands, double leg_length);

}  // namespace footfall::animate
