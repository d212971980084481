// Footfall — a path as a polyline measured by arc length.
#pragma once

#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall::detail {

/// Points joined by straight pieces, with the arc length at each point.
class Polyline {
 public:
  explicit Polyline(std::vector<Vec2> points);

  double length() const { return along_.empty() ? 0.0 : along_.back(); }
  const std::vector<Vec2>& points() const { return points_; }
  /// The point `s` metres along (clamped to the ends). [m]
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

}  // namespace footfall::detail
