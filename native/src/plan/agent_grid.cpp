// Footfall — the crowd's neighbour grid (agent_grid.hpp).
#include "plan/agent_grid.hpp"

#include <algorithm>
#include <cmath>

namespace footfall {

AgentGrid::AgentGrid(const std::vector<Vec2>& positions, double cell) : agents_(positions.size()) {
  if (positions.empty()) return;
  Vec2 high = positions.front();
  low_ = high;
  for (const Vec2& p : positions) {
    low_ = {std::min(low_.x, p.x), std::min(low_.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  }
  // Cells no smaller than the crowd's area shared out among its agents: a
  // crowd spread thin over kilometres would otherwise fill millions of empty
  // cells at every tick.
  const double area = std::max(high.x - low_.x, cell) * std::max(high.y - low_.y, cell);
  cell_ = std::max(cell, std::sqrt(area / static_cast<double>(positions.size())));
  columns_ = static_cast<long>((high.x - low_.x) / cell_) + 1;
  rows_ = static_cast<long>((high.y - low_.y) / cell_) + 1;
  // Counting sort by cell; agents go in in ascending order, so each cell's
  // members stay ascending.
  std::vector<std::uint32_t> cell_of(positions.size());
  first_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
  for (std::size_t j = 0; j < positions.size(); ++j) {
    const long c = index(positions[j].y, low_.y, rows_) * columns_ +
                   index(positions[j].x, low_.x, columns_);
    cell_of[j] = static_cast<std::uint32_t>(c);
    ++first_[static_cast<std::size_t>(c) + 1];
  }
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  members_.resize(positions.size());
  std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
  for (std::size_t j = 0; j < positions.size(); ++j)
    members_[next[cell_of[j]]++] = static_cast<std::uint32_t>(j);
}

long AgentGrid::index(double v, double low, long count) const {
  const double k = std::floor((v - low) / cell_);
  return static_cast<long>(std::clamp(k, 0.0, static_cast<double>(count - 1)));
}

void AgentGrid::around(Vec2 centre, double radius, std::vector<std::size_t>& out) const {
  out.clear();
  if (agents_ == 0) return;
  // A little wider than asked: the caller's test of the distance rounds.
  radius = radius * (1.0 + 1e-9) + 1e-9;
  const Vec2 high = low_ + cell_ * Vec2{static_cast<double>(columns_), static_cast<double>(rows_)};
  if (centre.x + radius < low_.x || centre.y + radius < low_.y || centre.x - radius > high.x ||
      centre.y - radius > high.y)
    return;
  const long x0 = index(centre.x - radius, low_.x, columns_);
  const long x1 = index(centre.x + radius, low_.x, columns_);
  const long y0 = index(centre.y - radius, low_.y, rows_);
  const long y1 = index(centre.y + radius, low_.y, rows_);
  // The cells' members marked in a bitset and read back in order: ascending
  // without sorting, at a word per 64 agents.
  thread_local std::vector<std::uint64_t> marks;
  marks.assign((agents_ + 63) / 64, 0);
  for (long y = y0; y <= y1; ++y) {
    for (long x = x0; x <= x1; ++x) {
      const auto c = static_cast<std::size_t>(y * columns_ + x);
      for (std::uint32_t m = first_[c]; m < first_[c + 1]; ++m)
        marks[members_[m] / 64] |= std::uint64_t{1} << (members_[m] % 64);
    }
  }
  for (std::size_t w = 0; w < marks.size(); ++w)
    for (std::uint64_t bits = marks[w]; bits != 0; bits &= bits - 1)
      out.push_back(w * 64 + static_cast<std::size_t>(__builtin_ctzll(bits)));
}

}  // namespace footfall
