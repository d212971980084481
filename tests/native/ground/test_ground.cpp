// Ground: the levels of walkable ground under a point, the one near a height,
// the share of a sole held, and the refusal of bad surfaces.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "footfall/ground/ground.hpp"

namespace footfall {
namespace {

std::vector<Vec2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

/// A flight of `count` treads 0.3 m deep and 0.17 m up each, from x = 0,
/// 2 m wide, on a floor from x = -5 to 0 at height 0.
std::vector<GroundSurface> flight(int count) {
  std::vector<GroundSurface> ground{ground_prism(rectangle(-5, -1, 0, 1), 0.0)};
  for (int k = 0; k < count; ++k)
    ground.push_back(ground_prism(rectangle(0.3 * k, -1, 0.3 * (k + 1), 1), 0.17 * (k + 1)));
  return ground;
}

/// A ramp 4 m long rising 1 m toward +x, 2 m wide, as two triangles wound
/// counter-clockwise seen from above (`up`) or clockwise (facing down).
GroundSurface ramp(bool up = true) {
  GroundSurface surface;
  surface.mesh.vertices = {{0, -1, 0}, {4, -1, 1}, {4, 1, 1}, {0, 1, 0}};
  surface.mesh.triangles = up ? std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}
                              : std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 3, 2}};
  return surface;
}

Sole sole_at(Vec3 centre, double heading = 0.0, Vec3 normal = {0, 0, 1}) {
  return {centre, normal, heading, 0.26, 0.10};
}

std::string refusal(std::vector<GroundSurface> surfaces) {
  try {
    const Ground ground(std::move(surfaces));
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(Ground, EachTreadIsALevelAtItsHeightAndBesideTheFlightThereIsNone) {
  const Ground ground(flight(5));
  EXPECT_EQ(ground.walkable_faces(), 6u);
  for (int k = 0; k < 5; ++k) {
    const std::vector<GroundPoint> levels = ground.levels_at({0.3 * k + 0.15, 0.5});
    ASSERT_EQ(levels.size(), 1u) << "tread " << k;
    EXPECT_DOUBLE_EQ(levels[0].z, 0.17 * (k + 1));
    EXPECT_EQ(levels[0].surface, k + 1);
    EXPECT_DOUBLE_EQ(levels[0].normal.z, 1.0);
  }
  EXPECT_DOUBLE_EQ(ground.levels_at({-2, 0}).at(0).z, 0.0);
  EXPECT_TRUE(ground.levels_at({0.5, 1.2}).empty()) << "beside the flight";
  EXPECT_TRUE(ground.levels_at({1.6, 0}).empty()) << "past its top";
}

TEST(Ground, ARampsHeightAndSlopeFollowItsTriangles) {
  const Ground ground({ramp()});
  const std::vector<GroundPoint> levels = ground.levels_at({2.0, 0.3});
  ASSERT_EQ(levels.size(), 1u) << "the shared edge's two triangles are one level";
  EXPECT_NEAR(levels[0].z, 0.5, 1e-12);
  // Rising 1 in 4 along x: the normal leans back against the rise.
  EXPECT_NEAR(levels[0].normal.x, -1.0 / std::sqrt(17.0), 1e-12);
  EXPECT_NEAR(levels[0].normal.z, 4.0 / std::sqrt(17.0), 1e-12);
  ASSERT_EQ(ground.levels_at({3.0, 1.0}).size(), 1u) << "on its edge";
}

TEST(Ground, TrianglesFacingDownOrStandingOnEdgeAreNotWalkedOn) {
  GroundSurface wall;
  wall.mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}};
  wall.mesh.triangles = {{0, 1, 2}};
  const Ground ground({ramp(false), wall});
  EXPECT_EQ(ground.walkable_faces(), 0u);
  EXPECT_TRUE(ground.levels_at({2.0, 0.0}).empty());
}

TEST(Ground, UnderABridgeDeckTwoLevelsAndTheNearerIsFound) {
  const Ground ground({ground_prism(rectangle(-10, -10, 10, 10), 0.0),
                       ground_prism(rectangle(-2, -10, 2, 10), 4.5)});
  const std::vector<GroundPoint> levels = ground.levels_at({0, 3});
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_DOUBLE_EQ(levels[0].z, 0.0);
  EXPECT_DOUBLE_EQ(levels[1].z, 4.5);
  EXPECT_DOUBLE_EQ(ground.level_near({0, 3}, 0.3, 0.5)->z, 0.0);
  EXPECT_DOUBLE_EQ(ground.level_near({0, 3}, 4.3, 0.5)->z, 4.5);
  EXPECT_FALSE(ground.level_near({0, 3}, 2.0, 0.5)) << "between the levels, neither within reach";
  EXPECT_EQ(ground.levels_at({5, 3}).size(), 1u) << "beside the deck";
}

TEST(Ground, ASoleIsHeldWholeOnATreadAndInPartOverItsNosing) {
  const Ground ground(flight(3));
  // The second tread spans x 0.3-0.6 at 0.34 m; a sole 0.26 m long fits.
  EXPECT_DOUBLE_EQ(ground.support(sole_at({0.45, 0, 0.34}), 0.02, 0.8), 1.0);
  // Turned across the flight it fits as well (0.10 m along x).
  EXPECT_DOUBLE_EQ(ground.support(sole_at({0.45, 0, 0.34}, 0.5 * M_PI), 0.02, 0.8), 1.0);
  // Its toe half over the edge into the air above the first tread.
  const double over = ground.support(sole_at({0.33, 0, 0.34}), 0.02, 0.8);
  EXPECT_GT(over, 0.3);
  EXPECT_LT(over, 0.85);
  // At the wrong height it is held nowhere.
  EXPECT_DOUBLE_EQ(ground.support(sole_at({0.45, 0, 0.30}), 0.02, 0.8), 0.0);
}

TEST(Ground, ASoleWhoseToeRunsIntoTheNextRiserIsHeldNowhere) {
  const Ground ground(flight(3));
  // On the second tread (x 0.3-0.6 at 0.34 m), the toe 3 cm into the third
  // tread's riser: six of its seven rows lie on the tread, the toe's in the step.
  EXPECT_DOUBLE_EQ(ground.support(sole_at({0.5, 0, 0.34}), 0.02, 0.8), 0.0);
  // 3 cm short of the riser it is held whole.
  EXPECT_DOUBLE_EQ(ground.support(sole_at({0.44, 0, 0.34}), 0.02, 0.8), 1.0);
  // A floor with a platform on it: beside the platform held whole, against it held nowhere.
  const Ground floor_and_platform(
      {ground_prism(rectangle(-5, -5, 5, 5), 0.0), ground_prism(rectangle(1, -1, 2, 1), 0.4)});
  EXPECT_DOUBLE_EQ(floor_and_platform.support(sole_at({0.8, 0, 0}), 0.02, 0.8), 1.0);
  EXPECT_DOUBLE_EQ(floor_and_platform.support(sole_at({0.9, 0, 0}), 0.02, 0.8), 0.0);
}

TEST(Ground, OnARampASoleAlongTheSlopeIsHeldAndAFlatOneOrATooSteepSlopeIsNot) {
  const Ground ground({ramp()});
  const GroundPoint under = ground.levels_at({2, 0})[0];
  EXPECT_DOUBLE_EQ(ground.support(sole_at({2, 0, under.z}, 0.0, under.normal), 0.02, 0.9), 1.0);
  // A flat sole along the rise: its heel and toe are 3 cm off the ramp.
  EXPECT_LT(ground.support(sole_at({2, 0, under.z}), 0.02, 0.9), 0.85);
  // A slope of 14 degrees with a limit of 10 holds nothing.
  EXPECT_DOUBLE_EQ(
      ground.support(sole_at({2, 0, under.z}, 0.0, under.normal), 0.02, std::cos(10 * M_PI / 180)),
      0.0);
}

/// Total length of the walls whose middles satisfy `where`.
template <class Where>
double wall_length(const std::vector<GroundWall>& walls, Where&& where) {
  double sum = 0.0;
  for (const GroundWall& wall : walls)
    if (where(0.5 * (wall.a + wall.b))) sum += distance(wall.a, wall.b);
  return sum;
}

TEST(Ground, AFloorUnderAPlatformOrATooLowDeckIsCoveredAndUnderAHighDeckItIsNot) {
  const Ground ground({ground_prism(rectangle(-10, -10, 10, 10), 0.0),
                       ground_prism(rectangle(-8, -8, -6, -6), 0.8),
                       prism(rectangle(0, -10, 2, 10), 1.2, 1.0),
                       prism(rectangle(5, -10, 7, 10), 4.5, 4.3)});
  ASSERT_EQ(ground.levels_at({-7, -7}).size(), 2u);
  ASSERT_EQ(ground.standable_at({-7, -7}, 1.75).size(), 1u);
  EXPECT_DOUBLE_EQ(ground.standable_at({-7, -7}, 1.75)[0].z, 0.8);
  ASSERT_EQ(ground.standable_at({1, 0}, 1.75).size(), 1u);
  EXPECT_DOUBLE_EQ(ground.standable_at({1, 0}, 1.75)[0].z, 1.2) << "under 1 m of headroom";
  ASSERT_EQ(ground.standable_at({6, 0}, 1.75).size(), 2u) << "4.3 m of headroom";
}

TEST(Ground, AFlightIsWalledAtItsSidesAndOpenAtEveryTreadWithinTheStep) {
  std::vector<GroundSurface> surfaces = flight(5);
  surfaces.push_back(ground_prism(rectangle(1.5, -1, 4, 1), 0.85));  // the landing
  const Ground ground(surfaces);
  const auto across_the_flight = [](Vec2 m) {
    return m.x > -4.99 && m.x < 3.99 && std::fabs(m.y) < 0.99;
  };
  const std::vector<GroundWall> walls = ground.walls(0.25, 1.75, 0.0);
  EXPECT_EQ(wall_length(walls, across_the_flight), 0.0);
  // Its sides, from the first tread to the landing, both sides.
  EXPECT_NEAR(wall_length(walls, [](Vec2 m) { return m.x > 0 && m.x < 1.5; }), 3.0, 1e-9);
  // All round: floor, flight and landing, 9 m by 2 m.
  EXPECT_NEAR(wall_length(walls, [](Vec2) { return true; }), 22.0, 1e-9);
  // Risers of 0.17 m are walls to a body that steps 0.15 m at most: the
  // five below the landing, each seen from the tread above and below.
  EXPECT_NEAR(wall_length(ground.walls(0.15, 1.75, 0.0), across_the_flight), 2.0 * 5 * 2, 1e-9);
}

TEST(Ground, APlatformTooHighToStepIsReachedByTheRampBesideIt) {
  GroundSurface up;  // 0 to 0.8 m over x 0-4, 2 m wide
  up.mesh.vertices = {{0, -1, 0}, {4, -1, 0.8}, {4, 1, 0.8}, {0, 1, 0}};
  up.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Ground ground({ground_prism(rectangle(-5, -5, 10, 5), 0.0),
                       ground_prism(rectangle(4, -5, 10, 5), 0.8), up});
  EXPECT_EQ(ground.standable_at({2, 0}, 1.75).size(), 1u) << "the floor under the ramp is covered";
  const std::vector<GroundWall> walls = ground.walls(0.25, 1.75, 0.0);
  // The platform's edge is a wall but where the ramp meets it.
  EXPECT_NEAR(wall_length(walls, [](Vec2 m) { return std::fabs(m.x - 4) < 0.01; }), 8.0, 1e-9);
  // The ramp's sides are walls where it is a step above the floor: from
  // x = 0.25 / 0.2 = 1.25 m on (to the sample's 5 cm).
  const double sides =
      wall_length(walls, [](Vec2 m) { return std::fabs(std::fabs(m.y) - 1) < 0.01 && m.x < 4; });
  EXPECT_NEAR(sides, 2 * (4 - 1.25), 0.1);
  // Across the ramp's two ends, none.
  const auto across_the_ramp = [](Vec2 m) {
    return std::fabs(m.y) < 0.99 && m.x > -4.99 && m.x < 9.99;
  };
  EXPECT_EQ(wall_length(walls, across_the_ramp), 0.0);
}

TEST(Ground, LevelsAboveOneAnotherAreFoundWhereABodyFitsBetweenThem) {
  const GroundSurface floor = ground_prism(rectangle(-10, -10, 10, 10), 0.0);
  const auto layers = [](const std::vector<GroundSurface>& surfaces) {
    return Ground(surfaces).layers(0.25, 1.75, 0.0).count();
  };
  EXPECT_EQ(layers({floor, prism(rectangle(5, -10, 7, 10), 4.5, 4.3)}), 2);  // a deck over it
  EXPECT_EQ(layers({floor, prism(rectangle(5, -10, 7, 10), 1.2, 1.0)}), 1);  // too low to walk under
  EXPECT_EQ(layers({floor, ground_prism(rectangle(5, -1, 7, 1), 0.8)}), 1);  // a platform on it
  EXPECT_EQ(layers(flight(5)), 1);
}

TEST(Ground, NoSurfacesIsNoGround) {
  const Ground ground;
  EXPECT_TRUE(ground.empty());
  EXPECT_TRUE(ground.levels_at({0, 0}).empty());
}

TEST(Ground, BadSurfacesAreRefusedNamingTheField) {
  EXPECT_EQ(refusal({ground_prism({{0, 0}, {1, 0}}, 0.0)}),
            "ground[0].polygon: needs at least 3 points, got 2");
  EXPECT_EQ(refusal({ground_prism(rectangle(0, 0, 1, 1), 0.0),
                     ground_prism(rectangle(0, 0, 1, NAN), 0.0)}),
            "ground[1].polygon[2]: coordinates must be finite numbers within 1e9 m of the origin");
  EXPECT_EQ(refusal({ground_prism(rectangle(0, 0, 1, 1), 1500.0)}),
            "ground[0].height: must be in [-1000, 1000] m, got 1500");
  EXPECT_EQ(refusal({prism(rectangle(0, 0, 1, 1), 0.5, 0.8)}),
            "ground[0].base: must be in [-1000, height] = [-1000, 0.5] m, got 0.8");
  GroundSurface bad = ramp();
  bad.mesh.triangles[1][2] = 9;
  EXPECT_EQ(refusal({bad}), "ground[0].mesh.triangles[1][2]: vertex index 9 is not in [0, 4)");
}

TEST(Ground, NegativeHeightsAreSunkenFloors) {
  const GroundSurface pit = ground_prism(rectangle(0, 0, 2, 2), -0.5);
  EXPECT_DOUBLE_EQ(pit.base, -0.5);
  EXPECT_DOUBLE_EQ(ground_prism(rectangle(0, 0, 2, 2), 0.8).base, 0.0);
  const Ground ground({pit});
  EXPECT_DOUBLE_EQ(ground.levels_at({1, 1}).at(0).z, -0.5);
}

TEST(Ground, TooManyTrianglesAreRefusedBeforeAnyIsIndexed) {
  GroundSurface huge;
  huge.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  huge.mesh.triangles.assign(Ground::kMaxTriangles + 1, {0, 1, 2});
  EXPECT_EQ(refusal({huge}), "ground: 2000001 triangles in all meshes, at most 2000000");
}

TEST(Ground, AHeightFieldWithASpikeAnswersEveryPoint) {
  // 60 x 60 cells of 1 m, one vertex raised 1,000 m: the spike's steep
  // triangles are indexed with the rest and answered where they are.
  constexpr int n = 60;
  GroundSurface field;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      field.mesh.vertices.push_back({double(i), double(j), i == 30 && j == 30 ? 1000.0 : 0.0});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * (n + 1) + j, b = a + n + 1;
      field.mesh.triangles.push_back({a, b, b + 1});
      field.mesh.triangles.push_back({a, b + 1, a + 1});
    }
  const Ground ground({field});
  EXPECT_EQ(ground.walkable_faces(), 2u * n * n);
  // Walls only round its rim (the spike's slopes are the step limit's
  // business, not the walls'): the triangles' shared edges are not sampled.
  EXPECT_NEAR(wall_length(ground.walls(0.25, 1.75, 0.0), [](Vec2) { return true; }), 4.0 * n, 1e-9);
  EXPECT_DOUBLE_EQ(ground.levels_at({10.3, 20.7}).at(0).z, 0.0);
  EXPECT_NEAR(ground.levels_at({29.75, 30.0}).at(0).z, 750.0, 1e-6);
}

}  // namespace
}  // namespace footfall
