// Footfall — where the crowd is thick, and ways round it (crowd_planner.cpp).
// People take the next street when this one is full: a way whose first
// stretch runs through a crowd denser than free walking allows is compared
// with the cheapest way across a grid of the walkable ground on which
// crowded cells cost more than their length, and the cheaper is taken.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "behavior/local_goal.hpp"
#include "footfall/navmesh/navmesh.hpp"

namespace footfall::crowd {

/// The side of the grid's square cells, at least: larger where the ground
/// would take more than kMostCells of it (more than its square root along
/// its longer side). [m]
constexpr double kCrowdCell = 1.0;
constexpr double kMostCells = 250000;
/// Ways are looked at for crowds this far ahead. [m]
constexpr double kCrowdAhead = 15.0;
/// A way round rejoins the way at most this far along it: a street or two
/// over, and its search costs the square of this, not a city's size. [m]
constexpr double kRoundReach = 40.0;
/// An agent counts as spread over this much of the way ahead of it, where
/// it will be in the next seconds: a street that many are heading for counts
/// as crowded before they arrive. [m]
constexpr double kFlowAhead = 15.0;
/// Density at which people still walk freely (Fruin's level of service C
/// ends at about 0.5 people per square metre). [1/m^2]
constexpr double kFreeDensity = 0.5;
/// A metre of way through a crowd of density d costs
/// 1 + kCrowdWeight * (d - kFreeDensity) metres, above kFreeDensity: at 1.5
/// people per square metre (a standing queue) a metre costs nine.
constexpr double kCrowdWeight = 8.0;
/// A way round must cost this share less than the way through the crowd:
/// ways do not flip between two of about the same cost.
constexpr double kDetourGain = 0.15;

/// The walkable cells of a navigation mesh: those whose centre has room for
/// a disc of `radius`. Made once per crowd; read by every search.
class CrowdGrid {
 public:
  CrowdGrid(const NavMesh& mesh, double radius);

  /// Calls `visit(next, length)` for each walkable cell one step from
  /// `cell` (eight neighbours, diagonally only past two walkable cells: no
  /// corner is cut), with the step's length. [m]
  template <typename Visit>
  void for_each_step(long cell, Visit&& visit) const;

  /// The cell holding `p`, or -1 outside the grid.
  long cell_of(Vec2 p) const;
  bool walkable(long cell) const { return walkable_[static_cast<std::size_t>(cell)] != 0; }
  /// How many of the 3 x 3 cells round `cell` are walkable.
  std::uint32_t room(long cell) const { return room_[static_cast<std::size_t>(cell)]; }
  std::size_t cells() const { return walkable_.size(); }
  long columns() const { return columns_; }
  long rows() const { return rows_; }
  Vec2 centre(long cell) const;
  double cell() const { return cell_; }

 private:
  Vec2 low_;
  double cell_ = kCrowdCell;
  long columns_ = 0, rows_ = 0;
  std::vector<char> walkable_;
  std::vector<std::uint32_t> room_;
};

template <typename Visit>
void CrowdGrid::for_each_step(long cell, Visit&& visit) const {
  const long x = cell % columns_, y = cell / columns_;
  for (long dy = -1; dy <= 1; ++dy)
    for (long dx = -1; dx <= 1; ++dx) {
      const long u = x + dx, v = y + dy;
      if ((dx == 0 && dy == 0) || u < 0 || v < 0 || u >= columns_ || v >= rows_) continue;
      const long next = v * columns_ + u;
      if (!walkable(next) ||
          (dx != 0 && dy != 0 && !(walkable(y * columns_ + u) && walkable(v * columns_ + x))))
        continue;
      visit(next, cell_ * (dx != 0 && dy != 0 ? 1.4142135623730951 : 1.0));
    }
}

/// How many agents stand in each cell of a CrowdGrid at one tick, and the
/// ways that avoid where they are thick.
class CrowdDensity {
 public:
  CrowdDensity() = default;
  /// Counts the agents at `com` that are `present`; with `ways` (one per
  /// agent, or null), also where each is going: its next kFlowAhead of way.
  CrowdDensity(const CrowdGrid& grid, const std::vector<Vec2>& com,
               const std::vector<char>& present, const std::vector<const Way*>& ways = {});

  /// People per square metre of walkable ground in the 3 x 3 cells round
  /// `cell`. [1/m^2]
  double density(long cell) const { return density_[static_cast<std::size_t>(cell)]; }
  /// What a metre through `cell` costs, in metres. [>= 1]
  double cost_per_metre(long cell) const {
    return 1.0 + kCrowdWeight * std::max(0.0, density(cell) - kFreeDensity);
  }

  /// A way from `from` to `goal` round the crowds, when the first
  /// kCrowdAhead of `way` runs through one and the cheapest way across the
  /// grid to the point kRoundReach along `way` costs kDetourGain less than
  /// `way` to there; kept `radius` clear of the obstacles of `mesh` (its
  /// corners cut where the mesh allows), and on along `way` from there.
  std::optional<Way> way_round(const Way& way, const NavMesh& mesh, double radius) const;

 private:
  /// The cost of the first `ahead` metres of `points` (all of it: infinite). [m]
  double cost_of(const std::vector<Vec2>& points, double ahead) const;
  /// The cheapest path of cells from `from` to `goal` (A*), as cell centres
  /// with `from` and `goal` at the ends; empty if none costs under `budget`.
  std::vector<Vec2> cheapest_cells(Vec2 from, Vec2 goal, double budget) const;

  const CrowdGrid* grid_ = nullptr;
  /// Per cell, for every search of the tick to read: counted once. [1/m^2]
  std::vector<double> density_;
};

}  // namespace footfall::crowd
