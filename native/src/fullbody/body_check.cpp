// Footfall — the full-body check of a plan.
#include "footfall/fullbody/body_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"

namespace footfall {
namespace {

// The body's placement and motion time at `t` during `step`: a step is half
// a cycle, the left foot's the first half. Side-step motions travel along +X
// with the body facing +Y: their heading is a quarter turn right of facing.
void pose_of(const BodyModel& body, const AgentPlan& agent, const Footstep& step, double t,
             BodyPose& pose, GroundPlacement& placement) {
  const double span = std::max(step.end_time - step.start_time, 1e-9);
  const double fraction = std::clamp((t - step.start_time) / span, 0.0, 1.0);
  const double phase = 0.5 * fraction + (step.foot == Foot::kLeft ? 0.0 : 0.5);
  body.pose_at(step.behavior, phase * body.motion(step.behavior).cycle_duration, pose);
  const double facing = facing_at(agent, t);
  placement.position = com_at(agent, t).position;
  placement.heading = step.behavior == Behavior::kSideStep ? facing - 0.5 * kPi : facing;
}

}  // namespace

BodyCheck check_body(const Plan& plan, double pose_rate) {
  if (!(pose_rate >= 1 && pose_rate <= 1000))
    throw std::invalid_argument("pose rate: must be in [1, 1000] poses per second");
  const CollisionScene scene(plan.obstacles);
  const BodyModel body(plan.character);
  BodyCheck check;
  BodyPose pose;
  for (const AgentPlan& agent : plan.agents) {
    AgentBodyCheck figures;
    std::size_t index = 0;
    const double end = agent.end_time();
    const long long count = static_cast<long long>(std::floor(end * pose_rate));
    for (long long k = 0; k <= count && !agent.footsteps.empty(); ++k) {
      const double t = static_cast<double>(k) / pose_rate;
      while (index + 1 < agent.footsteps.size() && agent.footsteps[index].end_time < t) ++index;
      GroundPlacement placement;
      pose_of(body, agent, agent.footsteps[index], t, pose, placement);
      const Contact contact = scene.test(pose, placement, true);
      ++figures.poses;
      if (!contact) continue;
      figures.deepest = std::max(figures.deepest, contact.depth);
      figures.penetrations += contact.depth > kPenetrationTolerance ? 1 : 0;
    }
    check.poses += figures.poses;
    check.penetrations += figures.penetrations;
    check.deepest = std::max(check.deepest, figures.deepest);
    check.agents.push_back(figures);
  }
  return check;
}

}  // namespace footfall
