// Footfall — the full-body check of a plan.
#include "footfall/fullbody/body_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"
#include "footfall/fullbody/step_body_test.hpp"

namespace footfall {

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
      pose_during(body, agent.footsteps[index], t, pose, placement);
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
