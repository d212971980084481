#include "footfall/plan/ground_check.hpp"

#include "footfall/ground/foothold.hpp"

namespace footfall {

GroundCheck check_ground(const Plan& plan) {
  GroundCheck check;
  if (plan.ground.empty()) return check;
  const Ground ground(plan.ground);
  for (const AgentPlan& agent : plan.agents) {
    const CharacterParams& character = character_of(agent, plan.character);
    std::array<Vec2, 2> feet = agent.start.feet;
    for (const Footstep& step : agent.footsteps) {
      const int planted = static_cast<int>(step.foot);
      const OrientationInterval turned{step.foot_orientation, step.foot_orientation};
      ++check.footholds;
      switch (foothold_fault(ground, character, step.foot_position, turned, feet[1 - planted],
                             feet[planted])) {
        case FootholdFault::kNone: break;
        case FootholdFault::kOffGround: ++check.off_ground; break;
        case FootholdFault::kUnsupported: ++check.unsupported; break;
        case FootholdFault::kRise: ++check.over_rise; break;
        case FootholdFault::kSwing: ++check.swing; break;
      }
      feet[planted] = step.foot_position;
    }
  }
  return check;
}

}  // namespace footfall
