// Footfall — the way to an agent's goal and the local goal along it.
#include "behavior/local_goal.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "footfall/model/polyline.hpp"

namespace footfall {
namespace {

/// The way only places local goals; its arcs need not be fine. [m]
constexpr double kRouteArcTolerance = 0.05;
/// A local goal out of sight is looked for this much nearer, each time. [1]
constexpr double kSightBackOff = 0.6;
/// ...down to this far along the way, past a corner or not. [m]
constexpr double kMinAhead = 1.5;
/// A roomier way is taken if it is at most this much longer than the
/// tightest: kRoomyDetour times, plus kRoomyExtra. The tightest is dear and
/// chancy for the footsteps (a side step through a gap narrower than the
/// shoulders takes some 140 nodes, and a slot a little wider than the torso
/// circle may pass none): shorter detours leave more agents stuck among boxes
/// (docs/footstep-model.md).
constexpr double kRoomyDetour = 2.0;
constexpr double kRoomyExtra = 6.0;  // [m]
/// Room beside the shoulders, where there is room, for the body's sway. [m]
constexpr double kSwayMargin = 0.25;

/// True if the agent at `from` sees `to`: a straight line with room for a
/// circle of `radius` (the torso's, for a local goal grown as the
/// footsteps' checks grow it) joins them. A short-horizon search cannot go
/// round a wall to reach a point behind it.
bool in_sight(const NavMesh* mesh, double radius, Vec2 from, Vec2 to) {
  if (mesh == nullptr) return true;
  return mesh->clearance_between(from, to, radius) >= radius;
}

/// Where a way out of a tight place may end: this far from it, nearest first
/// ([m]), in kWayOutDirections directions.
constexpr double kWayOutReach[] = {0.5, 1.0, 1.5, 2.0, 3.0};
constexpr int kWayOutDirections = 16;

/// The way of `radius` for one standing where such a way cannot start (in a
/// gap between boxes, stuck there): out to a place with that room, passing
/// none of `others` (two stuck face to face in a gap each back out), then on
/// from there. Back to `back` (where it last had that room) along the mesh
/// for the torso circle, if it can; else straight out to the nearest place
/// in sight, the shortest such of the nearest places that have one. None
/// within kWayOutReach.
std::optional<Way> way_out(const NavMesh& mesh, const CharacterParams& character, Vec2 from, Vec2 goal,
                           double radius, const std::vector<Vec2>& others,
                           std::optional<Vec2> back) {
  const auto passes_someone = [&](const std::vector<Vec2>& points) {
    for (std::size_t k = 1; k < points.size(); ++k)
      for (const Vec2 other : others)
        if (distance_to_segment(other, points[k - 1], points[k]) < 2.0 * character.torso_radius)
          return true;
    return false;
  };
  // The way from `from` to `exit` (`to_exit`, its points from `from` on), then on.
  const auto through = [&](std::vector<Vec2> to_exit, double reach) -> std::optional<Way> {
    PathResult on = mesh.find_path({to_exit.back(), goal, radius, kRouteArcTolerance});
    if (on.status != PathStatus::kFound) return std::nullopt;
    to_exit.insert(to_exit.end(), on.points.begin() + 1, on.points.end());
    return Way{std::move(to_exit), reach + on.length};
  };
  if (back && mesh.clearance(*back) >= radius) {
    PathResult to_back = mesh.find_path({from, *back, character.torso_radius, kRouteArcTolerance});
    if (to_back.status == PathStatus::kFound && !passes_someone(to_back.points))
      if (std::optional<Way> way = through(std::move(to_back.points), to_back.length)) return way;
  }
  for (const double reach : kWayOutReach) {
    std::optional<Way> best;
    for (int k = 0; k < kWayOutDirections; ++k) {
      const Vec2 exit = from + reach * unit(2.0 * kPi * k / kWayOutDirections);
      if (mesh.clearance(exit) < radius || !in_sight(&mesh, character.torso_radius, from, exit) ||
          passes_someone({from, exit}))
        continue;
      std::optional<Way> way = through({from, exit}, reach);
      if (way && (!best || way->length < best->length)) best = std::move(way);
    }
    if (best) return best;
  }
  return std::nullopt;
}

}  // namespace

double sway_room(const CharacterParams& character) {
  return 0.5 * character.torso_width + kSwayMargin;
}

bool cramped(const NavMesh* mesh, const CharacterParams& character, Vec2 at) {
  return mesh != nullptr && mesh->clearance(at) < sway_room(character);
}

/// The way on the navigation mesh: the roomiest of three that is not much
/// longer than the tightest (at most kRoomyDetour times plus kRoomyExtra):
/// room to walk upright with a margin for the sway, just upright (half the
/// torso width), or only to side-step (the torso circle), as through a gap
/// narrower than the shoulders. With no way at all, the straight line, along
/// which the local search finds what it can. A `roomy` way (for an agent
/// stuck once) is the first of the two with room to walk upright that there
/// is, however long; from a place too tight to walk upright in, it leads
/// out of it first (way_out).
Way way_toward(const NavMesh* mesh, const CharacterParams& character, Vec2 from, Vec2 goal,
               bool roomy, const std::vector<Vec2>& others, std::optional<Vec2> back) {
  Way way{{from, goal}, distance(from, goal)};
  if (mesh == nullptr) return way;
  const double upright = 0.5 * character.torso_width;
  const auto roomy_enough = [roomy](const PathResult& path, double tight_length) {
    return path.status == PathStatus::kFound &&
           (roomy || path.length <= kRoomyDetour * tight_length + kRoomyExtra);
  };
  // The tight way is no shorter than the straight line: a roomiest way that
  // is not much longer than the line needs no tight way to compare with
  // (most ways, in the open), so most ways take one query, not two.
  PathResult roomiest = mesh->find_path({from, goal, sway_room(character), kRouteArcTolerance});
  if (roomy_enough(roomiest, way.length)) return {std::move(roomiest.points), roomiest.length};
  if (roomy && roomiest.status == PathStatus::kStartBlocked && mesh->clearance(from) < upright) {
    if (std::optional<Way> out = way_out(*mesh, character, from, goal, upright, others, back))
      return std::move(*out);
  }
  PathResult tight = mesh->find_path({from, goal, character.torso_radius, kRouteArcTolerance});
  if (tight.status != PathStatus::kFound) return way;
  if (roomy_enough(roomiest, tight.length)) return {std::move(roomiest.points), roomiest.length};
  PathResult upright_way = mesh->find_path({from, goal, upright, kRouteArcTolerance});
  if (roomy_enough(upright_way, tight.length))
    return {std::move(upright_way.points), upright_way.length};
  return {std::move(tight.points), tight.length};
}

Way way_start(const Way& way, double length) {
  if (way.length <= length) return way;
  return {Polyline(way.points).between(0.0, length), length};
}

/// A local goal out of sight is looked for nearer by steps of kSightBackOff,
/// down to kMinAhead: a short-horizon search cannot go round a wall to a
/// point behind it. The agent rests at a local goal until it replans, so it
/// is moved back along the way to where it could stand and turn.
LocalGoal local_goal(const FootstepPlanner& planner, const NavMesh* mesh, const Way& way) {
  const Vec2 from = way.points.front();
  const Polyline line(way.points);
  double reach = std::min(planner.params().local_goal_distance, way.length);
  // A moving step's torso is grown by half the sample spacing: a line with
  // room for the torso alone can lead through a gap no step passes.
  const double torso =
      planner.character().torso_radius + 0.5 * planner.params().collision_sample_spacing;
  while (reach > kMinAhead && !in_sight(mesh, torso, from, line.point_at(reach)))
    reach = std::max(kMinAhead, kSightBackOff * reach);
  if (way.length <= reach) return {way.points.back(), true};
  constexpr double kStep = 0.25;  // [m]
  // Not within the goal tolerance of the agent: it would count as there
  // already, and stand still for good (beside a box, where the way hugs it).
  // (A way that doubles back, out of a gap and in again, comes near it
  // farther along.)
  for (double along = reach; along > planner.params().goal_tolerance; along -= kStep) {
    const Vec2 point = line.point_at(along);
    const Vec2 ahead = line.point_at(along + kStep);
    const double facing = angle_of(ahead - point);
    if (distance(point, from) > planner.params().goal_tolerance &&
        planner.validity().room_to_turn(point) &&
        !planner.validity().collides(standing_state(point, facing, planner.character())))
      return {point, false};
  }
  return {line.point_at(reach), false};
}

}  // namespace footfall
