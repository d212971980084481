// Detailed outlines enter the navigation mesh simplified outward: the result
// holds the original, lies within the tolerance of it, stays simple, and
// keeps openings wider than the tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "footfall/navmesh/navmesh.hpp"
#include "navmesh/outline_simplify.hpp"

namespace footfall {
namespace {

// Inside or on the boundary of a polygon (crossing rule, boundary inclusive).
bool holds(const std::vector<Vec2>& polygon, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 a = polygon[j], b = polygon[i];
    if (distance_to_segment(p, a, b) < 1e-9) return true;
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}

double to_outline(const std::vector<Vec2>& polygon, Vec2 p) {
  double best = INFINITY;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    best = std::min(best, distance_to_segment(p, polygon[j], polygon[i]));
  return best;
}

// Closed segments [a, b] and [c, d] share a point.
bool meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const auto side = [](Vec2 p, Vec2 q, Vec2 r) {
    const double o = cross(q - p, r - p);
    return (o > 0) - (o < 0);
  };
  const auto within = [](Vec2 p, Vec2 q, Vec2 r) {  // r in the box of [p, q]
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  const int s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
  if (s1 != s2 && s3 != s4) return true;
  return (s1 == 0 && within(a, b, c)) || (s2 == 0 && within(a, b, d)) || (s3 == 0 && within(c, d, a)) ||
         (s4 == 0 && within(c, d, b));
}

bool simple(const std::vector<Vec2>& polygon) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a vertex
      if (meet(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n])) return false;
    }
  return true;
}

double area(const std::vector<Vec2>& polygon) {
  double twice = 0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) twice += cross(polygon[j], polygon[i]);
  return 0.5 * twice;
}

// Everything simplify_outward promises of `simplified` for `original`.
void expect_outward_simplification(const std::vector<Vec2>& original, const std::vector<Vec2>& simplified) {
  EXPECT_GT(area(simplified), 0.0);
  EXPECT_TRUE(simple(simplified));
  for (const Vec2 p : original) EXPECT_TRUE(holds(simplified, p)) << p.x << ", " << p.y;
  // The new outline, its vertices and its edges' middles, near the original.
  for (std::size_t i = 0; i < simplified.size(); ++i) {
    const Vec2 a = simplified[i], b = simplified[(i + 1) % simplified.size()];
    EXPECT_LE(to_outline(original, a), kOutlineTolerance + 1e-9);
    EXPECT_LE(to_outline(original, 0.5 * (a + b)), kOutlineTolerance + 1e-9);
  }
}

std::vector<Vec2> circle(int n, double radius, Vec2 centre = {0, 0}) {
  std::vector<Vec2> points;
  for (int k = 0; k < n; ++k) points.push_back(centre + radius * unit(2 * kPi * k / n));
  return points;
}

// The outline through `corners`, its straight edges cut into 1 cm pieces.
std::vector<Vec2> finely(const std::vector<Vec2>& corners) {
  std::vector<Vec2> points;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const int pieces = std::max(1, static_cast<int>(distance(a, b) / 0.01));
    for (int k = 0; k < pieces; ++k) points.push_back(a + (static_cast<double>(k) / pieces) * (b - a));
  }
  return points;
}

TEST(OutlineSimplify, AFineCircleKeepsFewVerticesAndHoldsTheOriginal) {
  const std::vector<Vec2> original = circle(4000, 3.0);
  const std::vector<Vec2> simplified = simplify_outward(original, kOutlineTolerance);
  // A circle of radius R within d needs about pi sqrt(R / 2d) vertices: 39
  // at best; greedy steps take more.
  EXPECT_LE(simplified.size(), 80u);
  expect_outward_simplification(original, simplified);
}

TEST(OutlineSimplify, OpeningsWiderThanTheToleranceStayOpen) {
  // A comb: teeth 5 cm wide, 1 m long, with slots 3 cm wide between them,
  // every edge cut into pieces of 1 cm.
  std::vector<Vec2> corners{{0, 0}};
  for (int tooth = 0; tooth < 10; ++tooth) {
    const double x = 0.08 * tooth;
    corners.push_back({x, 1});
    corners.push_back({x + 0.05, 1});
    corners.push_back({x + 0.05, 0.1});
    corners.push_back({x + 0.08, 0.1});
  }
  corners.back() = {0.77, 0};
  std::vector<Vec2> original = finely(corners);
  if (area(original) < 0) std::reverse(original.begin(), original.end());
  ASSERT_TRUE(simple(original));
  const std::vector<Vec2> simplified = simplify_outward(original, kOutlineTolerance);
  EXPECT_LT(simplified.size(), original.size() / 4);
  expect_outward_simplification(original, simplified);
  for (int slot = 0; slot < 9; ++slot) EXPECT_FALSE(holds(simplified, {0.08 * slot + 0.065, 0.6})) << slot;
}

TEST(OutlineSimplify, NoStepReachesAcrossANarrowGap) {
  // A "U" whose prongs have fine round tips and stand 3 mm apart: pushing a
  // tip's outline out by up to the tolerance would reach into the other prong.
  const double gap = 0.003, width = 0.5;
  std::vector<Vec2> corners{{0, -0.5}, {2 * width + gap, -0.5}};
  const auto tip = [&](double left, std::vector<Vec2>& out) {  // from the prong's right side to its left
    for (int k = 0; k <= 200; ++k) out.push_back(Vec2{left + width / 2, 2} + (width / 2) * unit(kPi * k / 200));
  };
  tip(width + gap, corners);
  corners.push_back({width + gap, 0});
  corners.push_back({width, 0});
  tip(0, corners);
  const std::vector<Vec2> original = finely(corners);
  ASSERT_TRUE(simple(original));
  ASSERT_GT(area(original), 0.0);
  expect_outward_simplification(original, simplify_outward(original, kOutlineTolerance));
}

TEST(OutlineSimplify, NoStepCoversAnotherPartOfTheOutline) {
  // A block with a chamfered corner under an arm of the same outline, whose
  // spike reaches down into the corner the chamfer cut off (2 mm above the
  // block's top): squaring the corner again, or cutting the notches beside
  // the spike, would cross it.
  const std::vector<Vec2> original{{0, 0},         {3, 0},           {3, 0.996},   {2.996, 1},
                                   {2.2, 1},       {2.2, 1.002},     {2.998, 1.002}, {2.999, 0.9995},
                                   {3.0, 1.002},   {3.5, 1.002},     {3.5, 1.5},   {0, 1.5}};
  ASSERT_TRUE(simple(original));
  ASSERT_GT(area(original), 0.0);
  expect_outward_simplification(original, simplify_outward(original, kOutlineTolerance));
}

TEST(OutlineSimplify, RoughOutlinesStaySimple) {
  // Stars whose radius jumps at random between neighbouring vertices, and
  // two fine arcs 2 cm apart facing each other: whatever is cut or extended,
  // no part of the outline crosses another.
  std::mt19937 random(5);
  for (int trial = 0; trial < 20; ++trial) {
    std::uniform_real_distribution<double> jump(0.0, trial % 2 ? 0.02 : 0.3);
    std::vector<Vec2> original;
    const int n = 500 + 100 * trial;
    for (int k = 0; k < n; ++k) original.push_back((2.0 + jump(random)) * unit(2 * kPi * k / n));
    expect_outward_simplification(original, simplify_outward(original, kOutlineTolerance));
  }
  std::vector<Vec2> arcs;  // a "C": outer arc, then inner arc back, with a 2 cm mouth
  for (int k = 0; k <= 600; ++k) arcs.push_back(1.0 * unit(0.01 + (2 * kPi - 0.02) * k / 600));
  for (int k = 600; k >= 0; --k) arcs.push_back(0.98 * unit(0.01 + (2 * kPi - 0.02) * k / 600));
  const std::vector<Vec2> simplified = simplify_outward(arcs, kOutlineTolerance);
  expect_outward_simplification(arcs, simplified);
}

TEST(OutlineSimplify, TheMeshPlansRoundAFineCircleWithItsClearance) {
  // A path round a 4,000-gon of radius 3 for a disc of 0.3 m: as long as the
  // way round the true circle (within the tolerance), and clear of it.
  NavMesh mesh({-10, -10}, {10, 10});
  const std::vector<Vec2> original = circle(4000, 3.0);
  mesh.add_polygon(original);
  const PathResult result = mesh.find_path({{-6, 0.01}, {6, 0}, 0.3, 0.01});
  ASSERT_EQ(result.status, PathStatus::kFound);
  const double r = 3.3;  // round the circle at the disc's distance: tangent, arc, tangent
  EXPECT_NEAR(result.length, 2 * std::sqrt(36 - r * r) + r * (kPi - 2 * std::acos(r / 6)), 0.05);
  for (std::size_t i = 0; i + 1 < result.points.size(); ++i)
    for (int k = 0; k <= 10; ++k) {
      const Vec2 p = result.points[i] + (k / 10.0) * (result.points[i + 1] - result.points[i]);
      EXPECT_GE(length(p), 3.3 - 1e-6);
    }
}

}  // namespace
}  // namespace footfall
