// Footfall — TESTCOLLISION: the body swept along a path with one behaviour,
// pose by pose, against the scene.
#pragma once

#include <vector>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"
#include "footfall/model/polyline.hpp"

namespace footfall {

/// The first colliding pose of a sweep.
struct BodyCollision {
  bool hit = false;
  double time = 0;   ///< Motion time of the pose. [s]
  double along = 0;  ///< Where the root was along the path. [m]
  Vec2 root;         ///< The root there. [m]
  Contact contact;   ///< The limb and its point.
};

/// Sweeps the body with `behavior` from `from` to `to` metres along `path`,
/// the motion `start_time` seconds in at `from`, testing `pose_rate` poses
/// per second of motion and the pose at `to`; counts them in `poses`.
BodyCollision sweep_body(const CollisionScene& scene, const BodyModel& body, Behavior behavior,
                         const Polyline& path, double from, double to,
                         double start_time, double pose_rate, long long& poses);

/// The same along the whole of `points`, from phase 0.
BodyCollision sweep_body(const CollisionScene& scene, const BodyModel& body, Behavior behavior,
                         const std::vector<Vec2>& points, double pose_rate);

}  // namespace footfall
