// Footfall — when each upper-body clip plays: the plan's steps grouped into
// sections of one behaviour (stops and standing play "idle"), each played by
// its behaviour's clip, stretched so that a gait cycle spans two walking
// steps and phased so that the clip's right heel strike falls on the plan's.
// Laid out as the add-on lays its NLA strips (bridge/animate.py with
// core/clip_timing.py) and blended as Blender's NLA blends them, so that both
// play the same motion: over a base track that plays "idle" throughout,
// strips overlap their neighbours by twice kBlendSeconds, within the section
// whose arms reach wider, on two alternating tracks, the upper one fading in
// and out; a walking strip's influence is also the share of its amplitude
// (UpperBodyFollower::swing_at).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "animate/rig_data.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall::animate {

constexpr double kBlendSeconds = 0.25;  ///< a strip's fades; half its overlap with a neighbour

/// One clip playing at one instant: at `time` of its animation, with
/// `influence` over what the tracks below give.
struct ClipLayer {
  const Clip* clip = nullptr;
  double time = 0;  ///< [s] in the clip's animation
  double influence = 1;
  bool walk = false;  ///< a walking section's strip
};

class SectionTiming {
 public:
  /// `clips`: by behaviour, with "walk", "arms_in", "side_step" and "idle";
  /// the last strip plays on to `scene_end` [s]; frames at `fps` place the
  /// strips on their tracks as Blender does.
  SectionTiming(const AgentPlan& plan, const std::map<std::string, Clip>& clips, double scene_end, double fps);
  /// What plays at scene time `t` [s], lowest track first.
  std::vector<ClipLayer> at(double t) const;

 private:
  struct Strip {
    const Clip* clip = nullptr;
    double start = 0, end = 0;  ///< [s], with the overlaps
    int track = 0;
    double blend_in = 0, blend_out = 0;  ///< [s]
    bool hold = false;                   ///< the last: holds its end after it
    bool walk = false;                   ///< a walking section's
    double scale = 1;                    ///< scene seconds per clip second
    double offset = 0;                   ///< [s] into the clip's cycle at `start`
  };
  std::vector<Strip> strips_;
  int tracks_ = 3;  ///< the idle base, then two for the sections by turns
};

}  // namespace footfall::animate
