// Footfall — the crowd workloads of the footstep paper's table 1, from seeded
// generators: an egress through a door, a two-way hall, a crowd among boxes.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "footfall/fullbody/behavioral_planner.hpp"
#include "footfall/planner/validity_checker.hpp"
#include "footfall/scenes/scenes.hpp"
#include "util/seeded_random.hpp"

namespace footfall {
namespace {

/// Agents start, and stand at their goals, at least this far apart. [m]
constexpr double kSpacing = 0.9;
/// Draws per agent before a generator gives up.
constexpr int kMaxAttempts = 100000;

/// Where standing characters fit: clear of the obstacles, free to set off,
/// and away from the points kept before.
class Room {
 public:
  explicit Room(const Scenario& scenario)
      : character_(scenario.character),
        map_(scenario.obstacles),
        validity_(scenario.character, scenario.planner, map_) {}

  bool fits(Vec2 p, double facing) const {
    // Free to set off too: a character wedged between boxes could never step.
    const FootstepState standing = standing_state(p, facing, character_);
    if (validity_.collides(standing) || !validity_.free_to_set_off(standing)) return false;
    for (const Vec2 q : kept_)
      if (distance(p, q) < kSpacing) return false;
    return true;
  }
  void keep(Vec2 p) { kept_.push_back(p); }

 private:
  CharacterParams character_;
  ObstacleMap map_;
  ValidityChecker validity_;
  std::vector<Vec2> kept_;
};

/// Adds `count` agents whose start and goal `draw` returns, drawing again
/// while the start (facing its goal) does not fit among the starts, or the
/// goal among the goals (only when `goals_apart`: agents that leave may
/// share their exit), or, given `ways`, they find no way from the start to
/// the goal that the body passes, side-stepping where it must (a goal in a
/// pocket that boxes seal, or that only gaps narrower than the body lead to,
/// is no workload: nobody could reach it). Every agent leaves at its goal.
template <typename Draw>
void add_agents(Scenario& scenario, int count, bool goals_apart, Draw draw,
                BehavioralPlanner* ways = nullptr) {
  Room starts(scenario), goals(scenario);
  const auto reachable = [&](Vec2 start, Vec2 goal) {
    return ways == nullptr || ways->plan(start, goal).status == BehaviorPathStatus::kFound;
  };
  for (int i = 0; i < count; ++i) {
    for (int attempt = 0;; ++attempt) {
      if (attempt == kMaxAttempts)
        throw std::invalid_argument("no room for agent " + std::to_string(i) +
                                    ": the generator's region is too small for the crowd");
      const auto [start, goal] = draw();
      const double facing = angle_of(goal - start);
      if (!starts.fits(start, facing) || (goals_apart && !goals.fits(goal, facing)) ||
          !reachable(start, goal))
        continue;
      starts.keep(start);
      goals.keep(goal);
      scenario.agents.push_back({"agent" + std::to_string(i), start, facing, {goal}, true});
      break;
    }
  }
}

}  // namespace

Scenario egress_scenario(int agents, std::uint64_t seed) {
  Scenario scenario;
  // A 10 x 10 m room; the door, 1.2 m wide, in the middle of its east wall.
  scenario.obstacles = wall_with_door(5.0, 1.2, 0.0, 5.2);
  scenario.obstacles.push_back(box_obstacle({-5.0, 0.0}, {0.2, 10.4}, 2.5));
  scenario.obstacles.push_back(box_obstacle({0.0, 5.1}, {10.0, 0.2}, 2.5));
  scenario.obstacles.push_back(box_obstacle({0.0, -5.1}, {10.0, 0.2}, 2.5));
  SeededRandom random(seed);
  add_agents(scenario, agents, false, [&] {
    return std::pair{Vec2{random.uniform(-4.4, 4.0), random.uniform(-4.4, 4.4)},
                     Vec2{12.0, random.uniform(-3.0, 3.0)}};
  });
  return scenario;
}

Scenario two_way_hall_scenario(int agents, std::uint64_t seed, double width) {
  if (!(width >= 2.0 && width <= 1000.0))
    throw std::invalid_argument("width: the hall must be 2-1000 m wide");
  Scenario scenario;
  // A hall 80 m long, open at both ends; half the crowd starts in each half
  // (0.4 m clear of the walls) and leaves by the far end.
  const double half = 0.5 * width;
  scenario.obstacles.push_back(box_obstacle({0.0, half + 0.1}, {80.0, 0.2}, 2.5));
  scenario.obstacles.push_back(box_obstacle({0.0, -half - 0.1}, {80.0, 0.2}, 2.5));
  SeededRandom random(seed);
  add_agents(scenario, agents, false, [&] {
    const double end = scenario.agents.size() % 2 == 0 ? -1.0 : 1.0;
    return std::pair{Vec2{end * random.uniform(4.0, 39.5), random.uniform(0.4 - half, half - 0.4)},
                     Vec2{-end * 41.0, random.uniform(0.5 - half, half - 0.5)}};
  });
  return scenario;
}

Scenario box_field_crowd_scenario(int agents, int boxes, std::uint64_t seed) {
  Scenario scenario;
  scenario.obstacles = box_field(boxes, 80.0, seed);
  SeededRandom random(seed + 1);
  // Each walks 10-20 m in a random direction, within the field (the mesh
  // spans the boxes and beyond).
  NavMesh mesh = navmesh_of(scenario);
  const CollisionScene scene(scenario.obstacles);
  const BodyModel body(scenario.character);
  BehavioralPlanner ways(mesh, scene, body, scenario.planner);
  add_agents(
      scenario, agents, true,
      [&] {
        const Vec2 start{random.uniform(-38.0, 38.0), random.uniform(-38.0, 38.0)};
        Vec2 goal;
        do goal = start + random.uniform(10.0, 20.0) * unit(random.uniform(-kPi, kPi));
        while (std::abs(goal.x) > 38.0 || std::abs(goal.y) > 38.0);
        return std::pair{start, goal};
      },
      &ways);
  return scenario;
}

namespace {

/// The grid's period and how many blocks span a city of side `size`. [m]
constexpr double kCityPeriod = kCityBlock + kCityStreet;
static_assert(kCityPeriod == 10.0, "the size error names the period");
int blocks_across(double size) {
  const double blocks = size / kCityPeriod;
  if (!(blocks >= 1.0 && blocks <= 1000.0) || std::abs(blocks - std::round(blocks)) > 1e-9)
    throw std::invalid_argument("size: a city's side is a multiple of 10 m (a block and a "
                                "street) from 10 to 10000 m");
  return static_cast<int>(std::round(blocks));
}

/// Whether p (within the city) is on a street, `margin` clear of every block.
bool on_street(Vec2 p, double size, double margin) {
  const auto in_block = [&](double c) {
    const double offset = std::fmod(c + 0.5 * size, kCityPeriod);  // from the block's street edge
    const double lo = 0.5 * kCityStreet - margin, hi = 0.5 * kCityStreet + kCityBlock + margin;
    return offset > lo && offset < hi;
  };
  return !(in_block(p.x) && in_block(p.y));
}

}  // namespace

std::vector<Obstacle> city_blocks(double size) {
  const int n = blocks_across(size);
  std::vector<Obstacle> blocks;
  blocks.reserve(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec2 centre{-0.5 * size + (i + 0.5) * kCityPeriod,
                        -0.5 * size + (j + 0.5) * kCityPeriod};
      blocks.push_back(box_obstacle(centre, {kCityBlock, kCityBlock}, 3.0));
    }
  return blocks;
}

double city_street_area(double size) {
  const double n = blocks_across(size);
  return size * size - n * n * kCityBlock * kCityBlock;
}

Scenario city_scenario(int agents, double size, std::uint64_t seed) {
  Scenario scenario;
  scenario.obstacles = city_blocks(size);
  // Far enough from the blocks that a standing body fits; the generator's
  // Room checks it exactly.
  constexpr double kKerb = 0.35;  // [m]
  constexpr double kLeastTrip = 20.0;  // [m]
  if (size * std::sqrt(2.0) < kLeastTrip + 2.0)
    throw std::invalid_argument("size: a city under 20 m across has no trips of 20 m");
  SeededRandom random(seed);
  const auto street_point = [&] {
    for (;;) {
      const Vec2 p{random.uniform(-0.5 * size, 0.5 * size), random.uniform(-0.5 * size, 0.5 * size)};
      if (on_street(p, size, kKerb)) return p;
    }
  };
  add_agents(scenario, agents, true, [&] {
    const Vec2 start = street_point();
    Vec2 goal;
    do goal = street_point();
    while (distance(start, goal) < kLeastTrip);
    return std::pair{start, goal};
  });
  return scenario;
}

}  // namespace footfall
