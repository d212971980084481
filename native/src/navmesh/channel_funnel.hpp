// Footfall — the funnel algorithm for a disc: the shortest path through a
// channel of portals that keeps `radius` away from every portal end.
#pragma once

#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall {

/// One edge crossed by the channel, named as seen walking through it.
struct Portal {
  Vec2 left;   ///< End on the walker's left. [m]
  Vec2 right;  ///< End on the walker's right. [m]
};

/// What the funnel found.
struct FunnelPath {
  bool ok = false;         ///< False when two corners on opposite sides leave no room between them.
  int failed_portal = -1;  ///< The portal where that happened.
  std::vector<Vec2> points;  ///< Polyline, arcs sampled outside their circles. [m]
};

/// Shortest path from `start` to `goal` through `portals` (in order) that
/// wraps around portal ends at `radius`: tangent segments joined by arcs.
/// Arcs are sampled on the circumscribed polygon, so no chord comes nearer
/// than `radius` to its corner and no vertex farther than `radius + tolerance`.
/// A corner that ends a portal is taken to cross it on its arc; with
/// `strict_ends`, the portal's other end is also checked against a tangent
/// beside the corner that crosses the portal (the arc can stop short of the
/// last portals of the corner's fan). That is the exact rule, but it can
/// enforce corners the lenient one lets slip that then clash with corners
/// across the path, leaving long channels to the slow exact fallback: it is
/// for a channel the lenient rule fails.
FunnelPath funnel(Vec2 start, Vec2 goal, const std::vector<Portal>& portals, double radius,
                  double tolerance, bool strict_ends = false);

}  // namespace footfall
