#include "footfall/plan/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "plan/agent_grid.hpp"

namespace footfall {
namespace {

// Depth by which the circle reaches into obstacle `index` (<= 0: it does not).
double penetration(const ObstacleMap& map, int index, const Circle& circle) {
  const std::vector<Vec2>& polygon = map.obstacles()[index].polygon;
  double nearest = INFINITY;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    nearest = std::min(nearest, distance_to_segment(circle.center, polygon[j], polygon[i]));
  }
  return map.contains(index, circle.center) ? circle.radius + nearest : circle.radius - nearest;
}

bool circles_overlap(const Circle& a, const Circle& b) {
  return distance(a.center, b.center) < a.radius + b.radius;
}

// No two circles of agents whose COMs are this far apart can touch: each circle
// lies within a stride plus a foot of its COM. [m]
constexpr double kNear = 3.0;

// The highest sampling rate: beyond it the samples say nothing new and cost
// time in proportion. [Hz]
constexpr double kMaxRate = 1000.0;

}  // namespace

PlanMetrics measure_plan(const Plan& plan, double rate) {
  if (!(rate > 0.0 && rate <= kMaxRate))
    throw std::invalid_argument("rate: must be in (0, " + std::to_string(std::lround(kMaxRate)) +
                                "] Hz, got " + std::to_string(rate));
  const ObstacleMap map(plan.obstacles);
  const size_t n = plan.agents.size();
  double end = 0.0;
  for (const AgentPlan& agent : plan.agents) end = std::max(end, agent.end_time());
  // Checked before the conversion: a plan read from a file may last long.
  if (!(end <= kMaxPlanTime))
    throw std::invalid_argument("the plan ends at " + std::to_string(end) +
                                " s, after the latest time a plan may hold (" +
                                std::to_string(std::lround(kMaxPlanTime)) + " s)");
  const long samples = static_cast<long>(std::floor(end * rate)) + 1;

  PlanMetrics result;
  result.rate = rate;
  result.agents.resize(n);
  for (size_t a = 0; a < n; ++a) {
    AgentMetrics& m = result.agents[a];
    m.name = plan.agents[a].name;
    m.reached = plan.agents[a].status == AgentStatus::kReached;
    m.time = plan.agents[a].end_time();
    m.effort = plan.agents[a].total_cost();
  }
  std::vector<Vec2> position(n), previous(n), velocity(n), previous_velocity(n);
  std::vector<double> ground(n);  // agents on levels apart never meet
  std::vector<std::size_t> around;
  std::vector<bool> colliding(n, false), present(n, true);
  std::vector<std::vector<Circle>> circles(n);
  const auto apart = [&](std::size_t a, std::size_t b) {
    return levels_apart(ground[a], ground[b], plan.character.body_height);
  };
  const double dt = 1.0 / rate;
  for (long s = 0; s < samples; ++s) {
    const double t = static_cast<double>(s) * dt;
    for (size_t a = 0; a < n; ++a) {
      position[a] = com_at(plan.agents[a], t).position;
      ground[a] = ground_at(plan.agents[a], t);
      circles[a] = collision_circles(plan.agents[a], plan.character, t);
      present[a] = present_at(plan.agents[a], t);
    }
    const AgentGrid grid(position, kNear);
    for (size_t a = 0; a < n; ++a) {
      if (!present[a]) continue;  // gone, as SteerBench removes an agent at its goal
      AgentMetrics& m = result.agents[a];
      // SteerBench: torso discs, an episode when an overlap deeper than 1 mm begins.
      bool now = false;
      const Circle disc{position[a], kSteerBenchRadius};
      const Circle reach{position[a], kSteerBenchRadius + 1.0};
      std::vector<int> near;
      map.gather(reach, near);
      for (const int o : near) now = now || penetration(map, o, disc) > kSteerBenchPenetration;
      grid.around(position[a], kNear, around);  // all that could overlap, and more
      for (const size_t b : around) {
        now = now || (b != a && present[b] && !apart(a, b) &&
                      2 * kSteerBenchRadius - distance(position[a], position[b]) >
                          kSteerBenchPenetration);
      }
      if (now && !colliding[a]) ++m.collision_episodes;
      colliding[a] = now;
      // Our five circles against the obstacles and every other agent's. The
      // planner tests every agent's shoulders and arms in 3-D (check_body),
      // over low obstacles too: against obstacles only its torso's centre
      // circle (the first) and its feet count.
      bool overlap = false;
      for (std::size_t c = 0; c < circles[a].size(); ++c)
        overlap = overlap || (c != 1 && c != 2 && map.overlaps(circles[a][c]));
      for (const size_t b : around) {
        if (overlap || b == a || !present[b] || apart(a, b) ||
            distance(position[a], position[b]) > kNear)
          continue;
        for (const Circle& c : circles[a]) {
          for (const Circle& d : circles[b]) overlap = overlap || circles_overlap(c, d);
        }
      }
      m.overlaps += overlap ? 1 : 0;
      // SteerBench's energy and acceleration, by finite differences.
      if (s > 0) {
        velocity[a] = rate * (position[a] - previous[a]);
        m.path_length += distance(position[a], previous[a]);
        m.energy += 0.5 * dot(velocity[a], velocity[a]);
        if (s > 1) m.acceleration += rate * length(velocity[a] - previous_velocity[a]);
        previous_velocity[a] = velocity[a];
      }
      previous[a] = position[a];
    }
  }
  double collisions = 0, time = 0, energy = 0, acceleration = 0;
  for (const AgentMetrics& m : result.agents) {
    collisions += m.collision_episodes;
    time += m.time;
    energy += m.energy;
    acceleration += m.acceleration;
    result.overlaps += m.overlaps;
  }
  const double count = std::max<double>(1.0, static_cast<double>(n));
  result.composite01 = 50.0 * collisions / count + time / count + energy / count;
  result.composite02 = result.composite01 + acceleration / count;
  return result;
}

}  // namespace footfall
