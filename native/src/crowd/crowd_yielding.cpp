// Footfall — how the crowd's agents make way for each other (crowd_yielding.hpp).
#include "crowd/crowd_yielding.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/contact.hpp"

namespace footfall::crowd {
namespace {

/// The nearest places round `state` (in rings 0.75 m apart, up to 3.75 m)
/// where the agent could stand out of `keep_out`, clear of the obstacles and
/// of the plans of `others`, nearest first by the way there in steps of a
/// ring (on the mesh, for the torso circle: out of a gap between boxes the
/// room may be round its end, and only side-on may it get there; of places
/// as near, the one with the most room round it, from the others where they
/// are now); at most kAsideTries of them.
std::vector<Vec2> room_aside(const FootstepState& state, const KeepOut& keep_out,
                             const MovingObstacles& others, const FootstepPlanner& planner,
                             const NavMesh* mesh) {
  constexpr int kDirections = 16, kRings = 5;
  constexpr double kRingStep = 0.75;  // [m]
  constexpr double kDetour = 1.5;     // [m] at most this much longer than the straight line
  std::vector<Vec2> now;
  for (const MovingObstacle& other : others)
    now.push_back(com_at(*other.plan, state.time).position);
  struct Place {
    FootstepState standing;
    int rings;  // the way there, in rings (rounded up)
    double room;
  };
  std::vector<Place> places;
  for (int r = 1; r <= kRings; ++r) {
    const double ring = kRingStep * r;
    for (int k = 0; k < kDirections; ++k) {
      const Vec2 point = state.com + ring * unit(2.0 * kPi * k / kDirections);
      double room = std::numeric_limits<double>::infinity();
      for (const Vec2 where : now) room = std::min(room, distance(where, point));
      if (room < planner.character().torso_width) continue;  // another stands there now
      FootstepState there = standing_state(point, state.facing, planner.character());
      there.time = state.time;
      if (!planner.validity().room_to_turn(point) || !planner.validity().keeps_out(there, keep_out) ||
          planner.validity().collides(there))
        continue;
      int rings = r;
      if (mesh != nullptr) {
        const PathResult path =
            mesh->find_path({state.com, point, planner.character().torso_radius});
        if (path.status != PathStatus::kFound || path.length > ring + kDetour) continue;
        rings = static_cast<int>(std::ceil(path.length / kRingStep - 1e-6));
      }
      places.push_back({there, rings, room});
    }
  }
  std::stable_sort(places.begin(), places.end(), [](const Place& a, const Place& b) {
    return a.rings < b.rings || (a.rings == b.rings && a.room > b.room);
  });
  std::vector<FootstepState> states;
  for (const Place& place : places) states.push_back(place.standing);
  std::vector<Vec2> clear;
  for (const std::size_t k : planner.validity().standing_clear(states, others, kAsideTries))
    clear.push_back(states[k].com);
  return clear;
}

}  // namespace

KeepOut wish_discs(const std::vector<Footstep>& steps, const CharacterParams& character) {
  KeepOut discs;
  const Vec2 from = steps.front().com_start;
  for (const Footstep& step : steps) {
    discs.push_back({step.foot_position, character.foot_radius + kWishPad});
    for (long k = first_contact_instant(step.start_time);
         static_cast<double>(k) * kContactDt <= step.end_time; ++k) {
      const Vec2 com = com_at(step, static_cast<double>(k) * kContactDt).position;
      if (distance(com, from) > kWishReach) return discs;
      for (Circle circle : torso_circles(com, step.phi, character, 0.0, step.behavior)) {
        circle.radius += kWishPad;
        discs.push_back(circle);
      }
    }
  }
  discs.push_back({steps.back().com_end, 0.5 * character.torso_width + kRestRoom});
  return discs;
}

bool gives_way(const std::vector<Walker>& walkers, std::size_t i, const Snapshot& now) {
  const Walker& w = walkers[i];
  if (w.done || w.dormant || w.blocked < kGiveWayBlocked || patient(w, w.state)) return false;
  const Vec2 bound = bound_of(w, now.com[i]);
  std::vector<std::size_t> around;
  now.around(i, kJamDistance, around);
  for (const std::size_t j : around) {
    if (walkers[j].done || walkers[j].dormant || !now.present[j] ||
        distance(now.com[j], now.com[i]) > kJamDistance)
      continue;
    if (dot(bound_of(walkers[j], now.com[j]), bound) < 0.0) return true;
  }
  return false;
}

LocalGoal keep_right(const std::vector<Walker>& walkers, std::size_t i, LocalGoal target,
                     const std::vector<std::size_t>& seen, const Snapshot& now,
                     const FootstepPlanner& planner, const NavMesh* mesh) {
  const Vec2 from = walkers[i].state.com, to = target.point - from;
  if (target.is_goal || length(to) < 1e-6) return target;
  const Vec2 ahead = unit(angle_of(to));
  const bool oncoming = std::any_of(seen.begin(), seen.end(), [&](std::size_t j) {
    const Vec2 d = now.com[j] - from;
    const double along = dot(d, ahead);
    if (along <= 0.0 || along > kKeepRightAhead || std::fabs(cross(ahead, d)) > kKeepRightBand)
      return false;
    // Walking this way, and bound this way too: not one stepping back to
    // make room (near a door, all bound the same way).
    const Vec2 bound = bound_of(walkers[j], now.com[j]);
    return dot(com_at(walkers[j].plan, now.t).velocity, ahead) < -kOncomingSpeed &&
           dot(bound, ahead) < -0.5 * length(bound);
  });
  if (!oncoming || (mesh != nullptr && mesh->clearance(from) < kKeepRightRoom)) return target;
  for (double shift = kKeepRightShift; shift >= 0.5; shift -= 0.5) {
    const Vec2 point = target.point - shift * perp(ahead);
    if (planner.validity().room_to_turn(point) &&
        !planner.validity().collides(standing_state(point, angle_of(to), planner.character())) &&
        (mesh == nullptr || mesh->clearance_between(from, point, kKeepRightRoom) >= kKeepRightRoom))
      return {point, false};
  }
  return target;
}

std::optional<SearchResult> step_aside(const FootstepState& state, const KeepOut& keep_out,
                                       const MovingObstacles& others,
                                       const FootstepPlanner& planner, const NavMesh* mesh,
                                       const SearchOptions& options) {
  SearchOptions to_place = options;
  to_place.reach_or_nothing = true;
  for (const Vec2 place : room_aside(state, keep_out, others, planner, mesh)) {
    SearchResult result = planner.plan(state, place, others, to_place);
    if (result.status == Status::kSuccess && !result.footsteps.empty()) return result;
  }
  return std::nullopt;
}

bool must_make_room(const std::vector<Walker>& walkers, std::size_t i, const Snapshot& now,
                    const FootstepPlanner& planner) {
  const Walker& w = walkers[i];
  const Vec2 bound = bound_of(w, w.state.com);
  return std::any_of(w.yielding_to.begin(), w.yielding_to.end(), [&](std::size_t j) {
    return (walkers[j].wish_makes_room || dot(bound_of(walkers[j], now.com[j]), bound) < 0.0) &&
           !planner.validity().keeps_out(w.state, walkers[j].wish);
  });
}

void show_wish(std::vector<Walker>& walkers, std::size_t i, Attempt& a, const Snapshot& now,
               const std::vector<std::size_t>& near, std::vector<std::size_t>& asked) {
  const double t = now.t;
  Walker& w = walkers[i];
  if (w.done || w.blocked == 0 || a.wish.empty()) {
    w.wish.clear();
    w.wish_makes_room = false;
    return;
  }
  w.wish = std::move(a.wish);
  w.wish_makes_room = a.wish_makes_room;
  for (const std::size_t j : near) {
    Walker& other = walkers[j];
    if (other.done || goes_first(walkers, now, j, i) ||
        other.planner->validity().keeps_out(rest_of(other), w.wish))
      continue;
    if (std::find(other.yielding_to.begin(), other.yielding_to.end(), i) != other.yielding_to.end())
      continue;  // asked before
    if (other.dormant) wake(other, t);
    other.yielding_to.push_back(i);
    other.retry_at = std::min(other.retry_at, t);
    other.news_at = t;
    asked.push_back(j);
  }
}

}  // namespace footfall::crowd
