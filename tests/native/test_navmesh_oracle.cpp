// The navigation mesh against the brute-force oracle of navmesh_oracle.hpp
// (checked in turn against a roadmap, a grid flood fill and a finer version
// of itself): random scenes, and passages whose answer flips as the radius
// grows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "footfall/navmesh.hpp"
#include "navmesh_oracle.hpp"

namespace footfall {
namespace {

using testing::NavScene;
using testing::OracleAnswer;

constexpr double kPi = 3.14159265358979323846;

/// Uniform numbers of our own: the standard distributions differ between
/// libraries, and the cases must not.
class Random {
 public:
  explicit Random(std::uint32_t seed) : engine_(seed) {}
  /// In [lo, hi).
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(engine_()) / 4294967296.0);
  }
  /// In [lo, hi] (the modulo's bias does not matter here).
  int integer(int lo, int hi) {
    return lo + static_cast<int>(engine_() % static_cast<std::uint32_t>(hi - lo + 1));
  }
  /// In the rectangle [lo, hi).
  Vec2 point(Vec2 lo, Vec2 hi) { return {uniform(lo.x, hi.x), uniform(lo.y, hi.y)}; }

 private:
  std::mt19937 engine_;
};

/// `shape` turned by `angle` about the origin, then moved to `centre`.
std::vector<Vec2> placed(const std::vector<Vec2>& shape, Vec2 centre, double angle) {
  std::vector<Vec2> out;
  for (Vec2 p : shape) out.push_back(centre + rotate(p, angle));
  return out;
}

/// The corners of the rectangle [lo, hi], counter-clockwise.
std::vector<Vec2> rectangle(Vec2 lo, Vec2 hi) { return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}; }

/// A box, turned box, triangle, convex polygon or wall (a segment) near
/// `centre`, in either winding.
std::vector<Vec2> random_obstacle(Random& random, Vec2 centre) {
  std::vector<Vec2> shape;
  const int kind = random.integer(0, 4);
  if (kind <= 1) {
    const Vec2 half{random.uniform(0.2, 2.5), random.uniform(0.2, 2.5)};
    shape =
        placed(rectangle(-1.0 * half, half), centre, kind == 0 ? 0.0 : random.uniform(0, 2 * kPi));
  } else if (kind == 2) {
    const Vec2 reach{2.5, 2.5};
    for (int i = 0; i < 3; ++i) shape.push_back(random.point(centre - reach, centre + reach));
  } else if (kind == 3) {
    std::vector<double> angles(random.integer(4, 7));
    for (double& angle : angles) angle = random.uniform(0, 2 * kPi);
    std::sort(angles.begin(), angles.end());
    const double radius = random.uniform(0.3, 2.5);
    for (double angle : angles) shape.push_back(centre + radius * unit(angle));
  } else {
    // One draw per statement: the order of a call's operands is unspecified.
    const double span = random.uniform(1.0, 6.0);
    shape = {centre, centre + span * unit(random.uniform(0, 2 * kPi))};
  }
  if (random.integer(0, 1) == 1) std::reverse(shape.begin(), shape.end());
  return shape;
}

/// A domain of about 20 x 20 m anywhere near the origin, with 3 to 15
/// obstacles (some overlapping, some across the boundary) and up to 3 points.
NavScene random_scene(Random& random) {
  NavScene scene;
  scene.min_corner = random.point({-20, -20}, {20, 20});
  scene.max_corner = scene.min_corner + Vec2{random.uniform(16, 24), random.uniform(16, 24)};
  const int polygons = random.integer(3, 15);
  for (int i = 0; i < polygons; ++i) {
    scene.polygons.push_back(
        random_obstacle(random, random.point(scene.min_corner, scene.max_corner)));
  }
  const int points = random.integer(0, 3);
  for (int i = 0; i < points; ++i) {
    scene.points.push_back(random.point(scene.min_corner, scene.max_corner));
  }
  return scene;
}

/// A point in the domain; four times in five one that the disc fits on (if
/// found soon), so that most queries test paths, and some test blocked ends.
Vec2 random_end(Random& random, const NavScene& scene, double radius) {
  const bool free = random.integer(0, 4) > 0;
  Vec2 p = random.point(scene.min_corner, scene.max_corner);
  for (int i = 0; free && i < 100 && testing::clearance(scene, p) < radius; ++i) {
    p = random.point(scene.min_corner, scene.max_corner);
  }
  return p;
}

NavMesh build_mesh(const NavScene& scene) {
  NavMesh mesh(scene.min_corner, scene.max_corner);
  for (const std::vector<Vec2>& polygon : scene.polygons) mesh.add_polygon(polygon);
  for (Vec2 p : scene.points) mesh.add_point(p);
  return mesh;
}

double polyline_length(const std::vector<Vec2>& line) {
  double total = 0.0;
  for (size_t i = 1; i < line.size(); ++i) total += distance(line[i - 1], line[i]);
  return total;
}

/// How the queries compared.
struct Tally {
  int found = 0;           ///< Both found a path.
  int no_path = 0;         ///< Both found none.
  int blocked = 0;         ///< Start or goal blocked, and the mesh said so.
  int ambiguous = 0;       ///< Skipped: the oracle's answer changes within 1e-3 of the radius.
  int at_threshold = 0;    ///< Skipped: an end's clearance is within 1e-6 of the radius.
  double worst_ratio = 0;  ///< Largest ratio of the mesh's length to the oracle's.
  double best_ratio = INFINITY;  ///< Smallest ratio of the mesh's length to the oracle's.

  void print(const char* name) const {
    std::printf(
        "[ %s ] agreed found %d, agreed no path %d, agreed blocked %d, skipped ambiguous %d, "
        "skipped at threshold %d, length ratio (mesh / oracle) %.7f to %.7f\n",
        name, found, no_path, blocked, ambiguous, at_threshold, best_ratio, worst_ratio);
  }
};

/// Checks a found path against the oracle's.
void check_found(const NavScene& scene, const PathQuery& query, const PathResult& result,
                 const OracleAnswer& oracle, Tally& tally) {
  ASSERT_STREQ(to_string(result.status), "found");
  ASSERT_FALSE(result.points.empty());
  EXPECT_TRUE(result.points.front() == query.from);
  EXPECT_TRUE(result.points.back() == query.to);
  const double polyline = polyline_length(result.points);
  EXPECT_NEAR(result.length, polyline, 1e-9 * std::max(1.0, polyline));
  const double clear = testing::path_clearance(scene, result.points);
  EXPECT_GE(clear, query.radius - 1e-6);
  EXPECT_NEAR(result.min_clearance, clear, 1e-6);
  // The oracle's arcs are polylines outside the corners' circles, so its
  // length is at most oracle_excess (2.0e-4 with 128 sides) above the true
  // one; lower_bound divides that out of its length at radius * (1 - 1e-3),
  // which no path of the radius can beat. A correct mesh's path, with its own
  // arcs outside the circles too, is at least the true length: the check is
  // as tight as the oracle allows. Above, the mesh's arcs (0.01 m from their
  // circles) may cost a little more than the oracle's.
  EXPECT_GE(result.length, oracle.lower_bound - 1e-9)
      << "shorter than the shortest: oracle " << oracle.path.length;
  EXPECT_LE(result.length, oracle.path.length * 1.01) << "oracle " << oracle.path.length;
  const double ratio = result.length / oracle.path.length;
  tally.worst_ratio = std::max(tally.worst_ratio, ratio);
  tally.best_ratio = std::min(tally.best_ratio, ratio);
  ++tally.found;
}

/// Compares the mesh's answer to one query with the oracle's.
void check_query(const NavScene& scene, const NavMesh& mesh, const PathQuery& query, Tally& tally) {
  SCOPED_TRACE(testing::describe(scene, query.from, query.to, query.radius));
  const PathResult result = mesh.find_path(query);
  // Blocked ends first, in the mesh's order; too close to call is skipped.
  for (const auto& [end, status] : {std::pair{query.from, PathStatus::kStartBlocked},
                                    std::pair{query.to, PathStatus::kGoalBlocked}}) {
    const double room = testing::clearance(scene, end) - query.radius;
    if (std::fabs(room) <= 1e-6) {
      ++tally.at_threshold;
      return;
    }
    if (room < 0) {
      EXPECT_STREQ(to_string(result.status), to_string(status));
      tally.blocked += result.status == status;
      return;
    }
  }
  const OracleAnswer oracle = testing::judge_query(scene, query.from, query.to, query.radius);
  if (oracle.ambiguous) {
    ++tally.ambiguous;
    return;
  }
  if (!oracle.path.found) {
    EXPECT_STREQ(to_string(result.status), "no_path");
    // A path returned anyway tells by its clearance which of the two is wrong.
    if (!result.points.empty()) {
      ADD_FAILURE() << "the mesh's path clears " << testing::path_clearance(scene, result.points);
    }
    tally.no_path += result.status == PathStatus::kNoPath;
    return;
  }
  ASSERT_GE(testing::path_clearance(scene, oracle.path.points), query.radius) << "oracle";
  check_found(scene, query, result, oracle, tally);
}

/// Failed checks so far in the running test.
int failures() {
  return ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
}

/// After this many failing cases the rest would only repeat them.
constexpr int kMaxFailingCases = 10;

TEST(NavMeshOracle, OracleMatchesTheLengthAroundAPoint) {
  // Around one point 3 m from both ends: two tangents and the arc between them.
  const NavScene scene{{0, 0}, {10, 10}, {}, {{5, 5}}};
  for (double radius : {0.1, 0.5, 1.5}) {
    const testing::OraclePath path = testing::shortest_path(scene, {2, 5}, {8, 5}, radius);
    const double exact =
        2 * std::sqrt(9 - radius * radius) + radius * (kPi - 2 * std::acos(radius / 3));
    ASSERT_TRUE(path.found);
    EXPECT_GE(path.length, exact * (1 - 1e-12));
    EXPECT_LE(path.length, exact * (1 + testing::oracle_excess()));
    EXPECT_GE(testing::path_clearance(scene, path.points), radius);
  }
}

TEST(NavMeshOracle, OraclePathClearanceSeesBetweenThePoints) {
  const NavScene scene{{0, 0}, {10, 10}, {rectangle({4, 4}, {6, 6})}, {{5, 8.5}}};
  EXPECT_DOUBLE_EQ(testing::path_clearance(scene, {{1, 8}, {9, 8}}), 0.5);
  EXPECT_DOUBLE_EQ(testing::path_clearance(scene, {{1, 1}, {9, 9}}), 0.0);  // through the box
  EXPECT_DOUBLE_EQ(testing::path_clearance(scene, {{1, 2}, {9, 2}, {9, 3}}), 1.0);
  EXPECT_DOUBLE_EQ(testing::clearance(scene, {5, 5}), 0.0);
  EXPECT_DOUBLE_EQ(testing::clearance(scene, {11, 5}), 0.0);
}

TEST(NavMeshOracle, ClearanceAgreesWithTheOracle) {
  Random random(7);
  for (int c = 0; c < 50; ++c) {
    const NavScene scene = random_scene(random);
    const NavMesh mesh = build_mesh(scene);
    for (int i = 0; i < 20; ++i) {
      const Vec2 p = random.point(scene.min_corner, scene.max_corner);
      SCOPED_TRACE(testing::describe(scene, p, p, 0.0));
      EXPECT_NEAR(mesh.clearance(p), testing::clearance(scene, p), 1e-9);
    }
    if (failures() >= kMaxFailingCases) break;
  }
}

TEST(NavMeshOracle, RandomScenesAgreeWithTheOracle) {
  Random random(20240601);
  Tally tally;
  for (int c = 0; c < 300; ++c) {
    const NavScene scene = random_scene(random);
    const double radius = random.uniform(0.05, 1.5);
    const Vec2 from = random_end(random, scene, radius);
    const Vec2 to = random_end(random, scene, radius);
    SCOPED_TRACE(::testing::Message() << "case " << c);
    check_query(scene, build_mesh(scene), {from, to, radius}, tally);
    if (failures() >= kMaxFailingCases) break;
  }
  tally.print("random scenes");
  EXPECT_GT(tally.found, 150);  // the cases must mostly test something
}

/// A wall across the whole domain [0, 20]^2 along `angle` through `centre`,
/// open there by a gap `gap` wide between the square ends of two boxes.
NavScene wall_with_gap(Vec2 centre, double angle, double gap) {
  NavScene scene{{0, 0}, {20, 20}, {}, {}};
  const std::vector<Vec2> half_wall = rectangle({0.5 * gap, -0.2}, {0.5 * gap + 60, 0.2});
  scene.polygons.push_back(placed(half_wall, centre, angle));
  scene.polygons.push_back(placed(half_wall, centre, angle + kPi));
  return scene;
}

/// A wall across the whole domain [0, 20]^2 along `angle`, open where a point
/// stands `gap` from two box corners: at `lean` above the wall from one, the
/// other mirrored, so a disc passes on either side of it if 2 r <= gap.
NavScene wall_with_point(Vec2 corner, double angle, double lean, double gap) {
  NavScene scene{{0, 0}, {20, 20}, {}, {}};
  const double slot = 2 * gap * std::cos(lean);
  scene.polygons.push_back(placed(rectangle({-60, -0.4}, {0, 0}), corner, angle));
  scene.polygons.push_back(placed(rectangle({slot, -0.4}, {slot + 60, 0}), corner, angle));
  scene.points.push_back(corner + rotate(gap * unit(lean), angle));
  return scene;
}

/// Checks that both the oracle and the mesh find a path through the gap just
/// below its radius and none just above, and compares the paths.
void check_passage(const NavScene& scene, Vec2 from, Vec2 to, double gap, Tally& tally) {
  const NavMesh mesh = build_mesh(scene);
  for (double factor : {0.5, 1 - 2e-3, 1 + 2e-3, 1.5}) {
    const double radius = 0.5 * gap * factor;
    SCOPED_TRACE(testing::describe(scene, from, to, radius));
    EXPECT_EQ(testing::shortest_path(scene, from, to, radius).found, factor < 1) << "oracle";
    EXPECT_STREQ(to_string(mesh.find_path({from, to, radius}).status),
                 factor < 1 ? "found" : "no_path");
    check_query(scene, mesh, {from, to, radius}, tally);
  }
}

TEST(NavMeshOracle, GapInAWallOpensBelowHalfItsWidth) {
  Random random(11);
  Tally tally;
  for (int c = 0; c < 40; ++c) {
    const Vec2 centre = random.point({8, 8}, {12, 12});
    const double angle = random.uniform(0, 2 * kPi);
    const double gap = random.uniform(0.2, 2.0);
    const Vec2 across = 5.0 * perp(unit(angle));
    check_passage(wall_with_gap(centre, angle, gap), centre - across, centre + across, gap, tally);
    if (failures() >= kMaxFailingCases) break;
  }
  tally.print("wall gaps");
}

TEST(NavMeshOracle, GapBetweenAPointAndACornerOpensBelowHalfItsWidth) {
  Random random(12);
  Tally tally;
  for (int c = 0; c < 40; ++c) {
    const Vec2 corner = random.point({8, 8}, {12, 12});
    const double angle = random.uniform(0, 2 * kPi);
    const double lean = random.uniform(30, 50) * kPi / 180;
    const double gap = random.uniform(0.2, 2.0);
    // Across the wall from the middle of the slot between the corners.
    const Vec2 middle = corner + rotate({gap * std::cos(lean), 0}, angle);
    const Vec2 across = 5.0 * perp(unit(angle));
    check_passage(wall_with_point(corner, angle, lean, gap), middle - across, middle + across, gap,
                  tally);
    if (failures() >= kMaxFailingCases) break;
  }
  tally.print("point-corner gaps");
}

}  // namespace
}  // namespace footfall
