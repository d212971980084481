// The crowd's neighbour grid (native/src/plan/agent_grid.hpp): every agent within
// the radius comes back, in ascending order, whatever the crowd's spread.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "plan/agent_grid.hpp"

namespace footfall {
namespace {

/// Checks around() against a pass over every agent for `queries` random
/// centres and radii.
void expect_agrees(const std::vector<Vec2>& positions, double cell, double span, int queries) {
  const AgentGrid grid(positions, cell);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-span, span), radius(0.0, 0.5 * span);
  std::vector<std::size_t> out;
  for (int q = 0; q < queries; ++q) {
    const Vec2 centre{coordinate(random), coordinate(random)};
    const double r = radius(random);
    grid.around(centre, r, out);
    ASSERT_TRUE(std::is_sorted(out.begin(), out.end()));
    ASSERT_EQ(std::adjacent_find(out.begin(), out.end()), out.end()) << "an agent twice";
    for (std::size_t j = 0; j < positions.size(); ++j) {
      if (distance(positions[j], centre) <= r) {
        ASSERT_TRUE(std::binary_search(out.begin(), out.end(), j))
            << "agent " << j << " within " << r << " m of the query left out";
      }
    }
    for (const std::size_t j : out) ASSERT_LT(j, positions.size());
  }
}

TEST(AgentGrid, ReturnsEveryAgentWithinTheRadiusInOrder) {
  std::mt19937 random(1);
  std::uniform_real_distribution<double> coordinate(-40.0, 40.0);
  std::vector<Vec2> crowd;
  for (int j = 0; j < 500; ++j) crowd.push_back({coordinate(random), coordinate(random)});
  // Agents on one spot, and on cell borders.
  for (int j = 0; j < 5; ++j) crowd.push_back({1.0, 1.0});
  for (double x = -40.0; x <= 40.0; x += 5.0) crowd.push_back({x, 0.0});
  expect_agrees(crowd, 5.0, 50.0, 2000);
}

TEST(AgentGrid, ASparseCrowdOverKilometresStaysSmall) {
  // Cells grow with the spread (about one agent a cell), and a far outlier
  // is found like any other. In cells of 5 m the first crowd would need
  // some 2,000,000 cells, and the long thin second one 800,000.
  std::vector<Vec2> outliers{{0.0, 0.0}, {1.0, 0.0}, {5000.0, -3000.0}, {-2000.0, 4000.0}};
  std::mt19937 random(2);
  std::uniform_real_distribution<double> along(-10000.0, 10000.0), across(-500.0, 500.0);
  std::vector<Vec2> strip;
  for (int j = 0; j < 300; ++j) strip.push_back({along(random), across(random)});
  for (const std::vector<Vec2>* crowd : {&outliers, &strip}) {
    EXPECT_LE(AgentGrid(*crowd, 5.0).cells(), 2 * crowd->size() + 2);
    expect_agrees(*crowd, 5.0, 10000.0, 2000);
  }
}

TEST(AgentGrid, AQueryAwayFromTheCrowdOrWithNoCrowdFindsNone) {
  std::vector<std::size_t> out{42};
  AgentGrid().around({0.0, 0.0}, 10.0, out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(AgentGrid().cells(), 0u);
  const AgentGrid one({{3.0, 4.0}}, 5.0);
  one.around({100.0, 100.0}, 10.0, out);
  EXPECT_TRUE(out.empty());
  one.around({0.0, 0.0}, 5.0, out);
  EXPECT_EQ(out, std::vector<std::size_t>{0});
}

}  // namespace
}  // namespace footfall
