// Footfall — the short-horizon best-first footstep planner (section 4 of Singh
// et al.): A* over footstep states that stops after a fixed number of
// expansions and then returns the path to the most promising closed node.
#pragma once

#include <array>
#include <limits>
#include <vector>

#include "footfall/model/footstep.hpp"
#include "footfall/model/obstacles.hpp"
#include "footfall/model/params.hpp"
#include "footfall/model/status.hpp"

namespace footfall {

struct AgentPlan;
class PlanBounds;
namespace detail {
class SampledAgents;
class PlanSamples;
}

/// Another agent's plan, which a search keeps clear of as a moving obstacle:
/// at every sampled time of a step, the five circles the plan gives at that
/// time (section 4). It is taken to share the planner's character.
struct MovingObstacle {
  /// Implicit: a list of plans alone is a list of moving obstacles.
  MovingObstacle(const AgentPlan* its_plan, const PlanBounds* its_bounds = nullptr,
                 const detail::PlanSamples* its_samples = nullptr)
      : plan(its_plan), bounds(its_bounds), samples(its_samples) {}
  const AgentPlan* plan;
  /// Its PlanBounds, when the caller keeps them (a crowd does); null: a
  /// search finds the bounds it needs itself.
  const PlanBounds* bounds;
  /// Samples of the plan already taken, when the caller keeps them (a crowd
  /// keeps those of its commit check); null: a search samples it itself.
  const detail::PlanSamples* samples;
};
using MovingObstacles = std::vector<MovingObstacle>;

/// Discs that a search's rests keep out of: the way another agent waits to
/// take (the crowd's yielding). The steps may cross them.
using KeepOut = std::vector<Circle>;

/// What one search is asked besides reaching its goal.
struct SearchOptions {
  /// The character is gone at the goal (after its last step), so needs no
  /// room to come to rest there: in a crowd packed round a shared exit there
  /// is none.
  bool leaves = false;
  KeepOut keep_out;  ///< Discs its rests keep out of.
  /// Nodes expanded at most; 0: the planner's max_expansions. [>= 0]
  int horizon = 0;
  /// How long a walking other is taken to stand where its plan ends, after
  /// it ends (infinity: for good). A crowd's plans end in provisional rests,
  /// replaced as their agents plan on; taken for good, oncoming agents' rests
  /// fill the way ahead. The steps found are then cut before the first that
  /// runs into a rest taken for good; rests found keep clear of them anyway.
  double rest_grace = std::numeric_limits<double>::infinity();
  /// Nodes expanded without one nearer the goal before the search stops;
  /// 0: the planner's stall_expansions. [>= 0]
  int stall = 0;
};

/// Stop steps that bring a character to rest, and where they leave it.
struct Rest {
  std::vector<Footstep> steps;
  FootstepState state;    ///< After the steps.
  bool complete = false;  ///< False when even the shortest stop would run into an obstacle.
};

/// Result of one footstep search.
struct SearchResult {
  /// kSuccess: the goal was reached, where the character can come to rest
  /// among `others`, outside the keep-out discs, free to set off again
  /// (unless it leaves there).
  /// kPartial: the horizon was reached first and `footsteps` lead to the
  /// closed node with the best heuristic among those the character can come
  /// to rest from, outside the keep-out discs and free to set off again where
  /// it rests (free_to_set_off). A standing start takes only a node nearer the
  /// goal, unless it stands in a keep-out disc; with none, a single wait step.
  /// Also kPartial: steps cut before a rest taken for good (rest_grace);
  /// where the character can rest then is for the caller to find.
  /// kNoPath: not even that is possible. kInvalidStart: the start collides.
  /// kInvalidGoal: the goal lies inside an obstacle.
  Status status = Status::kPartial;
  std::vector<Footstep> footsteps;  ///< The planned steps, in order.
  FootstepState end_state;          ///< State after the last step.
  int nodes_generated = 0;          ///< Valid successors created.
  int nodes_expanded = 0;           ///< Nodes taken off the open list.
  /// Indices into `others` of the agents that turned down a step or a rest
  /// the search tried. Every check asks whether any of `others` is in the
  /// way, so the same search among fewer others, all of these among them,
  /// finds the same.
  std::vector<std::size_t> refused_by;
};

/// Plans footsteps for one character among static obstacles. Stateless between
/// calls; const methods may run on several threads at once.
class FootstepPlanner {
 public:
  /// Validates both parameter sets (std::invalid_argument). `obstacles` must
  /// outlive the planner.
  FootstepPlanner(const CharacterParams& character, const PlannerParams& planner,
                  const ObstacleMap& obstacles);
  ~FootstepPlanner();
  FootstepPlanner(const FootstepPlanner&) = delete;
  FootstepPlanner& operator=(const FootstepPlanner&) = delete;

  /// Best-first search from `start` toward `goal`, bounded by the horizon.
  /// Throws std::invalid_argument for a non-finite or far-away start or goal.
  /// The foot orientations of the result are chosen by the post-process over
  /// these steps alone; a caller that chains searches runs
  /// choose_foot_orientations once more over the whole chain.
  SearchResult plan(const FootstepState& start, Vec2 goal, const MovingObstacles& others = {},
                    const SearchOptions& options = {}) const;

  /// Heuristic of equation 6: the cost of one normal step times the number of
  /// normal steps to the goal (the distance less the goal tolerance). [J]
  double heuristic(const FootstepState& state, Vec2 goal) const;
  /// Cost of one normal step: straight, at the preferred speed and duration. [J]
  double expected_step_cost() const { return expected_step_cost_; }
  /// COM travel of one normal step. [m]
  double expected_step_length() const { return expected_step_length_; }

  /// True if the step collides with an obstacle (its landing foot, or the
  /// torso circles at samples no further apart than the sample spacing), or
  /// if at an instant of the contact grid (every 0.05 s, as the crowd's
  /// commit check and `footfall metrics` sample) its torso or planted foot
  /// touches a circle of one of `others`.
  bool collides(const Footstep& step, const MovingObstacles& others = {}) const;
  /// True if the standing or walking state's planted feet or torso collide.
  bool collides(const FootstepState& state) const;
  /// Brings the character to rest with its feet side by side: a stop to
  /// decelerate (when walking), then one to close the feet, each halved in
  /// duration (down to an eighth) while it would run into an obstacle or one
  /// of `others` (the COM still coasts while it decelerates). The rest is
  /// complete only if the character, standing there, keeps room to turn on
  /// the spot among `others` while their plans last.
  Rest come_to_rest(const FootstepState& state, const MovingObstacles& others = {}) const;
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
  bool free_to_set_off(const FootstepState& rested) const;
  /// The stop step from `state` lasting `duration`, with validity kCollides if
  /// it runs into an obstacle.
  StepResult stop_step(const FootstepState& state, double duration,
                       const MovingObstacles& others = {}) const;
  /// The stop step of the planner's stop_duration.
  StepResult stop_step(const FootstepState& state, const MovingObstacles& others = {}) const;

  /// The character parameters.
  const CharacterParams& character() const { return character_; }
  /// The planner parameters.
  const PlannerParams& params() const { return params_; }

 private:
  struct Node;
  struct Search;
  // A walking action of the discretised set, precomputed in its local frame.
  struct TabledAction;
  void expand(Search& search, int index, Vec2 goal) const;
  // Calls visit(step, phi, shape) for each tabled walking step `foot` may
  // take from `state`, until one call returns true (then returns true).
  template <class Visit>
  bool tabled_walks(const FootstepState& state, Foot foot, Visit&& visit) const;
  // The checks against other agents, reading `others` sampled once per search.
  // `from_standing`: the step sets off from a standing state.
  bool collides(const Footstep& step, detail::SampledAgents& others, bool from_standing) const;
  bool hits_obstacles(const Footstep& step) const;
  bool touches_agents(const Footstep& step, detail::SampledAgents& others,
                      bool from_standing) const;
  void cut_before_rests(const FootstepState& start, detail::SampledAgents& others,
                        SearchResult& result) const;
  Rest come_to_rest(const FootstepState& state, detail::SampledAgents& others) const;
  bool stands_clear(const FootstepState& state, detail::SampledAgents& others) const;
  StepResult stop_step(const FootstepState& state, double duration,
                       detail::SampledAgents& others) const;
  // True if the character comes to rest from `state` among `others`, outside
  // `keep_out`, free to set off from there.
  bool rests_well(const FootstepState& state, detail::SampledAgents& others,
                  const KeepOut& keep_out) const;
  // A side step the search tries from standing, toward `way`: by the foot
  // that did not step last, at kSideStepSpeed, for the stop duration.
  StepResult side_step(const FootstepState& standing, double way) const;

  CharacterParams character_;
  PlannerParams params_;
  const ObstacleMap& obstacles_;
  double expected_step_cost_ = 0;
  double expected_step_length_ = 0;
  double torso_extent_ = 0;  // how far the torso circles reach from the COM [m]
  std::vector<TabledAction> actions_;
};

/// Chooses exact foot orientations (section 4's post-process): each interval
/// is narrowed by the next step's, then, from the first step on, every foot is
/// turned as close as its interval allows to its step's phi. `initial` holds
/// the orientation intervals of both feet before the first step.
void choose_foot_orientations(std::vector<Footstep>& steps,
                              const std::array<OrientationInterval, 2>& initial,
                              const CharacterParams& character);

}  // namespace footfall
