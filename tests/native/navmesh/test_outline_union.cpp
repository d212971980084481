// Overlapping obstacles enter the mesh as the region they cover together:
// the same walkable space as each one entered alone, at the cost of their
// union, with holes open.
#include <gtest/gtest.h>

#include <random>

#include "footfall/crowd/scenario.hpp"
#include "footfall/navmesh/navmesh.hpp"
#include "footfall/scenes/box_scenes.hpp"
#include "navmesh/outline_union.hpp"

namespace footfall {
namespace {

using bench::box_between;

// `count` boxes of 5 m at random with their corners in a square of `side`.
std::vector<std::vector<Vec2>> scattered_boxes(int count, double side, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> at(0.0, side);
  std::vector<std::vector<Vec2>> boxes;
  for (int i = 0; i < count; ++i) {
    const Vec2 lo{at(random), at(random)};
    boxes.push_back(box_between(lo, lo + Vec2{5, 5}));
  }
  return boxes;
}

TEST(OutlineUnion, GroupsOnlyWhatOverlaps) {
  const std::vector<std::vector<Vec2>> outlines{
      box_between({0, 0}, {2, 2}),    box_between({1, 1}, {3, 3}),  // overlapping
      box_between({10, 0}, {12, 2}),                          // apart
      box_between({2.5, 2.5}, {4, 4}),                        // overlapping the second
      box_between({4, 4}, {5, 5}),                            // touching the fourth at a corner only
      {{20, 0}, {22, 2}, {22, 0}, {20, 2}},           // a bow tie: crosses itself, left alone
      box_between({21, 0}, {23, 2})};
  const std::vector<OverlapGroup> groups = overlapping_groups(outlines);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].members, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(groups[0].region.holes.size(), 0u);
}

TEST(OutlineUnion, AWalledCourtyardKeepsItsHoleOpen) {
  // Four overlapping walls round a 6 x 6 m courtyard.
  const std::vector<std::vector<Vec2>> walls{box_between({0, 0}, {8, 1}), box_between({7, 0}, {8, 8}), box_between({0, 7}, {8, 8}),
                                             box_between({0, 0}, {1, 8})};
  const std::vector<OverlapGroup> groups = overlapping_groups(walls);
  ASSERT_EQ(groups.size(), 1u);
  ASSERT_EQ(groups[0].region.outlines.size(), 1u);
  ASSERT_EQ(groups[0].region.holes.size(), 1u);
  NavMesh mesh({-5, -5}, {13, 13});
  const int id = mesh.add_region(groups[0].region.outlines, groups[0].region.holes, "walls");
  EXPECT_NEAR(mesh.clearance({4, 4}), 3.0, 1e-9);  // inside the courtyard, 3 m from every wall
  EXPECT_EQ(mesh.clearance({0.5, 4}), 0.0);         // inside a wall
  EXPECT_EQ(mesh.find_path({{2, 2}, {6, 6}, 0.3, 0.01}).status, PathStatus::kFound);
  EXPECT_EQ(mesh.find_path({{4, 4}, {10, 4}, 0.3, 0.01}).status, PathStatus::kNoPath);
  mesh.remove(id);
  EXPECT_EQ(mesh.find_path({{4, 4}, {10, 4}, 0.3, 0.01}).status, PathStatus::kFound);
  EXPECT_GT(mesh.clearance({0.5, 4}), 0.0);
}

TEST(OutlineUnion, TheUnionIsAsWalkableAsTheBoxesOneByOne) {
  const std::vector<std::vector<Vec2>> boxes = scattered_boxes(60, 30.0, 3);
  NavMesh one_by_one({-5, -5}, {40, 40}), united({-5, -5}, {40, 40});
  for (const auto& b : boxes) one_by_one.add_polygon(b);
  std::vector<bool> grouped(boxes.size(), false);
  for (const OverlapGroup& group : overlapping_groups(boxes)) {
    united.add_region(group.region.outlines, group.region.holes);
    for (int i : group.members) grouped[i] = true;
  }
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (!grouped[i]) united.add_polygon(boxes[i]);
  EXPECT_LT(united.triangle_count(), one_by_one.triangle_count());
  std::mt19937 random(8);
  std::uniform_real_distribution<double> at(-4.0, 39.0);
  int found = 0;
  for (int k = 0; k < 300; ++k) {
    const PathQuery query{{at(random), at(random)}, {at(random), at(random)}, 0.3, 0.01};
    // The same but where a long outline entered simplified (within 1 cm).
    EXPECT_NEAR(united.clearance(query.from), one_by_one.clearance(query.from), 0.01);
    const PathResult a = united.find_path(query), b = one_by_one.find_path(query);
    ASSERT_EQ(a.status, b.status) << k;
    if (a.status != PathStatus::kFound) continue;
    ++found;
    EXPECT_NEAR(a.length, b.length, 0.01 * b.length) << k;
  }
  EXPECT_GT(found, 50);
}

TEST(OutlineUnion, AScenariosOverlappingObstaclesCostTheirUnion) {
  // 500 boxes of 5 m in a square of 6 m (one SteerSuite obstacleRegion): one
  // region, under the first obstacle's id; the others' ids block nothing.
  Scenario scenario;
  for (const auto& b : scattered_boxes(500, 6.0, 4)) scenario.obstacles.push_back({b, 2.0, 0.0, {}});
  NavMesh mesh = navmesh_of(scenario);
  EXPECT_LT(mesh.triangle_count(), 1000u);  // 500 boxes entered one by one: some 500,000
  for (int i = 0; i < 500; ++i) EXPECT_TRUE(mesh.contains(i));
  EXPECT_EQ(mesh.clearance({5, 5}), 0.0);
  mesh.remove(7);
  EXPECT_EQ(mesh.clearance({5, 5}), 0.0);
  mesh.remove(0);
  EXPECT_GT(mesh.clearance({5, 5}), 0.0);
}

}  // namespace
}  // namespace footfall
