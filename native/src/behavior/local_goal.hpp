// Footfall — where an agent's next footstep search aims: its way to the goal
// on the navigation mesh, and the local goal along that way.
#pragma once

#include <optional>
#include <vector>

#include "footfall/navmesh/navmesh.hpp"
#include "footfall/planner/planner.hpp"

namespace footfall {

/// The way from an agent to its goal, and its length. [m]
struct Way {
  std::vector<Vec2> points;
  double length = 0.0;
};

/// The way on `mesh`: the roomiest of three clearances (room to walk upright
/// with a margin for the sway, just upright, or only to side-step) that is not
/// much longer than the tightest; with no mesh or no path, the straight line.
/// `roomy`: the roomier of the first two that has a way, however long (else
/// as above), from a place too tight for either out of it first, not
/// through any of `others` (where other agents stand): back to `back`, where
/// the agent last stood with room to walk upright, if given (the way it came
/// in is one its steps passed), else to the nearest such place in sight.
Way way_toward(const NavMesh* mesh, const CharacterParams& character, Vec2 from, Vec2 goal,
               bool roomy = false, const std::vector<Vec2>& others = {},
               std::optional<Vec2> back = std::nullopt);

/// The first `length` metres of `way` (all of it if shorter). [m]
Way way_start(const Way& way, double length);

/// The room to walk upright with the body's sway: the radius of the disc
/// that the roomiest ways keep clear. [m]
double sway_room(const CharacterParams& character);

/// True if at `at` there is no room to walk upright with the body's sway
/// (in a gap between boxes, against a wall); never without a mesh.
bool cramped(const NavMesh* mesh, const CharacterParams& character, Vec2 at);

/// Where the next search aims, and whether that is the goal itself.
struct LocalGoal {
  Vec2 point;
  bool is_goal = false;
};

/// The goal if the way to it is within local_goal_distance and in sight;
/// else the farthest point of the way within that distance that is in sight,
/// moved back along the way until the agent could stand there (but not to
/// within the goal tolerance of it: then the point in sight, standing room
/// or not).
LocalGoal local_goal(const FootstepPlanner& planner, const NavMesh* mesh, const Way& way);

}  // namespace footfall
