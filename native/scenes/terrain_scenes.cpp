// Footfall — built-in scenes on ground (scenes.hpp): a flight of stairs, a
// platform with a ramp beside its edge, a hill.
#include <cmath>

#include "footfall/ground/ground.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall {
namespace {

std::vector<Vec2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace

Scenario stairs_scenario(int up, int down) {
  Scenario scenario;
  scenario.ground.push_back(ground_prism(rectangle(-8, -kStairsWidth / 2, 0, kStairsWidth / 2), 0));
  for (int k = 0; k < kStairsTreads; ++k)
    scenario.ground.push_back(ground_prism(
        rectangle(kTreadDepth * k, -kStairsWidth / 2, kTreadDepth * (k + 1), kStairsWidth / 2),
        kRiser * (k + 1)));
  const double top = kTreadDepth * kStairsTreads;
  scenario.ground.push_back(ground_prism(
      rectangle(top, -kStairsWidth / 2, top + 8, kStairsWidth / 2), kRiser * kStairsTreads));
  // Each way on its own right half of the flight, two abreast 0.7 m apart,
  // rows 1 m apart.
  for (int i = 0; i < up + down; ++i) {
    const bool going_up = i < up;
    const int n = going_up ? i : i - up;
    const double lane = 0.4 + 0.7 * (n % 2);  // from the middle of the flight
    const double back = 1.0 * (n / 2);
    const Vec2 start = going_up ? Vec2{-2.0 - back, -lane} : Vec2{top + 2.0 + back, lane};
    // The first rows go furthest: none has to pass one standing at its goal.
    const Vec2 goal = going_up ? Vec2{top + 6.0 - back, -lane} : Vec2{-6.0 + back, lane};
    scenario.agents.push_back({(going_up ? "up" : "down") + std::to_string(n), start,
                               going_up ? 0.0 : kPi, {goal}});
  }
  return scenario;
}

Scenario ramp_scenario() {
  Scenario scenario;
  scenario.ground.push_back(ground_prism(rectangle(-6, -4, 4, 4), 0.0));
  scenario.ground.push_back(ground_prism(rectangle(4, -4, 10, 4), kPlatformHeight));
  GroundSurface ramp;  // x 0-4 up to the platform, y 2-4
  ramp.mesh.vertices = {{0, 2, 0}, {4, 2, kPlatformHeight}, {4, 4, kPlatformHeight}, {0, 4, 0}};
  ramp.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  scenario.ground.push_back(ramp);
  scenario.agents.push_back({"walker", {-3, -2}, 0.0, {{7, -2}}});
  return scenario;
}

GroundSurface hill_field(int cells, double cell, double height, double spread) {
  GroundSurface field;
  const double half = 0.5 * cells * cell;
  for (int i = 0; i <= cells; ++i)
    for (int j = 0; j <= cells; ++j) {
      const double x = i * cell - half, y = j * cell - half;
      const double z = height * std::exp(-(x * x + y * y) / (2 * spread * spread));
      field.mesh.vertices.push_back({x, y, z});
    }
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      const int a = i * (cells + 1) + j, b = a + cells + 1;
      field.mesh.triangles.push_back({a, b, b + 1});  // anticlockwise from above
      field.mesh.triangles.push_back({a, b + 1, a + 1});
    }
  return field;
}

Scenario hill_scenario() {
  Scenario scenario;
  scenario.ground.push_back(hill_field(100, 0.3, 3.0, 5.0));
  scenario.agents.push_back({"over", {-12, -1}, 0.0, {{12, 1}}});
  scenario.agents.push_back({"across", {-12, 3}, 0.0, {{12, -3}}});
  return scenario;
}

}  // namespace footfall
