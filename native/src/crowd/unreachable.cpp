// Footfall — a goal no way leads to for an agent's body.
#include "crowd/unreachable.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "footfall/model/polyline.hpp"

namespace footfall::detail {

namespace {

/// Halvings of the widest disc's radius: to well under a millimetre.
constexpr int kHalvings = 20;
/// Samples along the way, and across it. [m]
constexpr double kSample = 0.01;
constexpr double kAcrossStep = 0.005;
/// Half widths this close are the same passage's. [m]
constexpr double kSameWidth = 1e-3;

PathResult path_for(const NavMesh& mesh, Vec2 from, Vec2 to, double radius) {
  PathQuery query;
  query.from = from;
  query.to = to;
  query.radius = radius;
  return mesh.find_path(query);
}

struct Sample {
  double along;  // [m]
  double half;   // half the passage's width there [m]
  Vec2 middle;   // the passage's middle there [m]
};

// The passage `along` the way: the most clearance across it there, and
// where, looking `reach` to each side up to the first blocked point. Round a
// corner the clearance grows away from it (to `reach` more), in a passage
// narrower than 2 `reach` it is greatest in the middle (the way, bent round
// a narrower passage farther on, need not pass this one in the middle).
Sample across_way(const NavMesh& mesh, const Polyline& way, double along, double reach) {
  const double heading = way.heading_at(along);
  const Vec2 across{-std::sin(heading), std::cos(heading)};
  const Vec2 p = way.point_at(along);
  Sample most{along, mesh.clearance(p), p};
  for (const double side : {-1.0, 1.0}) {
    for (double s = kAcrossStep; s <= reach + kAcrossStep; s += kAcrossStep) {
      const Vec2 q = p + (side * s) * across;
      const double c = mesh.clearance(q);
      if (c <= 0.0) break;
      if (c > most.half) most = {along, c, q};
    }
  }
  return most;
}

// Where along `way` its first passage narrower than 2 `clearance` is
// narrowest: the middle of its narrowest part (if the samples miss every
// such passage, by a hair, the tightest sample).
Sample narrowest_on(const NavMesh& mesh, const Polyline& way, double clearance) {
  // The samples of that passage, from the first one narrower on.
  std::vector<Sample> passage;
  Sample tightest{0.0, clearance, way.point_at(0.0)};
  for (double s = 0.0; s < way.length() + kSample; s += kSample) {
    const double along = std::min(s, way.length());
    const Vec2 p = way.point_at(along);
    const double clear = mesh.clearance(p);
    if (clear < tightest.half) tightest = {along, clear, p};
    if (clear >= clearance && passage.empty()) continue;
    const Sample sample =
        clear < clearance ? across_way(mesh, way, along, clearance) : Sample{along, clear, p};
    if (sample.half < clearance)
      passage.push_back(sample);
    else if (!passage.empty())
      break;
  }
  if (passage.empty()) return tightest;
  const auto narrower = [](const Sample& a, const Sample& b) { return a.half < b.half; };
  const auto least = std::min_element(passage.begin(), passage.end(), narrower);
  // The run of samples as narrow as the least around it (a slot's depth).
  const auto same = [&](const Sample& s) { return s.half <= least->half + kSameWidth; };
  auto first = least, last = least;
  while (first != passage.begin() && same(*(first - 1))) --first;
  while (last + 1 != passage.end() && same(*(last + 1))) ++last;
  return across_way(mesh, way, 0.5 * (first->along + last->along), clearance);
}

}  // namespace

std::optional<ShortOfGoal> short_of_goal(const NavMesh& mesh, double clearance, Vec2 from,
                                         Vec2 to) {
  if (path_for(mesh, from, to, clearance).status != PathStatus::kNoPath) return std::nullopt;
  const double needs = 2.0 * clearance;
  PathResult widest = path_for(mesh, from, to, kThinnest);
  if (widest.status != PathStatus::kFound)
    return ShortOfGoal{{from, 0.0, needs, Behavior::kSideStep}, from};
  double lo = kThinnest, hi = clearance;
  for (int k = 0; k < kHalvings; ++k) {
    const double mid = 0.5 * (lo + hi);
    PathResult path = path_for(mesh, from, to, mid);
    if (path.status == PathStatus::kFound) {
      lo = mid;
      widest = std::move(path);
    } else {
      hi = mid;
    }
  }
  const Polyline way(widest.points);
  const Sample narrowest = narrowest_on(mesh, way, clearance);
  ShortOfGoal result{{narrowest.middle, 2.0 * narrowest.half, needs, Behavior::kSideStep}, from};
  for (double s = narrowest.along - kStandBack; s > 0.0; s -= kSample) {
    if (mesh.clearance(way.point_at(s)) >= clearance + kStandRoom) {
      result.stand = way.point_at(s);
      break;
    }
  }
  return result;
}

}  // namespace footfall::detail
