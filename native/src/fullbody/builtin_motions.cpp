// Footfall — the built-in motions: a simple kinematic body with the limb
// proportions of an average adult (segment lengths as fractions of the
// height, after Drillis and Contini's table), walking, walking with the arms
// in, and side-stepping. docs/full-body.md describes them.
#include <algorithm>
#include <cmath>

#include "footfall/fullbody/body_model.hpp"

namespace footfall {
namespace {

// Fractions of the body height.
constexpr double kHipHeight = 0.53;
constexpr double kShoulderHeight = 0.82;
constexpr double kNeckHeight = 0.87;
constexpr double kHeadRadius = 0.06;
constexpr double kUpperArm = 0.186;
constexpr double kForearmToPalm = 0.2;  // forearm and half the hand
constexpr double kAnkleHeight = 0.039;
constexpr double kFootLength = 0.152;
constexpr double kFootRadius = 0.02;
// The gait.
constexpr double kStance = 0.6;          // fraction of the cycle a foot bears weight
constexpr double kWalkLift = 0.1;        // swing foot clearance [m]
constexpr double kSideStepLift = 0.06;   // [m]
constexpr double kArmSwing = 0.35;       // shoulder swing amplitude [rad]
constexpr double kElbowBend = 0.25;      // [rad]
constexpr double kSideStepCycle = 1.2;   // [s]

struct Body {
  double height, hip_y, shoulder_y, arm_radius, leg_radius, chest_radius, chest_half;
  double thigh, shin, foot_radius, foot_length;

  explicit Body(const CharacterParams& c)
      : height(c.body_height),
        hip_y(std::min(c.foot_offset, 0.25 * c.shoulder_width)),
        shoulder_y(0.5 * c.shoulder_width - c.arm_radius),
        arm_radius(c.arm_radius),
        leg_radius(c.leg_radius),
        chest_radius(0.5 * c.chest_depth),
        chest_half(std::max(0.5 * c.shoulder_width - 2 * c.arm_radius, 0.5 * c.chest_depth)),
        thigh(0.51 * (kHipHeight - kAnkleHeight) * c.body_height),
        shin(thigh),
        foot_radius(std::max(kFootRadius * c.body_height, 0.01)),
        foot_length(kFootLength * c.body_height) {}
};

Vec3 lerp(Vec3 a, Vec3 b, double t) { return a + t * (b - a); }

// Knee of a two-bone leg from hip to ankle, bent toward `forward` (unit).
Vec3 knee_of(const Body& body, Vec3 hip, Vec3& ankle, Vec3 forward) {
  Vec3 reach = ankle - hip;
  double d = length(reach);
  const double longest = 0.999 * (body.thigh + body.shin);
  if (d > longest) {
    ankle = hip + (longest / d) * reach;
    reach = ankle - hip;
    d = longest;
  }
  const double out = std::sqrt(std::max(0.0, body.thigh * body.thigh - 0.25 * d * d));
  // The bend direction: `forward`, made square to the leg.
  const Vec3 axis = (1.0 / d) * reach;
  Vec3 bend = forward - dot(forward, axis) * axis;
  const double bend_length = length(bend);
  bend = bend_length > 0 ? (1.0 / bend_length) * bend : Vec3{1, 0, 0};
  return lerp(hip, ankle, 0.5) + out * bend;
}

// A foot's place relative to the root over its cycle `u` in [0, 1): planted
// (moving back at the travel speed) for kStance of the cycle, then swung
// forward and lifted. Returns the offset along the travel and the lift.
void foot_track(double u, double stride, double lift_height, double& along, double& lift) {
  const double half = 0.5 * kStance * stride;
  if (u < kStance) {
    along = half - stride * u;
    lift = 0;
  } else {
    const double w = (u - kStance) / (1 - kStance);
    along = -half + 2 * half * 0.5 * (1 - std::cos(kPi * w));
    lift = lift_height * std::sin(kPi * w);
  }
}

void set_trunk(const Body& b, BodyPose& pose, bool across) {
  const double z_hip = kHipHeight * b.height, z_shoulder = kShoulderHeight * b.height;
  const double r_head = kHeadRadius * b.height;
  const double chest_r = std::min(b.chest_radius, b.chest_half);
  const double half_span = b.chest_half - chest_r;
  // `across`: the body faces +Y (side-stepping), its shoulders along X.
  const auto side = [&](double s, double z) {
    return across ? Vec3{s, 0, z} : Vec3{0, s, z};
  };
  pose[static_cast<int>(Limb::kHead)] = {{0, 0, kNeckHeight * b.height + r_head},
                                         {0, 0, b.height - r_head}, r_head};
  pose[static_cast<int>(Limb::kShoulders)] = {side(-half_span, z_shoulder - chest_r),
                                              side(half_span, z_shoulder - chest_r), chest_r};
  pose[static_cast<int>(Limb::kTorso)] = {{0, 0, z_hip + chest_r},
                                          {0, 0, z_shoulder - chest_r}, chest_r};
  const double pelvis_r = std::min(chest_r, b.hip_y + b.leg_radius);
  const double pelvis_half = std::max(0.0, b.hip_y + b.leg_radius - pelvis_r);
  pose[static_cast<int>(Limb::kPelvis)] = {side(-pelvis_half, z_hip), side(pelvis_half, z_hip),
                                           pelvis_r};
}

// Legs stepping along `travel` (unit, in the ground plane) with hips at
// ±hip_y along `hips` (unit), knees and toes toward `facing`. With `hike`,
// the swinging leg's hip rises as its foot does (the pelvis tilts), so that
// its knee bends no further than the standing one's.
void set_legs(const Body& b, BodyPose& pose, double phase, double stride, double lift_height,
              Vec3 travel, Vec3 hips, Vec3 facing, bool hike) {
  const double z_hip = kHipHeight * b.height, z_ankle = kAnkleHeight * b.height;
  for (int leg = 0; leg < 2; ++leg) {
    const double sign = leg == 0 ? 1.0 : -1.0;  // 0: left (+hips)
    const double u = std::fmod(phase + 0.5 * leg, 1.0);
    double along = 0, lift = 0;
    foot_track(u, stride, lift_height, along, lift);
    const Vec3 hip = Vec3{0, 0, z_hip + (hike ? lift : 0.0)} + sign * b.hip_y * hips;
    Vec3 ankle = Vec3{0, 0, z_ankle + lift} + sign * b.hip_y * hips + along * travel;
    const Vec3 knee = knee_of(b, hip, ankle, facing);
    const int thigh = static_cast<int>(leg == 0 ? Limb::kThighLeft : Limb::kThighRight);
    const int shin = static_cast<int>(leg == 0 ? Limb::kShinLeft : Limb::kShinRight);
    const int foot = static_cast<int>(leg == 0 ? Limb::kFootLeft : Limb::kFootRight);
    pose[thigh] = {hip, knee, b.leg_radius};
    pose[shin] = {knee, ankle, b.leg_radius};
    const Vec3 sole{0, 0, b.foot_radius - z_ankle};
    const Vec3 heel = ankle + sole - (0.25 * b.foot_length - b.foot_radius) * facing;
    const Vec3 toe = ankle + sole + (0.75 * b.foot_length - b.foot_radius) * facing;
    pose[foot] = {heel, toe, b.foot_radius};
  }
}

void set_arm(const Body& b, BodyPose& pose, int arm, Vec3 shoulder, Vec3 elbow, Vec3 hand) {
  pose[static_cast<int>(arm == 0 ? Limb::kUpperArmLeft : Limb::kUpperArmRight)] = {
      shoulder, elbow, b.arm_radius};
  pose[static_cast<int>(arm == 0 ? Limb::kForearmLeft : Limb::kForearmRight)] = {
      elbow, hand, b.arm_radius};
}

BodyPose walk_pose(const Body& b, const CharacterParams& c, double phase, bool arms_in) {
  BodyPose pose;
  set_trunk(b, pose, false);
  const double stride = c.preferred_speed * 2 * c.preferred_step_duration;
  set_legs(b, pose, phase, stride, kWalkLift, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, false);
  const double z_shoulder = kShoulderHeight * b.height;
  const double upper = kUpperArm * b.height, fore = kForearmToPalm * b.height;
  for (int arm = 0; arm < 2; ++arm) {
    const double sign = arm == 0 ? 1.0 : -1.0;
    // Each arm swings against its own leg: back while that foot strikes ahead.
    const double u = std::fmod(phase + 0.5 * arm, 1.0);
    const Vec3 shoulder{0, sign * b.shoulder_y, z_shoulder};
    if (arms_in) {
      // Upper arm against the side, forearm across the belly.
      const double sway = 0.08 * -std::cos(2 * kPi * u);
      const Vec3 elbow = shoulder + Vec3{upper * std::sin(sway), 0, -upper * std::cos(sway)};
      const double inward = std::max(0.0, b.shoulder_y - 0.35 * fore);
      const Vec3 hand{elbow.x + 0.9 * fore, sign * inward, elbow.z + 0.3 * fore};
      set_arm(b, pose, arm, shoulder, elbow, hand);
      continue;
    }
    const double swing = -kArmSwing * std::cos(2 * kPi * u);
    const double bend = kElbowBend * (1.5 + std::sin(swing / kArmSwing * 0.5 * kPi));
    // The hands pass the hips widest, at arm_swing_width.
    const double widest = 0.5 * c.arm_swing_width - c.arm_radius - b.shoulder_y;
    const double out = widest * 0.5 * (1 - std::cos(4 * kPi * u));
    const Vec3 elbow = shoulder + Vec3{upper * std::sin(swing), sign * 0.5 * out,
                                       -upper * std::cos(swing)};
    const Vec3 hand{elbow.x + fore * std::sin(swing + bend), sign * (b.shoulder_y + out),
                    elbow.z - fore * std::cos(swing + bend)};
    set_arm(b, pose, arm, shoulder, elbow, hand);
  }
  return pose;
}

BodyPose side_step_pose(const Body& b, const CharacterParams& c, double phase) {
  BodyPose pose;
  set_trunk(b, pose, true);
  const double stride = c.side_step_speed * kSideStepCycle;
  // Travel +X, facing +Y: the hips lie along X; leg 0 (the body's left) is at -X.
  set_legs(b, pose, phase, stride, kSideStepLift, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, true);
  const double z_shoulder = kShoulderHeight * b.height;
  const double upper = kUpperArm * b.height, fore = kForearmToPalm * b.height;
  for (int arm = 0; arm < 2; ++arm) {
    const double sign = arm == 0 ? -1.0 : 1.0;
    // Arms hang at the sides, the hands a little in front of the thighs.
    const Vec3 shoulder{sign * b.shoulder_y, 0, z_shoulder};
    const Vec3 elbow = shoulder + Vec3{0, 0.1 * upper, -upper};
    const double reach = std::min(0.6 * fore, b.chest_radius - b.arm_radius);
    const Vec3 hand{elbow.x, std::max(0.0, reach), elbow.z - fore};
    set_arm(b, pose, arm, shoulder, elbow, hand);
  }
  return pose;
}

}  // namespace

BehaviorMotion builtin_motion(Behavior behavior, const CharacterParams& character) {
  const Body body(character);
  BehaviorMotion motion;
  const bool side = behavior == Behavior::kSideStep;
  motion.cycle_duration = side ? kSideStepCycle : 2 * character.preferred_step_duration;
  motion.speed = side ? character.side_step_speed : character.preferred_speed;
  for (int i = 0; i < kBuiltinPhases; ++i) {
    const double phase = static_cast<double>(i) / kBuiltinPhases;
    motion.poses.push_back(side ? side_step_pose(body, character, phase)
                                : walk_pose(body, character, phase,
                                            behavior == Behavior::kArmsIn));
  }
  if (side) {
    // Centre the body across the way: the toes reach further forward than the back.
    double lo = INFINITY, hi = -INFINITY;
    for (const BodyPose& pose : motion.poses)
      for (const Capsule& c : pose)
        for (const Vec3 p : {c.a, c.b}) {
          lo = std::min(lo, p.y - c.radius);
          hi = std::max(hi, p.y + c.radius);
        }
    const Vec3 shift{0, -0.5 * (lo + hi), 0};
    for (BodyPose& pose : motion.poses)
      for (Capsule& c : pose) c = {c.a + shift, c.b + shift, c.radius};
  }
  return motion;
}

}  // namespace footfall
