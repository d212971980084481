#include "footfall/geometry.hpp"

#include <algorithm>

namespace footfall {

double wrap_angle(double angle) {
  constexpr double kPi = 3.14159265358979323846;
  // Most angles are within a turn of the range: one addition, no division.
  if (angle > -kPi && angle <= kPi) return angle;
  if (angle > kPi && angle <= 3.0 * kPi) return angle - 2.0 * kPi;
  if (angle > -3.0 * kPi && angle <= -kPi) return angle + 2.0 * kPi;
  double wrapped = std::remainder(angle, 2.0 * kPi);  // in [-pi, pi]
  if (wrapped <= -kPi) wrapped += 2.0 * kPi;
  return wrapped;
}

Vec2 closest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) { return distance(p, closest_on_segment(p, a, b)); }

}  // namespace footfall
