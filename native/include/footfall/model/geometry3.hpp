// Footfall — space geometry for the full body: points, segments and capsules.
// Blender's frame: Z up, the ground is the XY plane; metres.
#pragma once

#include <cmath>

#include "footfall/model/geometry.hpp"

namespace footfall {

/// A point or vector in space. [m]
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
/// True if every coordinate is finite.
inline bool is_finite(Vec3 a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}
/// The ground projection.
inline Vec2 ground(Vec3 a) { return {a.x, a.y}; }

/// A capsule: the points within `radius` of the segment [a, b].
struct Capsule {
  Vec3 a;             ///< One end of the axis. [m]
  Vec3 b;             ///< The other end. [m]
  double radius = 0;  ///< [m] [> 0]
};

/// A rigid placement on the ground: turn by `heading` about Z, then move to
/// `position`, raised to the ground's `height` there (the root of a body pose).
struct GroundPlacement {
  Vec2 position;       ///< [m]
  double heading = 0;  ///< [rad]
  double height = 0;   ///< [m]

  Vec3 apply(Vec3 p) const {
    const double c = std::cos(heading), s = std::sin(heading);
    return {position.x + c * p.x - s * p.y, position.y + s * p.x + c * p.y, p.z + height};
  }
  Capsule apply(const Capsule& capsule) const {
    return {apply(capsule.a), apply(capsule.b), capsule.radius};
  }
};

}  // namespace footfall
