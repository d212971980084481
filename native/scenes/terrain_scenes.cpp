// Footfall — built-in scenes on ground (scenes.hpp): a flight of stairs, a
// platform with a ramp beside its edge, a street under a footbridge, a hill.
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

Scenario bridge_scenario(int under, int over) {
  Scenario scenario;
  constexpr double kEnd = 12.0, kDeck = 1.0, kStairsWest = 6.0, kStairsEast = 8.0;
  const double w = kStreetHalfWidth, h = kBridgeHeight;
  const double top = w + kTreadDepth * (kBridgeRisers - 1);  // the flight's top tread's end
  scenario.ground.push_back(ground_prism(rectangle(-kEnd, -w, kEnd, w), 0.0));
  scenario.ground.push_back(ground_prism(rectangle(-kEnd, -kEnd, kEnd, -w), h));
  scenario.ground.push_back(ground_prism({{-kEnd, w}, {kStairsWest, w}, {kStairsWest, top},
                                          {kStairsEast, top}, {kStairsEast, w}, {kEnd, w},
                                          {kEnd, kEnd}, {-kEnd, kEnd}},
                                         h));
  scenario.ground.push_back(prism(rectangle(-kDeck, -w, kDeck, w), h, h - 0.2));
  for (int k = 1; k < kBridgeRisers; ++k)
    scenario.ground.push_back(ground_prism(
        rectangle(kStairsWest, w + kTreadDepth * (k - 1), kStairsEast, w + kTreadDepth * k),
        kRiser * k));
  for (int n = 0; n < under; ++n) {
    const bool east = n % 2 == 0;
    const double back = 1.0 * (n / 2), lane = east ? -1.5 : 1.5;
    scenario.agents.push_back({"under" + std::to_string(n),
                               {east ? -10.0 + back : 10.0 - back, lane},
                               east ? 0.0 : kPi,
                               {{east ? 10.0 - back : -10.0 + back, lane}}});
  }
  for (int n = 0; n < over; ++n) {
    const double back = 1.0 * (n / 2), lane = n % 2 == 0 ? -0.4 : 0.4;
    scenario.agents.push_back(
        {"over" + std::to_string(n), {lane, -6.0 - back}, 0.5 * kPi, {{lane, 9.0 - back}}});
  }
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
