// Footfall — the character and planner parameters. Plain structs with the
// paper's defaults (Singh et al., "Footstep Navigation for Dynamic Crowds",
// section 5); every field names its unit and valid range, and validate()
// enforces the ranges.
#pragma once

#include <string>
#include <vector>

namespace footfall {

/// Limits on the steps taken by one foot. Separate limits per foot make a limp
/// a parameter change (section 3.2).
struct FootLimits {
  double min_step_duration = 0.2;  ///< Shortest step. [s] [> 0]
  double max_step_duration = 0.8;  ///< Longest step. [s] [>= min_step_duration, <= 5]
  double min_step_length = 0.1;    ///< Shortest COM travel (chord) over a walking step. [m] [> 0]
  double max_step_length =
      1.0;  ///< Longest COM travel (chord) over a walking step. [m] [>= min_step_length, <= 3]
  double min_speed = 0.2;  ///< Slowest desired COM speed of a walking step. [m/s] [> 0]
  double max_speed =
      2.5;  ///< Fastest desired COM speed of a walking step. [m/s] [>= min_speed, <= 10]
};

/// The walking character: pendulum model, energy model and collision model.
struct CharacterParams {
  double com_height = 1.0;  ///< Height of the centre of mass, the pendulum length. [m] [0.2, 3]
  double mass = 70.0;       ///< Body mass m. [kg] (0, 500]
  /// Fixed energy rate R (equation 3). The default puts the cheapest cost per
  /// metre of the default gaits at the preferred speed. [J/s] [0, 1e5]
  double energy_rate = 150.0;
  double curvature_weight =
      0.35;  ///< Curvature weight w (equation 5); the paper uses 0.2-0.5. [1] [0, 1]
  double foot_offset =
      0.1;  ///< Lateral distance d from the COM to the stance foot at rest. [m] (0, 0.5]
  double torso_width = 0.6;      ///< Shoulder to shoulder. [m] (0, 1.5]
  double torso_radius = 0.15;    ///< Radius of the central torso circle. [m] (0, torso_width / 2]
  double shoulder_radius = 0.1;  ///< Radius of each shoulder circle; its outer edge is at
                                 ///< torso_width / 2. [m] (0, torso_width / 2]
  double foot_radius = 0.08;     ///< Radius of a planted foot's circle. [m] (0, 0.5]
  double preferred_speed = 1.3;  ///< Speed of a normal step, used by the heuristic. [m/s] (0, 10]
  double preferred_step_duration =
      0.5;  ///< Duration of a normal step, used by the heuristic. [s] (0, 5]
  /// How far the next foot may turn outward past the previous foot's inner
  /// bound (the pi/2 of the orientation rule, section 3.2). [rad] (0, pi]
  double max_foot_turn = 1.5707963267948966;
  FootLimits left;   ///< Limits on left-foot steps.
  FootLimits right;  ///< Limits on right-foot steps.
};

/// One walking gait of the discretised action space: a desired speed and a
/// step duration, paired because the two are inversely correlated (section 4).
struct Gait {
  double speed = 1.3;     ///< Desired COM speed. [m/s] (0, 10]
  double duration = 0.5;  ///< Step duration. [s] (0, 5]
};

/// The short-horizon best-first footstep planner (section 4).
struct PlannerParams {
  int max_expansions = 1000;  ///< Horizon: nodes expanded per search. [1] [1, 1000000]
  /// A search that has expanded no node nearer its goal (lower h) for this
  /// many nodes stops there, as at the horizon; 0: never. [1] [0, 1000000]
  int stall_expansions = 300;
  /// Weight of h in f = g + weight * h. 1 is the paper's plain A*; the
  /// default 1.5 leans the search toward the goal and expands 3-10 times
  /// fewer nodes around obstacles (equation 6's h is not admissible, so this
  /// is a preference, not a bound on the cost). [1] [1, 10]
  double heuristic_weight = 1.5;
  /// The goal is reached when the COM is this close. [m] (0, 10], < local_goal_distance
  double goal_tolerance = 0.3;
  /// Each search aims at most this far along the way. [m] [1, 1000]
  double local_goal_distance = 10;
  double max_time = 300;       ///< Simulated time limit per agent. [s] (0, 100000]
  double stop_duration = 0.5;  ///< Duration of a stop (or wait) step. [s] (0, 5]
  /// Largest COM travel between two collision samples; circles are padded by
  /// half of it, so a thin obstacle is never stepped through. [m] [0.005, 0.05]
  double collision_sample_spacing = 0.05;
  /// A search that shortens the agent's way to its goal by less than this
  /// gains nothing; in a crowd, 15 s without a gain means stuck. [m] (0, 10]
  double min_progress = 0.05;
  /// Gaits tried at every expansion. Three are enough with the goal-directed
  /// phi (section 4); more cost time, not quality. [non-empty, at most 16]
  std::vector<Gait> gaits{{0.6, 0.65}, {1.3, 0.5}, {1.6, 0.45}};
  /// Parabola orientations tried at every expansion, as inward angles between
  /// the incoming velocity and phi; the chord turns by twice the angle, so
  /// values near pi/2 are almost U-turns. Small ones matter most: the
  /// goal-directed phi covers the rest. [rad] each in (0, pi/2) [at most 32]
  std::vector<double> turn_angles{0.04, 0.15, 0.35, 0.7, 1.1, 1.4};
};

/// Throws std::invalid_argument naming the field (prefixed by `path`, e.g.
/// "character.left.max_speed") and the limit it breaks.
void validate(const CharacterParams& params, const std::string& path = "character");
/// Throws std::invalid_argument naming the field and the limit it breaks.
void validate(const PlannerParams& params, const std::string& path = "planner");

}  // namespace footfall
