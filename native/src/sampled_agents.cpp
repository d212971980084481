#include "sampled_agents.hpp"

#include <algorithm>
#include <cmath>

#include "footfall/plan.hpp"
#include "contact.hpp"

namespace footfall::detail {

void SampledAgents::reset(const MovingObstacles& others, const CharacterParams& character,
                          double from) {
  others_ = &others;
  character_ = &character;
  first_ = first_contact_instant(from);
  ++stamp_;
}

SampledAgents::Entry& SampledAgents::entry(std::size_t j, long k) {
  if (k < first_) {  // earlier than announced: rows are added in front
    rows_.insert(rows_.begin(), static_cast<std::size_t>(first_ - k), {});
    first_ = k;
  }
  const auto row = static_cast<std::size_t>(k - first_);
  if (row >= rows_.size()) rows_.resize(row + 1);
  std::vector<Entry>& entries = rows_[row];
  if (entries.size() < others_->size()) entries.resize(others_->size());
  return entries[j];
}

const AgentSample& SampledAgents::at(std::size_t j, long k) {
  Entry& e = entry(j, k);
  if (e.sampled != stamp_) {
    const AgentPlan& plan = *(*others_)[j];
    const double t = static_cast<double>(k) * kContactDt;
    const ComSample com = com_at(plan, t);
    e.sample.present = present_at(plan, t);
    e.sample.com = com.position;
    e.sample.speed = length(com.velocity);
    e.sample.count = 0;
    e.sampled = stamp_;
  }
  return e.sample;
}

const AgentSample& SampledAgents::with_circles(std::size_t j, long k) {
  at(j, k);
  Entry& e = entry(j, k);
  if (e.circled != stamp_) {
    const double t = static_cast<double>(k) * kContactDt;
    const std::vector<Circle> circles = collision_circles(*(*others_)[j], *character_, t);
    e.sample.count = static_cast<int>(std::min(circles.size(), e.sample.circles.size()));
    std::copy_n(circles.begin(), e.sample.count, e.sample.circles.begin());
    e.sample.extent = 0.0;
    for (int i = 0; i < e.sample.count; ++i) {
      const Circle& c = e.sample.circles[i];
      e.sample.extent = std::max(e.sample.extent, distance(c.center, e.sample.com) + c.radius);
    }
    e.circled = stamp_;
  }
  return e.sample;
}

double SampledAgents::top_speed(std::size_t j) {
  if (top_speed_.size() < others_->size()) top_speed_.resize(others_->size());
  auto& [stamp, speed] = top_speed_[j];
  if (stamp != stamp_) {
    speed = 0.0;
    for (const Footstep& step : (*others_)[j]->footsteps)
      speed = std::max({speed, length(step.com_velocity_start), length(step.com_velocity_end)});
    stamp = stamp_;
  }
  return speed;
}

}  // namespace footfall::detail
