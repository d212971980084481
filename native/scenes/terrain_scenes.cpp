// Footfall — built-in scenes on ground (scenes.hpp): a flight of stairs, a
// platform with a ramp beside its edge, a hill.
#include <cmath>

#include "footfall/terrain/ground.hpp"
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
  scenario.ground.push_back(
      ground_prism(rectangle(top, -kStairsWidth / 2, top + 8, kStairsWidth / 2), kRiser * kStairsTreads));
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

}  // namespace footfall
