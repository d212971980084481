#include "planner/sampled_agents.hpp"

#include <algorithm>
#include <cmath>

#include "model/contact.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/plan/plan_samples.hpp"

namespace footfall::detail {

void SampledAgents::reset(const MovingObstacles& others, const CharacterParams& character,
                          double from) {
  others_ = &others;
  character_ = &character;
  rest_grace_ = std::numeric_limits<double>::infinity();
  blocker_ = std::numeric_limits<std::size_t>::max();
  refusers_.clear();
  ++stamp_;  // every sample held is stale now
  // Rows as wide as these agents, none held yet: the vectors keep the memory
  // of the largest search so far (a new stamp makes it stale), not a row as
  // wide as the most agents times as many rows as the longest search.
  stride_ = others.size();
  rows_ = 0;
  if (bounds_.size() < others.size()) bounds_.resize(others.size());
  first_ = first_contact_instant(from);
}

void SampledAgents::grow(long k) {
  if (k < first_) {  // earlier than announced: rows are added in front
    const auto added = static_cast<std::size_t>(first_ - k) * stride_;
    where_.insert(where_.begin(), added, AgentWhere{});
    shape_.insert(shape_.begin(), added, AgentShape{});
    rows_ += first_ - k;
    first_ = k;
    for (Bounds& bounds : bounds_) bounds.stamp = 0;  // bounds from first_ on
  } else {
    rows_ = k - first_ + 1;
    const std::size_t cells = static_cast<std::size_t>(rows_) * stride_;
    if (where_.size() < cells) {
      where_.resize(cells);
      shape_.resize(cells);
    }
  }
}

void SampledAgents::fill(std::size_t j, long k, AgentWhere& where) const {
  const MovingObstacle& other = (*others_)[j];
  const AgentPlan& plan = *other.plan;
  const double t = static_cast<double>(k) * kContactDt;
  const PlanSample* known = other.samples != nullptr ? other.samples->taken(k) : nullptr;
  const bool held = known != nullptr && known->sampled;
  const ComSample com = held ? known->com : com_at(plan, t);
  where.ground = held ? known->ground : ground_at(plan, t);
  where.present = present_at(plan, t);
  where.com = com.position;
  where.speed = length(com.velocity);
  where.stamp = stamp_;
}

void SampledAgents::fill(std::size_t j, long k, AgentShape& shape) {
  const MovingObstacle& other = (*others_)[j];
  const double t = static_cast<double>(k) * kContactDt;
  const PlanSample* known = other.samples != nullptr ? other.samples->taken(k) : nullptr;
  if (known != nullptr && known->shaped) {
    shape.count = known->count;
    shape.circles = known->circles;
    shape.extent = known->extent;
    shape.stamp = stamp_;
    return;
  }
  shape.count = collision_circles(*other.plan, *character_, t, shape.circles);
  const Vec2 com = at(j, k).com;  // row k is held already: `shape` stays where it is
  shape.extent = 0.0;
  for (int i = 0; i < shape.count; ++i) {
    const Circle& c = shape.circles[i];
    shape.extent = std::max(shape.extent, distance(c.center, com) + c.radius);
  }
  shape.stamp = stamp_;
}

void SampledAgents::fill_bounds(std::size_t j, Bounds& bounds) const {
  const double from = static_cast<double>(first_) * kContactDt;
  const MovingObstacle& other = (*others_)[j];
  if (other.bounds != nullptr) {
    bounds.from = other.bounds->from(from);
  } else {
    bounds.from.top_speed = top_com_speed(*other.plan, from);
    bounds.from.reach = circle_reach(*other.plan, *character_, from);
    constexpr double kAll = std::numeric_limits<double>::infinity();
    bounds.from.com_box = {{-kAll, -kAll}, {kAll, kAll}};
  }
  bounds.stamp = stamp_;
}

}  // namespace footfall::detail
