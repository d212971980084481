// Footfall — a plan's samples on the contact grid (plan_samples.hpp).
#include "footfall/plan/plan_samples.hpp"

#include <algorithm>

#include "model/contact.hpp"

namespace footfall {

PlanSamples::PlanSamples(const AgentPlan& plan, long first)
    : first_(first),
      still_(std::max(first, first_contact_instant(plan.end_time()) + 1)),
      // Every instant it can be sampled at: one allocation, not one per doubling.
      samples_(static_cast<std::size_t>(still_ - first_ + 1)) {}

const PlanSample& PlanSamples::at(const AgentPlan& plan, const CharacterParams& character, long k,
                                  bool shaped) {
  const long held = std::min(k, still_);
  PlanSample& sample = samples_[static_cast<std::size_t>(held - first_)];
  const double t = static_cast<double>(held) * kContactDt;
  if (!sample.sampled) {
    sample.com = com_at(plan, t);
    sample.ground = ground_at(plan, t);
    sample.sampled = true;
  }
  if (shaped && !sample.shaped) {
    sample.count = collision_circles(plan, character, t, sample.circles);
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

}  // namespace footfall
