// Crowded streets: ways round a crowd, and the crowd taking them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "crowd/congestion.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall::crowd {
namespace {

/// Two streets 3 m wide from x = -10 to 10, either side of a block 2 m deep:
/// the south one (y in [-4, -1]) and the north one (y in [1, 4]), the only
/// ways between two walled squares 10 m wide at either end. The south street
/// is the straight way from (-14, -2.5) to (14, -2.5).
std::vector<Obstacle> two_streets() {
  return {box_obstacle({0.0, 0.0}, {20.0, 2.0}, 3.0),   box_obstacle({0.0, 5.0}, {20.0, 2.0}, 3.0),
          box_obstacle({0.0, -5.0}, {20.0, 2.0}, 3.0),  box_obstacle({0.0, 6.5}, {42.0, 1.0}, 3.0),
          box_obstacle({0.0, -6.5}, {42.0, 1.0}, 3.0),  box_obstacle({-20.5, 0.0}, {1.0, 12.0}, 3.0),
          box_obstacle({20.5, 0.0}, {1.0, 12.0}, 3.0)};
}

/// Whether the way passes the north street (its points by the street's ends
/// and beyond north of the middle block).
bool goes_north(const std::vector<Vec2>& points) {
  return std::any_of(points.begin(), points.end(),
                     [](Vec2 p) { return std::abs(p.x) < 11.0 && p.y > 0.5; });
}

/// People standing 0.8 m apart filling the south street from x = -8 to 8.
std::vector<Vec2> south_street_full() {
  std::vector<Vec2> people;
  for (double x = -8.0; x <= 8.0; x += 0.8)
    for (const double y : {-3.3, -2.5, -1.7}) people.push_back({x, y});
  return people;
}

TEST(CrowdDensity, AFullStreetSendsTheWayByTheNextOne) {
  Scenario scenario;
  scenario.obstacles = two_streets();
  scenario.agents.push_back({"a", {-14.0, -2.5}, 0.0, {{14.0, -2.5}}});
  const NavMesh mesh = navmesh_of(scenario);
  const CrowdGrid grid(mesh, 0.5);
  const Way straight{{{-14.0, -2.5}, {14.0, -2.5}}, 28.0};

  const std::vector<Vec2> people = south_street_full();
  const CrowdDensity full(grid, people, std::vector<char>(people.size(), 1));
  EXPECT_GT(full.density(grid.cell_of({0.0, -2.5})), 1.0);
  const std::optional<Way> round = full.way_round(straight, mesh, 0.5);
  ASSERT_TRUE(round.has_value());
  EXPECT_TRUE(goes_north(round->points));
  EXPECT_EQ(round->points.front(), straight.points.front());
  EXPECT_EQ(round->points.back(), straight.points.back());
  for (std::size_t k = 1; k < round->points.size(); ++k)
    EXPECT_GT(mesh.clearance_between(round->points[k - 1], round->points[k]), 0.0)
        << k << ": " << round->points[k - 1].x << "," << round->points[k - 1].y << " to "
        << round->points[k].x << "," << round->points[k].y;

  // Absent, the same people are no crowd; nor are a few in the street.
  const CrowdDensity gone(grid, people, std::vector<char>(people.size(), 0));
  EXPECT_FALSE(gone.way_round(straight, mesh, 0.5).has_value());
  const std::vector<Vec2> few{{-3.0, -2.5}, {3.0, -2.0}};
  EXPECT_FALSE(CrowdDensity(grid, few, {1, 1}).way_round(straight, mesh, 0.5).has_value());
}

TEST(CrowdDensity, AStreetManyAreHeadingForIsCrowdedBeforeTheyArrive) {
  // Forty people in the west square, none yet in the streets, each with its
  // way east through the south street: the street counts as crowded, and a
  // way through it goes by the north one. Without their ways it is empty.
  Scenario scenario;
  scenario.obstacles = two_streets();
  scenario.agents.push_back({"a", {-14.0, -2.5}, 0.0, {{14.0, -2.5}}});
  const NavMesh mesh = navmesh_of(scenario);
  const CrowdGrid grid(mesh, 0.5);
  std::vector<Vec2> people;
  std::vector<Way> heading;
  for (int k = 0; k < 40; ++k) {
    const Vec2 at{-12.0 - 0.2 * (k % 10), -3.3 + 0.4 * (k / 10)};
    people.push_back(at);
    heading.push_back({{at, {-10.0, -2.5}, {14.0, -2.5}}, 0.0});
    heading.back().length = polyline_length(heading.back().points);
  }
  std::vector<const Way*> ways;
  for (const Way& way : heading) ways.push_back(&way);
  const std::vector<char> present(people.size(), 1);
  const Way straight{{{-14.0, -2.5}, {14.0, -2.5}}, 28.0};

  const CrowdDensity going(grid, people, present, ways);
  EXPECT_GT(going.density(grid.cell_of({-3.0, -2.5})), kFreeDensity);
  const std::optional<Way> round = going.way_round(straight, mesh, 0.5);
  ASSERT_TRUE(round.has_value());
  EXPECT_TRUE(goes_north(round->points));

  const CrowdDensity standing(grid, people, present);
  EXPECT_EQ(standing.density(grid.cell_of({-3.0, -2.5})), 0.0);
}

TEST(CrowdDensity, AWayRoundMustGainOnTheWayThrough) {
  // One street only, full: there is no way round, and the way stays.
  Scenario scenario;
  scenario.obstacles = two_streets();
  scenario.obstacles.push_back(box_obstacle({0.0, 2.5}, {2.0, 3.0}, 3.0));  // the north one shut
  scenario.agents.push_back({"a", {-14.0, -2.5}, 0.0, {{14.0, -2.5}}});
  const NavMesh mesh = navmesh_of(scenario);
  const CrowdGrid grid(mesh, 0.5);
  const std::vector<Vec2> people = south_street_full();
  const CrowdDensity full(grid, people, std::vector<char>(people.size(), 1));
  EXPECT_FALSE(full.way_round({{{-14.0, -2.5}, {14.0, -2.5}}, 28.0}, mesh, 0.5).has_value());
}

TEST(CrowdDensity, AWayRoundRejoinsTheWayWithinItsReach) {
  // A city 100 m wide: its street along y = 0 is full from x = -40 to 30,
  // and the way runs 90 m along it. The way round takes the next street and
  // comes back to the way kRoundReach along it; from there on it is the way.
  Scenario scenario;
  scenario.obstacles = city_blocks(100.0);
  scenario.agents.push_back({"a", {-45.0, 0.0}, 0.0, {{45.0, 0.0}}});
  const NavMesh mesh = navmesh_of(scenario);
  const CrowdGrid grid(mesh, 0.5);
  std::vector<Vec2> people;
  for (double x = -40.0; x <= 30.0; x += 0.8)
    for (const double y : {-1.2, -0.4, 0.4, 1.2}) people.push_back({x, y});
  const CrowdDensity full(grid, people, std::vector<char>(people.size(), 1));
  const Way along{{{-45.0, 0.0}, {45.0, 0.0}}, 90.0};
  const std::optional<Way> round = full.way_round(along, mesh, 0.5);
  ASSERT_TRUE(round.has_value());
  EXPECT_TRUE(std::any_of(round->points.begin(), round->points.end(),
                          [](Vec2 p) { return std::abs(p.y) > 5.0; }));
  const Vec2 rejoin{-45.0 + kRoundReach, 0.0};
  EXPECT_NE(std::find(round->points.begin(), round->points.end(), rejoin), round->points.end());
  for (const Vec2 p : round->points) {
    if (p.x > rejoin.x) {
      EXPECT_EQ(p.y, 0.0) << p.x;
    }
  }
  EXPECT_EQ(round->points.back(), along.points.back());
  EXPECT_NEAR(round->length, polyline_length(round->points), 1e-9);
}

TEST(CrowdGrid, IsCoarserOnVastGround) {
  for (const Vec2 corner : {Vec2{5000.0, 5000.0}, Vec2{1e9, 3.0}}) {
    const NavMesh mesh(-1.0 * corner, corner);
    const CrowdGrid grid(mesh, 0.5);
    EXPECT_LE(static_cast<double>(grid.cells()), 1.01 * kMostCells) << corner.x;
    EXPECT_GT(grid.cell(), kCrowdCell) << corner.x;
  }
}

TEST(CrowdedStreets, AStreetThatFillsSendsLaterAgentsByTheNextOne) {
  // People stand in the south street (a market, a queue); four cross from
  // the west square to the east one, which the south street leads to
  // straight: they take the north street, and lose no time at the crowd.
  Scenario scenario;
  scenario.obstacles = two_streets();
  int n = 0;
  for (const Vec2 p : south_street_full())
    scenario.agents.push_back({"standing" + std::to_string(n++), p, 0.0, {p}});
  for (int k = 0; k < 4; ++k) {
    const double y = -3.5 + 1.0 * k;
    AgentSpec crossing{"crossing" + std::to_string(k), {-17.0, y}, 0.0, {{17.0, y}}};
    crossing.leave_at_goal = true;
    scenario.agents.push_back(crossing);
  }
  const Plan plan = plan_scenario(scenario);
  EXPECT_EQ(measure_plan(plan).overlaps, 0);
  for (const AgentPlan& agent : plan.agents) {
    if (agent.name.rfind("crossing", 0) != 0) continue;
    EXPECT_EQ(agent.status, AgentStatus::kReached) << agent.name;
    std::vector<Vec2> path;
    for (const Footstep& step : agent.footsteps) path.push_back(step.com_end);
    EXPECT_TRUE(goes_north(path)) << agent.name;
    // By the north street it is some 36 m; alone, 28 s.
    EXPECT_LT(agent.end_time(), 45.0) << agent.name;
  }
}

}  // namespace
}  // namespace footfall::crowd
