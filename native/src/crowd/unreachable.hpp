// Footfall — a goal no way leads to for an agent's body: where its way is
// narrowest, and where short of there the agent stands.
#pragma once

#include <optional>

#include "footfall/navmesh/navmesh.hpp"
#include "footfall/plan/plan.hpp"

namespace footfall::detail {

/// Where the way from `from` to `to` is too narrow for a body whose
/// narrowest behaviour (side_step) keeps `clearance`, and where the body
/// stands short of there.
struct ShortOfGoal {
  Narrowest narrowest;
  Vec2 stand;  ///< The nearest point before the narrowest one with room to stand. [m]
};

/// Nothing if a disc of `clearance` finds a path from `from` to `to` on
/// `mesh`, or cannot stand at either end: then the way is not too narrow.
/// Otherwise, on the widest way (the widest disc's path, found by halving),
/// the middle of the narrowest part of the first passage narrower than
/// 2 `clearance`, and where, walking back from there along that way, the
/// clearance first reaches `clearance` + kStandRoom, kStandBack or more from
/// it (else `from`). With no way for even a disc of kThinnest, the narrowest
/// point is `from`, 0 wide.
std::optional<ShortOfGoal> short_of_goal(const NavMesh& mesh, double clearance, Vec2 from,
                                         Vec2 to);

/// The room kept beyond the side-stepping clearance where the agent stands:
/// its feet's spread and the sway of its last steps. [m]
constexpr double kStandRoom = 0.1;
/// It stands at least this far back along the way from the narrowest point:
/// out of the mouth of the passage, where others that pass it walk. [m]
constexpr double kStandBack = 1.0;
/// A way narrower than twice this is no way. [m]
constexpr double kThinnest = 0.005;

}  // namespace footfall::detail
