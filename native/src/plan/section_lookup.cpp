// Footfall — behaviours of places and footsteps from an agent's sections.
#include "footfall/plan/section_lookup.hpp"

#include <algorithm>
#include <cmath>

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

namespace {

/// The point `reach` along polyline `points` from `from`, which lies on
/// the segment ending at points[segment]: forward for a positive reach,
/// back for a negative one, and no farther than its ends.
Vec2 along_polyline(const std::vector<Vec2>& points, std::size_t segment, Vec2 from, double reach) {
  const int step = reach >= 0.0 ? 1 : -1;
  double left = std::fabs(reach);
  // The next point in that direction: the segment's end ahead, its start back.
  long next = step > 0 ? static_cast<long>(segment) : static_cast<long>(segment) - 1;
  Vec2 at = from;
  for (; next >= 0 && next < static_cast<long>(points.size()); next += step) {
    const Vec2 to = points[static_cast<std::size_t>(next)];
    const double d = distance(at, to);
    if (d >= left) return left > 0.0 ? at + (left / d) * (to - at) : at;
    left -= d;
    at = to;
  }
  return at;
}

}  // namespace

std::optional<WayLine> SectionLookup::narrower_way(Vec2 point) const {
  const Nearest found = nearest(point);
  if (!found.section || found.section->behavior == Behavior::kWalk) return std::nullopt;
  const std::vector<Vec2>& points = found.section->points;
  const Vec2 a = points[found.segment - 1], b = points[found.segment];
  const Vec2 nearest = closest_on_segment(point, a, b);
  // The way's direction over a stretch of it, not its nearest segment's: a
  // way planned from where the agent stands starts with segments of a few
  // millimetres, pointing anywhere.
  const Vec2 chord = along_polyline(points, found.segment, nearest, kWayLineSpan) -
                     along_polyline(points, found.segment, nearest, -kWayLineSpan);
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
