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

namespace {

[[noreturn]] void refuse(const std::string& field, const std::string& what) {
  throw std::invalid_argument(field + ": " + what);
}

void validate_mesh(const TriangleMesh& mesh, const std::string& name) {
  if (mesh.triangles.empty()) refuse(name + ".mesh.triangles", "needs at least one triangle");
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    const Vec3 v = mesh.vertices[k];
    if (!is_finite(v) || !in_world(ground(v)) || std::fabs(v.z) > 1000.0)
      refuse(name + ".mesh.vertices[" + std::to_string(k) + "]",
             "coordinates must be finite, x and y within 1e9 m of the origin, z within 1000 m");
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const int index = mesh.triangles[t][c];
      if (index < 0 || index >= static_cast<int>(mesh.vertices.size()))
        refuse(name + ".mesh.triangles[" + std::to_string(t) + "][" + std::to_string(c) + "]",
               "vertex index " + std::to_string(index) + " is not in [0, " +
                   std::to_string(mesh.vertices.size()) + ")");
    }
  }
}

// Andrew's monotone chain; collinear points are dropped, so a flat-on-edge
// set gives its two ends (or one point).
std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

void validate(const Obstacle& obstacle, const std::string& name) {
  if (obstacle.is_mesh()) {
    validate_mesh(obstacle.mesh, name);
    return;
  }
  if (obstacle.polygon.size() < 3)
    refuse(name + ".polygon", "needs at least 3 points, got " +
                                  std::to_string(obstacle.polygon.size()));
  for (std::size_t k = 0; k < obstacle.polygon.size(); ++k) {
    if (!in_world(obstacle.polygon[k]))
      refuse(name + ".polygon[" + std::to_string(k) + "]",
             "coordinates must be finite numbers within 1e9 m of the origin");
  }
  if (!(std::isfinite(obstacle.height) && obstacle.height > 0.0 && obstacle.height <= 1000.0))
    refuse(name + ".height", "must be in (0, 1000], got " + std::to_string(obstacle.height));
  if (!(std::isfinite(obstacle.base) && obstacle.base >= 0.0 && obstacle.base < obstacle.height))
    refuse(name + ".base", "must be in [0, height) = [0, " + std::to_string(obstacle.height) +
                               "), got " + std::to_string(obstacle.base));
}

std::vector<Vec2> footprint(const Obstacle& obstacle, double cut_height) {
  if (!obstacle.is_mesh()) {
    if (obstacle.base >= cut_height) return {};
    return obstacle.polygon;
  }
  // The part below the cut: vertices below it, and where edges cross it.
  std::vector<Vec2> below;
  const auto& v = obstacle.mesh.vertices;
  for (const auto& triangle : obstacle.mesh.triangles) {
    for (int c = 0; c < 3; ++c) {
      const Vec3 p = v[triangle[c]], q = v[triangle[(c + 1) % 3]];
      if (p.z <= cut_height) below.push_back(ground(p));
      if ((p.z < cut_height) != (q.z < cut_height) && p.z != q.z) {
        const double t = (cut_height - p.z) / (q.z - p.z);
        below.push_back(ground(p + t * (q - p)));
      }
    }
  }
  return convex_hull(std::move(below));
}

ObstacleMap::ObstacleMap(std::vector<Obstacle> obstacles, double cut_height)
    : obstacles_(std::move(obstacles)) {
  index_footprints(std::vector<double>(obstacles_.size(), cut_height));
}

ObstacleMap::ObstacleMap(std::vector<Obstacle> obstacles, const std::vector<double>& cut_heights)
    : obstacles_(std::move(obstacles)) {
  index_footprints(cut_heights);
}

void ObstacleMap::index_footprints(const std::vector<double>& cut_heights) {
  boxes_.reserve(obstacles_.size());
  footprints_.reserve(obstacles_.size());
  for (size_t i = 0; i < obstacles_.size(); ++i) {
    validate(obstacles_[i], "obstacles[" + std::to_string(i) + "]");
    footprints_.push_back(footprint(obstacles_[i], cut_heights.at(i)));
    const std::vector<Vec2>& polygon = footprints_.back();
    // An obstacle above the cut gets an empty box (min > max): nothing meets it.
    Box box{{1, 1}, {-1, -1}};
    if (!polygon.empty()) {
      box = {polygon.front(), polygon.front()};
      for (const Vec2 p : polygon) box.take_in(p);
    }
    boxes_.push_back(box);
  }
  bool any = false;
  for (const Box& box : boxes_) {
    if (box.min.x > box.max.x) continue;
    if (!any) bounds_ = box;
    bounds_.take_in(box);
    any = true;
  }
  if (!any) return;
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
    if (box.min.x > box.max.x) continue;
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
  const std::vector<Vec2>& polygon = footprints_.at(index);
  return !polygon.empty() && inside_even_odd(polygon, point);
}

bool ObstacleMap::circle_overlaps(int index, const Circle& circle) const {
  const Box& box = boxes_[index];
  const Vec2 c = circle.center;
  const double r = circle.radius;
  if (c.x + r < box.min.x || c.x - r > box.max.x || c.y + r < box.min.y || c.y - r > box.max.y) {
    return false;
  }
  const std::vector<Vec2>& polygon = footprints_[index];
  if (polygon.empty()) return false;
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
