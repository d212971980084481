// Footfall — when each upper-body clip plays: the plan's steps grouped into
// sections of one behaviour (stops and standing play "idle"), each
// section's clip stretched to its steps and phased so that the clip's right
// heel strike falls on the plan's, as the add-on's core/clip_timing.py
// times its NLA strips; neighbouring sections cross-fade.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "animate/rig_data.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall::animate {

constexpr double kBlendSeconds = 0.25;  ///< cross-fade between two sections' clips, centred on their boundary

/// What plays at one instant: a clip at its time, and, across a section
/// boundary, the next one at its time with its weight.
struct ClipPhase {
  const Clip* clip = nullptr;
  double time = 0;  ///< [s] in the clip's animation
  const Clip* next = nullptr;
  double next_time = 0;
  double next_weight = 0;  ///< 0: `clip` alone
};

class SectionTiming {
 public:
  /// `clips`: by behaviour, with "walk", "arms_in", "side_step" and "idle".
  SectionTiming(const AgentPlan& plan, const std::map<std::string, Clip>& clips);
  /// At scene time `t` [s]; past the plan the last section plays on.
  ClipPhase at(double t) const;

 private:
  struct Section {
    const Clip* clip = nullptr;
    double start = 0, end = 0;  ///< [s]
    double scale = 1;           ///< scene seconds per clip second
    double anchor = 0;          ///< a scene time at which the clip is at `anchor_phase`
    double anchor_phase = 0;    ///< [s] into the cycle
  };
  double clip_time(const Section& section, double t) const;
  std::vector<Section> sections_;
};

}  // namespace footfall::animate
