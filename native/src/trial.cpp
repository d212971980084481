#include "trial.hpp"

#include <algorithm>
#include <limits>

#include "contact.hpp"

namespace footfall::detail {

Trial::Trial(AgentPlan plan, double from, const CharacterParams& character)
    : plan_(std::move(plan)),
      character_(&character),
      bounds_(plan_, character),
      from_(from),
      bounds_from_(bounds_.from(from)) {
  // Every instant it can be sampled at, from `from` to where it stands (at()):
  // one allocation, not one per doubling while it is checked.
  instants_.resize(static_cast<std::size_t>(first_contact_instant(plan_.end_time()) + 2 -
                                            first_contact_instant(from_)));
}

const Trial::Instant& Trial::at(long k, bool shaped) {
  // After its last step it stands, or is gone, as at the first instant past
  // its end.
  const long first = first_contact_instant(from_);
  const long still = first_contact_instant(plan_.end_time()) + 1;
  const long held = std::min(k, still);
  Instant& sample = instants_[static_cast<std::size_t>(held - first)];
  const double t = static_cast<double>(held) * kContactDt;
  if (!sample.sampled) {
    sample.com = com_at(plan_, t);
    sample.sampled = true;
  }
  if (shaped && !sample.shaped) {
    sample.count = collision_circles(plan_, *character_, t, sample.circles);
    sample.extent = 0.0;
    for (int i = 0; i < sample.count; ++i) {
      const Circle& circle = sample.circles[i];
      sample.extent =
          std::max(sample.extent, distance(circle.center, sample.com.position) + circle.radius);
    }
    sample.shaped = true;
  }
  return sample;
}

bool Trial::touches(const AgentPlan& other, const PlanBounds& bounds) {
  const double end = std::max(plan_.end_time(), other.end_time()) + kContactDt;
  // While the pair is far apart, instants they cannot close the distance
  // in are skipped (most of those checked are never near).
  const PlanBounds::From& mine = bounds_from_;
  const PlanBounds::From theirs = bounds.from(from_);
  const double closing = (mine.top_speed + theirs.top_speed) * kContactDt;
  // Farther apart than this, no circles of the pair come within the padding.
  const double near = mine.reach + theirs.reach + 0.5 * closing;
  // Their COMs keep farther apart than that throughout: none is near.
  if (squared_distance(mine.com_box, theirs.com_box) > near * near) return false;
  // The gap where the trial starts (see touching()).
  double start_gap = std::numeric_limits<double>::infinity();
  const long first = first_contact_instant(from_);
  PlanWalk them_at(other);  // at instants in order
  for (long k = first, next = first;; k = next) {
    const double t = static_cast<double>(k) * kContactDt;
    if (t > end) break;
    const ComSample me = at(k, false).com, them = them_at.com_at(t);
    const double between = distance(me.position, them.position);
    next = k + 1;
    if (between > near) {
      if (closing > 0.0) next = k + std::max(1L, static_cast<long>((between - near) / closing));
      continue;
    }
    const double pad = 0.5 * (length(me.velocity) + length(them.velocity)) * kContactDt;
    const Instant& now = at(k, true);
    // Out of reach of the trial's circles as they are now (after the first
    // instant: its gap is wanted, see touching()).
    if (k != first && between - now.extent - theirs.reach > pad) continue;
    std::array<Circle, 5> circles;
    const int count = them_at.collision_circles(*character_, t, circles);
    Gap gap;
    for (int i = 0; i < count; ++i)
      for (int m = 0; m < now.count; ++m) gap.add(now.circles[m], circles[i], pad);
    if (k == first && standing_still(length(me.velocity), length(them.velocity)))
      start_gap = gap.outright;
    if (touching(gap, start_gap)) return true;
  }
  return false;
}

}  // namespace footfall::detail
