// Footfall — rigid and affine transforms for posing a rig: 4x4 matrices,
// quaternions, and the glTF node transform (translation, rotation, scale).
#pragma once

#include <array>
#include <cmath>

#include "footfall/model/geometry3.hpp"

namespace footfall::animate {

/// A unit quaternion (w, x, y, z).
struct Quat {
  double w = 1, x = 0, y = 0, z = 0;
};

Quat operator*(const Quat& a, const Quat& b);
/// Of unit length; a zero quaternion gives no turn.
Quat normalized(Quat q);
/// The turn by `angle` [rad] about the unit `axis`.
Quat axis_angle(Vec3 axis, double angle);
/// Normalised linear interpolation on the shorter arc (slerp, for nearly equal turns).
Quat nlerp(Quat a, Quat b, double w);
/// Spherical linear interpolation on the shorter arc (glTF's LINEAR rotations).
Quat slerp(Quat a, Quat b, double w);
Vec3 rotate(const Quat& q, Vec3 v);

/// An affine transform, row-major: m[row][column], points as columns.
struct Mat4 {
  std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

  Vec3 translation() const { return {m[0][3], m[1][3], m[2][3]}; }
  Vec3 column(int c) const { return {m[0][c], m[1][c], m[2][c]}; }
};

/// The matrix of 16 values stored column by column, as glTF stores them.
Mat4 from_columns(const double* values);
Mat4 operator*(const Mat4& a, const Mat4& b);
Vec3 transform_point(const Mat4& a, Vec3 p);
Vec3 transform_direction(const Mat4& a, Vec3 v);
/// The inverse of an invertible affine transform.
Mat4 inverse(const Mat4& a);
Mat4 translation(Vec3 t);
Mat4 rotation(const Quat& q);

/// A glTF node's local transform: T * R * S.
struct Trs {
  Vec3 translation{0, 0, 0};
  Quat rotation;
  Vec3 scale{1, 1, 1};
};

Mat4 to_matrix(const Trs& trs);
/// T, R and S of a transform without shear (a positive scale per axis).
Trs decompose(const Mat4& a);
/// The rotation of a pure rotation matrix's 3x3 part.
Quat to_quat(const Mat4& a);

inline Vec3 normalized(Vec3 v) { return (1.0 / length(v)) * v; }

}  // namespace footfall::animate
