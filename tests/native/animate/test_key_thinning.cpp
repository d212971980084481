#include "footfall/animate/key_thinning.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace footfall::animate {
namespace {

std::vector<double> frames(std::size_t n) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i);
  return t;
}

// Channel c of the keys' curves at frame t (times are frames).
double curve_at(const std::vector<double>& values, const ThinnedKeys& keys, std::size_t channels,
                std::size_t c, double t, KeyCurve kind = KeyCurve::kCubic) {
  for (std::size_t k = 0; k + 1 < keys.kept.size(); ++k) {
    const std::size_t a = keys.kept[k], b = keys.kept[k + 1];
    if (t < static_cast<double>(a) || t > static_cast<double>(b)) continue;
    const double h = static_cast<double>(b - a), u = (t - static_cast<double>(a)) / h;
    const double ya = values[a * channels + c], yb = values[b * channels + c];
    if (kind == KeyCurve::kLinear) return ya + u * (yb - ya);
    const double ma = keys.slopes[k * channels + c], mb = keys.slopes[(k + 1) * channels + c];
    return (2 * u * u * u - 3 * u * u + 1) * ya + (u * u * u - 2 * u * u + u) * h * ma +
           (3 * u * u - 2 * u * u * u) * yb + (u * u * u - u * u) * h * mb;
  }
  return NAN;
}

TEST(KeyThinning, AStillStretchIsKeyedAtItsEndsAndStaysExactlyStill) {
  std::vector<double> x(100, 0.0);
  for (std::size_t i = 40; i < 100; ++i)
    x[i] = i < 60 ? 0.5 - 0.5 * std::cos(M_PI * static_cast<double>(i - 40) / 20.0) : 1.0;
  const ThinnedKeys keys = keys_to_keep(frames(100), x, {1e-4});
  for (const std::size_t k : keys.kept) EXPECT_TRUE(k == 0 || k >= 40) << k;
  for (const std::size_t k : keys.kept) EXPECT_TRUE(k <= 60 || k == 99) << k;
  EXPECT_LE(keys.kept.size(), 14u);  // the ends, and the ease every other frame (at 1e-4 of its size)
  for (double t = 0; t <= 40; t += 0.25) EXPECT_EQ(curve_at(x, keys, 1, 0, t), 0.0) << t;
  for (double t = 60; t <= 99; t += 0.25) EXPECT_EQ(curve_at(x, keys, 1, 0, t), 1.0) << t;
}

class KeyThinningEither : public testing::TestWithParam<KeyCurve> {};

TEST_P(KeyThinningEither, EverySampleComesBackWithinItsChannelsTolerance) {
  const std::size_t n = 2000;
  std::vector<double> values(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    values[2 * i] = 0.03 * std::sin(static_cast<double>(i) / 5.0);  // a bob
    values[2 * i + 1] = std::floor(static_cast<double>(i) / 300.0);  // a stair
  }
  const std::vector<double> tolerance{1e-4, 1e-3};
  const ThinnedKeys keys = keys_to_keep(frames(n), values, tolerance, GetParam());
  ASSERT_GE(keys.kept.size(), 2u);
  ASSERT_EQ(keys.slopes.size(), 2 * keys.kept.size());
  EXPECT_EQ(keys.kept.front(), 0u);
  EXPECT_EQ(keys.kept.back(), n - 1);
  EXPECT_LT(keys.kept.size(), GetParam() == KeyCurve::kCubic ? n / 2 : n);
  for (std::size_t c = 0; c < 2; ++c)
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_LE(std::fabs(curve_at(values, keys, 2, c, static_cast<double>(i), GetParam()) - values[2 * i + c]),
                tolerance[c] * (1 + 1e-12))
          << "channel " << c << " at " << i;
}

INSTANTIATE_TEST_SUITE_P(CubicAndStraight, KeyThinningEither, testing::Values(KeyCurve::kCubic, KeyCurve::kLinear));

TEST(KeyThinning, CubicKeysAreFewerThanStraightOnesForASmoothMotion) {
  std::vector<double> bob(500);
  for (std::size_t i = 0; i < bob.size(); ++i) bob[i] = 0.03 * std::sin(static_cast<double>(i) / 6.0);
  EXPECT_LT(3 * keys_to_keep(frames(500), bob, {1e-4}, KeyCurve::kCubic).kept.size(),
            keys_to_keep(frames(500), bob, {1e-4}, KeyCurve::kLinear).kept.size());
}

TEST(KeyThinning, AScaleLoosensTheFitWhereItIsLarge) {
  std::vector<double> bob(400), scale(400, 1.0);
  for (std::size_t i = 0; i < bob.size(); ++i) bob[i] = 0.03 * std::sin(static_cast<double>(i) / 4.0);
  for (std::size_t i = 200; i < scale.size(); ++i) scale[i] = 10.0;
  const ThinnedKeys keys = keys_to_keep(frames(400), bob, {1e-4}, KeyCurve::kCubic, scale);
  std::size_t first_half = 0;
  for (const std::size_t k : keys.kept) first_half += k < 200;
  EXPECT_GT(first_half, keys.kept.size() - first_half + 10);
  for (std::size_t i = 0; i < bob.size(); ++i)
    ASSERT_LE(std::fabs(curve_at(bob, keys, 1, 0, static_cast<double>(i)) - bob[i]), 1e-4 * scale[i] * (1 + 1e-12));
  EXPECT_THROW(keys_to_keep(frames(400), bob, {1e-4}, KeyCurve::kCubic, {1.0}), std::invalid_argument);
  scale[7] = 0.0;
  EXPECT_THROW(keys_to_keep(frames(400), bob, {1e-4}, KeyCurve::kCubic, scale), std::invalid_argument);
}

TEST(KeyThinning, RefusesMismatchedSizesAndBadTolerances) {
  EXPECT_THROW(keys_to_keep(frames(3), {0, 1}, {0.1}), std::invalid_argument);
  EXPECT_THROW(keys_to_keep(frames(2), {0, 1}, {}), std::invalid_argument);
  EXPECT_THROW(keys_to_keep(frames(2), {0, 1}, {-1.0}), std::invalid_argument);
  EXPECT_THROW(keys_to_keep(frames(2), {0, 1}, {NAN}), std::invalid_argument);
  EXPECT_THROW(keys_to_keep({0, 0}, {0, 1}, {0.1}), std::invalid_argument);
  EXPECT_THROW(keys_to_keep({1, 0}, {0, 1}, {0.1}), std::invalid_argument);
  EXPECT_THROW(keys_to_keep(frames(2), {0, INFINITY}, {0.1}), std::invalid_argument);
}

}  // namespace
}  // namespace footfall::animate
