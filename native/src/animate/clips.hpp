// Footfall — a rig's upper-body clips: read from its animations (with the
// gait cycle found from the motion, as the add-on's core/clip_cycle.py finds
// it) or made procedurally (as the add-on's bridge/procedural_clips.py), and
// sampled at any time.
#pragma once

#include <string>

#include "animate/rig_data.hpp"

namespace footfall::animate {

/// The rig's animation `animation` as a clip, its cycle and right heel strike
/// found from its feet (or, for an upper-body clip, its hands).
Clip clip_from_animation(const RigData& rig, int animation);
/// A procedural clip for `behavior`: an arm swing for "walk", the arms held
/// against the body for "arms_in", a still upper body otherwise.
Clip procedural_clip(const RigData& rig, const std::string& behavior);
/// Node `node`'s local transform in the clip at animation time `t` [s]: its
/// rest (`rest`) with the clip's tracks of that node applied.
Trs sample(const Clip& clip, int node, const Trs& rest, double t);

}  // namespace footfall::animate
