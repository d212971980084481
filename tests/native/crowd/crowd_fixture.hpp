// A few agents kept as the crowd driver keeps them (Walker records, their
// plans' bounds, a snapshot of a tick), for tests of the driver's parts.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "crowd/crowd_walker.hpp"
#include "footfall/planner/planner.hpp"

namespace footfall::crowd {

/// Agents standing at their starts among `obstacles`, each with its way
/// taken as the straight line to its last goal.
struct CrowdFixture {
  ObstacleMap map;
  FootstepPlanner planner{CharacterParams{}, PlannerParams{}, map};
  std::vector<AgentSpec> specs;
  std::vector<Walker> walkers;

  explicit CrowdFixture(std::vector<AgentSpec> agents = {}, std::vector<Obstacle> obstacles = {})
      : map(std::move(obstacles)), specs(std::move(agents)) {
    for (const AgentSpec& spec : specs) {
      Walker w;
      w.spec = &spec;
      w.plan.name = spec.name;
      w.planner = &planner;
      w.plan.start = standing_state(spec.position, spec.facing, planner.character());
      w.state = w.plan.start;
      w.bounds = std::make_shared<const PlanBounds>(w.plan, planner.character());
      w.way = distance(spec.position, spec.goals.back());
      walkers.push_back(std::move(w));
    }
  }

  /// Where everyone is at time t, as a tick's searches see it.
  Snapshot at(double t) const {
    Snapshot s;
    s.t = t;
    for (const Walker& w : walkers) {
      s.com.push_back(com_at(w.plan, t).position);
      s.present.push_back(present_at(w.plan, t));
      s.bounds.push_back(w.bounds->from(0.0));
      s.ground.push_back(ground_at(w.plan, t));
    }
    s.headroom = planner.character().body_height;
    s.grid = AgentGrid(s.com, kGridCell);
    s.giving_way.assign(walkers.size(), 0);
    return s;
  }
};

}  // namespace footfall::crowd
