// Footfall — the short-horizon best-first footstep planner (section 4 of Singh
// et al.): A* over footstep states that stops after a fixed number of
// expansions and then returns the path to the most promising closed node.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "footfall/model/footstep.hpp"
#include "footfall/model/obstacles.hpp"
#include "footfall/model/params.hpp"
#include "footfall/model/status.hpp"
#include "footfall/fullbody/step_body_test.hpp"
#include "footfall/plan/section_lookup.hpp"
#include "footfall/planner/validity_checker.hpp"

namespace footfall {

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
  /// The character's annotated way (the full-body planner's sections), if
  /// any: each step takes the behaviour of its section, and inside a
  /// side-step section only lateral steps and stops are tried. Must outlive
  /// the search.
  const SectionLookup* sections = nullptr;
  /// From standing, also pivots of half the smaller tabled pivot (22.5
  /// degrees) either way: a body side-on in a slot may square up to step out
  /// only so. For a search the usual pivots left stuck (a crowd's stuck
  /// agent's second chance); everywhere, they made more agents stuck than
  /// they freed.
  bool fine_pivots = false;
  /// Only a way to the goal is wanted: a search that does not reach it
  /// gives kNoPath at once, not looking for where to stop short of it (most
  /// of a failed search's time in a crowd: a rest is tried at node after node).
  bool reach_or_nothing = false;
};

/// Result of one footstep search.
struct SearchResult {
  /// kSuccess: the goal was reached, where the character can come to rest
  /// among `others`, outside the keep-out discs, free to set off again
  /// (unless it leaves there).
  /// kPartial: the horizon was reached first and `footsteps` lead to the
  /// closed node with the best heuristic among those the character can come
  /// to rest from, outside the keep-out discs and free to set off again where
  /// it rests (ValidityChecker::free_to_set_off). A standing start takes only
  /// a node nearer the goal, unless it stands in a keep-out disc; with none, a
  /// single wait step.
  /// Also kPartial: steps cut before a rest taken for good (rest_grace);
  /// where the character can rest then is for the caller to find.
  /// kNoPath: not even that is possible (with reach_or_nothing: the goal
  /// was not reached). kInvalidStart: the start collides.
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
  /// outlive the planner, and so must `body`: with it, every step a search
  /// expands must also pass the full-body test against the obstacles in 3-D
  /// (whole_body()), a walking step labelled arms_in where only the arms
  /// held in clear them.
  FootstepPlanner(const CharacterParams& character, const PlannerParams& planner,
                  const ObstacleMap& obstacles, const StepBodyTest* body = nullptr,
                  const Ground* ground = nullptr);
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
  /// normal steps to the goal (the distance less the goal tolerance); on
  /// ground, and the climbs on the straight way there. [J]
  double heuristic(const FootstepState& state, Vec2 goal) const;
  /// Cost of one normal step: straight, at the preferred speed and duration. [J]
  double expected_step_cost() const { return expected_step_cost_; }
  /// COM travel of one normal step. [m]
  double expected_step_length() const { return expected_step_length_; }

  /// The character parameters.
  const CharacterParams& character() const { return validity_.character(); }
  /// The planner parameters.
  const PlannerParams& params() const { return validity_.params(); }

  /// The checks the search applies, for callers that check states and steps
  /// the same way (a crowd's rests, room and commits).
  const ValidityChecker& validity() const { return validity_; }
  /// The full-body checks of a search following `sections` (SearchOptions;
  /// null: walk everywhere), for its callers' rests and waits: none without
  /// a body.
  std::optional<WholeBody> whole_body(const SectionLookup* sections) const;
  /// True if every step it gives passed the full-body test, in the
  /// behaviour it is labelled with.
  bool tests_body() const { return body_ != nullptr; }

 private:
  struct Node;
  struct Search;
  void expand(Search& search, int index, Vec2 goal) const;
  /// On ground, node `index`'s walking step planted off it (a nosing, a
  /// riser too high) is taken again landing a little nearer or further,
  /// where the ground holds it: a stair's tread is barely longer than a sole.
  void land_on_ground(Search& search, int index, Vec2 goal) const;
  /// On ground, the cost of the climbs on the straight way from `from`, on
  /// the level near the height `z`, to `goal` (ValidityChecker's climb_cost,
  /// kept per 0.1 m cell and level); 0 without.
  double climb_to(Vec2 from, double z, Vec2 goal) const;

  ValidityChecker validity_;
  const StepBodyTest* body_ = nullptr;
  double expected_step_cost_ = 0;
  double expected_step_length_ = 0;
};

/// Chooses exact foot orientations (section 4's post-process): each interval
/// is narrowed by the next step's, then, from the first step on, every foot is
/// turned as close as its interval allows to its step's phi. `initial` holds
/// the orientation intervals of both feet before the first step.
void choose_foot_orientations(std::vector<Footstep>& steps,
                              const std::array<OrientationInterval, 2>& initial,
                              const CharacterParams& character);

}  // namespace footfall
