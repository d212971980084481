#include "footfall/model/geometry.hpp"

#include <algorithm>

namespace footfall {

double wrap_angle(double angle) {
  // Most angles are within a turn of the range: one addition, no division.
  if (angle > -kPi && angle <= kPi) return angle;
  if (angle > kPi && angle <= 3.0 * kPi) return angle - 2.0 * kPi;
  if (angle > -3.0 * kPi && angle <= -kPi) return angle + 2.0 * kPi;
  double wrapped = std::remainder(angle, 2.0 * kPi);  // in [-pi, pi]
  if (wrapped <= -kPi) wrapped += 2.0 * kPi;
  return wrapped;
}

double polyline_length(const std::vector<Vec2>& points) {
  double total = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) total += distance(points[k - 1], points[k]);
  return total;
}

}  // namespace footfall
