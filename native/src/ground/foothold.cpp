#include "footfall/ground/foothold.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace footfall {
namespace {

constexpr double kSoleTolerance = 0.02;  // [m] the sole's plane to the ground it rests on
constexpr double kSwingSpacing = 0.05;   // [m] between samples of a swinging foot's line
constexpr double kSwingReach = 0.5;      // [m] above the higher foothold: an overhang

}  // namespace

Sole sole_of(const CharacterParams& character, Vec2 foot, const GroundPoint& ground,
             double orientation) {
  const Vec2 ahead = ((0.5 - kHeelShare) * character.sole_length) * unit(orientation);
  const Vec3& n = ground.normal;
  const double z = ground.z - (n.x * ahead.x + n.y * ahead.y) / n.z;  // in the ground's plane
  return {{foot.x + ahead.x, foot.y + ahead.y, z}, n, orientation, character.sole_length,
          character.sole_width};
}

FootholdFault foothold_fault(const Ground& ground, const CharacterParams& character, Vec2 foot,
                             const OrientationInterval& turns, Vec2 other, Vec2 from) {
  const double min_normal_z = std::cos(character.max_slope);
  const auto standing = [&](Vec2 p) { return ground.standing_on(p, character.body_height); };
  const std::optional<GroundPoint> here = standing(foot);
  if (!here || here->normal.z < min_normal_z) return FootholdFault::kOffGround;
  if (const std::optional<GroundPoint> beside = standing(other)) {
    const double rise = here->z - beside->z;
    if (rise > character.max_step_up || -rise > character.max_step_down)
      return FootholdFault::kRise;
  }
  const double middle = turns.inner + 0.5 * wrap_angle(turns.outer - turns.inner);
  for (const double orientation : {turns.inner, turns.outer, middle}) {
    if (orientation != turns.inner && turns.outer == turns.inner) break;
    const Sole sole = sole_of(character, foot, *here, orientation);
    if (!ground.holds(sole, kSoleTolerance, min_normal_z, character.sole_support))
      return FootholdFault::kUnsupported;
  }
  const std::optional<GroundPoint> lifted = standing(from);
  if (!lifted || from == foot) return FootholdFault::kNone;
  const double top = std::max(lifted->z, here->z);
  const int samples = static_cast<int>(std::ceil(distance(from, foot) / kSwingSpacing));
  for (int i = 1; i < samples; ++i) {
    const double t = static_cast<double>(i) / samples;
    for (const GroundPoint& level : ground.levels_at(from + t * (foot - from)))
      if (level.z > top + kSoleTolerance && level.z <= top + kSwingReach)
        return FootholdFault::kSwing;
  }
  return FootholdFault::kNone;
}

}  // namespace footfall
