#include "animate/section_timing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "footfall/animate/foot_roll.hpp"

namespace footfall::animate {

namespace {

// A stop plays "idle", but where the planner held the arms in or turned the
// body side-on (it tests a stop there in that behaviour's standing pose),
// the stop plays its behaviour's clip: waiting in a door frame, the arms stay
// in. A walk up or down a stair (`climb`, stair_climbs()) plays the rig's
// stair clip, where `clips` has it.
const char* behavior_of(const Footstep& step, int climb, const std::map<std::string, Clip>& clips) {
  if (step.kind == StepKind::kStop && step.behavior == Behavior::kWalk) return "idle";
  if (step.behavior == Behavior::kWalk && climb != 0) {
    const char* stairs = climb > 0 ? "stairs_up" : "stairs_down";
    if (clips.count(stairs) > 0) return stairs;
  }
  switch (step.behavior) {
    case Behavior::kArmsIn: return "arms_in";
    case Behavior::kSideStep: return "side_step";
    default: return "walk";
  }
}

// How far each behaviour's arms reach across the way, narrowest first
// (core/clip_timing.py's REACH): a boundary's cross-fade lies wholly in the
// section that reaches wider, since the planner checks each section's own
// body only over its own time.
int reach(const std::string& behavior) {
  if (behavior == "side_step") return 0;
  if (behavior == "arms_in") return 1;
  return behavior == "idle" ? 2 : 3;
}

}  // namespace

SectionTiming::SectionTiming(const AgentPlan& plan, const std::map<std::string, Clip>& clips, double scene_end,
                             double fps) {
  struct Section {
    std::string behavior;
    std::size_t first, last;  // steps
  };
  std::vector<Section> sections;
  const auto& steps = plan.footsteps;
  const std::vector<int> climbs = stair_climbs(plan);
  const auto clip_of = [&](std::size_t k) { return std::string(behavior_of(steps[k], climbs[k], clips)); };
  for (std::size_t first = 0; first < steps.size();) {
    std::size_t last = first;
    while (last + 1 < steps.size() && clip_of(last + 1) == clip_of(first)) ++last;
    sections.push_back({clip_of(first), first, last});
    first = last + 1;
  }
  // Track 0 plays "idle" throughout, under the sections' strips.
  Strip base;
  base.clip = &clips.at("idle");
  base.end = std::max(scene_end, 0.0);
  base.hold = true;
  strips_.push_back(base);
  constexpr double kNever = -std::numeric_limits<double>::infinity();
  std::vector<double> ends{kNever, kNever, kNever};  // per track, where its last strip ends [s]
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const Section& section = sections[i];
    Strip strip;
    strip.clip = &clips.at(section.behavior);
    strip.walk = section.behavior == "walk" || section.behavior.rfind("stairs_", 0) == 0;
    const double start = steps[section.first].start_time, end = steps[section.last].end_time;
    const bool wider_than_before = i > 0 && reach(section.behavior) > reach(sections[i - 1].behavior);
    const bool wider_after = i + 1 < sections.size() && reach(sections[i + 1].behavior) > reach(section.behavior);
    const double lead = i > 0 && !wider_than_before ? 2 * kBlendSeconds : 0.0;
    const double tail = i + 1 == sections.size() ? std::max(scene_end - end, 0.0)
                        : wider_after             ? 2 * kBlendSeconds
                                                  : 0.0;
    strip.start = start - lead;
    const double cycle = strip.clip->cycle;
    double walking_time = 0, right_strike = -1, first_walk = 0;
    int walking = 0;
    for (std::size_t k = section.first; k <= section.last; ++k) {
      if (steps[k].kind != StepKind::kWalk) continue;
      if (walking == 0) first_walk = steps[k].start_time;
      walking_time += steps[k].duration();
      ++walking;
      if (right_strike < 0 && steps[k].foot == Foot::kRight) right_strike = steps[k].start_time;
    }
    if (section.behavior != "idle" && walking > 0) {
      // A cycle spans two steps; the clip's right heel strike on the plan's
      // (without a right step, one step after the first walking one).
      const double step_time = walking_time / walking;
      strip.scale = 2.0 * step_time / cycle;
      if (right_strike < 0) right_strike = first_walk + step_time;
      strip.offset = std::fmod(strip.clip->strike * cycle - (right_strike - strip.start) / strip.scale, cycle);
      if (strip.offset < 0) strip.offset += cycle;
    }
    strip.end = strip.start + std::max(end + tail - strip.start, 1e-3 * cycle * strip.scale);
    // Its track: A (1) or B (2) by turns, else the lowest free one above A,
    // else a new one (Blender first places a strip at the whole frame below
    // its start).
    const double start_frame = std::floor(strip.start * fps);
    int track = -1;
    std::vector<int> candidates{1 + static_cast<int>(i % 2)};
    for (int k = 2; k < tracks_; ++k) candidates.push_back(k);
    for (int k : candidates)
      if (ends[k] * fps <= start_frame + 1e-9) {
        track = k;
        break;
      }
    if (track < 0) {
      track = tracks_++;
      ends.push_back(kNever);
    }
    ends[track] = strip.end;
    strip.track = track;
    strip.hold = i + 1 == sections.size();
    if (track > 1) {
      // Strips above track A fade in and out over what is below; the last
      // holds its end, faded in only.
      const double blend = std::min(kBlendSeconds, 0.5 * (strip.end - strip.start));
      strip.blend_in = blend;
      strip.blend_out = strip.hold ? 0.0 : blend;
    }
    strips_.push_back(strip);
  }
}

std::vector<ClipLayer> SectionTiming::at(double t) const {
  std::vector<ClipLayer> layers;
  for (int track = 0; track < tracks_; ++track)
    for (const Strip& strip : strips_) {
      if (strip.track != track || t < strip.start || (t > strip.end && !strip.hold)) continue;
      const double local = std::min(t, strip.end) - strip.start;
      double influence = 1.0;
      if (strip.blend_in > 0) influence = std::min(influence, local / strip.blend_in);
      if (strip.blend_out > 0) influence = std::min(influence, (strip.end - std::min(t, strip.end)) / strip.blend_out);
      double phase = std::fmod(strip.offset + local / strip.scale, strip.clip->cycle);
      if (phase < 0) phase += strip.clip->cycle;
      layers.push_back({strip.clip, strip.clip->start + phase, std::clamp(influence, 0.0, 1.0), strip.walk});
      break;
    }
  return layers;
}

}  // namespace footfall::animate
