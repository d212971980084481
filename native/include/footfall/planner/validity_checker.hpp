// Footfall — the validity checks of footstep states and steps: static
// obstacles, and other agents' plans as moving obstacles. The footstep search
// and the crowd driver share them (the crowd checks rests, room and commits
// with the same tests the search applies), so they stand apart from the
// search, as OMPL keeps its StateValidityChecker apart from its planners.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "footfall/model/footstep.hpp"
#include "footfall/model/obstacles.hpp"
#include "footfall/model/params.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/plan/plan_samples.hpp"

namespace footfall {

/// Another agent's plan, which a search keeps clear of as a moving obstacle:
/// at every sampled time of a step, the five circles the plan gives at that
/// time (section 4). It is taken to share the planner's character.
struct MovingObstacle {
  /// Implicit: a list of plans alone is a list of moving obstacles.
  MovingObstacle(const AgentPlan* its_plan, const PlanBounds* its_bounds = nullptr,
                 const PlanSamples* its_samples = nullptr)
      : plan(its_plan), bounds(its_bounds), samples(its_samples) {}
  const AgentPlan* plan;
  /// Its PlanBounds, when the caller keeps them (a crowd does); null: a
  /// search finds the bounds it needs itself.
  const PlanBounds* bounds;
  /// Samples of the plan already taken, when the caller keeps them (a crowd
  /// keeps those of its commit check); null: a search samples it itself.
  const PlanSamples* samples;
};
using MovingObstacles = std::vector<MovingObstacle>;

/// Discs that a search's rests keep out of: the way another agent waits to
/// take (the crowd's yielding). The steps may cross them.
using KeepOut = std::vector<Circle>;

class Ground;
class SectionLookup;
class StepBodyTest;

/// The full-body checks of a search following its annotated way (planner
/// follow_sections). With `sections`, each step takes its section's
/// behaviour (the arms in narrow the torso; only lateral steps and stops
/// inside side-step sections), and with `body` it passes the full-body test
/// in 3-D, which alone then judges the shoulders and arms against obstacles
/// (in 2-D only the torso's centre circle); its rests are the same: a
/// character may stand in a passage too narrow to turn in, as long as it can
/// step out. Without sections every step walks, its 2-D torso whole.
struct WholeBody {
  const SectionLookup* sections = nullptr;  ///< Null: walk everywhere.
  const StepBodyTest* body = nullptr;       ///< Null: no 3-D test.

  /// True if the shoulders are judged in 3-D only.
  bool shoulders_in_3d() const { return sections != nullptr && body != nullptr; }
  /// Gives `step` its section's behaviour; false where it may not go (a
  /// walking step inside a side-step section).
  bool label(Footstep& step) const;
  /// True if `step`, taken from `before`, passes the body test as a plan
  /// holds it (a walk that sets off is split: split_set_off); a walking step
  /// whose limbs meet an obstacle passes if it does with the arms held in,
  /// and is then labelled arms_in.
  bool passes(Footstep& step, const FootstepState& before) const;
};

/// Stop steps that bring a character to rest, and where they leave it.
struct Rest {
  std::vector<Footstep> steps;
  FootstepState state;    ///< After the steps.
  bool complete = false;  ///< False when even the shortest stop would run into an obstacle.
};

/// The validity checks for one character among static obstacles. Stateless
/// between calls; const methods may run on several threads at once.
class ValidityChecker {
 public:
  /// Validates both parameter sets (std::invalid_argument). `obstacles`, and
  /// `ground` if given, must outlive the checker. Without ground the floor is
  /// the plane z = 0; with it, every foothold must be on it (off_ground).
  ValidityChecker(const CharacterParams& character, const PlannerParams& planner,
                  const ObstacleMap& obstacles, const Ground* ground = nullptr);
  ~ValidityChecker();
  ValidityChecker(const ValidityChecker&) = delete;
  ValidityChecker& operator=(const ValidityChecker&) = delete;

  /// True if the step collides with an obstacle (its landing foot, or the
  /// torso circles at samples no further apart than the sample spacing), or
  /// if at an instant of the contact grid (every 0.05 s, as the crowd's
  /// commit check and `footfall metrics` sample) its torso or planted foot
  /// touches a circle of one of `others`.
  bool collides(const Footstep& step, const MovingObstacles& others = {}) const;
  /// True if the standing or walking state's planted feet or torso collide
  /// (the torso's centre circle where `whole` judges the shoulders in 3-D).
  bool collides(const FootstepState& state, const WholeBody* whole = nullptr) const;
  /// Brings the character to rest with its feet side by side: a stop to
  /// decelerate (when walking), then one to close the feet, each halved in
  /// duration (down to an eighth) while it would run into an obstacle or one
  /// of `others` (the COM still coasts while it decelerates). The rest is
  /// complete only if the character, standing there, keeps room to turn on
  /// the spot among `others` while their plans last.
  /// With `whole`, the stops are checked as its searches check them.
  Rest come_to_rest(const FootstepState& state, const MovingObstacles& others = {},
                    const WholeBody* whole = nullptr) const;
  /// From `standing`, pivots on the spot (stops turning by at most 45°
  /// each, the feet by turns, then a stop of each foot) until the body and
  /// both feet face `facing`, each
  /// checked as come_to_rest checks its stops; it stops turning before one
  /// that would run into an obstacle or one of `others` (complete: it got
  /// all the way round).
  Rest turn_to(const FootstepState& standing, double facing, const MovingObstacles& others = {},
               const WholeBody* whole = nullptr) const;
  /// True if the character, standing at `state` from its time on, keeps
  /// clear of `others` while their plans last (after them, they stand too),
  /// with room to turn: a disc half the torso width round its COM, grown by
  /// 0.1 m against those standing still. A rest complete among `others`
  /// (come_to_rest) stands clear of them.
  bool stands_clear(const FootstepState& state, const MovingObstacles& others) const;
  /// For each agent of `others`, stands_clear(state, {that agent}): 1 if the
  /// character keeps clear of that agent's plan alone, 0 if not.
  std::vector<char> stands_clear_of_each(const FootstepState& state,
                                         const MovingObstacles& others) const;
  /// True if a character standing with its COM at `com` could turn on the
  /// spot: no static obstacle within half the torso width.
  bool room_to_turn(Vec2 com) const;
  /// True if a character standing at `rested` keeps out of every disc of
  /// `keep_out`: none of its five circles overlaps one.
  bool keeps_out(const FootstepState& rested, const KeepOut& keep_out) const;
  /// The indices of the first `at_most` of `states` (all at one time) that
  /// stand clear of `others` (stands_clear), sampling their plans once.
  std::vector<std::size_t> standing_clear(const std::vector<FootstepState>& states,
                                          const MovingObstacles& others,
                                          std::size_t at_most) const;
  /// True if a character standing at `rested` has room to turn and can set
  /// off: one of the tabled walking steps, the side step straight across or
  /// a pivot from there is clear of the static obstacles. A search that ends
  /// short of its goal ends where its rest leaves the character free to set
  /// off, so that the next search from there is not trapped. Room to turn
  /// alone is not enough: a walk sets off along the facing, and the steps'
  /// checks pad the torso, so a character facing a wall just over half its
  /// width away could otherwise take no step at all.
  /// With `whole`, the steps are checked as its searches check them; where
  /// it judges the shoulders in 3-D, room to turn is not asked: the torso's
  /// centre circle must be clear.
  bool free_to_set_off(const FootstepState& rested, const WholeBody* whole = nullptr) const;
  /// The stop step from `state` lasting `duration`, with validity kCollides if
  /// it runs into an obstacle (with `whole`, as its checks have it).
  StepResult stop_step(const FootstepState& state, double duration,
                       const MovingObstacles& others = {}, const WholeBody* whole = nullptr) const;
  /// The stop step of the planner's stop_duration.
  StepResult stop_step(const FootstepState& state, const MovingObstacles& others = {}) const;
  /// True if the step's landing foot, or its torso circles at samples no
  /// further apart than the sample spacing, overlap a static obstacle.
  bool hits_obstacles(const Footstep& step) const;
  /// With ground, true if `step` taken from `before` plants its foot off it:
  /// no standable level under the foot; a slope over max_slope; less than
  /// sole_support of the sole (sole_length by sole_width, at either end of
  /// the foot's orientation interval) on walkable ground within 2 cm of the
  /// sole's plane; a rise
  /// from the other foot over max_step_up or a drop over max_step_down; or a
  /// swinging foot that passes over ground more than 2 cm above the higher
  /// of its two footholds (a hump, not a nosing). Where levels lie above one
  /// another, the foot's is the one a step from the other foot's
  /// (foothold_level).
  bool off_ground(const Footstep& step, const FootstepState& before) const;
  /// True if the checker was given ground.
  bool on_ground() const;
  /// The character standing at `position` facing `facing`, each foot on the
  /// ground near `height` (standing_on_ground; without ground, standing_state).
  FootstepState standing(Vec2 position, double facing, std::optional<double> height) const;

  /// The character parameters.
  const CharacterParams& character() const;
  /// The planner parameters.
  const PlannerParams& params() const;

  /// The implementation, which the footstep search calls with the other
  /// agents it samples once per search (planner/validity_impl.hpp).
  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<const Impl> impl_;
};

}  // namespace footfall
