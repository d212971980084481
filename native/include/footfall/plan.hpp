// Footfall — a planned scene (every agent's footsteps) and its analytic
// evaluation at any time.
#pragma once

#include <array>
#include <vector>

#include "footfall/agent_planner.hpp"
#include "footfall/scenario.hpp"

namespace footfall {

/// The plan of a whole scenario.
struct Plan {
  std::vector<AgentPlan> agents;     ///< One per scenario agent, in the same order.
  CharacterParams character;         ///< The character the plan was made for.
  std::vector<Obstacle> obstacles;   ///< The scenario's static obstacles, for measuring the plan.
  Status status = Status::kSuccess;  ///< kCancelled if the run was stopped.
};

/// Plans every agent of a scenario together on its navigation mesh
/// (plan_agents). Deterministic: the same scenario gives bit-identical plans,
/// whatever the number of threads.
Plan plan_scenario(const Scenario& scenario, const RunControl& control = {});

/// A foot at one instant.
struct FootPose {
  Vec2 position;           ///< [m]
  double orientation = 0;  ///< [rad]
  double lift = 0;         ///< Height of the sole above the ground. [m]
  bool planted = true;     ///< On the ground (stance), or swinging.
};

/// COM of the agent at time `t` (before the first step: the start; after the
/// last: where it ends).
ComSample com_at(const AgentPlan& plan, double t);
/// The largest COM speed of the plan from time `from` on (a step's is
/// greatest at one of its ends): a bound for skipping ahead while two plans
/// are far apart. [m/s]
double top_com_speed(const AgentPlan& plan, double from);

/// How far from the COM the plan's collision circles (collision_circles)
/// reach from time `from` on, bounded step by step: the torso's, and each
/// planted foot's from the step's chord ends plus its sway. [m]
double circle_reach(const AgentPlan& plan, const CharacterParams& character, double from);

/// Both feet at time `t`, indexed by Foot. The foot of the current step is
/// planted; the other swings from where it was planted to where the next step
/// plants it, on an arc whose height grows with the stride (a foot that does
/// not move stays planted). The foot of a first step, or of a step from
/// standing by the foot that stopped last, swings in a lead-in of at most
/// 0.25 s (half the step) at the start of its step instead. No foot ever jumps.
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

}  // namespace footfall
