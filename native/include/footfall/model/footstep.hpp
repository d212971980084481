// Footfall — the footstep model of Singh et al. (section 3): a step is a
// parabolic arc of the centre of mass (COM) around a planted foot.
//
// Local parabola space (equation 1): x(t) = vx0 t, y(t) = alpha t^2 for
// t in [-T/2, T/2], the stance foot at (0, -d). The step is symmetric about
// the vertex, so its incoming velocity (vx0, -alpha T) fixes alpha from the
// duration T. The +x axis points along phi; +y points away from the stance
// foot, so the left foot's local frame is the mirror image of the right's.
#pragma once

#include <array>
#include <string>

#include "footfall/model/geometry.hpp"
#include "footfall/model/params.hpp"

namespace footfall {

/// Which foot.
enum class Foot { kLeft, kRight };

/// The other foot.
inline Foot other(Foot foot) { return foot == Foot::kLeft ? Foot::kRight : Foot::kLeft; }
/// +1 for the left foot (outward is counter-clockwise), -1 for the right.
inline double outward_sign(Foot foot) { return foot == Foot::kLeft ? 1.0 : -1.0; }
/// "left" or "right".
const char* to_string(Foot foot);

/// What a step does with the feet and the centre of mass (the footstep model).
/// Its behaviour (Behavior) is another axis: the posture of the path section
/// the step belongs to, which the animation plays. A lateral step is always
/// of a side-step section; a side-step section may also hold the stop that
/// ends it, and a walk may belong to an arms-in section.
enum class StepKind {
  kWalk,  ///< A parabolic step (equation 1).
  kStop,  ///< The special stop action: the COM comes to rest, the feet side by side.
  /// From standing, the COM moves across the facing to the stepping foot's
  /// side and comes to rest there; the torso keeps its facing.
  kSideStep,
  /// The beginning of a walk from standing whose foot had no step of the
  /// other to swing in (split_set_off): this foot stays planted where it
  /// stands while the walk's foot swings to its place and the COM sets off.
  kStart,
};

/// Longest swing of a foot into the first step of a walk from standing: the
/// duration of a start (split_set_off), or of the lead-in when a plan (from
/// an older planner) has none. [s]
constexpr double kSetOffSwing = 0.25;
/// Largest turn of one pivot: a stop from standing that turns the character
/// on the spot (FootstepAction::phi). [rad]
constexpr double kMaxPivot = 1.5707963267948966;
/// Largest angle between a side step's way (FootstepAction::phi) and straight
/// across the facing: a side step may lean a little forward or back. [rad]
constexpr double kMaxSideStepSkew = 0.39269908169872414;
/// "walk", "stop", "side_step" or "start".
const char* to_string(StepKind kind);

/// The behaviour of the path section a step belongs to (Juarez-Perez and
/// Kallmann): regular walking, walking with the arms held in, lateral
/// side-stepping. Steps take it from their agent's annotated way
/// (plan/section_lookup.hpp); a lateral step (StepKind::kSideStep) is always
/// kSideStep.
enum class Behavior { kWalk, kArmsIn, kSideStep };
/// "walk", "arms_in" or "side_step".
const char* to_string(Behavior behavior);

/// An interval of valid foot orientations (section 3.2), as world angles.
/// `outer` lies outward of `inner` (counter-clockwise for the left foot,
/// clockwise for the right) by `width()` >= 0.
struct OrientationInterval {
  double inner = 0;  ///< Inner bound. [rad]
  double outer = 0;  ///< Outer bound. [rad]
};

/// Width of `foot`'s interval. [rad] [>= 0]
double width(const OrientationInterval& interval, Foot foot);

/// The orientations that the other foot may take while `foot` may take
/// `interval` (section 3.2's rule, which is symmetric between the feet): inner
/// bound at `interval`'s outer bound, outward by its width plus max_foot_turn.
OrientationInterval reachable_orientations(const OrientationInterval& interval, Foot foot,
                                           double max_foot_turn);

/// Intersection of two intervals of `foot` into `out`; false if it is empty
/// (bounds closer than 1e-9 rad still meet).
bool intersect(const OrientationInterval& a, const OrientationInterval& b, Foot foot,
               OrientationInterval* out);

/// The orientation in `foot`'s `interval` closest to `angle`. [rad]
double clamp_orientation(double angle, const OrientationInterval& interval, Foot foot);

/// The character's state at the end of a step (section 3.1), with both feet.
struct FootstepState {
  Vec2 com;                                             ///< COM position. [m]
  Vec2 com_velocity;                                    ///< COM velocity; zero when standing. [m/s]
  Foot last_foot = Foot::kRight;                        ///< Foot placed by the last step.
  std::array<Vec2, 2> feet;                             ///< Foot positions, indexed by Foot. [m]
  std::array<OrientationInterval, 2> foot_orientation;  ///< Valid orientations per foot.
  /// The ground's height under each foot, indexed by Foot; 0 on flat ground.
  /// On ground, the footstep planner sets a planted foot's when it checks the
  /// foothold (each foot's level is the one within a step of the other's). [m]
  std::array<double, 2> foot_heights{};
  double facing = 0;  ///< Torso facing: phi of the last walking step. [rad]
  double time = 0;    ///< Time at the end of the step. [s]
  /// True before the first step: no foot has swung yet, so the first step may
  /// not move the foot it plants (a pivot or a side step waits one stop).
  bool before_first_step = false;

  /// True when the character stands still (after a stop, or at the start).
  bool standing() const { return com_velocity.x == 0.0 && com_velocity.y == 0.0; }
};

/// A character standing at `position` facing `facing`, feet side by side.
FootstepState standing_state(Vec2 position, double facing, const CharacterParams& character);

/// A footstep action (section 3.1): parabola orientation, desired speed, duration.
struct FootstepAction {
  StepKind kind = StepKind::kWalk;  ///< Walk, stop or side step.
  /// Stepping foot: the other one than the last, unless standing (a side
  /// step, too, takes the other one; it moves to this foot's side).
  Foot foot = Foot::kLeft;
  /// Parabola orientation. For a stop from standing, the facing after it (a
  /// pivot, at most kMaxPivot from the facing before); a stop from walking
  /// keeps the facing, whatever phi says. For a side step, the way the COM
  /// goes, at most kMaxSideStepSkew from straight across the facing to the
  /// stepping foot's side; the facing stays. [rad]
  double phi = 0;
  /// Desired COM speed: of a walk, the nominal speed of a side step (a stop:
  /// none). [m/s]
  double speed = 1.3;
  double duration = 0.5;  ///< Step duration T. [s]
};

/// The three energy terms of the step cost (section 3.3).
struct StepCost {
  double fixed_rate = 0;    ///< dE1 = R T. [J]
  double speed_change = 0;  ///< dE2 = m/2 |v_desired^2 - (v0 cos 2 theta)^2|. [J]
  double curvature = 0;     ///< dE3 = w m alpha length. [J]
  /// On ground: walking up or down it (terrain_cost). [J]
  double terrain = 0;
  /// Sum of the terms (equation 2, and the ground's). [J]
  double total() const { return fixed_rate + speed_change + curvature + terrain; }
};

/// One planned footstep with everything needed to evaluate it analytically.
struct Footstep {
  Foot foot = Foot::kLeft;                   ///< The foot planted through the step.
  StepKind kind = StepKind::kWalk;           ///< Walk, stop, side step or start.
  Behavior behavior = Behavior::kWalk;       ///< Behaviour of the path section.
  double start_time = 0;                     ///< [s]
  double end_time = 0;                       ///< [s]
  Vec2 foot_position;                        ///< Where the foot is planted. [m]
  /// The ground's height under the planted foot; 0 on flat ground. [m]
  double foot_height = 0;
  OrientationInterval orientation_interval;  ///< Valid orientations of the planted foot.
  double foot_orientation = 0;  ///< Chosen orientation (post-process, section 4). [rad]
  Vec2 com_start;               ///< [m]
  Vec2 com_end;                 ///< [m]
  Vec2 com_velocity_start;      ///< [m/s]
  Vec2 com_velocity_end;        ///< [m/s]
  double phi = 0;               ///< Parabola orientation, also the torso facing. [rad]
  double speed = 0;             ///< Desired speed. [m/s]
  double alpha = 0;             ///< Parabola coefficient of equation 1. [m/s^2]
  StepCost cost;                ///< Energy of the step. [J]

  /// Step duration. [s]
  double duration() const { return end_time - start_time; }
};

/// Why createFootstep refused an action.
enum class StepValidity {
  kValid,
  kWrongFoot,           ///< A walking or side-stepping character must alternate feet.
  kNotStanding,         ///< A side step sets off from standing only.
  kNotAnAction,         ///< A start is planned as part of a walk (split_set_off).
  kNoSwing,             ///< The first step would move its foot, which has had no time to swing.
  kDurationOutOfRange,  ///< T outside the foot's duration limits.
  kSpeedOutOfRange,     ///< Desired speed outside the foot's speed limits.
  kLengthOutOfRange,    ///< COM travel outside the foot's step-length limits.
  kNotPositive,         ///< The local parabola is not positive (COM not between the feet).
  kOrientationEmpty,    ///< The foot-orientation interval is empty.
  kNotFinite,           ///< A non-finite input.
  kCollides,            ///< Valid in the model, but it runs into an obstacle (set by the planner).
};
/// Short description of a validity value.
const char* to_string(StepValidity validity);

/// Result of create_footstep: the step and the state after it, if valid.
struct StepResult {
  StepValidity validity = StepValidity::kValid;  ///< kValid, or why not.
  Footstep step;                                 ///< The step (meaningful when valid).
  FootstepState state;                           ///< The state at its end (meaningful when valid).
  /// True when the action was valid.
  bool valid() const { return validity == StepValidity::kValid; }
};

/// createFootstep(s, a) of section 3.1, the stop action or the side step. The
/// pendulum angle theta of dE2 is the leg's angle from vertical at heel
/// strike, atan(half the COM chord / COM height); for a stop or a side step,
/// atan(COM travel / height). A walk starts at the incoming velocity (from
/// rest when standing) and reaches the parabola's by its end, so the COM's
/// velocity is continuous; a side step starts and ends at rest.
StepResult create_footstep(const FootstepState& state, const FootstepAction& action,
                           const CharacterParams& character);

/// Arc length of the COM over a walking step. [m]
double arc_length(double vx0, double alpha, double duration);

/// COM position and velocity.
struct ComSample {
  Vec2 position;  ///< [m]
  Vec2 velocity;  ///< [m/s]
};

/// COM of a step at absolute time `t` (clamped to the step). The cubic Hermite
/// through the step's end positions and velocities is exact for the parabola
/// of a walking step in a steady gait, and is the uniform deceleration of a
/// stop.
ComSample com_at(const Footstep& step, double t);

/// A walk from standing (`walk`, taken from `before`) as a start of `lead`
/// seconds by the other foot, planted where it stands while the walk's foot
/// swings to its place and the COM sets off along the walk's own curve, and
/// the rest of the walk: for a foot that had no step of the other to swing in
/// (the first step, or one by the foot that stopped last). The two trace the
/// walk's COM, torso and feet and cost what it costs.
std::array<Footstep, 2> split_set_off(const Footstep& walk, const FootstepState& before,
                                      double lead);
/// True if `walk`, taken from `before`, is such a walk: a plan holds it as a
/// start of set_off_lead(walk) seconds and the rest (split_set_off).
bool splits_on_set_off(const Footstep& walk, const FootstepState& before);
/// A split walk's start: kSetOffSwing, or half the walk if that is shorter. [s]
double set_off_lead(const Footstep& walk);

/// A bound on the COM's speed through a step: the largest of the velocity's
/// Bezier control points (the curve's velocity lies in their hull). [m/s]
double top_speed(const Footstep& step);

/// A bound on how far the COM strays from the chord between its ends, across
/// it or beyond them. [m]
double com_stray(const Footstep& step);

/// The three torso circles (centre, then left and right shoulder) for a COM
/// at `com` with the torso facing `facing`, each radius grown by `pad`. With
/// the arms in (`behavior`), the shoulder circles come in to shoulder_width.
std::array<Circle, 3> torso_circles(Vec2 com, double facing, const CharacterParams& character,
                                    double pad = 0.0, Behavior behavior = Behavior::kWalk);

/// The width a step's torso circles take among other agents: its behaviour's,
/// but a stop's body stands (coming to rest, waiting, pivoting), its arms
/// hanging, no wider than the shoulders: as with the arms in.
inline Behavior torso_width_of(const Footstep& step) {
  return step.kind == StepKind::kStop ? Behavior::kArmsIn : step.behavior;
}

/// The energy of walking `run` metres while the body rises `rise` metres
/// (negative: falls), over level walking's: Minetti et al. 2002's metabolic
/// cost per kilogram and metre of a gradient (a polynomial fitted for -45 %
/// to +45 %, cheapest near -10 %) less its level cost, times `mass` and
/// `run`; steeper down is held at -45 %, steeper up (stairs) costs 4.5
/// times the potential energy of the rise, if that is more. [J]
double terrain_cost(double mass, double run, double rise);

/// The state at the end of `step` taken from `state`: the COM where the step
/// leaves it, its foot planted, the torso facing the step's phi.
FootstepState state_after(const FootstepState& state, const Footstep& step);

}  // namespace footfall
