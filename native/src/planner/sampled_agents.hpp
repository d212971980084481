// Footfall — other agents' plans sampled at the instants of the contact grid,
// each sample computed once per search, however many candidate steps read it.
// A search checks hundreds of candidate steps against the same few plans at
// the same instants, so each plan is sampled (its COM, its feet, its circles)
// once per instant, not once per candidate.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "model/contact.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/planner/planner.hpp"
#include "util/huge_page_allocator.hpp"

namespace footfall::detail {

/// Where one other agent is at one instant of the contact grid.
struct AgentWhere {
  std::uint64_t stamp = 0;  ///< The reset that filled it (0: never).
  Vec2 com;
  double speed = 0.0;    ///< COM speed. [m/s]
  double ground = 0.0;   ///< The height of the ground it stands on (ground_at). [m]
  bool present = false;  ///< Not yet gone (an agent that leaves at its goal).
};

/// Its circles at that instant: torso, and planted feet.
struct AgentShape {
  std::uint64_t stamp = 0;
  int count = 0;
  double extent = 0.0;  ///< How far the circles reach from the COM. [m]
  std::array<Circle, 5> circles;
};

class SampledAgents {
 public:
  /// Starts over for `others` (which must outlive the samples taken), whose
  /// instants of interest begin at time `from`. Earlier samples are forgotten.
  void reset(const MovingObstacles& others, const CharacterParams& character, double from);
  std::size_t size() const { return others_->size(); }
  const AgentPlan& plan(std::size_t j) const { return *(*others_)[j].plan; }
  /// Agent j at instant k (t = k * kContactDt).
  const AgentWhere& at(std::size_t j, long k) {
    AgentWhere& where = where_[slot(j, k)];
    if (where.stamp != stamp_) fill(j, k, where);
    return where;
  }
  /// Its circles at instant k.
  const AgentShape& shape(std::size_t j, long k) {
    AgentShape& shape = shape_[slot(j, k)];
    if (shape.stamp != stamp_) fill(j, k, shape);
    return shape;
  }
  /// Agent j's plan's bounds from the first instant on: its top COM speed,
  /// how far its circles reach, and a box that holds its COM (those far from
  /// it need no samples; without PlanBounds, the whole plane).
  const PlanBounds::From& bounds(std::size_t j) {
    Bounds& held = bounds_[j];
    if (held.stamp != stamp_) fill_bounds(j, held);
    return held.from;
  }
  /// The agent a step checked against these samples touched last (or
  /// size() and up: none yet), for the next check to try first.
  std::size_t blocker() const { return blocker_; }
  /// Notes that agent j turned down a step or a rest: it is the blocker now.
  void turned_down_by(std::size_t j) {
    if (j == blocker_) return;
    blocker_ = j;
    if (std::find(refusers_.begin(), refusers_.end(), j) == refusers_.end()) refusers_.push_back(j);
  }
  /// Every agent that turned down a step or a rest since the reset.
  const std::vector<std::size_t>& refusers() const { return refusers_; }
  /// Walking others are taken to stand where their plans end for `grace`
  /// only (infinity: for good): their rests are provisional.
  void set_rest_grace(double grace) { rest_grace_ = grace; }
  /// Agent j counts at the instants up to this time, while present: those
  /// past the grace of a walking agent's rest do not. [s]
  double counted_until(std::size_t j) {
    if (rest_grace_ == std::numeric_limits<double>::infinity() || bounds(j).top_speed == 0.0)
      return std::numeric_limits<double>::infinity();
    return plan(j).end_time() + rest_grace_;
  }

 private:
  std::size_t slot(std::size_t j, long k) {
    if (k < first_ || k - first_ >= rows_) grow(k);
    return static_cast<std::size_t>(k - first_) * stride_ + j;
  }
  void grow(long k);
  void fill(std::size_t j, long k, AgentWhere& where) const;
  void fill(std::size_t j, long k, AgentShape& shape);
  struct Bounds {
    std::uint64_t stamp = 0;
    PlanBounds::From from;
  };
  void fill_bounds(std::size_t j, Bounds& bounds) const;

  double rest_grace_ = std::numeric_limits<double>::infinity();
  std::size_t blocker_ = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> refusers_;
  const MovingObstacles* others_ = nullptr;
  const CharacterParams* character_ = nullptr;
  std::uint64_t stamp_ = 0;        ///< Counts resets.
  long first_ = 0;                 ///< The instant of the first row.
  long rows_ = 0;                  ///< Instants held (this search).
  std::size_t stride_ = 0;         ///< Agents per row: size().
  LargeVector<AgentWhere> where_;  ///< [(k - first_) * stride_ + j]
  LargeVector<AgentShape> shape_;  ///< the same
  std::vector<Bounds> bounds_;     ///< [j]
};

}  // namespace footfall::detail
