// Footfall — whether a foot may be planted on the ground: the judgement the
// footstep planner applies to its steps and `footfall metrics` to a plan's.
#pragma once

#include <optional>

#include "footfall/model/footstep.hpp"
#include "footfall/model/params.hpp"
#include "footfall/ground/ground.hpp"

namespace footfall {

/// Of a sole's length, the share behind the point under the ankle (a foot
/// is planted by that point; its heel is a quarter of its length behind).
constexpr double kHeelShare = 0.25;

/// The sole of `character` of a foot planted at `foot` (the point under its
/// ankle), turned to `orientation`, in the plane of `ground` there:
/// kHeelShare of sole_length behind `foot`, the rest ahead.
Sole sole_of(const CharacterParams& character, Vec2 foot, const GroundPoint& ground,
             double orientation);

/// What is wrong with a foothold, if anything.
enum class FootholdFault {
  kNone,
  kOffGround,    ///< No standable level under the foot, or one steeper than max_slope.
  kUnsupported,  ///< Less than sole_support of the sole held (a nosing, an edge).
  kRise,         ///< Over max_step_up above the other foot, or max_step_down below it.
  kSwing,        ///< The swinging foot passes over ground above the higher foothold.
};

/// The standable level under a foot planted at `foot` beside a foot on
/// ground at the height `beside`: of the levels there (a street and a deck
/// over it), the nearest to `beside`; on ground of one level at every point,
/// the only one.
std::optional<GroundPoint> foothold_level(const Ground& ground, const CharacterParams& character,
                                          Vec2 foot, double beside);

/// The ground's layers (Ground::layers) for `character`: its height, the
/// lower of its step limits, its steepest slope.
GroundLayers layers_for(const Ground& ground, const CharacterParams& character);

/// A body of `character` standing at `position` facing `facing`
/// (standing_state) on the ground: each foot on the standable level nearest
/// `height` where given, else on the lowest (the only one, in a checked
/// scenario). Without ground, standing_state itself.
FootstepState standing_on_ground(const Ground& ground, const CharacterParams& character,
                                 Vec2 position, double facing, std::optional<double> height);

/// A foot planted at `foot`, turned anywhere in `turns` (its ends and its
/// middle are tested; inner == outer: one orientation), while the other foot
/// stands at `other` (its z: the ground's height under it), having swung
/// from `from` (as `other`): on its foothold_level, the sole of `character`
/// (sole_length by sole_width) held for at least sole_support within 2 cm of
/// its plane on a slope within max_slope, the rise within the step limits,
/// and the swing over nothing more than 2 cm above the higher of its two
/// footholds (a tread's nosing, a kerb; ground over 0.5 m above is an
/// overhang, the body's business).
FootholdFault foothold_fault(const Ground& ground, const CharacterParams& character, Vec2 foot,
                             const OrientationInterval& turns, Vec3 other, Vec3 from);

}  // namespace footfall
