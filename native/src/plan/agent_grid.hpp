// Footfall — neighbour queries among a crowd's agents (the crowd driver's and
// the plan's metrics): their positions at one instant, bucketed in square
// cells, so that finding those near one agent costs what lies near it, not a
// pass over the whole crowd.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall {

class AgentGrid {
 public:
  AgentGrid() = default;
  /// Buckets `positions` (one per agent, finite) in cells of side `cell`,
  /// or larger where the crowd is sparse: no smaller than the area the
  /// positions span shared out among them, so that a crowd of n spread over
  /// any area has at most 2 n + 2 cells. [m]
  AgentGrid(const std::vector<Vec2>& positions, double cell);

  /// Every agent in a cell that the square of half side `radius` round
  /// `centre` overlaps, in ascending order into `out`: all within `radius`
  /// of `centre` and some farther, for the caller's own exact test. In the
  /// order a pass over every agent would meet them, so that what the caller
  /// makes of them does not depend on the grid.
  void around(Vec2 centre, double radius, std::vector<std::size_t>& out) const;

  /// How many cells the grid holds; none without agents.
  std::size_t cells() const { return first_.empty() ? 0 : first_.size() - 1; }

 private:
  /// The cell's column (x) or row (y) of coordinate v from `low`, clamped.
  long index(double v, double low, long count) const;

  std::size_t agents_ = 0;
  Vec2 low_{0.0, 0.0};  ///< The corner of cell (0, 0).
  double cell_ = 1.0;
  long columns_ = 0, rows_ = 0;
  /// Cell c holds members_[first_[c] .. first_[c + 1]), ascending (row-major cells).
  std::vector<std::uint32_t> first_;
  std::vector<std::uint32_t> members_;
};

}  // namespace footfall
