// Footfall — a planned scene (every agent's footsteps) and its analytic
// evaluation at any time.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "footfall/model/footstep.hpp"
#include "footfall/model/obstacles.hpp"
#include "footfall/model/params.hpp"
#include "footfall/model/status.hpp"

namespace footfall {

/// How an agent's plan ended.
enum class AgentStatus {
  kReached,  ///< Every goal was reached; the agent stands at the last one.
  kPartial,  ///< The walk ended early; `AgentPlan::reason` says why.
};
/// "reached" or "partial".
const char* to_string(AgentStatus status);

/// The plan of one agent: its start and its timed footsteps.
/// One section of an agent's way, with the behaviour that passes it (the
/// full-body planner's annotated path, fullbody/behavioral_planner.hpp).
struct BehaviorSection {
  Behavior behavior = Behavior::kWalk;
  double clearance = 0;      ///< Radius of the path query the section came from. [m]
  std::vector<Vec2> points;  ///< From the section's start to its end. [m]
  double length = 0;         ///< [m]
};

/// Where the way to a goal an agent cannot reach is narrowest (its reason
/// "unreachable"): the narrowest point of the widest way there, which its
/// narrowest behaviour does not pass.
struct Narrowest {
  Vec2 at;            ///< The narrowest point; where it stands, if no way leads there. [m]
  double width = 0;   ///< Free width there: twice the clearance; 0 if no way leads there. [m]
  double needs = 0;   ///< The width its body needs with `behavior`: twice that clearance. [m]
  Behavior behavior = Behavior::kSideStep;  ///< The narrowest behaviour.
};

/// "cannot reach its goal: the way at (1.20, 3.40) is 0.25 m wide, its body
/// needs 0.42 m side-stepping" (or "...: no way leads there" for width 0).
std::string unreachable_text(const Narrowest& narrowest);

struct AgentPlan;

/// Why a partial agent stands short of its goals, for the user: its
/// unreachable_text, or "stands at (1.20, 3.40) short of its goal: its time
/// limit ran out" (walled in by others, or too slow for its way), "...: no
/// step it could take led on" (stuck) or "...: planning was cancelled".
std::string short_of_goal_text(const AgentPlan& agent);

struct AgentPlan {
  std::string name;                            ///< The agent's name.
  AgentStatus status = AgentStatus::kPartial;  ///< Reached or partial.
  /// Empty when reached; otherwise "unreachable", "stuck", "time limit" or
  /// "cancelled".
  std::string reason;
  /// With reason "unreachable": where its way is too narrow for its body. It
  /// walks to the nearest point before there where it stands clear, and
  /// stands; goals after the one it cannot reach are not visited.
  std::optional<Narrowest> narrowest;
  Vec2 stuck_at;                    ///< Where the agent stopped, when partial. [m]
  FootstepState start;              ///< Standing start state.
  std::vector<Footstep> footsteps;  ///< The timed footsteps, in order.
  int goals_reached = 0;            ///< Goals reached, in order.
  /// The agent walked through its last goal and is gone after its last step
  /// (present_at): no one can meet it there.
  bool leaves = false;
  int searches = 0;               ///< Footstep searches run.
  long long nodes_generated = 0;  ///< Summed over the searches.
  long long nodes_expanded = 0;   ///< Summed over the searches.
  /// The annotated way from the start through every goal, joined end to end,
  /// then for an agent stuck in a crowd its way annotated anew from where it
  /// stood; each footstep's behaviour is that of its section.
  std::vector<BehaviorSection> sections;
  /// The agent's own character, where it has one (a scenario's per-agent
  /// `character`); null: the plan's. Its body is measured with it.
  std::shared_ptr<const CharacterParams> character;
  /// Its body's size as a share of the rig's: the animation scales the rig
  /// by it (the scenario's per-agent `scale`). [kLeastScale, kMostScale]
  double scale = 1;

  /// Sum of the step costs. [J]
  double total_cost() const;
  /// Time at the end of the last step. [s] (Inline: crowd checks ask it
  /// at every sample.)
  double end_time() const { return footsteps.empty() ? 0.0 : footsteps.back().end_time; }
};

/// The character an agent walks with: its own, else `shared` (the plan's).
inline const CharacterParams& character_of(const AgentPlan& plan, const CharacterParams& shared) {
  return plan.character ? *plan.character : shared;
}

/// False once an agent that leaves has taken its last step.
inline bool present_at(const AgentPlan& plan, double t) {
  return !plan.leaves || t <= plan.end_time();
}

/// The latest time a plan may hold: twice the longest time limit the planner
/// takes (PlannerParams::max_time), so that a plan read from a file costs a
/// bounded effort to evaluate and measure. [s]
constexpr double kMaxPlanTime = 2e5;

/// The plan of a whole scenario.
struct Plan {
  std::vector<AgentPlan> agents;     ///< One per scenario agent, in the same order.
  CharacterParams character;         ///< The character the plan was made for.
  std::vector<Obstacle> obstacles;   ///< The scenario's static obstacles, for measuring the plan.
  /// The scenario's ground (ground/ground.hpp's surfaces); empty: the plane
  /// z = 0.
  std::vector<Obstacle> ground;
  Status status = Status::kSuccess;  ///< kCancelled if the run was stopped.
};

/// A foot at one instant.
struct FootPose {
  Vec2 position;           ///< [m]
  double orientation = 0;  ///< [rad]
  double lift = 0;         ///< Height of the sole above the ground. [m]
  bool planted = true;     ///< On the ground (stance), or swinging.
  /// The height of the ground under it where it was planted last (its
  /// step's foot_height; 0 on flat ground), and, while swinging, under where
  /// it will be. [m]
  double ground = 0, swing_to_ground = 0;
  /// While swinging: from where and which way it was planted, to where and
  /// which way it will be, and how far through the swing it is (0 to 1; the
  /// position and orientation follow it eased in and out).
  Vec2 swing_from, swing_to;            ///< [m]
  double swing_from_orientation = 0, swing_to_orientation = 0;  ///< [rad]
  double swing_phase = 0;
};

/// COM of the agent at time `t` (before the first step: the start; after the
/// last: where it ends).
ComSample com_at(const AgentPlan& plan, double t);
/// The height of the ground the agent stands on at time `t`: the planted
/// foot's of the step under way (before the first step, the higher of the
/// start's feet; after the last, its foot's); 0 on flat ground. [m]
double ground_at(const AgentPlan& plan, double t);
/// True if two agents standing on ground at heights `a` and `b` are on
/// levels apart, a body's height (`headroom`) or more (a street and a bridge's
/// deck over it): they never meet, whatever their places in plan.
inline bool levels_apart(double a, double b, double headroom) {
  return std::fabs(a - b) >= headroom;
}
/// The largest COM speed of the plan from time `from` on (a step's is
/// greatest at one of its ends): a bound for skipping ahead while two plans
/// are far apart. [m/s]
double top_com_speed(const AgentPlan& plan, double from);

/// How far from the COM the plan's collision circles (collision_circles)
/// reach from time `from` on, bounded step by step: the torso's, and each
/// planted foot's from the step's chord ends plus its sway. `character` is
/// the plan's shared one: an agent's own (AgentPlan::character) wins, here
/// and in PlanBounds and collision_circles. [m]
double circle_reach(const AgentPlan& plan, const CharacterParams& character, double from);

/// top_com_speed, circle_reach and a box round the COM path of one plan,
/// from any time on, found in O(log steps): kept per step as maxima over the
/// steps from there on. A crowd checks every plan against dozens of others
/// at every commit and search; scanning each plan's steps for these would cost
/// more than the checks they skip. A copy of what it needs: rebuild it whenever
/// the plan changes.
class PlanBounds {
 public:
  /// The plan's bounds from a time on.
  struct From {
    double top_speed = 0.0;  ///< top_com_speed(plan, from), the same to the bit. [m/s]
    double reach = 0.0;      ///< circle_reach(plan, character, from), the same to the bit. [m]
    /// Holds the COM: the chords of the steps from the one under way on,
    /// grown by their sway (and the start, before the first step).
    Box com_box;
  };

  PlanBounds() = default;
  PlanBounds(const AgentPlan& plan, const CharacterParams& character);
  /// The bounds from time `from` on.
  From from(double from) const;

 private:
  /// The steps' start times, searched apart from the bounds: a crowd asks
  /// for the bounds of dozens of plans at every commit. [s]
  std::vector<double> starts_;
  std::vector<From> suffix_;  ///< [i]: from step i on (the start's feet left out).
  From start_;  ///< Standing at the start: circle_reach's feet term, and the start COM.
};

/// How high a swinging foot is lifted over the line between its footholds,
/// `u` of the way through a swing of `stride`. [m]
double swing_lift(double stride, double u);

/// Both feet at time `t`, indexed by Foot. The foot of the current step is
/// planted; the other swings from where it was planted to where the next step
/// plants it, on an arc whose height grows with the stride (a foot that does
/// not move stays planted). The foot of a first step, or of a step from
/// standing by the foot that stopped last, swings in a lead-in of at most
/// 0.25 s (half the step) at the start of its step instead. During the last
/// step of an agent that leaves, the other foot swings a stride on (two COM
/// chords of that step), as the next step would: it walks off. No foot ever
/// jumps.
std::array<FootPose, 2> feet_at(const AgentPlan& plan, double t);

/// Torso facing at time `t`: phi of the current step. [rad]
double facing_at(const AgentPlan& plan, double t);

/// The collision circles of figure 1c at time `t`: three torso circles, then
/// one per planted foot (so four while a foot swings, five when both are down);
/// none once an agent that leaves is gone.
std::vector<Circle> collision_circles(const AgentPlan& plan, const CharacterParams& character,
                                      double t);

/// The same circles without allocating (crowd checks ask for millions):
/// they go to `out`, and the count is returned.
int collision_circles(const AgentPlan& plan, const CharacterParams& character, double t,
                      std::array<Circle, 5>& out);

/// How many of the plan's first steps may be dropped, with its start moved
/// to the state after them (drop_steps), leaving every answer about time
/// `from` and later the same to the bit: com_at, facing_at, feet_at,
/// collision_circles and PlanBounds::from. The steps kept reach back from the
/// one under way at `from` to where each foot was last planted before it
/// (feet_at reads those). A crowd keeps only what is still to be checked.
std::size_t droppable_steps(const AgentPlan& plan, double from);
/// Moves the plan's first `count` steps to the end of `past` and its start
/// to the state after them. (`past` holds what was dropped before.)
void drop_steps(AgentPlan& plan, std::size_t count, std::vector<Footstep>& past);

/// com_at and collision_circles of one plan, the same to the bit, for times
/// that mostly grow (a check walking through its instants, the crowd's
/// ticks): each step under way is found from the last, not searched for
/// again. An earlier time, or a plan cut short since, is searched for anew.
class PlanWalk {
 public:
  explicit PlanWalk(const AgentPlan& plan) : plan_(&plan) {}
  ComSample com_at(double t);
  int collision_circles(const CharacterParams& character, double t, std::array<Circle, 5>& out);

 private:
  /// The step under way at t, as com_at(plan, t) finds it.
  int step(double t);
  const AgentPlan* plan_;
  int step_ = -1;  ///< None yet.
};

}  // namespace footfall
