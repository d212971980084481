// The crowd's commits (native/src/crowd/crowd_commit.hpp) on small hand-built
// crowds: a proposal is refused for the first agent its plan runs into, or,
// resting somewhere new, has no room beside; a clear one is committed with a
// provisional rest; a refused one leaves the agent waiting at its old rest.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "crowd/crowd_commit.hpp"
#include "crowd/crowd_fixture.hpp"
#include "crowd/crowd_walker.hpp"
#include "footfall/planner/planner.hpp"

namespace footfall::crowd {
namespace {

/// A few agents standing on open ground.
struct OpenGround : CrowdFixture {
  using CrowdFixture::CrowdFixture;

  /// Agent i's attempt toward `goal`, searched alone (whoever is in the way),
  /// followed by the stops that bring it to rest in the open.
  Attempt attempt(std::size_t i, Vec2 goal) const {
    const Walker& w = walkers[i];
    const SearchResult found = planner.plan(w.state, goal);
    EXPECT_FALSE(found.footsteps.empty());
    Attempt a;
    a.from = w.state;
    a.steps = found.footsteps;
    a.end = found.end_state;
    a.rest.state = a.end;
    for (int stop = a.end.standing() ? 1 : 2; stop > 0; --stop) {
      const StepResult step = create_footstep(
          a.rest.state, {StepKind::kStop, Foot::kLeft, a.rest.state.facing, 0.0, 0.5},
          planner.character());
      EXPECT_TRUE(step.valid());
      a.rest.steps.push_back(step.step);
      a.rest.state = step.state;
    }
    a.rest.complete = true;
    a.way_from = distance(w.state.com, goal);
    a.way_left = distance(a.end.com, goal);
    a.searched = true;
    return a;
  }

  /// Agent i's attempt toward `goal`, searched among the plans of `seen`,
  /// followed by the stops that bring it to rest.
  Attempt attempt_among(std::size_t i, Vec2 goal, const std::vector<std::size_t>& seen) const {
    const Walker& w = walkers[i];
    const SearchResult found = planner.plan(w.state, goal, plans_of(walkers, seen));
    Attempt a;
    a.from = w.state;
    a.steps = found.footsteps;
    a.end = found.footsteps.empty() ? w.state : found.end_state;
    a.rest = planner.validity().come_to_rest(a.end, plans_of(walkers, seen));
    a.searched = true;
    return a;
  }

  /// Proposes agent i's attempt against `close`, and commits it at time t
  /// unless refused; returns the refusal (-1: none).
  int propose_and_commit(std::size_t i, const Attempt& a, std::vector<std::size_t> close,
                         double t) {
    Proposal p = propose(walkers, i, a, planner, std::move(close), at(t));
    const int refused = refusal(walkers, p, planner);
    commit(walkers, i, a, p, refused, planner, t);
    return refused;
  }
};

/// Agent 0 at the origin facing +x; the others as given, standing.
OpenGround crowd_with(std::vector<AgentSpec> others, bool leaves = false) {
  others.insert(others.begin(), AgentSpec{"mover", {0, 0}, 0.0, {{6, 0}}, leaves});
  return OpenGround(std::move(others));
}

// rest_until: a standing agent stands until t in waits no longer than kMaxWait, in place.
TEST(Commit, RestUntilStandsUntilTInWaitsOfAtMostMaxWait) {
  OpenGround crowd = crowd_with({});
  Walker& w = crowd.walkers[0];
  const std::uint64_t version = w.version;
  rest_until(w, crowd.planner, 12.0);
  ASSERT_EQ(w.plan.footsteps.size(), 3u);  // 5 + 5 + 2 s
  double t = 0.0;
  for (const Footstep& step : w.plan.footsteps) {
    EXPECT_TRUE(still(step, 0.0));
    EXPECT_DOUBLE_EQ(step.start_time, t);
    EXPECT_LE(step.duration(), kMaxWait + 1e-9);
    EXPECT_EQ(step.com_end, w.plan.start.com);
    t = step.end_time;
  }
  EXPECT_NEAR(w.state.time, 12.0, 1e-9);
  EXPECT_EQ(w.state.com, w.plan.start.com);
  EXPECT_GT(w.version, version);  // others see the plan changed
}

// rest_until: the provisional rest happens; nothing is added when it ends after t.
TEST(Commit, RestUntilLetsTheProvisionalRestHappen) {
  OpenGround crowd = crowd_with({});
  const Attempt a = crowd.attempt(0, {3, 0});
  ASSERT_EQ(crowd.propose_and_commit(0, a, {}, 0.0), -1);
  Walker& w = crowd.walkers[0];
  ASSERT_GT(w.resting, 0u);
  const std::size_t steps = w.plan.footsteps.size();
  const std::uint64_t version = w.version;
  rest_until(w, crowd.planner, 0.5);  // long before the rest ends
  EXPECT_EQ(w.resting, 0u);
  EXPECT_EQ(w.state.com, a.rest.state.com);
  EXPECT_DOUBLE_EQ(w.state.time, a.rest.state.time);
  EXPECT_EQ(w.plan.footsteps.size(), steps);
  EXPECT_EQ(w.version, version);
  // Later than the rest's end, it waits there until then.
  rest_until(w, crowd.planner, a.rest.state.time + 1.0);
  EXPECT_EQ(w.plan.footsteps.size(), steps + 1);
  EXPECT_NEAR(w.state.time, a.rest.state.time + 1.0, 1e-9);
  EXPECT_EQ(w.state.com, a.rest.state.com);
}

// rest_until: a wait stands as the rest before it stood, arms held in or
// side-on: everyone else was checked against it standing so. (Labelled anew
// from sections added since, a wait stood otherwise, could fail the
// full-body test, and the plan stopped short of t: among boxes, the next
// search began 29 s in the past and walked it into another agent.)
TEST(Commit, RestUntilWaitsInTheRestsPosture) {
  for (const Behavior posture : {Behavior::kArmsIn, Behavior::kSideStep}) {
    SCOPED_TRACE(to_string(posture));
    OpenGround crowd = crowd_with({});
    Attempt a = crowd.attempt(0, {3, 0});
    for (Footstep& stop : a.rest.steps) stop.behavior = posture;
    ASSERT_EQ(crowd.propose_and_commit(0, a, {}, 0.0), -1);
    Walker& w = crowd.walkers[0];
    const std::size_t steps = w.plan.footsteps.size();
    rest_until(w, crowd.planner, a.rest.state.time + 7.0);
    ASSERT_EQ(w.plan.footsteps.size(), steps + 2);  // 5 + 2 s
    for (std::size_t k = steps; k < w.plan.footsteps.size(); ++k)
      EXPECT_EQ(w.plan.footsteps[k].behavior, posture);
    EXPECT_NEAR(w.state.time, a.rest.state.time + 7.0, 1e-9);
  }
}

// What a search finds beside one standing close (0.5 m apart, within the
// check's padding) passes the commit check: both take the gap where the pair
// last stood still. A pivot may turn a shoulder nearer first; with the gap
// taken where the check starts instead, the walk after it was refused (28 of
// these searches; among boxes two agents stood for good so).
TEST(Commit, WhatTheSearchFindsBesideOneStandingCloseIsNotRefused) {
  int searched = 0;
  for (int side = 0; side < 16; ++side)
    for (int turn = 0; turn < 4; ++turn)
      for (int way = 0; way < 8; ++way) {
        const Vec2 other = 0.5 * unit(2.0 * kPi * side / 16);
        OpenGround crowd({{"mover", {0, 0}, 0.0, {{6, 0}}},
                          {"other", other, 0.5 * kPi * turn, {{-6, 0}}}});
        const Vec2 goal = 6.0 * unit(2.0 * kPi * way / 8);
        const Attempt a = crowd.attempt_among(0, goal, {1});
        if (a.steps.empty() || !a.rest.complete) continue;
        ++searched;
        EXPECT_EQ(crowd.propose_and_commit(0, a, {1}, 0.0), -1)
            << "the other at " << other.x << ", " << other.y << " facing " << 0.5 * kPi * turn
            << "; goal " << goal.x << ", " << goal.y;
      }
  EXPECT_GT(searched, 256);
}

// progress: the best way and its time change only on a gain of min_progress or more.
TEST(Commit, ProgressRecordsWhenTheWayLastShortenedByMinProgress) {
  OpenGround crowd = crowd_with({});
  Walker& w = crowd.walkers[0];
  const double min_progress = crowd.planner.params().min_progress;
  w.state.time = 1.0;
  progress(w, 10.0, crowd.planner);
  EXPECT_DOUBLE_EQ(w.first_way, 10.0);
  EXPECT_DOUBLE_EQ(w.best_way, 10.0);
  EXPECT_DOUBLE_EQ(w.improved_at, 1.0);
  w.state.time = 2.0;
  progress(w, 10.0 - 0.5 * min_progress, crowd.planner);  // too little gained
  EXPECT_DOUBLE_EQ(w.best_way, 10.0);
  EXPECT_DOUBLE_EQ(w.improved_at, 1.0);
  w.state.time = 3.0;
  progress(w, 12.0, crowd.planner);  // lost way
  EXPECT_DOUBLE_EQ(w.best_way, 10.0);
  EXPECT_DOUBLE_EQ(w.improved_at, 1.0);
  w.state.time = 4.0;
  progress(w, 9.0, crowd.planner);
  EXPECT_DOUBLE_EQ(w.best_way, 9.0);
  EXPECT_DOUBLE_EQ(w.improved_at, 4.0);
  EXPECT_DOUBLE_EQ(w.first_way, 10.0);  // the first measure stays
}

// propose/refusal/commit: a clear proposal is committed, its steps then a provisional rest.
TEST(Commit, ClearProposalIsCommittedWithAProvisionalRest) {
  OpenGround crowd = crowd_with({{"aside", {0, 5}, 0.0, {{0, 5}}}});
  const Attempt a = crowd.attempt(0, {3, 0});
  Proposal p = propose(crowd.walkers, 0, a, crowd.planner, {1}, crowd.at(0.0));
  EXPECT_TRUE(p.new_place);
  EXPECT_EQ(p.hits, std::vector<char>{0});
  EXPECT_EQ(p.no_room, std::vector<char>{0});
  const int refused = refusal(crowd.walkers, p, crowd.planner);
  ASSERT_EQ(refused, -1);
  const std::uint64_t version = crowd.walkers[0].version;
  commit(crowd.walkers, 0, a, p, refused, crowd.planner, 0.0);
  const Walker& w = crowd.walkers[0];
  ASSERT_EQ(w.plan.footsteps.size(), a.steps.size() + a.rest.steps.size());
  for (std::size_t k = 0; k < a.steps.size(); ++k)
    EXPECT_EQ(w.plan.footsteps[k].com_end, a.steps[k].com_end);
  for (std::size_t k = 0; k < a.rest.steps.size(); ++k)
    EXPECT_EQ(w.plan.footsteps[a.steps.size() + k].com_end, a.rest.steps[k].com_end);
  EXPECT_EQ(w.resting, a.rest.steps.size());
  EXPECT_EQ(w.state.com, a.end.com);         // the next search starts before the rest
  EXPECT_EQ(rest_of(w).com, a.rest.state.com);
  EXPECT_GT(w.version, version);
  EXPECT_EQ(w.failures, 0);
  EXPECT_DOUBLE_EQ(w.committed_at, 0.0);
  EXPECT_NEAR(w.best_way, a.way_left, 1e-12);
}

// refusal: a proposal whose steps run into another's plan is refused for that agent.
TEST(Commit, ProposalIntoAnotherPlanIsRefusedForThatAgent) {
  OpenGround crowd =
      crowd_with({{"far", {0, 8}, 0.0, {{0, 8}}}, {"in the way", {1.5, 0}, kPi, {{1.5, 0}}}});
  const Attempt a = crowd.attempt(0, {3, 0});
  Proposal p = propose(crowd.walkers, 0, a, crowd.planner, {1, 2}, crowd.at(0.0));
  EXPECT_EQ(p.hits, (std::vector<char>{0, 1}));
  EXPECT_EQ(refusal(crowd.walkers, p, crowd.planner), 1);  // p.close[1]: agent 2
}

// refusal: plans changed since the proposal are checked anew.
TEST(Commit, PlanChangedSinceTheProposalIsCheckedAnew) {
  OpenGround crowd = crowd_with({{"other", {0, 8}, 0.0, {{0, 8}}}});
  const Attempt a = crowd.attempt(0, {3, 0});
  Proposal p = propose(crowd.walkers, 0, a, crowd.planner, {1}, crowd.at(0.0));
  ASSERT_EQ(refusal(crowd.walkers, p, crowd.planner), -1);
  // Agent 1's plan changes: it now stands in the way.
  Walker& other = crowd.walkers[1];
  other.plan.start = standing_state({1.5, 0}, kPi, crowd.planner.character());
  other.state = other.plan.start;
  other.bounds = std::make_shared<const PlanBounds>(other.plan, crowd.planner.character());
  ++other.version;
  EXPECT_EQ(refusal(crowd.walkers, p, crowd.planner), 0);
}

// refusal: resting somewhere new needs room beside each agent, even one never touched.
TEST(Commit, RestWithNoRoomBesideAnotherIsRefused) {
  const Attempt a = crowd_with({}).attempt(0, {3, 0});
  // Shoulder to shoulder 0.09 m apart where the rest ends: no circles touch,
  // but there is no room to turn (half the torso width and 0.1 m).
  const FootstepState& rest = a.rest.state;
  const Vec2 beside = rest.com + 0.69 * unit(rest.facing + 0.5 * kPi);
  OpenGround crowd = crowd_with({{"beside", beside, rest.facing, {beside}}});
  Proposal p = propose(crowd.walkers, 0, a, crowd.planner, {1}, crowd.at(0.0));
  EXPECT_TRUE(p.new_place);
  EXPECT_EQ(p.hits, std::vector<char>{0});
  EXPECT_EQ(p.no_room, std::vector<char>{1});
  EXPECT_EQ(refusal(crowd.walkers, p, crowd.planner), 0);
}

// commit: a refused proposal leaves the agent waiting at its old rest, noticing who refused it.
TEST(Commit, RefusedProposalLeavesTheAgentAtItsOldRest) {
  OpenGround crowd =
      crowd_with({{"far", {0, 8}, 0.0, {{0, 8}}}, {"in the way", {4.5, 0}, kPi, {{4.5, 0}}}});
  const Attempt first = crowd.attempt(0, {2, 0});
  ASSERT_EQ(crowd.propose_and_commit(0, first, {}, 0.0), -1);
  const Walker before = crowd.walkers[0];
  const Attempt second = crowd.attempt(0, {6, 0});  // from before its rest, into agent 2
  const double t = before.state.time;
  ASSERT_EQ(crowd.propose_and_commit(0, second, {1, 2}, t), 1);
  const Walker& w = crowd.walkers[0];
  ASSERT_EQ(w.plan.footsteps.size(), before.plan.footsteps.size());
  for (std::size_t k = 0; k < w.plan.footsteps.size(); ++k)
    EXPECT_EQ(w.plan.footsteps[k].com_end, before.plan.footsteps[k].com_end);
  EXPECT_EQ(w.resting, 0u);  // the old rest is no longer provisional
  EXPECT_EQ(w.state.com, before.rested.com);
  EXPECT_EQ(w.noticed, std::vector<std::size_t>{2});
  EXPECT_DOUBLE_EQ(w.news_at, t);
  EXPECT_EQ(w.failures, 1);
  EXPECT_DOUBLE_EQ(w.retry_at, t + kRetryAfter);
  EXPECT_DOUBLE_EQ(w.best_way, before.best_way);  // no way gained
}

// commit: an agent with nothing to commit retries later, twice as late each time, up to 8 times.
TEST(Commit, WaitingRetriesLaterBackingOff) {
  OpenGround crowd = crowd_with({});
  const Attempt wait;  // nothing found
  double t = 0.0;
  for (const double after : {0.1, 0.2, 0.4, 0.8, 0.8}) {
    EXPECT_EQ(crowd.propose_and_commit(0, wait, {}, t), -1);
    EXPECT_NEAR(crowd.walkers[0].retry_at, t + after, 1e-12);
    EXPECT_NEAR(crowd.walkers[0].state.time, t, 1e-9);  // it stands until now
    t = crowd.walkers[0].retry_at;
  }
  EXPECT_EQ(crowd.walkers[0].failures, 5);
}

// commit: reaching the last goal ends the walk; one that leaves there walks on, with no rest.
TEST(Commit, ReachingTheLastGoalEndsTheWalk) {
  for (const bool leaves : {false, true}) {
    SCOPED_TRACE(leaves ? "leaves" : "stays");
    OpenGround crowd = crowd_with({}, leaves);
    Attempt a = crowd.attempt(0, {6, 0});
    a.reached = true;
    Proposal p = propose(crowd.walkers, 0, a, crowd.planner, {}, crowd.at(0.0));
    EXPECT_EQ(p.leaving, leaves);
    EXPECT_EQ(p.steps.size(), a.steps.size() + (leaves ? 0 : a.rest.steps.size()));
    commit(crowd.walkers, 0, a, p, refusal(crowd.walkers, p, crowd.planner), crowd.planner, 0.0);
    const Walker& w = crowd.walkers[0];
    EXPECT_TRUE(w.done);
    EXPECT_EQ(w.plan.status, AgentStatus::kReached);
    EXPECT_EQ(w.plan.goals_reached, 1);
    EXPECT_EQ(w.plan.leaves, leaves);
    EXPECT_EQ(w.plan.footsteps.size(), p.steps.size());
  }
}

}  // namespace
}  // namespace footfall::crowd
