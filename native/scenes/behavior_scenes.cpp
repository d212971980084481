// Footfall — the full-body planner's scenes. Sizes are the default body's
// (clearances c1 0.185, c2 0.25, c3 0.33 m), with a few centimetres to spare.
#include "footfall/scenes/behavior_scenes.hpp"

#include <cmath>
#include <stdexcept>

#include "footfall/scenes/scenes.hpp"
#include "util/seeded_random.hpp"

namespace footfall {
namespace {

constexpr double kTall = 2.2;   // walls [m]
constexpr double kKnee = 0.55;  // below the hands [m]

// Walls beside a passage along x from x0 to x1, `half_gap` from its axis,
// out to y = ±outer.
void add_sides(Scenario& s, double x0, double x1, double half_gap, double height,
               double outer = 4.0) {
  const double length = x1 - x0, depth = outer - half_gap;
  s.obstacles.push_back(box_obstacle({0.5 * (x0 + x1), half_gap + 0.5 * depth}, {length, depth}, height));
  s.obstacles.push_back(box_obstacle({0.5 * (x0 + x1), -half_gap - 0.5 * depth}, {length, depth}, height));
}

BehaviorScene single(Scenario scenario, Vec2 start, Vec2 goal) {
  scenario.agents.push_back({"walker", start, angle_of(goal - start), {goal}});
  return {std::move(scenario), start, {goal}};
}

}  // namespace

BehaviorScene door_scene() {
  Scenario s;
  // A wall across the way at x = 0 with a 0.54 m door: wider than the
  // shoulders (0.46), narrower than the swing (0.62).
  for (Obstacle& o : wall_with_door(0.0, 0.54, 0.0, 5.0, 0.2)) {
    o.height = kTall;
    s.obstacles.push_back(o);
  }
  // Cabinets each side of the straight way, 0.25 m from it: room for the
  // legs, not for the swinging hands.
  s.obstacles.push_back(box_obstacle({-3.0, 0.55}, {0.6, 0.6}, 1.2));
  s.obstacles.push_back(box_obstacle({-1.6, -0.55}, {0.6, 0.6}, 1.2));
  return single(std::move(s), {-5.0, 0.0}, {3.0, 0.0});
}

BehaviorScene corridor_scene(double last_gap) {
  Scenario s;
  add_sides(s, 0.0, 2.0, 0.29, kTall);  // arms in
  add_sides(s, 2.0, 4.5, 0.225, kKnee);  // walk: the arms swing above
  add_sides(s, 4.5, 6.5, 0.5 * last_gap, kTall);  // side-step only
  return single(std::move(s), {-2.0, 0.0}, {8.5, 0.0});
}

BehaviorScene gap_scene(double door) {
  Scenario s;
  // A 4 x 4 m room; its east wall's door (side-stepping needs 0.37 m).
  s.obstacles.push_back(box_obstacle({-2.0, 0.0}, {0.2, 4.2}, kTall));
  s.obstacles.push_back(box_obstacle({0.0, 2.0}, {4.2, 0.2}, kTall));
  s.obstacles.push_back(box_obstacle({0.0, -2.0}, {4.2, 0.2}, kTall));
  for (Obstacle& o : wall_with_door(2.0, door, 0.0, 2.1, 0.2)) {
    o.height = kTall;
    s.obstacles.push_back(o);
  }
  return single(std::move(s), {0.0, 0.0}, {5.0, 0.0});
}

BehaviorScene open_field_scene() {
  Scenario s;
  s.obstacles.push_back(box_obstacle({20.0, 20.0}, {1.0, 1.0}, 1.0));
  return single(std::move(s), {0.0, 0.0}, {8.0, 3.0});
}

BehaviorScene random_behavior_scene(bool dense, int steps, std::uint64_t seed) {
  Scenario s;
  SeededRandom random(seed * 7919 + (dense ? 1 : 0));
  const double half = 10.0;  // the field is 20 x 20 m around the start
  const int count = dense ? 150 : 50;
  const Vec2 start{0.0, 0.0};
  while (static_cast<int>(s.obstacles.size()) < count) {
    const Vec2 centre{random.uniform(-half, half), random.uniform(-half, half)};
    const Vec2 size{random.uniform(0.3, 1.6), random.uniform(0.3, 1.6)};
    const double kind = random.uniform(0, 1);
    Obstacle o = box_obstacle(centre, size, 1.0);
    if (kind < 0.35) {
      o.height = random.uniform(0.3, 0.7);  // low boxes: the hands pass over
    } else if (kind < 0.8) {
      o.height = random.uniform(1.0, 2.2);  // cabinets, pillars
    } else {
      o.base = random.uniform(0.6, 1.1);    // a table top, a shelf, a counter
      o.height = o.base + random.uniform(0.04, 0.4);
    }
    if (distance(centre, start) < 1.2 + 0.5 * length(size)) continue;  // room to stand
    s.obstacles.push_back(o);
  }
  // Goals at the distance of `steps` normal steps, where the body can stand.
  const double reach = steps * s.character.preferred_speed * s.character.preferred_step_duration;
  const ObstacleMap map(s.obstacles, s.character.body_height);
  std::vector<Vec2> goals;
  while (goals.size() < 100) {
    const Vec2 goal = start + reach * unit(random.uniform(-kPi, kPi));
    if (map.overlaps({goal, 0.35})) continue;
    goals.push_back(goal);
  }
  s.agents.push_back({"walker", start, angle_of(goals.front() - start), {goals.front()}});
  return {std::move(s), start, std::move(goals)};
}

std::vector<std::string> behavior_scene_names() {
  return {"door",           "corridor",         "gap",           "open_field",
          "random_normal_6", "random_normal_10", "random_dense_6", "random_dense_10"};
}

BehaviorScene behavior_scene(const std::string& name) {
  if (name == "door") return door_scene();
  if (name == "corridor") return corridor_scene();
  if (name == "gap") return gap_scene();
  if (name == "open_field") return open_field_scene();
  for (bool dense : {false, true})
    for (int steps : {6, 10})
      if (name == std::string("random_") + (dense ? "dense_" : "normal_") + std::to_string(steps))
        return random_behavior_scene(dense, steps);
  std::string known;
  for (const std::string& n : behavior_scene_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("no built-in scene \"" + name + "\" (known: " + known + ")");
}

}  // namespace footfall
