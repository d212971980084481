// Footfall — one plan sampled at the instants of the contact grid, kept with
// the plan: the crowd's commit check takes these samples of an agent's new
// plan anyway, and every later check and search against that plan reads them
// instead of sampling it again.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "footfall/plan/plan.hpp"

namespace footfall {

/// A plan at one instant k of the contact grid (t = k * kContactDt).
struct PlanSample {
  bool sampled = false;  ///< `com` holds com_at(plan, t), `ground` ground_at(plan, t).
  ComSample com;
  double ground = 0.0;  ///< [m]
  bool shaped = false;  ///< The circles hold collision_circles(plan, t).
  int count = 0;
  std::array<Circle, 5> circles;
  double extent = 0.0;  ///< How far they reach from the COM. [m]
};

/// Samples of one plan from instant `first` on, taken when first wanted. From
/// the first instant past the plan's end (`still`) on, every instant is as
/// that one: the agent stands where the plan ends, or is gone.
class PlanSamples {
 public:
  PlanSamples() = default;
  /// For `plan` as it is now, from instant `first` on.
  PlanSamples(const AgentPlan& plan, long first);

  /// The sample of `plan` (the plan given above) at instant k >= first, its
  /// circles too if `shaped`, taken now if it was not yet.
  const PlanSample& at(const AgentPlan& plan, const CharacterParams& character, long k,
                       bool shaped);
  /// The sample at instant k as far as it was taken (null: none was, or k is
  /// before the first): read-only, for checks on several threads at once.
  const PlanSample* taken(long k) const {
    if (k < first_ || samples_.empty()) return nullptr;
    return &samples_[static_cast<std::size_t>(std::min(k, still_) - first_)];
  }

 private:
  long first_ = 0, still_ = 0;
  std::vector<PlanSample> samples_;  ///< [k - first_], k from first_ to still_
};

}  // namespace footfall
