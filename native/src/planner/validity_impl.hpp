// Footfall — the validity checks' implementation. The footstep search calls
// it directly, with the other agents it samples once per search
// (SampledAgents); ValidityChecker's methods sample them per call.
#pragma once

#include <array>
#include <vector>

#include "footfall/planner/validity_checker.hpp"
#include "footfall/ground/foothold.hpp"
#include "model/footstep_shape.hpp"
#include "planner/sampled_agents.hpp"

namespace footfall {

namespace planner::detail {
constexpr double kPivotTurn = 0.25 * kPi;  // [rad] the smaller pivot the search tries
// [m/s] the side steps' speed: with the stop duration (0.5 s), 0.25 m across.
constexpr double kSideStepSpeed = 1.0;
// [rad] a final turn stops this near its facing
constexpr double kFacingTolerance = 1e-6;
}  // namespace planner::detail

struct ValidityChecker::Impl {
  // A walking action of the discretised set, precomputed in its local frame.
  struct TabledAction {
    detail::StepShape shape;
    std::array<bool, 2> allowed{};  // within each foot's limits
  };

  Impl(const CharacterParams& character, const PlannerParams& planner,
       const ObstacleMap& obstacles, const Ground* ground);

  // As ValidityChecker's, which forward here.
  bool collides(const FootstepState& state, const WholeBody* whole = nullptr) const;
  bool collides(const Footstep& step, const MovingObstacles& others) const;
  Rest come_to_rest(const FootstepState& state, const MovingObstacles& others,
                    const WholeBody* whole) const;
  Rest turn_to(const FootstepState& standing, double facing, const MovingObstacles& others,
               const WholeBody* whole) const;
  bool stands_clear(const FootstepState& state, const MovingObstacles& others) const;
  std::vector<char> stands_clear_of_each(const FootstepState& state,
                                         const MovingObstacles& others) const;
  std::vector<std::size_t> standing_clear(const std::vector<FootstepState>& states,
                                          const MovingObstacles& others,
                                          std::size_t at_most) const;
  bool room_to_turn(Vec2 com) const;
  bool keeps_out(const FootstepState& rested, const KeepOut& keep_out) const;
  bool free_to_set_off(const FootstepState& rested, const WholeBody* whole = nullptr) const;
  StepResult stop_step(const FootstepState& state, double duration, const MovingObstacles& others,
                       const WholeBody* whole) const;
  StepResult stop_step(const FootstepState& state, const MovingObstacles& others) const;
  // `shoulders_in_3d`: the caller tests the step's body in 3-D (StepBodyTest),
  // which sees the shoulders and arms exactly: against obstacles the torso is
  // then only its centre circle.
  bool hits_obstacles(const Footstep& step, bool shoulders_in_3d = false) const;
  // What is wrong with where off_ground's step plants its foot, if anything
  // (kUnsupported: a nosing, where a little nearer or further may do).
  FootholdFault foothold(const Footstep& step, const FootstepState& before) const;
  bool off_ground(const Footstep& step, const FootstepState& before) const {
    return foothold(step, before) != FootholdFault::kNone;
  }
  // With ground, `step`'s terrain_cost from `before`: the body rises as the
  // stance moves from the other foot's ground to this foot's. 0 without.
  double ground_cost(const Footstep& step, const FootstepState& before) const;
  // With ground, the climbs along the straight line from `from`, on ground
  // near the height `z`, to `to` (sampled every 0.5 m, each sample on the
  // level nearest the one before; descents count nothing) at stairs' cost,
  // 4.5 times their potential energy (more than a gentle slope's: the search
  // leans on it). 0 without ground. The search's heuristic adds it.
  double climb_cost(Vec2 from, double z, Vec2 to) const;
  bool on_ground() const { return ground_ != nullptr; }
  // The standable ground's height under `p` nearest `near`; 0 where there is none.
  double ground_height(Vec2 p, double near) const;
  // With ground, sets `step`'s foot_height (where its body is posed) and
  // that of its foot in `after`: its foothold_level beside the other foot.
  void place_on_ground(Footstep& step, const FootstepState& before, FootstepState& after) const {
    if (ground_ == nullptr) return;
    const int planted = static_cast<int>(step.foot);
    step.foot_height = ground_height(step.foot_position, before.foot_heights[1 - planted]);
    after.foot_heights[planted] = step.foot_height;
  }
  // hits_obstacles or off_ground: what no step may do, whoever is about.
  bool blocked(const Footstep& step, const FootstepState& before, bool shoulders_in_3d) const {
    return hits_obstacles(step, shoulders_in_3d) || off_ground(step, before);
  }

  // The same checks against `others` sampled once for many of them.
  // `from_standing`: the step sets off from a standing state.
  bool collides(const Footstep& step, detail::SampledAgents& others, bool from_standing,
                bool shoulders_in_3d = false) const;
  bool touches_agents(const Footstep& step, detail::SampledAgents& others,
                      bool from_standing) const;
  // touches_agents for `step` taken from `before`, a stop with both feet:
  // unless the foot that does not take it swings into the next step, it
  // stays planted through the stop (before a walk or a start by the same
  // foot), where it stands.
  bool step_touches_agents(const Footstep& step, const FootstepState& before,
                           detail::SampledAgents& others) const;
  Rest come_to_rest(const FootstepState& state, detail::SampledAgents& others,
                    const WholeBody* whole) const;
  bool stands_clear(const FootstepState& state, detail::SampledAgents& others) const;
  StepResult stop_step(const FootstepState& state, double duration, detail::SampledAgents& others,
                       const WholeBody* whole) const;
  // A stop turning the body to `facing` (a pivot), checked as stop_step's.
  StepResult stop_step(const FootstepState& state, double facing, double duration,
                       detail::SampledAgents& others, const WholeBody* whole) const;
  // True if the character comes to rest from `state` among `others`, outside
  // `keep_out`, free to set off from there.
  bool rests_well(const FootstepState& state, detail::SampledAgents& others,
                  const KeepOut& keep_out, const WholeBody* whole) const;
  // A side step the search tries from standing, toward `way`: by the foot
  // that did not step last, at kSideStepSpeed, for the stop duration.
  StepResult side_step(const FootstepState& standing, double way) const;
  // Calls visit(step, phi, shape) for each tabled walking step `foot` may
  // take from `state`, until one call returns true (then returns true).
  template <class Visit>
  bool tabled_walks(const FootstepState& state, Foot foot, Visit&& visit) const;

  CharacterParams character_;
  PlannerParams params_;
  const ObstacleMap& obstacles_;
  const Ground* ground_;  // null: the plane z = 0
  double torso_extent_ = 0;  // how far the torso circles reach from the COM [m]
  std::vector<TabledAction> actions_;
};

template <class Visit>
bool ValidityChecker::Impl::tabled_walks(const FootstepState& state, Foot foot, Visit&& visit) const {
  const footfall::detail::Heading heading = detail::heading_of(state);
  const int f = static_cast<int>(foot);
  const double inward = -outward_sign(foot);
  const OrientationInterval reach = reachable_orientations(
      state.foot_orientation[static_cast<int>(other(foot))], other(foot), character_.max_foot_turn);
  for (const TabledAction& action : actions_) {
    if (!action.allowed[f]) continue;
    const double phi = wrap_angle(heading.angle + inward * action.shape.turn);
    if (visit(detail::walk_step(state, foot, heading, action.shape, phi, reach, character_), phi,
              action.shape))
      return true;
  }
  return false;
}

}  // namespace footfall
