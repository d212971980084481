#include "footfall/plan/motion_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace footfall {

MotionCheck check_motion(const AgentPlan& plan, double rate) {
  if (!(rate > 0.0 && rate <= 10000.0))
    throw std::invalid_argument("rate: must be in (0, 10000] samples a second");
  MotionCheck check;
  Vec2 before{0.0, 0.0};  // standing at the start
  const auto& steps = plan.footsteps;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const Footstep& step = steps[k];
    const double jump = length(step.com_velocity_start - before);
    if (jump > check.velocity_jump) {
      check.velocity_jump = jump;
      check.worst_jump_step = static_cast<int>(k);
    }
    before = step.com_velocity_end;
    const double span = step.duration();
    const int samples = std::max(2, static_cast<int>(std::ceil(span * rate)));
    // The foot's turn is measured from the first instant of its stance (a
    // start keeps the foot as it was put down, whatever it records).
    const double turned_to = feet_at(plan, step.start_time)[static_cast<int>(step.foot)].orientation;
    for (int i = 0; i <= samples; ++i) {
      // The end itself belongs to the next step: the last sample is just before it.
      const double t = step.start_time + span * std::min(static_cast<double>(i) / samples, 1.0 - 1e-9);
      check.top_speed = std::max(check.top_speed, length(com_at(step, t).velocity));
      const FootPose foot = feet_at(plan, t)[static_cast<int>(step.foot)];
      // A turn of the foot counts as the travel of a point 0.1 m from the ankle.
      const double turn = std::fabs(wrap_angle(foot.orientation - turned_to));
      const double slide = std::max({distance(foot.position, step.foot_position), 0.1 * turn,
                                     foot.planted ? 0.0 : std::max(foot.lift, 1e-6)});
      if (slide > check.stance_slide) {
        check.stance_slide = slide;
        check.worst_slide_step = static_cast<int>(k);
      }
    }
  }
  return check;
}

}  // namespace footfall
