// Footfall — behaviours of places and footsteps from an agent's sections.
#include "footfall/plan/section_lookup.hpp"

namespace footfall {

SectionLookup::SectionLookup(std::vector<BehaviorSection> sections)
    : sections_(std::move(sections)) {
  for (const BehaviorSection& section : sections_) {
    if (section.behavior == Behavior::kWalk || section.points.empty()) continue;
    Box box{section.points.front(), section.points.front()};
    for (const Vec2 p : section.points) box.take_in(p);
    box.min = box.min - Vec2{kSectionReach, kSectionReach};
    box.max = box.max + Vec2{kSectionReach, kSectionReach};
    narrower_.push_back(box);
  }
}

Behavior SectionLookup::at(Vec2 point) const {
  bool near = false;
  for (const Box& box : narrower_)
    near = near || (point.x >= box.min.x && point.x <= box.max.x && point.y >= box.min.y &&
                    point.y <= box.max.y);
  if (!near) return Behavior::kWalk;
  double nearest = kSectionReach * kSectionReach;
  Behavior behavior = Behavior::kWalk;
  for (const BehaviorSection& section : sections_) {
    for (std::size_t k = 1; k < section.points.size(); ++k) {
      const double d = squared_distance_to_segment(point, section.points[k - 1], section.points[k]);
      if (d < nearest) {
        nearest = d;
        behavior = section.behavior;
      }
    }
  }
  return behavior;
}

Behavior SectionLookup::along(const Footstep& step) const {
  // Behaviours run from walk (0) to side_step (2), widest to narrowest.
  const auto narrower = [](Behavior a, Behavior b) {
    return static_cast<int>(a) >= static_cast<int>(b) ? a : b;
  };
  return narrower(narrower(at(step.com_start), at(0.5 * (step.com_start + step.com_end))),
                  at(step.com_end));
}

Behavior SectionLookup::of(const Footstep& step) const {
  if (step.kind == StepKind::kSideStep) return Behavior::kSideStep;
  const Behavior section = along(step);
  if (section == Behavior::kSideStep && step.kind == StepKind::kWalk) return Behavior::kArmsIn;
  return section;
}

}  // namespace footfall
