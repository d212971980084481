// SectionLookup: the behaviour a place takes from an agent's sections, and
// the way of a side-step section near it.
#include <gtest/gtest.h>

#include <cmath>

#include "footfall/plan/section_lookup.hpp"

namespace footfall {
namespace {

BehaviorSection section(Behavior behavior, std::vector<Vec2> points) {
  BehaviorSection s;
  s.behavior = behavior;
  s.points = std::move(points);
  return s;
}

TEST(SectionLookup, AWayPlannedFromWhereTheAgentStandsHeadsWhereItsStretchHeads) {
  // Planned anew from the agent's place, a way through a slot heading north
  // starts with two segments of a few millimetres, across and back.
  const SectionLookup lookup({section(Behavior::kSideStep, {{0.0, 0.0}, {0.0, -0.004},
                                                            {0.02, 0.016}, {0.02, 0.08},
                                                            {0.03, 0.4}})});
  const std::optional<WayLine> way = lookup.narrower_way({-0.001, -0.002});
  ASSERT_TRUE(way.has_value());
  EXPECT_NEAR(std::atan2(way->direction.y, way->direction.x), 0.5 * M_PI, 0.15);
  EXPECT_NEAR(way->nearest.x, 0.0, 1e-12);
  EXPECT_NEAR(way->nearest.y, -0.002, 1e-12);
  // Along its straight middle, its direction is that of the middle.
  const std::optional<WayLine> middle = lookup.narrower_way({0.0, 0.2});
  ASSERT_TRUE(middle.has_value());
  EXPECT_NEAR(std::atan2(middle->direction.y, middle->direction.x), 0.5 * M_PI, 0.1);
}

TEST(SectionLookup, OnlyASectionNarrowerThanWalkHasAWayToSquareUpTo) {
  const SectionLookup lookup({section(Behavior::kWalk, {{-3.0, 0.0}, {-1.5, 0.0}}),
                              section(Behavior::kArmsIn, {{0.0, 0.0}, {1.0, 0.0}}),
                              section(Behavior::kSideStep, {{3.0, 0.0}, {3.0, 1.0}})});
  EXPECT_FALSE(lookup.narrower_way({-2.0, 0.1}).has_value());
  const std::optional<WayLine> arms_in = lookup.narrower_way({0.5, 0.1});
  ASSERT_TRUE(arms_in.has_value());
  EXPECT_EQ(arms_in->behavior, Behavior::kArmsIn);
  EXPECT_NEAR(arms_in->direction.x, 1.0, 1e-12);
  const std::optional<WayLine> side_step = lookup.narrower_way({3.1, 0.5});
  ASSERT_TRUE(side_step.has_value());
  EXPECT_EQ(side_step->behavior, Behavior::kSideStep);
  EXPECT_FALSE(lookup.narrower_way({5.0, 0.5}).has_value());  // beyond the reach
  EXPECT_EQ(lookup.at({5.0, 0.5}), Behavior::kWalk);
}

}  // namespace
}  // namespace footfall
