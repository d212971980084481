#include "crowd/trial.hpp"

#include <algorithm>
#include <limits>

#include "model/contact.hpp"

namespace footfall::detail {

Trial::Trial(AgentPlan plan, double from, const CharacterParams& character)
    : plan_(std::move(plan)),
      character_(&character),
      bounds_(plan_, character),
      from_(from),
      bounds_from_(bounds_.from(from)),
      samples_(plan_, first_contact_instant(from_)) {}

PlanSamples Trial::take_samples() {
  // Where it stands after its end: searches check it there most.
  at(first_contact_instant(plan_.end_time()) + 1, true);
  return std::move(samples_);
}

Trial::Reach Trial::reach_to(const PlanBounds::From& theirs) const {
  const double closing = (bounds_from_.top_speed + theirs.top_speed) * kContactDt;
  return {closing, bounds_from_.reach + theirs.reach + 0.5 * closing};
}

bool Trial::apart(const PlanBounds::From& theirs) const {
  // Their COMs keep farther apart than `near` throughout: none is near.
  const double near = reach_to(theirs).near;
  return squared_distance(bounds_from_.com_box, theirs.com_box) > near * near;
}

bool Trial::touches(const AgentPlan& other, const PlanBounds& bounds,
                    const PlanSamples* samples) {
  const double end = std::max(plan_.end_time(), other.end_time()) + kContactDt;
  const PlanBounds::From theirs = bounds.from(from_);
  if (apart(theirs)) return false;
  // While the pair is far apart, instants they cannot close the distance
  // in are skipped (most of those checked are never near).
  const auto [closing, near] = reach_to(theirs);
  // The gap where the pair last stood still (see touching()).
  double start_gap = std::numeric_limits<double>::infinity();
  const long first = first_contact_instant(from_);
  PlanWalk them_at(other);  // at instants in order
  for (long k = first, next = first;; k = next) {
    const double t = static_cast<double>(k) * kContactDt;
    if (t > end) break;
    const PlanSample* known = samples != nullptr ? samples->taken(k) : nullptr;
    const ComSample me = at(k, false).com;
    const ComSample them = known != nullptr && known->sampled ? known->com : them_at.com_at(t);
    const double between = distance(me.position, them.position);
    next = k + 1;
    const double their_ground = known != nullptr && known->sampled ? known->ground
                                                                    : ground_at(other, t);
    if (levels_apart(at(k, false).ground, their_ground, character_->body_height)) continue;
    if (between > near) {
      if (closing > 0.0) next = k + std::max(1L, static_cast<long>((between - near) / closing));
      continue;
    }
    const double pad = 0.5 * (length(me.velocity) + length(them.velocity)) * kContactDt;
    const PlanSample& now = at(k, true);
    // Out of reach of the trial's circles as they are now (after the first
    // instant: its gap is wanted, see touching()).
    if (k != first && between - now.extent - theirs.reach > pad) continue;
    std::array<Circle, 5> circles;
    const bool shaped = known != nullptr && known->shaped;
    const int count = shaped ? known->count : them_at.collision_circles(*character_, t, circles);
    const std::array<Circle, 5>& theirs_now = shaped ? known->circles : circles;
    Gap gap;
    for (int i = 0; i < count; ++i)
      for (int m = 0; m < now.count; ++m) gap.add(now.circles[m], theirs_now[i], pad);
    // The gap where the pair last stood still, as the search takes it where
    // each of its steps starts, so that what the search finds passes here: a
    // pivot may turn a shoulder nearer, and the walk after it sets off from
    // there.
    if (standing_still(length(me.velocity), length(them.velocity))) start_gap = gap.outright;
    if (touching(gap, start_gap)) return true;
  }
  return false;
}

}  // namespace footfall::detail
