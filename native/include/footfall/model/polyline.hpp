// Footfall — a polyline measured by arc length: the one way every stage walks
// a distance along a path (a body's sweep, an agent's local goal, a narrower
// section's way near a place).
#pragma once

#include <cstddef>
#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall {

/// Points joined by straight pieces, with the arc length at each point.
class Polyline {
 public:
  explicit Polyline(std::vector<Vec2> points);

  double length() const { return along_.empty() ? 0.0 : along_.back(); }
  const std::vector<Vec2>& points() const { return points_; }
  /// The arc length at points()[k]. [m]
  double along(std::size_t k) const { return along_[k]; }
  /// The point `s` metres along (clamped to the ends; a zero-length piece
  /// gives its point). [m]
  Vec2 point_at(double s) const;
  /// The direction of travel `s` metres along: that of the piece holding it. [rad]
  double heading_at(double s) const;
  /// The part from `s0` to `s1` metres along, as points.
  std::vector<Vec2> between(double s0, double s1) const;

 private:
  std::size_t piece_at(double s) const;
  std::vector<Vec2> points_;
  std::vector<double> along_;
};

}  // namespace footfall
