// Footfall — plane geometry shared by every stage. Blender's frame: Z up, the
// ground is the XY plane; metres and radians.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace footfall {

/// A point or vector in the ground plane. [m] or [m/s]
struct Vec2 {
  double x = 0.0;  ///< X coordinate.
  double y = 0.0;  ///< Y coordinate.
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline Vec2 operator*(Vec2 a, double s) { return {s * a.x, s * a.y}; }
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

/// Dot product.
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// Z component of the 3-D cross product.
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// Euclidean length (plain sqrt: coordinates here are far from overflow).
inline double length(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }
/// Distance between two points. [m]
inline double distance(Vec2 a, Vec2 b) { return length(a - b); }
/// Unit vector at world angle `angle` (counter-clockwise from +X). [rad]
inline Vec2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
/// `a` rotated counter-clockwise by `angle`. [rad]
inline Vec2 rotate(Vec2 a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.x - s * a.y, s * a.x + c * a.y};
}
/// `a` rotated counter-clockwise by a quarter turn.
inline Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
/// World angle of a vector. [rad] in (-pi, pi]
inline double angle_of(Vec2 a) { return std::atan2(a.y, a.x); }
/// True if both coordinates are finite numbers.
inline bool is_finite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }

constexpr double kPi = 3.14159265358979323846;

/// Largest coordinate accepted in a scene: far beyond any real scene, and
/// small enough that sums and grid indices stay exact. [m]
constexpr double kMaxCoordinate = 1e9;
/// True if both coordinates are finite and within kMaxCoordinate of the origin.
inline bool in_world(Vec2 a) {
  return is_finite(a) && std::fabs(a.x) <= kMaxCoordinate && std::fabs(a.y) <= kMaxCoordinate;
}

/// `angle` wrapped into (-pi, pi]. [rad]
double wrap_angle(double angle);

/// Length of the polyline through `points` (0 for fewer than two). [m]
double polyline_length(const std::vector<Vec2>& points);

/// The point of the segment [a, b] nearest to `p`. [m]
inline Vec2 closest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

/// Squared distance from point `p` to the segment [a, b]. [m^2]
inline double squared_distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = p - closest_on_segment(p, a, b);
  return dot(d, d);
}

/// Distance from point `p` to the segment [a, b]. [m]
inline double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  return std::sqrt(squared_distance_to_segment(p, a, b));
}

/// True if the segments [a, b] and [c, d] cross at a point inside both
/// (touching at an end, or lying on one line, is not crossing).
inline bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double c_side = cross(b - a, c - a), d_side = cross(b - a, d - a);
  const double a_side = cross(d - c, a - c), b_side = cross(d - c, b - c);
  return ((c_side > 0 && d_side < 0) || (c_side < 0 && d_side > 0)) &&
         ((a_side > 0 && b_side < 0) || (a_side < 0 && b_side > 0));
}

/// True if `p` lies inside `polygon` by the even-odd rule (either winding;
/// a self-crossing polygon's overlaps count as outside).
inline bool inside_even_odd(const std::vector<Vec2>& polygon, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

/// An axis-aligned box in the ground plane.
struct Box {
  Vec2 min, max;  ///< Its corners. [m]

  /// Grows the box to hold `p`.
  void take_in(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  /// Grows the box to hold `box`.
  void take_in(const Box& box) {
    take_in(box.min);
    take_in(box.max);
  }
};

/// Squared distance between the nearest points of two boxes (0 where they
/// meet). [m^2]
inline double squared_distance(const Box& a, const Box& b) {
  const double dx = std::max({0.0, a.min.x - b.max.x, b.min.x - a.max.x});
  const double dy = std::max({0.0, a.min.y - b.max.y, b.min.y - a.max.y});
  return dx * dx + dy * dy;
}

/// A circle in the ground plane.
struct Circle {
  Vec2 center;        ///< Centre. [m]
  double radius = 0;  ///< Radius. [m] [>= 0]
};

}  // namespace footfall
