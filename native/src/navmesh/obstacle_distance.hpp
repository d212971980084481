// Footfall — distances from the walkable space to the nearest obstacles, found
// by walking the triangulation outward from where the question is asked.
#pragma once

#include <limits>

#include "navmesh/navmesh_impl.hpp"

namespace footfall {

/// The obstacle point nearest to a segment, and the obstacle edge it lies on.
struct NearestObstacle {
  Vec2 point;
  Vec2 edge_from, edge_to;  ///< Ends of that edge; both `point` at a vertex.
  bool on_vertex() const { return edge_from == point && edge_to == point; }
};

/// Distance from the segment [a, b] to the nearest obstacle or boundary.
/// `start` is a walkable face that contains `a`. Exact up to rounding: every
/// vertex lies on an obstacle, and the walk crosses only unconstrained edges
/// nearer to the segment than the best distance found so far, which the
/// segment from the nearest point to its obstacle always does. With
/// `nearest`, also where that obstacle is (unset if none is nearer than
/// `limit`). [m]
double obstacle_distance(const NavMeshState& mesh, Face start, Vec2 a, Vec2 b,
                         double limit = std::numeric_limits<double>::infinity(),
                         NearestObstacle* nearest = nullptr);

/// True if the segment [a, b] crosses no constrained edge and passes no vertex
/// nearer than `room` (every vertex is on an obstacle): a line of sight.
/// `start` is a walkable face that contains `a`. It walks only the faces the
/// segment crosses, so for `a` and `b` farther than `room` from every
/// obstacle it answers obstacle_distance(mesh, start, a, b, room) >= room at
/// a fraction of the cost (an agent's eyes are never that near one).
bool line_of_sight(const NavMeshState& mesh, Face start, Vec2 a, Vec2 b, double room);

/// Width of the passage around corner `corner` of walkable face `f`: the
/// distance from that corner to the nearest obstacle seen across the opposite
/// edge (within the corner's angle), capped by the two edges beside the corner.
/// A disc of radius r can only pass around the corner if this is at least 2r,
/// because its centre crosses every segment from the corner to such an obstacle.
/// Stops searching beyond `limit`. [m]
double corner_width(const NavMeshState& mesh, Face f, int corner,
                    double limit = std::numeric_limits<double>::infinity());

/// The same width within the wedge at `corner` from the ray through `from`
/// counter-clockwise to the ray through `to` (both inside the corner's angle),
/// without the cap by the edges beside the corner. A disc that starts or ends
/// at a point p in `f` reaches the edge from the corner to vertex v within `f`
/// only if this is at least 2r between v and p: a shorter segment from the
/// corner to an obstacle beyond would cut p off from that edge. [m]
double wedge_width(const NavMeshState& mesh, Face f, int corner, Vec2 from, Vec2 to,
                   double limit = std::numeric_limits<double>::infinity());

/// True if every point of edge `edge` of `f` is nearer than `radius` to a
/// vertex or a constrained edge of the two faces beside it, so that no disc
/// of that radius can cross it. Corner widths look across one edge only, so
/// they can pass a portal that an obstacle of the face on its other side
/// pinches (a disturbance, in Kallmann's words).
bool portal_covered(Face f, int edge, double radius);

/// Distance between the segments [a, b] and [c, d]. [m]
double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

}  // namespace footfall
