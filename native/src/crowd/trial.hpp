// Footfall — the crowd's commit check: whether an agent's new plan keeps
// clear of another agent's plan, under the five-circle model that measures
// plans (torso circles and planted feet; after its last step a plan stands
// where it ends), checked every kContactDt, the circles grown by half of both
// agents' travel in between (contact.hpp).
#pragma once

#include <array>
#include <vector>

#include "footfall/plan/plan.hpp"
#include "footfall/plan/plan_samples.hpp"

namespace footfall::detail {

/// An agent's plan with new steps in place of its old rest, to be checked
/// against the others' plans before it is committed.
class Trial {
 public:
  Trial() = default;
  /// `plan` differs from the agent's plan from time `from` on: during the
  /// last step kept, the free foot swings toward the first new step.
  Trial(AgentPlan plan, double from, const CharacterParams& character);
  /// The plan and its bounds, non-const for the commit to take them.
  AgentPlan& plan() { return plan_; }
  PlanBounds& bounds() { return bounds_; }
  /// The samples of the plan the checks took, and where it stands after its
  /// end, for the commit to keep with the plan: taken before the plan.
  PlanSamples take_samples();
  /// True if the trial, from its time `from` on, touches `other`, whose
  /// bounds are `bounds` and whose samples, as far as they were taken, are
  /// `samples` (may be null).
  bool touches(const AgentPlan& other, const PlanBounds& bounds, const PlanSamples* samples);
  /// True if the trial keeps clear of any plan whose bounds from `from()` on
  /// lie within `theirs`: touches() passes such a plan over at once. Bounds
  /// from an earlier time hold those from a later one, so one `theirs` per
  /// agent serves every trial from its time on.
  bool apart(const PlanBounds::From& theirs) const;
  /// The time from which the trial differs from the agent's plan. [s]
  double from() const { return from_; }

 private:
  /// The trial at instant k (from `from` on), its circles too if `shaped`:
  /// sampled when first wanted, for it is checked against dozens of plans at
  /// the same instants.
  const PlanSample& at(long k, bool shaped) { return samples_.at(plan_, *character_, k, shaped); }
  /// How far the trial and a plan with bounds `theirs` close in on each
  /// other per instant at most, and how near they come before any circles of
  /// the pair come within the padding.
  struct Reach {
    double closing, near;
  };
  Reach reach_to(const PlanBounds::From& theirs) const;

  AgentPlan plan_;
  const CharacterParams* character_ = nullptr;
  PlanBounds bounds_;
  double from_ = 0.0;
  PlanBounds::From bounds_from_;  ///< bounds_.from(from_)
  PlanSamples samples_;           ///< From first_contact_instant(from_) on.
};

}  // namespace footfall::detail
