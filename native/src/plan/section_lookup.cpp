// Footfall — behaviours of places and footsteps from an agent's sections.
#include "footfall/plan/section_lookup.hpp"

#include <algorithm>
#include <cmath>

namespace footfall {

SectionLookup::SectionLookup(std::vector<BehaviorSection> sections)
    : sections_(std::move(sections)) {
  for (const BehaviorSection& section : sections_) {
    ways_.emplace_back(section.points);
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

std::optional<WayLine> SectionLookup::narrower_way(Vec2 point) const {
  const Nearest found = nearest(point);
  if (!found.section || found.section->behavior == Behavior::kWalk) return std::nullopt;
  const Polyline& way = ways_[static_cast<std::size_t>(found.section - sections_.data())];
  const Vec2 a = way.points()[found.segment - 1], b = way.points()[found.segment];
  const Vec2 nearest = closest_on_segment(point, a, b);
  const double at = way.along(found.segment - 1) + distance(a, nearest);
  // The way's direction over a stretch of it, not its nearest segment's: a
  // way planned from where the agent stands starts with segments of a few
  // millimetres, pointing anywhere.
  const Vec2 chord = way.point_at(at + kWayLineSpan) - way.point_at(at - kWayLineSpan);
  const double length = std::sqrt(dot(chord, chord));
  if (length < 1e-9) return std::nullopt;
  return WayLine{nearest, (1.0 / length) * chord, found.section->behavior};
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
