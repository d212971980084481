#include "footfall/plan/ground_check.hpp"

#include <cmath>
#include <limits>

#include "footfall/ground/foothold.hpp"

namespace footfall {
namespace {

constexpr double kOnGround = 0.02;  // [m] a foot_height this near the ground is on it

}  // namespace

std::array<double, 2> start_foot_heights(const Ground& ground, const AgentPlan& agent,
                                         const CharacterParams& character) {
  const double first = agent.footsteps.empty() ? -std::numeric_limits<double>::infinity()
                                               : agent.footsteps.front().foot_height;
  std::array<double, 2> heights{};
  for (int f = 0; f < 2; ++f)
    if (const auto level = foothold_level(ground, character, agent.start.feet[f], first))
      heights[f] = level->z;
  return heights;
}

GroundCheck check_ground(const Plan& plan) {
  GroundCheck check;
  if (plan.ground.empty()) return check;
  const Ground ground(plan.ground);
  for (const AgentPlan& agent : plan.agents) {
    const CharacterParams& character = character_of(agent, plan.character);
    const std::array<double, 2> heights = start_foot_heights(ground, agent, character);
    std::array<Vec3, 2> feet;
    for (int f = 0; f < 2; ++f)
      feet[f] = {agent.start.feet[f].x, agent.start.feet[f].y, heights[f]};
    for (const Footstep& step : agent.footsteps) {
      const int planted = static_cast<int>(step.foot);
      const OrientationInterval turned{step.foot_orientation, step.foot_orientation};
      ++check.footholds;
      FootholdFault fault = foothold_fault(ground, character, step.foot_position, turned,
                                           feet[1 - planted], feet[planted]);
      // A foot held where the plan does not put it (in a tread, over a deck).
      const auto level = foothold_level(ground, character, step.foot_position, feet[1 - planted].z);
      if (fault == FootholdFault::kNone && std::fabs(level->z - step.foot_height) > kOnGround)
        fault = FootholdFault::kOffGround;
      switch (fault) {
        case FootholdFault::kNone: break;
        case FootholdFault::kOffGround: ++check.off_ground; break;
        case FootholdFault::kUnsupported: ++check.unsupported; break;
        case FootholdFault::kRise: ++check.over_rise; break;
        case FootholdFault::kSwing: ++check.swing; break;
      }
      feet[planted] = {step.foot_position.x, step.foot_position.y, step.foot_height};
    }
  }
  return check;
}

}  // namespace footfall
