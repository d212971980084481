#include "animate/section_timing.hpp"

#include <algorithm>
#include <cmath>

namespace footfall::animate {

namespace {

const char* behavior_of(const Footstep& step) {
  if (step.kind == StepKind::kStop) return "idle";
  switch (step.behavior) {
    case Behavior::kArmsIn: return "arms_in";
    case Behavior::kSideStep: return "side_step";
    default: return "walk";
  }
}

}  // namespace

SectionTiming::SectionTiming(const AgentPlan& plan, const std::map<std::string, Clip>& clips) {
  const auto& steps = plan.footsteps;
  std::size_t first = 0;
  while (first < steps.size()) {
    const std::string behavior = behavior_of(steps[first]);
    std::size_t last = first;
    while (last + 1 < steps.size() && behavior_of(steps[last + 1]) == behavior) ++last;
    Section section;
    section.clip = &clips.at(behavior);
    section.start = steps[first].start_time;
    section.end = steps[last].end_time;
    section.anchor = section.start;
    double walking_time = 0;
    int walking = 0;
    double right_strike = -1;
    for (std::size_t i = first; i <= last; ++i) {
      if (steps[i].kind != StepKind::kWalk) continue;
      walking_time += steps[i].duration();
      ++walking;
      if (right_strike < 0 && steps[i].foot == Foot::kRight) right_strike = steps[i].start_time;
    }
    if (behavior != "idle" && walking > 0) {
      // A cycle spans two steps; the clip's right heel strike on the plan's.
      const double step_time = walking_time / walking;
      section.scale = 2.0 * step_time / section.clip->cycle;
      section.anchor = right_strike >= 0 ? right_strike : section.start + step_time;
      section.anchor_phase = section.clip->strike * section.clip->cycle;
    }
    sections_.push_back(section);
    first = last + 1;
  }
  if (sections_.empty()) {  // standing still throughout
    Section idle;
    idle.clip = &clips.at("idle");
    sections_.push_back(idle);
  }
}

double SectionTiming::clip_time(const Section& section, double t) const {
  const double cycle = section.clip->cycle;
  double phase = std::fmod(section.anchor_phase + (t - section.anchor) / section.scale, cycle);
  if (phase < 0) phase += cycle;
  return section.clip->start + phase;
}

ClipPhase SectionTiming::at(double t) const {
  const auto later = std::upper_bound(sections_.begin(), sections_.end(), t,
                                      [](double time, const Section& s) { return time < s.start; });
  std::size_t k = later == sections_.begin() ? 0 : static_cast<std::size_t>(later - sections_.begin()) - 1;
  // Within half a blend of a boundary, the section before it fades into the one after.
  if (k > 0 && t < sections_[k].start + 0.5 * kBlendSeconds) --k;
  ClipPhase phase;
  phase.clip = sections_[k].clip;
  phase.time = clip_time(sections_[k], t);
  if (k + 1 < sections_.size()) {
    const double fade_start = sections_[k].end - 0.5 * kBlendSeconds;
    const double w = std::clamp((t - fade_start) / kBlendSeconds, 0.0, 1.0);
    if (w > 0) {
      phase.next = sections_[k + 1].clip;
      phase.next_time = clip_time(sections_[k + 1], t);
      phase.next_weight = w * w * (3 - 2 * w);
    }
  }
  return phase;
}

}  // namespace footfall::animate
