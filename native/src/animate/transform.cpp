#include "animate/transform.hpp"

#include <algorithm>

namespace footfall::animate {

Quat operator*(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

Quat normalized(Quat q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  if (!(n > 1e-300)) return {};  // no turn at all (a clip's zero quaternion, or two opposite ones mixed)
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

Quat axis_angle(Vec3 axis, double angle) {
  const double s = std::sin(0.5 * angle);
  return {std::cos(0.5 * angle), s * axis.x, s * axis.y, s * axis.z};
}

namespace {
double quat_dot(const Quat& a, const Quat& b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }
Quat negated(const Quat& q) { return {-q.w, -q.x, -q.y, -q.z}; }
}  // namespace

Quat nlerp(Quat a, Quat b, double w) {
  if (quat_dot(a, b) < 0) b = negated(b);
  return normalized({(1 - w) * a.w + w * b.w, (1 - w) * a.x + w * b.x, (1 - w) * a.y + w * b.y,
                     (1 - w) * a.z + w * b.z});
}

Quat slerp(Quat a, Quat b, double w) {
  double cosine = quat_dot(a, b);
  if (cosine < 0) {
    b = negated(b);
    cosine = -cosine;
  }
  if (cosine > 0.9995) return nlerp(a, b, w);  // nearly equal: the arc is a line
  const double angle = std::acos(std::min(cosine, 1.0));
  const double wa = std::sin((1 - w) * angle) / std::sin(angle);
  const double wb = std::sin(w * angle) / std::sin(angle);
  return normalized({wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y,
                     wa * a.z + wb * b.z});
}

Vec3 rotate(const Quat& q, Vec3 v) { return transform_direction(rotation(q), v); }

Mat4 from_columns(const double* values) {
  Mat4 r;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) r.m[row][c] = values[4 * c + row];
  return r;
}

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Vec3 transform_point(const Mat4& a, Vec3 p) {
  return transform_direction(a, p) + a.translation();
}

Vec3 transform_direction(const Mat4& a, Vec3 v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
          a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}

Mat4 inverse(const Mat4& a) {
  // The 3x3 part by its adjugate; the translation follows.
  const auto& m = a.m;
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  Mat4 r;
  r.m[0] = {c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det,
            (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det, 0};
  r.m[1] = {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det,
            (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det, 0};
  r.m[2] = {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det,
            (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det, 0};
  const Vec3 t = transform_direction(r, a.translation());
  r.m[0][3] = -t.x;
  r.m[1][3] = -t.y;
  r.m[2][3] = -t.z;
  return r;
}

Mat4 translation(Vec3 t) {
  Mat4 r;
  r.m[0][3] = t.x;
  r.m[1][3] = t.y;
  r.m[2][3] = t.z;
  return r;
}

Mat4 rotation(const Quat& q) {
  const auto [w, x, y, z] = normalized(q);
  Mat4 r;
  r.m[0] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 0};
  r.m[1] = {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 0};
  r.m[2] = {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), 0};
  return r;
}

Mat4 to_matrix(const Trs& trs) {
  Mat4 r = rotation(trs.rotation);
  const double s[3] = {trs.scale.x, trs.scale.y, trs.scale.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] *= s[j];
  r.m[0][3] = trs.translation.x;
  r.m[1][3] = trs.translation.y;
  r.m[2][3] = trs.translation.z;
  return r;
}

Quat to_quat(const Mat4& a) {
  const auto& m = a.m;
  const double trace = m[0][0] + m[1][1] + m[2][2];
  Quat q;
  if (trace > 0) {
    const double s = 2 * std::sqrt(trace + 1);
    q = {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
  } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    const double s = 2 * std::sqrt(1 + m[0][0] - m[1][1] - m[2][2]);
    q = {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
  } else if (m[1][1] > m[2][2]) {
    const double s = 2 * std::sqrt(1 + m[1][1] - m[0][0] - m[2][2]);
    q = {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
  } else {
    const double s = 2 * std::sqrt(1 + m[2][2] - m[0][0] - m[1][1]);
    q = {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
  }
  return normalized(q);
}

Trs decompose(const Mat4& a) {
  Trs trs;
  trs.translation = a.translation();
  Vec3 axes[3] = {a.column(0), a.column(1), a.column(2)};
  double s[3] = {length(axes[0]), length(axes[1]), length(axes[2])};
  // A mirror (negative determinant) goes into the first axis's scale.
  if (dot(cross(axes[0], axes[1]), axes[2]) < 0) s[0] = -s[0];
  Mat4 r;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) r.m[i][j] = a.m[i][j] / s[j];
  trs.rotation = to_quat(r);
  trs.scale = {s[0], s[1], s[2]};
  return trs;
}

}  // namespace footfall::animate
