#include "footfall/scenes/scenes.hpp"

#include <tuple>

#include "footfall/ground/ground.hpp"
#include "util/seeded_random.hpp"

namespace footfall {

Obstacle box_obstacle(Vec2 center, Vec2 size, double height) {
  const Vec2 h = 0.5 * size;
  return prism({{center.x - h.x, center.y - h.y},
                {center.x + h.x, center.y - h.y},
                {center.x + h.x, center.y + h.y},
                {center.x - h.x, center.y + h.y}},
               height);
}

std::vector<Obstacle> wall_with_door(double x, double door_width, double door_center,
                                     double half_length, double thickness) {
  const double low = door_center - 0.5 * door_width;
  const double high = door_center + 0.5 * door_width;
  return {box_obstacle({x, 0.5 * (-half_length + low)}, {thickness, low + half_length}, 2.5),
          box_obstacle({x, 0.5 * (high + half_length)}, {thickness, half_length - high}, 2.5)};
}

Scenario demo_scenario() {
  Scenario scenario;
  // A floor, and three steps up to a landing before the door and the room
  // behind it, half a storey up, the length of the wall.
  constexpr double kTread = 0.3, kFirstStep = 3.2;
  constexpr double kSteps[] = {0.17, 0.34, 0.51}, kRoom = kSteps[2];  // as written: short in the plan
  scenario.ground.push_back(ground_prism({{-14, -25}, {25, -25}, {25, 12}, {-14, 12}}, 0.0));
  for (int k = 0; k < 3; ++k) {
    const double x0 = kFirstStep + kTread * k, x1 = k < 2 ? x0 + kTread : 16.0;
    scenario.ground.push_back(ground_prism({{x0, -6}, {x1, -6}, {x1, 6}, {x0, 6}}, kSteps[k]));
  }
  scenario.obstacles = wall_with_door(5.0, 1.6);
  // The room behind the door, cluttered: boxes standing on its floor.
  for (const auto& [centre, size, height] : {std::tuple{Vec2{8.0, 0.0}, Vec2{1.0, 1.0}, 0.8},
                                             {Vec2{9.8, -2.2}, Vec2{0.8, 0.8}, 0.75},
                                             {Vec2{10.2, 2.6}, Vec2{1.4, 0.6}, 0.9},
                                             {Vec2{13.0, -0.6}, Vec2{0.6, 1.6}, 1.0}}) {
    Obstacle box = box_obstacle(centre, size, kRoom + height);
    box.base = kRoom;
    scenario.obstacles.push_back(box);
  }
  // Below the door the wall goes on as a block 2 m deep with two narrow gaps
  // for the project's rig (its body's clearances 0.25, 0.31 and 0.41 m):
  // 0.70 m, walked with the arms held in, and 0.56 m, side-stepped.
  const double gap_ends[] = {-6.0, -7.5 + 0.35, -7.5 - 0.35, -10.0 + 0.28, -10.0 - 0.28, -12.5};
  for (int piece = 0; piece < 3; ++piece) {
    const double top = gap_ends[2 * piece], bottom = gap_ends[2 * piece + 1];
    scenario.obstacles.push_back(box_obstacle({5.0, 0.5 * (top + bottom)}, {2.0, top - bottom}, 1.6));
  }
  // A crowd before it, each with its own place in the room, and one walker
  // for each gap.
  scenario.agents.push_back({"walker", {0.0, 0.5}, 0.0, {{11.0, 0.3}}});
  scenario.agents.push_back({"ada", {0.0, -1.0}, 0.0, {{14.5, -2.5}}});
  scenario.agents.push_back({"ben", {-1.5, 1.2}, 0.0, {{13.5, 2.0}}});
  scenario.agents.push_back({"cleo", {-1.5, -0.4}, 0.0, {{11.5, -2.0}}});
  scenario.agents.push_back({"dan", {-4.5, 0.3}, 0.0, {{8.5, 2.0}}});
  scenario.agents.push_back({"eve", {-3.0, 1.8}, 0.0, {{7.0, -2.5}}});
  scenario.agents.push_back({"fay", {1.0, -7.5}, 0.0, {{9.0, -7.5}}});
  scenario.agents.push_back({"gus", {1.0, -10.0}, 0.0, {{9.0, -10.0}}});
  return scenario;
}

std::vector<Obstacle> box_field(int count, double size, std::uint64_t seed) {
  SeededRandom random(seed);
  std::vector<Obstacle> boxes;
  boxes.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const Vec2 center{random.uniform(-0.5 * size, 0.5 * size),
                      random.uniform(-0.5 * size, 0.5 * size)};
    const Vec2 extent{random.uniform(0.5, 1.5), random.uniform(0.5, 1.5)};
    boxes.push_back(box_obstacle(center, extent, 1.0));
  }
  return boxes;
}

}  // namespace footfall
