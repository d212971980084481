#include "footfall/animate/ground_follow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace footfall::animate {
namespace {

constexpr double kRiseShare = 0.3;      // of a rising swing, over which it rises (and falls)
constexpr double kSwingTolerance = 0.005;  // [m] a swinging sole this far into the ground clears it
constexpr double kOverhang = 0.5;       // [m] over the higher foothold: the body's business, not the foot's
constexpr int kSwingSamples = 48;       // phases a swing's clearance is judged at
constexpr int kAlong = 7, kAcross = 3;  // the foot's samples, heel to toe and side to side
constexpr double kPitchReach = 0.02;    // [m] a pitched foot's heel or toe beyond its flat outline
constexpr double kLeastRun = 0.3;       // [m] the least travel a lean's climb is measured over
constexpr std::array<double, 4> kTravelStarts{0.0, 0.1, 0.2, kRiseShare};

double smoothstep(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * (3.0 - 2.0 * u);
}

Vec3 blend(Vec3 a, Vec3 b, double w) {
  const Vec3 n = (1 - w) * a + w * b;
  return (1.0 / length(n)) * n;
}

// How far a swing has travelled from one foothold to the other at phase u.
double travelled(double u, bool rises, double travel_start) {
  return rises ? smoothstep((u - travel_start) / (1 - 2 * travel_start)) : smoothstep(u);
}

}  // namespace

GroundFollower::GroundFollower(const AgentPlan& plan, const CharacterParams& character,
                               const Ground& ground, FootExtent foot)
    : plan_(plan), ground_(ground), extent_(foot), headroom_(character.body_height) {}

GroundPoint GroundFollower::under(Vec2 p, double near) const {
  return ground_.standable_near(p, near, headroom_).value_or(GroundPoint{0.0, {0, 0, 1}, -1});
}

double GroundFollower::highest_under(Vec3 sole, double heading, double ceiling) const {
  const Vec2 along = unit(heading), across = perp(along);
  double highest = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < kAlong; ++i)
    for (int j = 0; j < kAcross; ++j) {
      const double a = -(extent_.heel_back + kPitchReach) +
                       (extent_.heel_back + extent_.toe_ahead + 2 * kPitchReach) * i / (kAlong - 1);
      // The heel rounded, as the planner's sole: its row half as wide.
      const double b = (i == 0 ? 0.5 : 1.0) * extent_.width *
                       (static_cast<double>(j) / (kAcross - 1) - 0.5);
      for (const GroundPoint& level : ground_.levels_at(ground(sole) + a * along + b * across))
        if (level.z <= ceiling) highest = std::max(highest, level.z);
    }
  return highest;
}

FootOnGround GroundFollower::swinging(const FootPose& pose, const Swing& swing, double u) const {
  const double s = travelled(u, swing.rises, swing.travel_start);
  const Vec2 at = pose.swing_from + s * (pose.swing_to - pose.swing_from);
  double z = 0;
  if (swing.rises) {
    z = swing.top - (swing.top - swing.from_z) * (1 - smoothstep(u / kRiseShare)) -
        (swing.top - swing.to_z) * (1 - smoothstep((1 - u) / kRiseShare));
  } else {
    z = swing.from_z + s * (swing.to_z - swing.from_z) +
        swing_lift(distance(pose.swing_from, pose.swing_to), u);
  }
  const double heading = wrap_angle(
      pose.swing_from_orientation +
      s * wrap_angle(pose.swing_to_orientation - pose.swing_from_orientation));
  return {{at.x, at.y, z}, heading, blend(swing.from_normal, swing.to_normal, s)};
}

GroundFollower::Swing GroundFollower::plan_swing(const FootPose& pose) const {
  Swing swing;
  const GroundPoint from = under(pose.swing_from, pose.ground);
  GroundPoint to = under(pose.swing_to, pose.swing_to_ground);
  if (to.surface < 0) to = from;  // walking off the ground's end as it leaves
  swing.from_z = from.z;
  swing.to_z = to.z;
  swing.from_normal = from.normal;
  swing.to_normal = to.normal;
  // The highest ground under the foot at each phase, on its way along the line.
  const double ceiling = std::max(from.z, to.z) + kOverhang;
  std::array<double, kSwingSamples - 1> need;
  const auto clears = [&] {
    for (int i = 1; i < kSwingSamples; ++i)
      if (swinging(pose, swing, static_cast<double>(i) / kSwingSamples).sole.z + kSwingTolerance <
          need[i - 1])
        return false;
    return true;
  };
  double highest = -std::numeric_limits<double>::infinity();
  for (int i = 1; i < kSwingSamples; ++i) {
    const FootOnGround foot = swinging(pose, swing, static_cast<double>(i) / kSwingSamples);
    need[i - 1] = highest_under(foot.sole, foot.heading, ceiling);
    highest = std::max(highest, need[i - 1]);
  }
  if (clears()) return swing;
  // It rises first and comes down last, crossing clear of the highest ground:
  // its travel overlapping the rise and fall as far as that still clears.
  swing.rises = true;
  swing.top = std::max(highest + kSwingClearance,
                       std::max(from.z, to.z) +
                           swing_lift(distance(pose.swing_from, pose.swing_to), 0.5));
  // The headings (and so the foot's samples) follow the travel: judged again for each.
  for (const double start : kTravelStarts) {
    swing.travel_start = start;
    for (int i = 1; i < kSwingSamples; ++i) {
      const FootOnGround foot = swinging(pose, swing, static_cast<double>(i) / kSwingSamples);
      need[i - 1] = highest_under(foot.sole, foot.heading, ceiling);
    }
    if (clears()) break;
  }
  return swing;
}

const GroundFollower::Swing& GroundFollower::swing_of(const FootPose& pose) const {
  const std::array<double, 6> key{pose.swing_from.x, pose.swing_from.y, pose.ground,
                                  pose.swing_to.x,   pose.swing_to.y,   pose.swing_to_ground};
  auto found = swings_.find(key);
  if (found == swings_.end()) found = swings_.emplace(key, plan_swing(pose)).first;
  return found->second;
}

FootOnGround GroundFollower::foot(const FootPose& pose) const {
  if (ground_.empty())
    return {{pose.position.x, pose.position.y, pose.lift}, pose.orientation, {0, 0, 1}};
  if (pose.planted) {
    const GroundPoint point = under(pose.position, pose.ground);
    return {{pose.position.x, pose.position.y, point.z}, pose.orientation, point.normal};
  }
  return swinging(pose, swing_of(pose), pose.swing_phase);
}

double GroundFollower::body_height(const std::array<FootPose, 2>& feet) const {
  if (ground_.empty()) return 0.0;
  double sum = 0;
  for (const FootPose& pose : feet) {
    if (pose.planted) {
      sum += under(pose.position, pose.ground).z;
    } else {
      const Swing& swing = swing_of(pose);
      const double s = travelled(pose.swing_phase, swing.rises, swing.travel_start);
      sum += swing.from_z + s * (swing.to_z - swing.from_z);
    }
  }
  return 0.5 * sum;
}

double GroundFollower::lean(double t) const {
  if (ground_.empty()) return 0.0;
  const double before = std::max(t - kLeanWindow, 0.0), after = t + kLeanWindow;
  const double rise = body_height(feet_at(plan_, after)) - body_height(feet_at(plan_, before));
  const double run = distance(com_at(plan_, after).position, com_at(plan_, before).position);
  return std::clamp(kLeanShare * std::atan2(rise, std::max(run, kLeastRun)), -kMostLeanBack,
                    kMostLean);
}

}  // namespace footfall::animate
