// Polyline: walking a distance along a path, as the full-body sweeps, the
// local goal and a narrower section's way near a place all do.
#include <gtest/gtest.h>

#include <vector>

#include "footfall/model/polyline.hpp"

namespace footfall {
namespace {

void expect_point(Vec2 actual, Vec2 expected) {
  EXPECT_DOUBLE_EQ(actual.x, expected.x);
  EXPECT_DOUBLE_EQ(actual.y, expected.y);
}

// 3 m east, then 4 m north: 7 m in all.
const Polyline kElbow({{0, 0}, {3, 0}, {3, 4}});

TEST(Polyline, MeasuresTheArcLengthAtEachPoint) {
  EXPECT_DOUBLE_EQ(kElbow.length(), 7.0);
  EXPECT_DOUBLE_EQ(kElbow.along(0), 0.0);
  EXPECT_DOUBLE_EQ(kElbow.along(1), 3.0);
  EXPECT_DOUBLE_EQ(kElbow.along(2), 7.0);
}

TEST(Polyline, APointInsideAPieceLiesOnIt) {
  expect_point(kElbow.point_at(1.5), {1.5, 0});
  expect_point(kElbow.point_at(5.0), {3, 2});
  EXPECT_DOUBLE_EQ(kElbow.heading_at(1.5), 0.0);
  EXPECT_DOUBLE_EQ(kElbow.heading_at(5.0), 0.5 * kPi);
}

TEST(Polyline, AtACornerIsTheCornerAndHeadsOnAlongTheNextPiece) {
  expect_point(kElbow.point_at(3.0), {3, 0});
  EXPECT_DOUBLE_EQ(kElbow.heading_at(3.0), 0.5 * kPi);
}

TEST(Polyline, BeyondItsEndsIsClampedToThem) {
  expect_point(kElbow.point_at(-2.0), {0, 0});
  expect_point(kElbow.point_at(0.0), {0, 0});
  expect_point(kElbow.point_at(7.0), {3, 4});
  expect_point(kElbow.point_at(9.0), {3, 4});
  EXPECT_DOUBLE_EQ(kElbow.heading_at(-2.0), 0.0);
  EXPECT_DOUBLE_EQ(kElbow.heading_at(9.0), 0.5 * kPi);
}

TEST(Polyline, AZeroLengthPieceAddsNoLengthAndHasTheDirectionOfItsNeighbours) {
  // A way planned from where the agent stands may repeat its first point.
  const Polyline repeated({{0, 0}, {0, 0}, {2, 0}, {2, 0}, {2, 2}, {2, 2}});
  EXPECT_DOUBLE_EQ(repeated.length(), 4.0);
  expect_point(repeated.point_at(0.0), {0, 0});
  expect_point(repeated.point_at(1.0), {1, 0});
  expect_point(repeated.point_at(2.0), {2, 0});
  expect_point(repeated.point_at(3.0), {2, 1});
  expect_point(repeated.point_at(5.0), {2, 2});
  EXPECT_DOUBLE_EQ(repeated.heading_at(0.0), 0.0);        // the first piece with a length
  EXPECT_DOUBLE_EQ(repeated.heading_at(2.0), 0.5 * kPi);  // the piece starting there
  EXPECT_DOUBLE_EQ(repeated.heading_at(4.0), 0.5 * kPi);  // the last piece with a length
}

TEST(Polyline, OfOnePointIsThatPointEverywhere) {
  const Polyline point({{1, 2}});
  EXPECT_DOUBLE_EQ(point.length(), 0.0);
  expect_point(point.point_at(-1.0), {1, 2});
  expect_point(point.point_at(1.0), {1, 2});
}

TEST(Polyline, BetweenTwoDistancesTakesTheCornersInside) {
  const std::vector<Vec2> part = kElbow.between(1.0, 5.0);
  ASSERT_EQ(part.size(), 3u);
  expect_point(part[0], {1, 0});
  expect_point(part[1], {3, 0});
  expect_point(part[2], {3, 2});
  // From the start to a corner: the corner once, as the end.
  const std::vector<Vec2> to_corner = kElbow.between(0.0, 3.0);
  ASSERT_EQ(to_corner.size(), 2u);
  expect_point(to_corner[1], {3, 0});
}

}  // namespace
}  // namespace footfall
