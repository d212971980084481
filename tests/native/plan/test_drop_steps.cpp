// Dropping a plan's first steps (droppable_steps, drop_steps): what a crowd
// asks of the plan from a time on stays the same to the bit, and the steps
// dropped and kept join back into the plan.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "footfall/crowd/scenario.hpp"
#include "footfall/io/steersuite.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall {
namespace {

const std::string kCases = FOOTFALL_STEERSUITE_DIR;

/// Every answer about time t the crowd asks of a plan, compared bit for bit.
void expect_same_at(const AgentPlan& whole, const AgentPlan& kept, const PlanBounds& whole_bounds,
                    const PlanBounds& kept_bounds, const CharacterParams& character, double t) {
  const ComSample a = com_at(whole, t), b = com_at(kept, t);
  EXPECT_EQ(a.position, b.position) << whole.name << " at " << t;
  EXPECT_EQ(a.velocity, b.velocity) << whole.name << " at " << t;
  EXPECT_EQ(facing_at(whole, t), facing_at(kept, t)) << whole.name << " at " << t;
  const auto feet_a = feet_at(whole, t), feet_b = feet_at(kept, t);
  for (int f = 0; f < 2; ++f) {
    EXPECT_EQ(feet_a[f].position, feet_b[f].position) << whole.name << " at " << t;
    EXPECT_EQ(feet_a[f].orientation, feet_b[f].orientation) << whole.name << " at " << t;
    EXPECT_EQ(feet_a[f].lift, feet_b[f].lift) << whole.name << " at " << t;
    EXPECT_EQ(feet_a[f].planted, feet_b[f].planted) << whole.name << " at " << t;
  }
  std::array<Circle, 5> circles_a, circles_b;
  const int count = collision_circles(whole, character, t, circles_a);
  ASSERT_EQ(count, collision_circles(kept, character, t, circles_b)) << whole.name << " at " << t;
  PlanWalk walk(kept);
  std::array<Circle, 5> walked;
  ASSERT_EQ(count, walk.collision_circles(character, t, walked));
  for (int c = 0; c < count; ++c) {
    EXPECT_EQ(circles_a[c].center, circles_b[c].center) << whole.name << " at " << t;
    EXPECT_EQ(circles_a[c].radius, circles_b[c].radius) << whole.name << " at " << t;
    EXPECT_EQ(circles_a[c].center, walked[c].center) << whole.name << " at " << t;
  }
  const PlanBounds::From x = whole_bounds.from(t), y = kept_bounds.from(t);
  EXPECT_EQ(x.top_speed, y.top_speed) << whole.name << " at " << t;
  EXPECT_EQ(x.reach, y.reach) << whole.name << " at " << t;
  EXPECT_EQ(x.com_box.min, y.com_box.min) << whole.name << " at " << t;
  EXPECT_EQ(x.com_box.max, y.com_box.max) << whole.name << " at " << t;
}

TEST(DropSteps, APlanFromATimeOnAnswersAsTheWholePlan) {
  // Agents that wait, pivot and walk on past each other in a doorway.
  const Scenario scenario = load_steersuite(kCases + "/doorway-two-way.xml");
  const Plan plan = plan_scenario(scenario);
  int dropped_somewhere = 0;
  for (const AgentPlan& whole : plan.agents) {
    const PlanBounds whole_bounds(whole, plan.character);
    const double end = whole.end_time();
    for (double from = 0.0; from <= end + 1.0; from += 0.37) {
      AgentPlan kept = whole;
      std::vector<Footstep> past;
      const std::size_t count = droppable_steps(kept, from);
      drop_steps(kept, count, past);
      ASSERT_EQ(past.size(), count);
      ASSERT_FALSE(kept.footsteps.empty());
      if (count > 0) ++dropped_somewhere;
      const PlanBounds kept_bounds(kept, plan.character);
      for (double t = from; t <= end + 0.5; t += 0.013)
        expect_same_at(whole, kept, whole_bounds, kept_bounds, plan.character, t);
      // Joined back, the steps are the plan's.
      past.insert(past.end(), kept.footsteps.begin(), kept.footsteps.end());
      ASSERT_EQ(past.size(), whole.footsteps.size());
      for (std::size_t k = 0; k < past.size(); ++k)
        EXPECT_EQ(past[k].start_time, whole.footsteps[k].start_time);
    }
  }
  EXPECT_GT(dropped_somewhere, 10);
}

TEST(DropSteps, NothingGoesBeforeThePlanStartsOrWithoutBothFeetBehind) {
  const Scenario scenario = load_steersuite(kCases + "/doorway-two-way.xml");
  const AgentPlan plan = plan_scenario(scenario).agents.front();
  ASSERT_GT(plan.footsteps.size(), 4u);
  EXPECT_EQ(droppable_steps(plan, -1.0), 0u);
  EXPECT_EQ(droppable_steps(plan, plan.footsteps[1].start_time), 0u);
  // At the end, the last step and those back to each foot's last stay.
  const std::size_t count = droppable_steps(plan, plan.end_time() + 10.0);
  ASSERT_LT(count, plan.footsteps.size() - 2);
  const Foot last = plan.footsteps.back().foot;
  bool other_foot_kept = false;
  for (std::size_t k = count; k + 1 < plan.footsteps.size(); ++k)
    other_foot_kept = other_foot_kept || plan.footsteps[k].foot != last;
  EXPECT_TRUE(other_foot_kept);
}

}  // namespace
}  // namespace footfall
