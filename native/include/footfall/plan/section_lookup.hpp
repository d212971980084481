// Footfall — the behaviour an agent's annotated way (its sections) gives a
// place and a footstep.
#pragma once

#include <vector>

#include "footfall/plan/plan.hpp"

namespace footfall {

/// A place farther than this from every section (where the crowd pushed the
/// agent aside) has no section: it walks. [m]
constexpr double kSectionReach = 0.75;

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
  const std::vector<BehaviorSection>& sections() const { return sections_; }

 private:
  std::vector<BehaviorSection> sections_;
  std::vector<Box> narrower_;  // boxes of the sections other than walk, grown by the reach
};

}  // namespace footfall
