// Transforms for posing rigs: inverses, decomposition and interpolation.
#include <gtest/gtest.h>

#include "animate/transform.hpp"

namespace footfall::animate {
namespace {

constexpr double kPi = 3.14159265358979323846;

void expect_near(const Mat4& a, const Mat4& b, double tolerance = 1e-12) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(a.m[i][j], b.m[i][j], tolerance) << i << "," << j;
}

TEST(Transform, InverseUndoesATurnedScaledMove) {
  const Mat4 a = to_matrix({{1, -2, 3}, axis_angle(normalized(Vec3{1, 2, 3}), 0.7), {0.01, 0.01, 0.01}});
  expect_near(a * inverse(a), Mat4{}, 1e-9);
  expect_near(inverse(a) * a, Mat4{}, 1e-9);
}

TEST(Transform, DecomposeGivesBackTranslationRotationAndScale) {
  const Trs trs{{0.5, 1, -2}, axis_angle(normalized(Vec3{0, 1, 1}), 2.5), {2, 3, 4}};
  const Trs back = decompose(to_matrix(trs));
  expect_near(to_matrix(back), to_matrix(trs), 1e-12);
  EXPECT_NEAR(back.scale.y, 3, 1e-12);
}

TEST(Transform, DecomposeFindsRotationsPastAHalfTurn) {
  // Near a half turn the trace is negative: the other branches of to_quat.
  for (const Vec3 axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, normalized(Vec3{1, -1, 0.2})}) {
    const Mat4 m = rotation(axis_angle(axis, 0.97 * kPi));
    expect_near(to_matrix(decompose(m)), m, 1e-12);
  }
}

TEST(Transform, SlerpTurnsEvenlyOnTheShorterArc) {
  const Quat a{1, 0, 0, 0};
  const Quat b = axis_angle({0, 1, 0}, kPi / 2);
  const Vec3 x = rotate(slerp(a, b, 0.25), {1, 0, 0});
  EXPECT_NEAR(std::atan2(-x.z, x.x), kPi / 8, 1e-12);  // a quarter of the way: 22.5 deg
  const Quat flipped{-b.w, -b.x, -b.y, -b.z};          // the same turn, the other sign
  const Vec3 y = rotate(slerp(a, flipped, 0.5), {1, 0, 0});
  EXPECT_NEAR(std::atan2(-y.z, y.x), kPi / 4, 1e-12);
}

}  // namespace
}  // namespace footfall::animate
