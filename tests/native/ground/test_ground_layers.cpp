// Ground layers: levels above one another split into layers with one level
// over any point, each walled on its own, joined by portals; and ways found
// over them (LayeredNavigation).
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "footfall/crowd/navigation.hpp"
#include "footfall/ground/ground.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall {
namespace {

constexpr double kStep = 0.25, kHeadroom = 1.75;

/// The layer of the standable level over `p` nearest `z`.
int layer_near(const GroundLayers& layers, const Ground& ground, Vec2 p, double z) {
  const std::optional<GroundPoint> level = ground.level_near(p, z, 0.05);
  return level ? layers.layer_of(*level) : -1;
}

/// True if one of `walls` passes within `reach` of `p`.
bool wall_near(const std::vector<GroundWall>& walls, Vec2 p, double reach) {
  return std::any_of(walls.begin(), walls.end(), [&](const GroundWall& wall) {
    return distance_to_segment(p, wall.a, wall.b) <= reach;
  });
}

TEST(GroundLayers, GroundWithOneLevelEverywhereIsOneLayerWithItsWalls) {
  const Ground ground(stairs_scenario(0, 0).ground);
  const GroundLayers layers = ground.layers(kStep, kHeadroom, 0.0);
  ASSERT_EQ(layers.count(), 1);
  EXPECT_TRUE(layers.portals().empty());
  const std::vector<GroundWall> walls = ground.walls(kStep, kHeadroom, 0.0);
  ASSERT_EQ(layers.walls(0).size(), walls.size());
  for (std::size_t i = 0; i < walls.size(); ++i) {
    EXPECT_EQ(layers.walls(0)[i].a, walls[i].a);
    EXPECT_EQ(layers.walls(0)[i].b, walls[i].b);
  }
}

TEST(GroundLayers, ABridgesDeckIsALayerOfItsOwnJoinedToTheBanks) {
  const Ground ground(bridge_scenario(0, 0).ground);
  const GroundLayers layers = ground.layers(kStep, kHeadroom, 0.0);
  ASSERT_EQ(layers.count(), 2);
  const int street = layer_near(layers, ground, {0, 0}, 0.0);
  const int deck = layer_near(layers, ground, {0, 0}, kBridgeHeight);
  EXPECT_NE(street, deck);
  // The banks, the stairs and the street are one layer, joined by steps.
  EXPECT_EQ(layer_near(layers, ground, {0, -8}, kBridgeHeight), street);
  EXPECT_EQ(layer_near(layers, ground, {7, 6}, 0.17 * 7), street);
  EXPECT_EQ(layers.level_on({0, 0}, deck)->z, kBridgeHeight);
  EXPECT_EQ(layers.level_on({0, 0}, street)->z, 0.0);
  EXPECT_FALSE(layers.level_on({5, 0}, deck));
  // The street runs under the deck unwalled; the deck is walled along its sides.
  EXPECT_FALSE(wall_near(layers.walls(street), {1.0, 0}, 0.1));
  EXPECT_FALSE(wall_near(layers.walls(street), {-1.0, 2}, 0.1));
  EXPECT_TRUE(wall_near(layers.walls(deck), {1.0, 0}, 0.05));
  EXPECT_TRUE(wall_near(layers.walls(deck), {-1.0, 2}, 0.05));
  // The banks' sides wall the street, where the deck meets them too.
  EXPECT_TRUE(wall_near(layers.walls(street), {0.5, kStreetHalfWidth}, 0.05));
  // Portals at both ends of the deck, each its width, and nowhere else.
  double length = 0;
  for (const GroundPortal& portal : layers.portals()) {
    EXPECT_NEAR(std::fabs(portal.a.y), kStreetHalfWidth, 0.03);
    EXPECT_NEAR(std::fabs(portal.b.y), kStreetHalfWidth, 0.03);
    EXPECT_TRUE((portal.from == street && portal.to == deck) ||
                (portal.from == deck && portal.to == street));
    length += distance(portal.a, portal.b);
  }
  EXPECT_NEAR(length, 2 * 2 * 2.0, 0.2);  // each end found from both of its faces
}

TEST(GroundLayers, PierUnderTheDeckBlocksTheStreetOnly) {
  Scenario scenario = bridge_scenario(0, 0);
  scenario.obstacles.push_back(prism({{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}},
                                     kBridgeHeight - 0.2, 0.0));
  const Ground ground(scenario.ground);
  const GroundLayers layers = ground.layers(kStep, kHeadroom, 0.0);
  const int street = layer_near(layers, ground, {0, 0}, 0.0);
  const int deck = 1 - street;
  EXPECT_EQ(cut_heights(layers, scenario.obstacles, street)[0], kHeadroom);
  EXPECT_EQ(cut_heights(layers, scenario.obstacles, deck)[0],
            -std::numeric_limits<double>::infinity());
}

TEST(LayeredNavigation, WaysCrossTheDeckAndPassUnderIt) {
  const LayeredNavigation navigation(bridge_scenario(0, 0));
  ASSERT_EQ(navigation.layers(), 2);
  const int deck = navigation.layer_at({0, 0}, kBridgeHeight, "to");
  const int street = navigation.layer_at({0, 0}, 0.0, "to");
  const int bank = navigation.layer_at({0, -8}, std::nullopt, "from");
  // Over the deck from bank to bank: straight, at the deck's height all the way.
  const PathResult over = navigation.find_path({{0, -8}, {0, 8}, 0.25}, bank, bank);
  ASSERT_EQ(over.status, PathStatus::kFound);
  EXPECT_NEAR(over.length, 16.0, 0.05);
  ASSERT_EQ(over.heights.size(), over.points.size());
  for (const double z : over.heights) EXPECT_DOUBLE_EQ(z, kBridgeHeight);
  // Along the street under it: straight at 0.
  const PathResult under = navigation.find_path({{-10, 0}, {10, 0}, 0.25}, street, street);
  ASSERT_EQ(under.status, PathStatus::kFound);
  EXPECT_NEAR(under.length, 20.0, 1e-9);
  for (const double z : under.heights) EXPECT_EQ(z, 0.0);
  // From the deck down to the street below it: off the deck, along the
  // north bank, down the flight (x 6-8) and back along the street.
  const PathResult down = navigation.find_path({{0, 0}, {0, 0.5}, 0.25}, deck, street);
  ASSERT_EQ(down.status, PathStatus::kFound);
  EXPECT_GT(down.length, 2 * (7.0 + kStreetHalfWidth));
  EXPECT_EQ(down.heights.front(), kBridgeHeight);
  EXPECT_EQ(down.heights.back(), 0.0);
  const auto on_flight = std::find_if(down.points.begin(), down.points.end(), [](Vec2 p) {
    return p.x > 6.0 && p.x < 8.0 && p.y > kStreetHalfWidth;
  });
  EXPECT_NE(on_flight, down.points.end());
}

TEST(LayeredNavigation, APointBetweenLevelsNeedsItsHeight) {
  const LayeredNavigation navigation(bridge_scenario(0, 0));
  try {
    navigation.layer_at({0, 0}, std::nullopt, "--from");
    FAIL() << "no refusal";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "--from: 2 levels at (0.00, 0.00), at 0.00 and 2.89 m: give its height (X,Y,Z)");
  }
  EXPECT_THROW(navigation.layer_at({0, 0}, 1.4, "--to"), std::invalid_argument);
  EXPECT_THROW(navigation.layer_at({30, 0}, std::nullopt, "--to"), std::invalid_argument);
}

}  // namespace
}  // namespace footfall
