// Footfall — how the crowd's agents make way for each other (crowd_planner.cpp). A
// blocked agent shows the agents after it (in the order of way left) that rest
// in its way where it would go; they rest out of it. In a face-off, where no
// one can rest ahead, those in the way of one bound against them step aside to
// the nearest room (must_make_room()). One stalled there, with one bound
// against it near, goes last (gives_way()). Before two blocks of agents meet
// head on, each keeps right (keep_right()).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "crowd/crowd_walker.hpp"
#include "footfall/navmesh/navmesh.hpp"

namespace footfall::crowd {

/// What a wish along `steps` keeps others out of, until its COM is
/// kWishReach from where it set off: the torso circles every kContactDt and
/// the planted feet, grown by kWishPad (room to pass); and where the steps
/// end, if within reach, room to rest.
KeepOut wish_discs(const std::vector<Footstep>& steps, const CharacterParams& character);

/// True if agent i gives way to all: blocked kGiveWayBlocked searches in a
/// row, its patience run out (its way has not shortened for kJamPatience),
/// with one bound against it (their goals more than 90 degrees apart) within
/// kJamDistance. In a knot (agents bound every way in a gap between boxes,
/// all waiting) the one that goes first may have nowhere to go that the
/// others can make room for; it then goes last, and the next one's wish is
/// kept clear instead. In a queue, all bound one way, the order stands.
bool gives_way(const std::vector<Walker>& walkers, std::size_t i, const Snapshot& now);

/// The local goal moved to the right of the line from agent i to it (by
/// kKeepRightShift, else by less, 0.5 m at the least, where it could stand
/// with room all along the way there), if one it sees walks the other way
/// ahead near that line and it has room round it; `target` otherwise. Lanes
/// form before two blocks of agents meet: without it, a dense two-way hall can
/// jam wall to wall where the flows meet.
LocalGoal keep_right(const std::vector<Walker>& walkers, std::size_t i, LocalGoal target,
                     const std::vector<std::size_t>& seen, const Snapshot& now,
                     const FootstepPlanner& planner, const NavMesh* mesh);

/// Steps to the nearest place that room_aside() offers and a search of
/// `options` reaches (the nearest may be behind the very agents it makes
/// room for); none if no such search succeeds.
std::optional<SearchResult> step_aside(const FootstepState& state, const KeepOut& keep_out,
                                       const MovingObstacles& others,
                                       const FootstepPlanner& planner, const NavMesh* mesh,
                                       const SearchOptions& options);

/// True if agent i stands in the wish of one it yields to that is bound
/// against it (their goals more than 90 degrees apart), or whose wish makes
/// room for such a one. Among agents bound the same way (a queue at a door)
/// a wish passes once those ahead move on.
bool must_make_room(const std::vector<Walker>& walkers, std::size_t i, const Snapshot& now,
                    const FootstepPlanner& planner);

/// Shows agent i's wish, if its attempt found one and it is still blocked,
/// to the agents `near` that go after it (as of `now`, the tick of its
/// search) and rest in it: they keep out of it, searching again at the next
/// tick, and go into `asked`. Otherwise withdraws it.
void show_wish(std::vector<Walker>& walkers, std::size_t i, Attempt& a, const Snapshot& now,
               const std::vector<std::size_t>& near, std::vector<std::size_t>& asked);

}  // namespace footfall::crowd
