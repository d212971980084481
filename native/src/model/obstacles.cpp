#include "footfall/model/obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace footfall {
namespace {

constexpr double kCellSize = 2.0;           // [m] grid cell; boxes are ~1-6 m
constexpr long long kMaxCells = 4'000'000;  // the cell grows for huge scenes

}  // namespace

ObstacleMap::ObstacleMap(std::vector<Obstacle> obstacles) : obstacles_(std::move(obstacles)) {
  boxes_.reserve(obstacles_.size());
  for (size_t i = 0; i < obstacles_.size(); ++i) {
    const Obstacle& obstacle = obstacles_[i];
    const std::string name = "obstacles[" + std::to_string(i) + "]";
    if (obstacle.polygon.size() < 3) {
      throw std::invalid_argument(name + ".polygon: needs at least 3 points, got " +
                                  std::to_string(obstacle.polygon.size()));
    }
    if (!(std::isfinite(obstacle.height) && obstacle.height > 0.0 && obstacle.height <= 1000.0)) {
      throw std::invalid_argument(name + ".height: must be in (0, 1000], got " +
                                  std::to_string(obstacle.height));
    }
    Box box{obstacle.polygon.front(), obstacle.polygon.front()};
    for (size_t k = 0; k < obstacle.polygon.size(); ++k) {
      const Vec2 p = obstacle.polygon[k];
      if (!in_world(p)) {
        throw std::invalid_argument(
            name + ".polygon[" + std::to_string(k) +
            "]: coordinates must be finite numbers within 1e9 m of the origin");
      }
      box.take_in(p);
    }
    boxes_.push_back(box);
  }
  if (boxes_.empty()) return;
  bounds_ = boxes_.front();
  for (const Box& box : boxes_) bounds_.take_in(box);
  const double w = bounds_.max.x - bounds_.min.x, h = bounds_.max.y - bounds_.min.y;
  // About kMaxCells cells at most: larger cells for larger scenes, and for long thin
  // ones a cap per axis.
  cell_size_ = std::max({kCellSize, std::sqrt(w * h / static_cast<double>(kMaxCells)),
                         std::max(w, h) / static_cast<double>(kMaxCells / 16)});
  columns_ = static_cast<int>(w / cell_size_) + 1;
  rows_ = static_cast<int>(h / cell_size_) + 1;
  cells_.assign(static_cast<size_t>(columns_) * rows_, {});
  for (size_t i = 0; i < boxes_.size(); ++i) {
    const Box& box = boxes_[i];
    const int c0 = cell_of(box.min.x, bounds_.min.x, columns_);
    const int c1 = cell_of(box.max.x, bounds_.min.x, columns_);
    const int r0 = cell_of(box.min.y, bounds_.min.y, rows_);
    const int r1 = cell_of(box.max.y, bounds_.min.y, rows_);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c)
        cells_[static_cast<size_t>(r) * columns_ + c].push_back(int(i));
    }
  }
}

bool ObstacleMap::contains(int index, Vec2 point) const {
  const std::vector<Vec2>& polygon = obstacles_.at(index).polygon;
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 a = polygon[i], b = polygon[j];
    if ((a.y > point.y) != (b.y > point.y) &&
        point.x < (b.x - a.x) * (point.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

bool ObstacleMap::circle_overlaps(int index, const Circle& circle) const {
  const Box& box = boxes_[index];
  const Vec2 c = circle.center;
  const double r = circle.radius;
  if (c.x + r < box.min.x || c.x - r > box.max.x || c.y + r < box.min.y || c.y - r > box.max.y) {
    return false;
  }
  const std::vector<Vec2>& polygon = obstacles_[index].polygon;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    if (distance_to_segment(c, polygon[j], polygon[i]) <= r) return true;
  }
  return contains(index, c);
}

int ObstacleMap::cell_of(double v, double origin, int count) const {
  // Clamped before the conversion: a huge query must not overflow the int.
  const double cell = std::floor((v - origin) / cell_size_);
  if (!(cell >= 0.0)) return 0;  // also NaN
  return static_cast<int>(std::min(cell, static_cast<double>(count - 1)));
}

template <typename Visit>
int ObstacleMap::visit_near(const Circle& circle, Visit visit) const {
  if (cells_.empty()) return -1;
  const Vec2 c = circle.center;
  const double r = circle.radius;
  if (c.x + r < bounds_.min.x || c.x - r > bounds_.max.x || c.y + r < bounds_.min.y ||
      c.y - r > bounds_.max.y) {
    return -1;
  }
  const int c0 = cell_of(c.x - r, bounds_.min.x, columns_);
  const int c1 = cell_of(c.x + r, bounds_.min.x, columns_);
  const int r0 = cell_of(c.y - r, bounds_.min.y, rows_);
  const int r1 = cell_of(c.y + r, bounds_.min.y, rows_);
  for (int row = r0; row <= r1; ++row) {
    for (int col = c0; col <= c1; ++col) {
      for (const int index : cells_[static_cast<size_t>(row) * columns_ + col]) {
        const Box& box = boxes_[index];
        if (c.x + r < box.min.x || c.x - r > box.max.x || c.y + r < box.min.y ||
            c.y - r > box.max.y) {
          continue;
        }
        // Visit each obstacle in one cell only: the first cell that both the
        // query's and the obstacle's boxes cover.
        const int first_col = std::max(c0, cell_of(box.min.x, bounds_.min.x, columns_));
        const int first_row = std::max(r0, cell_of(box.min.y, bounds_.min.y, rows_));
        if (col != first_col || row != first_row) continue;
        if (visit(index)) return index;
      }
    }
  }
  return -1;
}

int ObstacleMap::first_overlap(const Circle& circle) const {
  return visit_near(circle, [&](int index) { return circle_overlaps(index, circle); });
}

void ObstacleMap::gather(const Circle& region, std::vector<int>& out) const {
  visit_near(region, [&](int index) {
    out.push_back(index);
    return false;
  });
}

int ObstacleMap::first_overlap(const Circle& circle, const std::vector<int>& candidates) const {
  for (const int index : candidates) {
    if (circle_overlaps(index, circle)) return index;
  }
  return -1;
}

}  // namespace footfall
