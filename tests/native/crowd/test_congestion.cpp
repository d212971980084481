// Crowded streets: ways round a crowd, and the crowd taking them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

/// Each cell's length of way from `from`, by Dijkstra's search over the
/// grid's steps: the oracle the landmarks' bound is held to. [m]
std::vector<double> lengths_across(const CrowdGrid& grid, long from) {
  std::vector<double> length(grid.cells(), std::numeric_limits<double>::infinity());
  std::vector<long> open{from};
  length[static_cast<std::size_t>(from)] = 0.0;
  // Bellman-Ford by rounds: slow, plain, and no priority queue to get wrong.
  for (bool changed = true; changed;) {
    changed = false;
    for (long cell = 0; cell < static_cast<long>(grid.cells()); ++cell) {
      const double here = length[static_cast<std::size_t>(cell)];
      if (!std::isfinite(here)) continue;
      grid.for_each_step(cell, [&](long next, double step) {
        if (here + step < length[static_cast<std::size_t>(next)] - 1e-12) {
          length[static_cast<std::size_t>(next)] = here + step;
          changed = true;
        }
      });
    }
  }
  return length;
}

TEST(CrowdGrid, LeastLengthIsNeverMoreThanTheWayAndSeesRoundBlocks) {
  const NavMesh mesh = navmesh_of(city_scenario(1, 30.0, 1));
  const CrowdGrid grid(mesh, 0.5);
  double beyond_line = 1.0;  // the most the bound exceeds the straight line by
  for (const Vec2 from : {Vec2{-14.0, -14.0}, Vec2{-5.0, 0.0}, Vec2{5.0, 5.0}}) {
    const long start = grid.cell_of(from);
    ASSERT_TRUE(grid.walkable(start));
    const std::vector<double> way = lengths_across(grid, start);
    for (long cell = 0; cell < static_cast<long>(grid.cells()); ++cell) {
      if (!std::isfinite(way[static_cast<std::size_t>(cell)]) || cell == start) continue;
      const double least = grid.least_length(start, cell);
      const double line = distance(grid.centre(start), grid.centre(cell));
      EXPECT_LE(least, way[static_cast<std::size_t>(cell)] + 1e-9) << from.x << " " << cell;
      EXPECT_GE(least, line - 1e-9);
      beyond_line = std::max(beyond_line, least / line);
    }
  }
  // Across a block the way goes round it: the landmarks know it is longer
  // than the line through the block.
  EXPECT_GT(beyond_line, 1.25);
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
