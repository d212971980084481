#include "sampled_agents.hpp"

#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "footfall/plan.hpp"

namespace footfall::detail {

void SampledAgents::reset(const MovingObstacles& others, const CharacterParams& character,
                          double from) {
  others_ = &others;
  character_ = &character;
  rest_grace_ = std::numeric_limits<double>::infinity();
  blocker_ = std::numeric_limits<std::size_t>::max();
  refusers_.clear();
  ++stamp_;
  if (others.size() > stride_) {  // a wider row: the old samples are stale anyway
    stride_ = others.size();
    where_.clear();
    shape_.clear();
    rows_ = 0;
  }
  if (top_speed_.size() < others.size()) {
    top_speed_.resize(others.size());
    reach_.resize(others.size());
    com_box_.resize(others.size());
    bounds_stamp_.resize(others.size(), 0);
  }
  first_ = first_contact_instant(from);  // the rows held keep their memory, not their samples
}

void SampledAgents::grow(long k) {
  if (k < first_) {  // earlier than announced: rows are added in front
    const auto added = static_cast<std::size_t>(first_ - k) * stride_;
    where_.insert(where_.begin(), added, AgentWhere{});
    shape_.insert(shape_.begin(), added, AgentShape{});
    rows_ += first_ - k;
    first_ = k;
    std::fill(bounds_stamp_.begin(), bounds_stamp_.end(), 0);  // bounds from first_ on
  } else {
    rows_ = k - first_ + 1;
    where_.resize(static_cast<std::size_t>(rows_) * stride_);
    shape_.resize(static_cast<std::size_t>(rows_) * stride_);
  }
}

void SampledAgents::fill(std::size_t j, long k, AgentWhere& where) const {
  const AgentPlan& plan = *(*others_)[j].plan;
  const double t = static_cast<double>(k) * kContactDt;
  const ComSample com = com_at(plan, t);
  where.present = present_at(plan, t);
  where.com = com.position;
  where.speed = length(com.velocity);
  where.stamp = stamp_;
}

void SampledAgents::fill(std::size_t j, long k, AgentShape& shape) {
  const AgentPlan& plan = *(*others_)[j].plan;
  const double t = static_cast<double>(k) * kContactDt;
  shape.count = collision_circles(plan, *character_, t, shape.circles);
  const Vec2 com = at(j, k).com;  // row k is held already: `shape` stays where it is
  shape.extent = 0.0;
  for (int i = 0; i < shape.count; ++i) {
    const Circle& c = shape.circles[i];
    shape.extent = std::max(shape.extent, distance(c.center, com) + c.radius);
  }
  shape.stamp = stamp_;
}

void SampledAgents::fill_bounds(std::size_t j) {
  const double from = static_cast<double>(first_) * kContactDt;
  const MovingObstacle& other = (*others_)[j];
  if (other.bounds != nullptr) {
    const PlanBounds::From bounds = other.bounds->from(from);
    top_speed_[j] = bounds.top_speed;
    reach_[j] = bounds.reach;
    com_box_[j] = bounds.com_box;
  } else {
    top_speed_[j] = top_com_speed(*other.plan, from);
    reach_[j] = circle_reach(*other.plan, *character_, from);
    constexpr double kAll = std::numeric_limits<double>::infinity();
    com_box_[j] = {{-kAll, -kAll}, {kAll, kAll}};
  }
  bounds_stamp_[j] = stamp_;
}

}  // namespace footfall::detail
