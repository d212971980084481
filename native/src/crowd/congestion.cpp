#include "crowd/congestion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

#include "footfall/model/polyline.hpp"

namespace footfall::crowd {
namespace {

/// Cells the cheapest-way search expands at most: a way round is a street or
/// two over, not across a whole city of small cells.
constexpr int kMostExpanded = 40000;

/// Per cell of a grid `columns` wide, the sum of `v` over the 3 x 3 cells
/// round it: a row's sums over three, then a column's.
std::vector<std::uint32_t> box_sums(std::vector<std::uint32_t> v, long columns) {
  const long rows = static_cast<long>(v.size()) / columns;
  const auto at = [columns](long x, long y) { return static_cast<std::size_t>(y * columns + x); };
  std::vector<std::uint32_t> rowwise(v.size());
  for (long y = 0; y < rows; ++y)
    for (long x = 0; x < columns; ++x)
      rowwise[at(x, y)] = v[at(x, y)] + (x > 0 ? v[at(x - 1, y)] : 0) +
                          (x + 1 < columns ? v[at(x + 1, y)] : 0);
  for (long y = 0; y < rows; ++y)
    for (long x = 0; x < columns; ++x)
      v[at(x, y)] = rowwise[at(x, y)] + (y > 0 ? rowwise[at(x, y - 1)] : 0) +
                    (y + 1 < rows ? rowwise[at(x, y + 1)] : 0);
  return v;
}

/// The cheapest-way search's tables, kept per thread from search to search:
/// a search touches a few thousand cells of a grid that may hold 250,000.
/// A cell's entries hold only if its stamp is the search's.
struct CellTables {
  std::vector<double> cost;
  std::vector<long> parent;
  std::vector<std::uint32_t> stamp;
  std::uint32_t search = 0;

  void begin(std::size_t cells) {
    if (stamp.size() < cells || search == std::numeric_limits<std::uint32_t>::max()) {
      cost.resize(std::max(cells, cost.size()));
      parent.resize(cost.size());
      stamp.assign(cost.size(), 0);
      search = 0;
    }
    ++search;
  }
  double cost_of(long cell) const {
    const auto k = static_cast<std::size_t>(cell);
    return stamp[k] == search ? cost[k] : std::numeric_limits<double>::infinity();
  }
  long parent_of(long cell) const {
    const auto k = static_cast<std::size_t>(cell);
    return stamp[k] == search ? parent[k] : -1;
  }
  void set(long cell, double c, long p) {
    const auto k = static_cast<std::size_t>(cell);
    stamp[k] = search;
    cost[k] = c;
    parent[k] = p;
  }
};

}  // namespace

CrowdGrid::CrowdGrid(const NavMesh& mesh, double radius) : low_(mesh.min_corner()) {
  const Vec2 size = mesh.max_corner() - low_;
  // Sized by the longer side, so that a long thin domain is no more cells.
  cell_ = std::max(kCrowdCell, std::max(size.x, size.y) / std::sqrt(kMostCells));
  columns_ = std::max(1L, static_cast<long>(std::ceil(size.x / cell_)));
  rows_ = std::max(1L, static_cast<long>(std::ceil(size.y / cell_)));
  walkable_.resize(static_cast<std::size_t>(columns_ * rows_));
  std::vector<std::uint32_t> open(walkable_.size());
  for (long c = 0; c < columns_ * rows_; ++c) {
    walkable_[static_cast<std::size_t>(c)] = mesh.clearance(centre(c)) >= radius ? 1 : 0;
    open[static_cast<std::size_t>(c)] = walkable_[static_cast<std::size_t>(c)];
  }
  room_ = box_sums(std::move(open), columns_);
}

long CrowdGrid::cell_of(Vec2 p) const {
  const double x = std::floor((p.x - low_.x) / cell_);
  const double y = std::floor((p.y - low_.y) / cell_);
  if (!(x >= 0 && y >= 0 && x < static_cast<double>(columns_) &&
        y < static_cast<double>(rows_)))
    return -1;
  return static_cast<long>(y) * columns_ + static_cast<long>(x);
}

Vec2 CrowdGrid::centre(long cell) const {
  return low_ + cell_ * Vec2{static_cast<double>(cell % columns_) + 0.5,
                             static_cast<double>(cell / columns_) + 0.5};
}

CrowdDensity::CrowdDensity(const CrowdGrid& grid, const std::vector<Vec2>& com,
                           const std::vector<char>& present, const std::vector<const Way*>& ways)
    : grid_(&grid), density_(grid.cells(), 0.0) {
  // Counted in kShares of a person, so that a person spread along its way
  // sums in integers.
  constexpr std::uint32_t kShares = 20;
  const double sample = kFlowAhead / kShares;  // [m]
  std::vector<std::uint32_t> people(grid.cells(), 0), going(grid.cells(), 0);
  for (std::size_t j = 0; j < com.size(); ++j) {
    if (!present[j]) continue;
    const long cell = grid.cell_of(com[j]);
    if (cell >= 0) people[static_cast<std::size_t>(cell)] += kShares;
    if (j >= ways.size() || ways[j] == nullptr || ways[j]->points.size() < 2) {
      if (cell >= 0) going[static_cast<std::size_t>(cell)] += kShares;
      continue;
    }
    const Polyline way(ways[j]->points);
    for (std::uint32_t k = 0; k < kShares; ++k) {
      const long at = grid.cell_of(way.point_at((k + 0.5) * sample));
      if (at >= 0) ++going[static_cast<std::size_t>(at)];
    }
  }
  const std::vector<std::uint32_t> now = box_sums(std::move(people), grid.columns());
  const std::vector<std::uint32_t> soon = box_sums(std::move(going), grid.columns());
  const double cell_area = grid.cell() * grid.cell();
  for (long c = 0; c < grid.columns() * grid.rows(); ++c)
    if (const std::uint32_t room = grid.room(c); room > 0) {
      const auto k = static_cast<std::size_t>(c);
      density_[k] = std::max(now[k], soon[k]) / (kShares * room * cell_area);
    }
}

double CrowdDensity::cost_of(const std::vector<Vec2>& points, double ahead) const {
  const double sample = 0.5 * grid_->cell();  // [m]
  double cost = 0.0, along = 0.0;
  for (std::size_t k = 1; k < points.size() && along < ahead; ++k) {
    const double piece = distance(points[k - 1], points[k]);
    const int samples = std::max(1, static_cast<int>(std::ceil(piece / sample)));
    for (int s = 0; s < samples && along < ahead; ++s) {
      const Vec2 p = points[k - 1] + ((s + 0.5) / samples) * (points[k] - points[k - 1]);
      const long cell = grid_->cell_of(p);
      const double ds = piece / samples;
      cost += ds * (cell >= 0 ? cost_per_metre(cell) : 1.0);
      along += ds;
    }
  }
  return cost;
}

std::vector<Vec2> CrowdDensity::cheapest_cells(Vec2 from, Vec2 goal, double budget) const {
  const long start = grid_->cell_of(from), end = grid_->cell_of(goal);
  if (start < 0 || end < 0) return {};
  thread_local CellTables tables;
  tables.begin(grid_->cells());
  struct Entry {
    double bound;  ///< cost so far plus the straight line on
    long cell;
    double cost;  ///< so far: the entry is stale once the cell costs less
    bool operator>(const Entry& e) const {
      return bound > e.bound || (bound == e.bound && cell > e.cell);
    }
  };
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  const Vec2 target = grid_->centre(end);
  tables.set(start, 0.0, -1);
  open.push({distance(grid_->centre(start), target), start, 0.0});
  int expanded = 0;
  while (!open.empty()) {
    const Entry top = open.top();
    open.pop();
    if (top.cost > tables.cost_of(top.cell)) continue;
    if (top.bound >= budget || ++expanded > kMostExpanded) return {};
    if (top.cell == end) break;
    grid_->for_each_step(top.cell, [&](long next, double step) {
      const double through =
          top.cost + 0.5 * step * (cost_per_metre(top.cell) + cost_per_metre(next));
      if (through >= tables.cost_of(next)) return;
      tables.set(next, through, top.cell);
      open.push({through + distance(grid_->centre(next), target), next, through});
    });
  }
  if (tables.parent_of(end) < 0 && end != start) return {};
  std::vector<Vec2> path{goal};
  for (long c = tables.parent_of(end); c >= 0 && c != start; c = tables.parent_of(c))
    path.push_back(grid_->centre(c));
  path.push_back(from);
  std::reverse(path.begin(), path.end());
  return path;
}

std::optional<Way> CrowdDensity::way_round(const Way& way, const NavMesh& mesh,
                                           double radius) const {
  if (grid_ == nullptr || way.points.size() < 2) return std::nullopt;
  if (cost_of(way.points, kCrowdAhead) <= std::min(kCrowdAhead, way.length) + 1e-9)
    return std::nullopt;  // no crowd on its first stretch
  // The way as far as a way round may rejoin it, and on from there.
  const Polyline line(way.points);
  const bool long_way = line.length() > kRoundReach;
  const std::vector<Vec2> head = long_way ? line.between(0.0, kRoundReach) : way.points;
  // A way round costs at least its length, at least the straight line's: the
  // search stops short of the cost it must beat (where the crowd fills the
  // only way, such as a door everyone leaves by, at once or nearly).
  const double infinite = std::numeric_limits<double>::infinity();
  const double budget = (1.0 - kDetourGain) * cost_of(head, infinite);
  // Pulled tight, a path of cells may shorten by up to 1 / cos(22.5 deg), as
  // eight directions approximate any.
  constexpr double kPulled = 1.0824;
  const std::vector<Vec2> cells = cheapest_cells(head.front(), head.back(), kPulled * budget);
  if (cells.size() < 2) return std::nullopt;
  // The cells' path pulled tight: from each point on to the farthest in a
  // row that it sees with `radius` of room.
  Way round{{cells.front()}, 0.0};
  for (std::size_t at = 0; at + 1 < cells.size();) {
    std::size_t next = at + 1;
    while (next + 1 < cells.size() &&
           mesh.clearance_between(cells[at], cells[next + 1], radius) >= radius)
      ++next;
    round.points.push_back(cells[next]);
    at = next;
  }
  if (cost_of(round.points, infinite) > budget) return std::nullopt;
  if (long_way) {
    const std::vector<Vec2> rest = line.between(kRoundReach, line.length());
    round.points.insert(round.points.end(), rest.begin() + 1, rest.end());
  }
  round.length = polyline_length(round.points);
  return round;
}

}  // namespace footfall::crowd
