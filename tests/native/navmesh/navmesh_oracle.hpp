// Test oracle for the navigation mesh: shortest paths of a disc among polygon
// and point obstacles, by brute force on a tangent visibility graph with its
// own plane geometry (no CGAL, nothing from the navmesh).
#pragma once

#include <string>
#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall::testing {

/// A walkable rectangle with obstacles. The rectangle's boundary is an
/// obstacle; a point is blocked inside a polygon by the non-zero rule, and
/// polygon edges are obstacles too (so a two-vertex polygon is a wall).
struct NavScene {
  Vec2 min_corner;                          ///< Domain's lower corner. [m]
  Vec2 max_corner;                          ///< Domain's upper corner. [m]
  std::vector<std::vector<Vec2>> polygons;  ///< Polygon obstacles, either winding. [m]
  std::vector<Vec2> points;                 ///< Point obstacles. [m]
};

/// The scene and a query as text with every digit, to rebuild a failing case.
std::string describe(const NavScene& scene, Vec2 from, Vec2 to, double radius);

/// Distance from `p` to the nearest obstacle; 0 inside a polygon or outside the domain. [m]
double clearance(const NavScene& scene, Vec2 p);

/// Smallest distance from the polyline's segments (not only its points) to an obstacle. [m]
double path_clearance(const NavScene& scene, const std::vector<Vec2>& polyline);

/// The oracle's shortest path.
struct OraclePath {
  bool found = false;        ///< A path of the asked clearance exists.
  double length = 0.0;       ///< Its length; 0 if not found. [m]
  std::vector<Vec2> points;  ///< The path, every segment at least the radius from obstacles.
};

/// Shortest path for a disc of `radius` from `from` to `to`. Arcs around
/// obstacle corners are polylines of at most `circle_sides` pieces per turn,
/// circumscribed about the corner's circle, so the length is at most
/// (1 + oracle_excess(circle_sides)) times the true one, and never below it.
OraclePath shortest_path(const NavScene& scene, Vec2 from, Vec2 to, double radius,
                         int circle_sides = 128);

/// Relative bound of the oracle's overestimate of a shortest path's length.
double oracle_excess(int circle_sides = 128);

/// The oracle's answer to one query, with what is needed to judge another answer.
struct OracleAnswer {
  OraclePath path;           ///< The path at the radius.
  double lower_bound = 0.0;  ///< No path of the radius is shorter than this. [m]
  /// The answer changes within 1e-3 of the radius (a passage opens or closes):
  /// found differs, or the length jumps, between radius * (1 -+ 1e-3).
  bool ambiguous = false;
};

/// shortest_path at `radius` and just below and above it.
OracleAnswer judge_query(const NavScene& scene, Vec2 from, Vec2 to, double radius);

}  // namespace footfall::testing
