// Footfall — the character and planner parameters: plain structs with the
// paper's defaults (Singh et al., "Footstep Navigation for Dynamic Crowds",
// section 5), each followed by its table, which declares every field's name,
// unit, valid range and meaning once (param_table.hpp). validate() enforces
// the ranges; the files, the Python module and docs/parameters.md read the
// same tables.
#pragma once

#include <string>
#include <tuple>
#include <vector>

#include "footfall/model/body.hpp"
#include "footfall/model/param_table.hpp"

namespace footfall {

/// Limits on the steps taken by one foot. Separate limits per foot make a limp
/// a parameter change (section 3.2). Fields: ParamTable<FootLimits>.
struct FootLimits {
  double min_step_duration = 0.2;
  double max_step_duration = 0.8;
  double min_step_length = 0.1;
  double max_step_length = 1.0;
  double min_speed = 0.2;
  double max_speed = 2.5;
};

/// The fastest speed any speed parameter may ask for. [m/s]
constexpr double kMostSpeed = 10.0;

template <>
struct ParamTable<FootLimits> {
  using S = FootLimits;
  static constexpr const char* name = "FootLimits";
  static constexpr auto fields = std::make_tuple(
      param("min_step_duration", &S::min_step_duration, "s", above_up_to(0, 5), "Shortest step."),
      param("max_step_duration", &S::max_step_duration, "s", from_field("min_step_duration", 5),
            "Longest step."),
      param("min_step_length", &S::min_step_length, "m", above_up_to(0, 3),
            "Shortest COM travel (chord) over a walking step."),
      param("max_step_length", &S::max_step_length, "m", from_field("min_step_length", 3),
            "Longest COM travel (chord) over a walking step."),
      param("min_speed", &S::min_speed, "m/s", above_up_to(0, kMostSpeed),
            "Slowest desired COM speed of a walking step."),
      param("max_speed", &S::max_speed, "m/s", from_field("min_speed", kMostSpeed),
            "Fastest desired COM speed of a walking step."));
};

/// The walking character: pendulum model, energy model and collision model.
/// Fields: ParamTable<CharacterParams>.
struct CharacterParams {
  double com_height = 1.0;
  double mass = 70.0;
  double energy_rate = 150.0;
  double curvature_weight = 0.35;
  double foot_offset = 0.1;
  double torso_width = 0.6;
  double torso_radius = 0.15;
  double shoulder_radius = 0.1;
  double foot_radius = 0.08;
  double preferred_speed = 1.3;
  double preferred_step_duration = 0.5;
  double max_foot_turn = 1.5707963267948966;
  double body_height = 1.75;
  double shoulder_width = 0.46;
  double chest_depth = 0.26;
  double arm_swing_width = 0.62;
  double arm_radius = 0.045;
  double leg_radius = 0.065;
  double side_step_speed = 0.6;
  double walk_clearance = 0;
  double arms_in_clearance = 0;
  double side_step_clearance = 0;
  double max_step_up = 0.25;
  double max_step_down = 0.3;
  double max_slope = 0.4363323129985824;
  double sole_support = 0.85;
  double sole_length = 0.26;
  double sole_width = 0.1;
  FootLimits left;
  FootLimits right;
  /// Sampled motions per behaviour (index: Behavior), from the scenario's
  /// "behaviors"; an empty one is the built-in motion (fullbody/body_model.hpp).
  std::array<BehaviorMotion, 3> motions;
};

template <>
struct ParamTable<CharacterParams> {
  using S = CharacterParams;
  static constexpr const char* name = "CharacterParams";
  static constexpr auto fields = std::make_tuple(
      param("com_height", &S::com_height, "m", closed(0.2, 3),
            "Height of the centre of mass, the pendulum length."),
      param("mass", &S::mass, "kg", above_up_to(0, 500), "Body mass m."),
      param("energy_rate", &S::energy_rate, "J/s", closed(0, 1e5),
            "Fixed energy rate R (equation 3). The default puts the cheapest cost per metre of "
            "the default gaits at the preferred speed."),
      param("curvature_weight", &S::curvature_weight, "1", closed(0, 1),
            "Curvature weight w (equation 5); the paper uses 0.2-0.5."),
      param("foot_offset", &S::foot_offset, "m", above_up_to(0, 0.5),
            "Lateral distance d from the COM to the stance foot at rest."),
      param("torso_width", &S::torso_width, "m", above_up_to(0, 1.5), "Shoulder to shoulder."),
      param("torso_radius", &S::torso_radius, "m", above_up_to_field(0, "torso_width", 0.5),
            "Radius of the central torso circle."),
      param("shoulder_radius", &S::shoulder_radius, "m",
            above_up_to_field(0, "torso_width", 0.5),
            "Radius of each shoulder circle; its outer edge is at torso_width / 2."),
      param("foot_radius", &S::foot_radius, "m", above_up_to(0, 0.5),
            "Radius of a planted foot's circle."),
      param("preferred_speed", &S::preferred_speed, "m/s", above_up_to(0, kMostSpeed),
            "Speed of a normal step, used by the heuristic."),
      param("preferred_step_duration", &S::preferred_step_duration, "s", above_up_to(0, 5),
            "Duration of a normal step, used by the heuristic."),
      param("max_foot_turn", &S::max_foot_turn, "rad", above_up_to(0, 3.141592653589793),
            "How far the next foot may turn outward past the previous foot's inner bound (the "
            "pi/2 of the orientation rule, section 3.2)."),
      param("body_height", &S::body_height, "m", closed(0.5, 3),
            "Standing height. Obstacles whose underside is at or above it (on ground, above the "
            "ground under them) are left out of the navigation mesh and the footsteps' "
            "collision model."),
      param("shoulder_width", &S::shoulder_width, "m", above_up_to(0, 1.5),
            "Across the outside of the shoulders and the upper arms hanging at rest."),
      param("chest_depth", &S::chest_depth, "m", above_up_to(0, 1), "Front to back at the chest."),
      param("arm_swing_width", &S::arm_swing_width, "m", from_field("shoulder_width", 3),
            "The hands' widest lateral extent, hand to hand, during the built-in walk's swing."),
      param("arm_radius", &S::arm_radius, "m", above_up_to(0, 0.3),
            "Radius of the arm capsules (the hand is inside the forearm's)."),
      param("leg_radius", &S::leg_radius, "m", above_up_to(0, 0.3),
            "Radius of the thigh and shin capsules."),
      param("side_step_speed", &S::side_step_speed, "m/s", above_up_to(0, 5),
            "Travel speed of the built-in side-step motion."),
      param("walk_clearance", &S::walk_clearance, "m", closed(0, 2),
            "Clearance c3 of walking; 0: derived from the body and its motion "
            "(docs/full-body.md)."),
      param("arms_in_clearance", &S::arms_in_clearance, "m", closed(0, 2),
            "Clearance c2 of walking with the arms in; 0: derived."),
      param("side_step_clearance", &S::side_step_clearance, "m", closed(0, 2),
            "Clearance c1 of side-stepping; 0: derived."),
      param("max_step_up", &S::max_step_up, "m", above_up_to(0, 1),
            "On ground: the highest a foothold may lie above the other foot's. Stair risers "
            "are 0.15-0.20 m and kerbs up to about 0.2 m; a humanoid robot's footstep planner "
            "allows 0.28 m."),
      param("max_step_down", &S::max_step_down, "m", above_up_to(0, 1),
            "On ground: the lowest a foothold may lie below the other foot's."),
      param("max_slope", &S::max_slope, "rad", above_up_to(0, 1.2),
            "On ground: the steepest slope a foot stands on (25 degrees; Minetti et al. 2002 "
            "measured walking on gradients up to 45 %, 24 degrees)."),
      param("sole_support", &S::sole_support, "1", above_up_to(0, 1),
            "On ground: the share of the sole that must rest on walkable ground within 2 cm "
            "of its plane (a robot footstep planner's default is 85 %)."),
      param("sole_length", &S::sole_length, "m", above_up_to(0, 1),
            "Heel to toe, for the ground's support of a foothold."),
      param("sole_width", &S::sole_width, "m", above_up_to_field(0, "sole_length", 1),
            "Across the sole, for the ground's support of a foothold."),
      nested_param("left", &S::left, "Limits on left-foot steps."),
      nested_param("right", &S::right, "Limits on right-foot steps."));
};

/// The fields of CharacterParams that only ground (a scenario's "ground")
/// uses: plans of flat scenarios leave them out of their files.
constexpr const char* kGroundCharacterFields[] = {"max_step_up",  "max_step_down", "max_slope",
                                                  "sole_support", "sole_length",   "sole_width"};

/// One walking gait of the discretised action space: a desired speed and a
/// step duration, paired because the two are inversely correlated (section 4).
struct Gait {
  double speed = 1.3;
  double duration = 0.5;
};

template <>
struct ParamTable<Gait> {
  using S = Gait;
  static constexpr const char* name = "Gait";
  static constexpr auto fields =
      std::make_tuple(param("speed", &S::speed, "m/s", above_up_to(0, kMostSpeed),
                            "Desired COM speed."),
                      param("duration", &S::duration, "s", above_up_to(0, 5), "Step duration."));
};

/// The longest time limit an agent can have (PlannerParams::max_time, an
/// agent's own time_limit). [s]
constexpr double kMaxTimeLimit = 1e5;

/// The short-horizon best-first footstep planner (section 4).
/// Fields: ParamTable<PlannerParams>.
struct PlannerParams {
  int max_expansions = 1000;
  int stall_expansions = 300;
  double heuristic_weight = 1.5;
  double goal_tolerance = 0.3;
  double local_goal_distance = 10;
  double max_time = 300;
  double stop_duration = 0.5;
  double collision_sample_spacing = 0.05;
  double min_progress = 0.05;
  double pose_rate = 30;
  double point_obstacle_fraction = 0.5;
  double detour_limit = 2.0;
  double behavior_horizon = 1000;
  double behavior_time_limit = 0.5;
  int follow_sections = 1;
  std::vector<Gait> gaits{{0.6, 0.65}, {1.3, 0.5}, {1.6, 0.45}};
  std::vector<double> turn_angles{0.04, 0.15, 0.35, 0.7, 1.1, 1.4};
};

template <>
struct ParamTable<PlannerParams> {
  using S = PlannerParams;
  static constexpr const char* name = "PlannerParams";
  static constexpr auto fields = std::make_tuple(
      param("max_expansions", &S::max_expansions, "1", closed(1, 1000000),
            "Horizon: nodes expanded per search. A search also stops once it holds 500,000 "
            "nodes (about 180 MB), whatever the horizon; the default horizon holds some 50,000."),
      param("stall_expansions", &S::stall_expansions, "1", closed(0, 1000000),
            "A search that has expanded no node nearer its goal (lower h) for this many nodes "
            "stops there, as at the horizon; 0: never."),
      param("heuristic_weight", &S::heuristic_weight, "1", closed(1, 10),
            "Weight of h in f = g + weight * h. 1 is the paper's plain A*; 1.5 leans the search "
            "toward the goal and expands far fewer nodes around obstacles (equation 6's "
            "h is not admissible, so this is a preference, not a bound on the cost)."),
      param("goal_tolerance", &S::goal_tolerance, "m",
            and_below(above_up_to(0, 10), "local_goal_distance"),
            "The goal is reached when the COM is this close."),
      param("local_goal_distance", &S::local_goal_distance, "m", closed(1, 1000),
            "Each search aims at most this far along the way."),
      param("max_time", &S::max_time, "s", above_up_to(0, kMaxTimeLimit),
            "Simulated time limit of an agent without a time_limit of its own, at least: one "
            "whose route (through its goals, in straight lines) takes longer than a quarter of "
            "it at the preferred speed gets four times that walking time (up to 100000 s)."),
      param("stop_duration", &S::stop_duration, "s", above_up_to(0, 5),
            "Duration of a stop (or wait) step."),
      param("collision_sample_spacing", &S::collision_sample_spacing, "m", closed(0.005, 0.05),
            "Largest COM travel between two collision samples; circles are padded by half of "
            "it, so a thin obstacle is never stepped through."),
      param("min_progress", &S::min_progress, "m", above_up_to(0, 10),
            "A search that shortens the agent's way to its goal by less than this gains "
            "nothing; in a crowd, 15 s without a gain means stuck."),
      param("pose_rate", &S::pose_rate, "1/s", closed(1, 1000),
            "Body poses tested per second of motion by the full-body planner."),
      param("point_obstacle_fraction", &S::point_obstacle_fraction, "1", open_range(0, 1),
            "Where the full-body planner puts a point obstacle, from the floor projection of "
            "the colliding limb point (0) to the root (1)."),
      param("detour_limit", &S::detour_limit, "m", closed(0, 1000),
            "l_t: a path bent by point obstacles is taken unless it is longer than this much "
            "over the path it replaces; else a narrower behaviour is tried."),
      param("behavior_horizon", &S::behavior_horizon, "m", above_up_to(0, 1e9),
            "h: the full-body planner annotates the way up to this far; the rest is cut."),
      param("behavior_time_limit", &S::behavior_time_limit, "s", above_up_to(0, 3600),
            "Wall-clock limit of one full-body query; past it the best complete annotated "
            "path so far is returned."),
      param("follow_sections", &S::follow_sections, "1", closed(0, 1),
            "1: an agent whose annotated way has a section other than walk follows it: its "
            "way is the annotated one, its steps take their sections' behaviours (the arms in "
            "narrow the torso; only lateral steps inside side-step sections), its shoulders "
            "are judged by the full-body test alone, and it may rest where it cannot turn. "
            "0: steps follow the mesh's way, each labelled with the behaviour the full-body "
            "test passed it in (walk, arms_in where only that passes, side_step for lateral "
            "steps; docs/full-body.md)."),
      StructListParam<S, Gait>{"gaits", &S::gaits, 1, 16, "gaits",
                               "Gaits tried at every expansion. Three are enough with the "
                               "goal-directed phi (section 4); more cost time, not quality."},
      NumberListParam<S>{"turn_angles", &S::turn_angles, 1, 32, "angles", "rad",
                         open_range(0, 1.5707963267948966),
                         "Parabola orientations tried at every expansion, as inward angles "
                         "between the incoming velocity and phi; the chord turns by twice the "
                         "angle, so values near pi/2 are almost U-turns. Small ones matter "
                         "most: the goal-directed phi covers the rest."});
};

/// The smallest and largest body size an agent's `scale` may give (the
/// default character's parameters stay in their ranges: a child of about
/// 0.9 m to a giant of 2.8 m).
constexpr double kLeastScale = 0.5, kMostScale = 1.6;
constexpr const char* kScaleRange = "must be in [0.5, 1.6]";
/// True if `scale` is in [kLeastScale, kMostScale] (NaN is not).
constexpr bool in_scale_range(double scale) { return scale >= kLeastScale && scale <= kMostScale; }

/// The character `scale` times as large: every length (the body, its
/// motions' capsules, the step lengths, the clearances) times `scale`;
/// speeds and durations times its square root, so that it walks alike
/// (equal Froude number, as a rig's character is derived:
/// blender_addon/footfall/core/character.py); mass and energy rate kept.
CharacterParams scaled(const CharacterParams& character, double scale);

/// Throws std::invalid_argument naming the field (prefixed by `path`, e.g.
/// "character.left.max_speed") and the limit it breaks.
void validate(const CharacterParams& params, const std::string& path = "character");
/// Throws std::invalid_argument naming the field and the limit it breaks.
void validate(const PlannerParams& params, const std::string& path = "planner");

}  // namespace footfall
