#include "footfall/ground/foothold.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

std::optional<GroundPoint> foothold_level(const Ground& ground, const CharacterParams& character,
                                          Vec2 foot, double beside) {
  return ground.standable_near(foot, beside, character.body_height);
}

GroundLayers layers_for(const Ground& ground, const CharacterParams& character) {
  return ground.layers(std::min(character.max_step_up, character.max_step_down),
                       character.body_height, std::cos(character.max_slope));
}

FootstepState standing_on_ground(const Ground& ground, const CharacterParams& character,
                                 Vec2 position, double facing, std::optional<double> height) {
  FootstepState state = standing_state(position, facing, character);
  if (ground.empty()) return state;
  const double near = height.value_or(-std::numeric_limits<double>::infinity());
  for (int f = 0; f < 2; ++f)
    if (const auto level = foothold_level(ground, character, state.feet[f], near))
      state.foot_heights[f] = level->z;
  return state;
}

FootholdFault foothold_fault(const Ground& ground, const CharacterParams& character, Vec2 foot,
                             const OrientationInterval& turns, Vec3 other, Vec3 from) {
  const double min_normal_z = std::cos(character.max_slope);
  const std::optional<GroundPoint> here = foothold_level(ground, character, foot, other.z);
  if (!here || here->normal.z < min_normal_z) return FootholdFault::kOffGround;
  const double rise = here->z - other.z;
  if (rise > character.max_step_up || -rise > character.max_step_down) return FootholdFault::kRise;
  const double middle = turns.inner + 0.5 * wrap_angle(turns.outer - turns.inner);
  for (const double orientation : {turns.inner, turns.outer, middle}) {
    if (orientation != turns.inner && turns.outer == turns.inner) break;
    const Sole sole = sole_of(character, foot, *here, orientation);
    if (!ground.holds(sole, kSoleTolerance, min_normal_z, character.sole_support))
      return FootholdFault::kUnsupported;
  }
  const Vec2 lifted = footfall::ground(from);
  if (lifted == foot) return FootholdFault::kNone;
  const double top = std::max(from.z, here->z);
  const int samples = static_cast<int>(std::ceil(distance(lifted, foot) / kSwingSpacing));
  for (int i = 1; i < samples; ++i) {
    const double t = static_cast<double>(i) / samples;
    for (const GroundPoint& level : ground.levels_at(lifted + t * (foot - lifted)))
      if (level.z > top + kSoleTolerance && level.z <= top + kSwingReach)
        return FootholdFault::kSwing;
  }
  return FootholdFault::kNone;
}

}  // namespace footfall
