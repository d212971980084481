// Footfall — a goal no way leads to for an agent's body.
#include "crowd/unreachable.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "footfall/model/polyline.hpp"

namespace footfall::detail {

namespace {

/// Halvings of the widest disc's radius: to well under a millimetre.
constexpr int kHalvings = 20;
/// Samples along the way. [m]
constexpr double kSample = 0.01;
/// A sample this much roomier than the tightest one may still be the
/// narrowest place: the widest way passes its bottleneck and the corners it
/// turns round alike at its disc's radius, up to the arcs' sampling. [m]
constexpr double kNear = 0.02;
/// How far across the way a sample looks for the middle of its passage, and
/// in what steps: round a corner the clearance grows away from it, in a
/// passage it is greatest in the middle. [m]
constexpr double kAcross = 0.1;
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

// Half the width of the passage `along` the way: the most clearance across
// it there, looking to each side as far as the first blocked point.
double half_width(const NavMesh& mesh, const Polyline& way, double along) {
  const double heading = way.heading_at(along);
  const Vec2 across{-std::sin(heading), std::cos(heading)};
  const Vec2 p = way.point_at(along);
  double most = mesh.clearance(p);
  for (const double side : {-1.0, 1.0}) {
    for (double s = kAcrossStep; s <= kAcross + 1e-12; s += kAcrossStep) {
      const double c = mesh.clearance(p + (side * s) * across);
      if (c <= 0.0) break;
      most = std::max(most, c);
    }
  }
  return most;
}

struct Sample {
  double along;  // [m]
  double half;   // half_width there [m]
};

// How far along `way` it is narrowest: the middle of the narrowest passage.
double narrowest_along(const NavMesh& mesh, const Polyline& way) {
  std::vector<double> along;
  std::vector<double> clear;
  for (double s = 0.0; s < way.length() + kSample; s += kSample) {
    along.push_back(std::min(s, way.length()));
    clear.push_back(mesh.clearance(way.point_at(along.back())));
  }
  const double tightest = *std::min_element(clear.begin(), clear.end());
  std::vector<Sample> near;
  for (std::size_t k = 0; k < along.size(); ++k)
    if (clear[k] <= tightest + kNear) near.push_back({along[k], half_width(mesh, way, along[k])});
  const auto least = std::min_element(near.begin(), near.end(), [](const Sample& a, const Sample& b) {
    return a.half < b.half;
  });
  // The run of samples next to each other as narrow as the least.
  const auto same = [&](std::size_t a, std::size_t b) {
    return near[b].along - near[a].along <= 1.5 * kSample && near[b].half <= least->half + kSameWidth;
  };
  std::size_t first = static_cast<std::size_t>(least - near.begin()), last = first;
  while (first > 0 && same(first - 1, first)) --first;
  while (last + 1 < near.size() && same(last, last + 1)) ++last;
  return 0.5 * (near[first].along + near[last].along);
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
  const double at = narrowest_along(mesh, way);
  const Vec2 point = way.point_at(at);
  ShortOfGoal result{{point, 2.0 * mesh.clearance(point), needs, Behavior::kSideStep}, from};
  for (double s = at - kStandBack; s > 0.0; s -= kSample) {
    if (mesh.clearance(way.point_at(s)) >= clearance + kStandRoom) {
      result.stand = way.point_at(s);
      break;
    }
  }
  return result;
}

}  // namespace footfall::detail
