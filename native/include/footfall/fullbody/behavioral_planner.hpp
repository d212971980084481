// Footfall — the full-body behavioural path planner (Juarez-Perez and
// Kallmann, Algorithms 1 and 2): a path of sections, each with the behaviour
// (walk, arms in, side-step) that carries the body through it without
// touching an obstacle, bent by point obstacles where that is cheap.
#pragma once

#include <string>
#include <vector>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"
#include "footfall/model/footstep.hpp"
#include "footfall/model/params.hpp"
#include "footfall/navmesh/navmesh.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {

/// How a behavioural query ended.
enum class BehaviorPathStatus {
  kFound,         ///< The sections reach the goal.
  kHorizon,       ///< The sections reach the horizon h along the way to the goal.
  kTimeLimit,     ///< Out of time: the rest of the way is one side_step section, untested.
  kNoPath,        ///< No path with side-stepping's clearance, or no behaviour passes.
  kStartBlocked,  ///< The start is closer than side-stepping's clearance to an obstacle.
  kGoalBlocked,   ///< So is the goal.
  kOutside,       ///< The start or the goal lies outside the domain.
};
/// "found", "horizon", "time_limit", "no_path", "start_blocked", "goal_blocked", "outside".
const char* to_string(BehaviorPathStatus status);

/// An annotated path and what finding it took.
struct BehaviorPath {
  BehaviorPathStatus status = BehaviorPathStatus::kNoPath;
  std::vector<BehaviorSection> sections;  ///< Joined end to end; empty without a path.
  double length = 0;                      ///< Sum of the sections'. [m]
  /// Smallest distance from the path to an obstacle's footprint. [m]
  double min_clearance = 0;
  int point_obstacles = 0;                ///< Point obstacles inserted (all removed again).
  long long poses_tested = 0;             ///< Body poses tested against the scene.
  int path_queries = 0;                   ///< Navigation mesh queries.
  std::string reason;                     ///< Why, when no path was found.
};

/// Plans annotated paths on a navigation mesh of the scene's footprints.
/// A query inserts point obstacles into the mesh and removes every one
/// before it returns (also when it throws): afterwards the mesh answers
/// exactly as before. Not thread-safe: it changes the mesh during a query.
class BehavioralPlanner {
 public:
  BehavioralPlanner(NavMesh& mesh, const CollisionScene& scene, const BodyModel& body,
                    const PlannerParams& params);

  /// The annotated path from `from` to `to` (Algorithm 1).
  BehaviorPath plan(Vec2 from, Vec2 to);

 private:
  NavMesh& mesh_;
  const CollisionScene& scene_;
  const BodyModel& body_;
  PlannerParams params_;
};

}  // namespace footfall
