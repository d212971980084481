// Footfall — the full-body test of single footsteps: the body, in the step's
// behaviour and phase, swept over the step against the obstacles in 3-D. The
// footstep search asks it of every step it expands; the plan's check
// (body_check.hpp) places the body the same way.
#pragma once

#include <array>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"

namespace footfall {

/// The body's pose and its placement at time `t` of `step`: a step is half a
/// cycle of its behaviour's motion, the left foot's the first half (a stop
/// step, which brings the feet together or waits, the standing pose); the root
/// on the COM, heading along the torso's facing (the step's phi), a
/// side-step's a quarter turn right of it (its motion travels along +x with
/// the body facing +y).
void pose_during(const BodyModel& body, const Footstep& step, double t, BodyPose& pose,
                 GroundPlacement& placement);

/// Tests footsteps; immutable, so searches on several threads may share it.
class StepBodyTest {
 public:
  /// `scene` and `body` must outlive the test. [pose_rate: 1 to 1000 a second]
  StepBodyTest(const CollisionScene& scene, const BodyModel& body, double pose_rate);

  /// True if a pose of the step, at its ends and at each multiple of
  /// 1/pose_rate s between them (where check_body poses a plan), meets an
  /// obstacle. Only the limbs whose sweep over the step comes near a
  /// surface are placed and tested, against those surfaces alone.
  bool hits(const Footstep& step) const;

 private:
  const CollisionScene& scene_;
  const BodyModel& body_;
  double pose_rate_;
  // Per behaviour, each limb's box in the travel frame over every pose and
  // the standing one. [m]
  std::array<std::array<FrameBox, kLimbCount>, 3> limb_boxes_{};
};

}  // namespace footfall
