// A plan made of footstep actions taken in turn by the model, for tests of
// what is evaluated from plans.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "footfall/model/footstep.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {

// An agent standing at the origin facing +x that takes `actions` in turn.
inline AgentPlan plan_of(const std::vector<FootstepAction>& actions) {
  const CharacterParams character;
  AgentPlan plan;
  plan.name = "a";
  plan.start = standing_state({0.0, 0.0}, 0.0, character);
  FootstepState state = plan.start;
  for (const FootstepAction& action : actions) {
    const StepResult r = create_footstep(state, action, character);
    EXPECT_TRUE(r.valid()) << to_string(r.validity);
    plan.footsteps.push_back(r.step);
    state = r.state;
  }
  return plan;
}

}  // namespace footfall
