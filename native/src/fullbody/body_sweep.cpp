// Footfall — sweeping the body along a path.
#include "footfall/fullbody/body_sweep.hpp"

#include <algorithm>

namespace footfall {

BodyCollision sweep_body(const CollisionScene& scene, const BodyModel& body, Behavior behavior,
                         const Polyline& path, double from, double to,
                         double start_time, double pose_rate, long long& poses) {
  const double speed = body.speed(behavior);
  const double duration = std::max(0.0, to - from) / speed;
  BodyPose pose;
  for (long long k = 0;; ++k) {
    const double time = std::min(static_cast<double>(k) / pose_rate, duration);
    const double along = from + speed * time;
    body.pose_at(behavior, start_time + time, pose);
    const GroundPlacement placement{path.point_at(along), path.heading_at(along)};
    ++poses;
    const Contact contact = scene.test(pose, placement);
    if (contact) return {true, start_time + time, along, placement.position, contact};
    if (time >= duration) return {};
  }
}

BodyCollision sweep_body(const CollisionScene& scene, const BodyModel& body, Behavior behavior,
                         const std::vector<Vec2>& points, double pose_rate) {
  const Polyline path(points);
  long long poses = 0;
  return sweep_body(scene, body, behavior, path, 0, path.length(), 0, pose_rate, poses);
}

}  // namespace footfall
