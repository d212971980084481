// Footfall — the behaviour an agent's annotated way (its sections) gives a
// place and a footstep.
#pragma once

#include <optional>
#include <vector>

#include "footfall/model/polyline.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {

/// A place farther than this from every section (where the crowd pushed the
/// agent aside) has no section: it walks. [m]
constexpr double kSectionReach = 0.75;

/// Half the stretch of a narrower section's way whose chord gives the way's
/// direction at a place (SectionLookup::narrower_way). [m]
constexpr double kWayLineSpan = 0.25;

/// A narrower section's way near a place: its nearest point, and the
/// direction of the way's chord from kWayLineSpan before it to kWayLineSpan
/// after it.
struct WayLine {
  Vec2 nearest;    ///< The point of the way nearest the place. [m]
  Vec2 direction;  ///< Unit, from the section's start toward its end.
  Behavior behavior = Behavior::kArmsIn;  ///< The section's: arms_in or side_step.
};

/// An agent's sections, ready to be asked. Cheap where no section other than
/// walk is near: most places of most ways.
class SectionLookup {
 public:
  SectionLookup() = default;
  explicit SectionLookup(std::vector<BehaviorSection> sections);

  /// True if a section is not walk.
  bool any_narrower() const { return !narrower_.empty(); }
  /// The behaviour of the section nearest to `point` within kSectionReach;
  /// walk when none is.
  Behavior at(Vec2 point) const;
  /// The narrowest behaviour at the start, the middle and the end of a
  /// footstep's COM chord: a step that ends in a narrower section already
  /// takes its behaviour.
  Behavior along(const Footstep& step) const;
  /// A footstep's behaviour: side_step for a lateral step; else along(), and
  /// arms_in for a walking step reaching a side_step section (the narrowest
  /// frontal behaviour).
  Behavior of(const Footstep& step) const;
  /// The way of the section nearest `point` within kSectionReach, if that
  /// section is narrower than walk.
  std::optional<WayLine> narrower_way(Vec2 point) const;
  const std::vector<BehaviorSection>& sections() const { return sections_; }

 private:
  struct Nearest {
    const BehaviorSection* section = nullptr;  ///< None within kSectionReach.
    std::size_t segment = 0;                   ///< From points[segment - 1] to points[segment].
  };
  Nearest nearest(Vec2 point) const;

  std::vector<BehaviorSection> sections_;
  std::vector<Polyline> ways_;  // each section's points by arc length
  std::vector<Box> narrower_;  // boxes of the sections other than walk, grown by the reach
};

}  // namespace footfall
