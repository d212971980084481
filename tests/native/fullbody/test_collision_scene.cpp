// The scene in 3-D: exact segment-triangle distances, prisms with a base and
// concave caps, meshes, and the tree against a brute-force check.
#include <gtest/gtest.h>

#include <cmath>

#include "footfall/fullbody/collision_scene.hpp"
#include "fullbody/capsule_triangle.hpp"
#include "util/seeded_random.hpp"

namespace footfall {
namespace {

Vec3 random_point(SeededRandom& r, double size) {
  return {r.uniform(-size, size), r.uniform(-size, size), r.uniform(-size, size)};
}

// The distance by dense sampling of both shapes: never below the exact one,
// and above it by at most the sampling's reach.
double sampled_distance(Vec3 p, Vec3 q, Vec3 a, Vec3 b, Vec3 c) {
  double best = INFINITY;
  constexpr int kN = 60;
  for (int i = 0; i <= kN; ++i) {
    const Vec3 s = p + (static_cast<double>(i) / kN) * (q - p);
    for (int u = 0; u <= kN; ++u)
      for (int v = 0; u + v <= kN; ++v) {
        const Vec3 t = a + (static_cast<double>(u) / kN) * (b - a) + (static_cast<double>(v) / kN) * (c - a);
        best = std::min(best, length(s - t));
      }
  }
  return best;
}

TEST(CapsuleTriangle, DistanceMatchesDenseSampling) {
  SeededRandom random(11);
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3 p = random_point(random, 1), q = random_point(random, 1);
    const Vec3 a = random_point(random, 1), b = random_point(random, 1), c = random_point(random, 1);
    const auto exact = detail::segment_triangle_distance(p, q, a, b, c);
    const double sampled = sampled_distance(p, q, a, b, c);
    EXPECT_LE(std::sqrt(exact.squared), sampled + 1e-9) << trial;
    EXPECT_GE(std::sqrt(exact.squared), sampled - 0.08) << trial;
    EXPECT_NEAR(length(exact.on_segment - exact.on_triangle), std::sqrt(exact.squared), 1e-9);
  }
}

TEST(CapsuleTriangle, APiercingSegmentIsAtDistanceZero) {
  const auto d = detail::segment_triangle_distance({0.2, 0.2, -1}, {0.2, 0.2, 1}, {0, 0, 0},
                                                   {1, 0, 0}, {0, 1, 0});
  EXPECT_EQ(d.squared, 0.0);
  EXPECT_NEAR(d.on_segment.z, 0.0, 1e-12);
}

Capsule upright(Vec2 at, double z0, double z1, double radius) {
  return {{at.x, at.y, z0}, {at.x, at.y, z1}, radius};
}

TEST(CollisionScene, PrismsHaveABaseAndATop) {
  // A table top from 0.72 to 0.76 m over [0, 1] x [0, 1].
  const CollisionScene scene({prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.76, 0.72)});
  EXPECT_FALSE(scene.test(upright({0.5, 0.5}, 0.1, 0.5, 0.1)));  // a leg under it
  EXPECT_FALSE(scene.test(upright({0.5, 0.5}, 0.9, 1.5, 0.1)));  // a torso over it
  EXPECT_TRUE(scene.test(upright({0.5, 0.5}, 0.5, 1.0, 0.05)));  // through it
  const Contact beside = scene.test(upright({1.08, 0.5}, 0.6, 0.9, 0.1));
  ASSERT_TRUE(beside);
  EXPECT_NEAR(beside.depth, 0.02, 1e-9);
  EXPECT_EQ(beside.obstacle, 0);
  EXPECT_FALSE(scene.test(upright({1.11, 0.5}, 0.6, 0.9, 0.1)));
}

TEST(CollisionScene, ConcaveCapsCoverOnlyThePolygon) {
  // An L: its notch [1, 2] x [1, 2] is free; a fan from a corner would cover it.
  const CollisionScene scene(
      {prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1.0)});
  EXPECT_FALSE(scene.test(Capsule{{1.5, 1.5, 1.05}, {1.6, 1.6, 1.05}, 0.04}));
  EXPECT_TRUE(scene.test(Capsule{{0.5, 0.5, 1.05}, {0.6, 0.6, 1.05}, 0.06}));
}

TEST(CollisionScene, MeshesAreTheirTriangles) {
  Obstacle sheet;
  sheet.mesh.vertices = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  sheet.mesh.triangles = {{0, 1, 2}};
  const CollisionScene scene({sheet});
  EXPECT_EQ(scene.triangle_count(), 1u);
  EXPECT_TRUE(scene.test(upright({0.2, 0.2}, 0.5, 1.5, 0.01)));
  EXPECT_FALSE(scene.test(upright({0.8, 0.8}, 0.5, 1.5, 0.01)));
}

TEST(CollisionScene, TheTreeFindsWhatBruteForceFinds) {
  SeededRandom random(5);
  std::vector<Obstacle> obstacles;
  Obstacle soup;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 centre = random_point(random, 10);
    const int first = static_cast<int>(soup.mesh.vertices.size());
    for (int k = 0; k < 3; ++k) soup.mesh.vertices.push_back(centre + 0.3 * random_point(random, 1));
    soup.mesh.triangles.push_back({first, first + 1, first + 2});
  }
  const CollisionScene scene({soup});
  int hits = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Vec3 a = random_point(random, 10);
    const Capsule capsule{a, a + 0.5 * random_point(random, 1), random.uniform(0.02, 0.3)};
    bool brute = false;
    for (const auto& t : soup.mesh.triangles) {
      const auto& v = soup.mesh.vertices;
      brute = brute || detail::segment_triangle_distance(capsule.a, capsule.b, v[t[0]], v[t[1]],
                                                         v[t[2]]).squared <=
                           capsule.radius * capsule.radius;
    }
    EXPECT_EQ(static_cast<bool>(scene.test(capsule)), brute) << trial;
    hits += brute ? 1 : 0;
  }
  EXPECT_GT(hits, 20);  // the check saw both answers
  EXPECT_LT(hits, 380);
}

}  // namespace
}  // namespace footfall
