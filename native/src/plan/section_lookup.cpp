// Footfall — behaviours of places and footsteps from an agent's sections.
#include "footfall/plan/section_lookup.hpp"

#include <algorithm>

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

SectionLookup::Nearest SectionLookup::nearest(Vec2 point) const {
  bool near = false;
  for (const Box& box : narrower_)
    near = near || (point.x >= box.min.x && point.x <= box.max.x && point.y >= box.min.y &&
                    point.y <= box.max.y);
  Nearest found;
  if (!near) return found;
  double nearest = kSectionReach * kSectionReach;
  for (const BehaviorSection& section : sections_) {
    for (std::size_t k = 1; k < section.points.size(); ++k) {
      const double d = squared_distance_to_segment(point, section.points[k - 1], section.points[k]);
      if (d < nearest) {
        nearest = d;
        found = {&section, k};
      }
    }
  }
  return found;
}

Behavior SectionLookup::at(Vec2 point) const {
  const Nearest found = nearest(point);
  return found.section ? found.section->behavior : Behavior::kWalk;
}

std::optional<WayLine> SectionLookup::side_step_way(Vec2 point) const {
  const Nearest found = nearest(point);
  if (!found.section || found.section->behavior != Behavior::kSideStep) return std::nullopt;
  const Vec2 a = found.section->points[found.segment - 1], b = found.section->points[found.segment];
  const double length = distance(a, b);
  if (length < 1e-9) return std::nullopt;
  const Vec2 direction = (1.0 / length) * (b - a);
  const double along = std::clamp(dot(point - a, direction), 0.0, length);
  return WayLine{a + along * direction, direction};
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
