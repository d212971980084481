// Footfall — the navigation mesh: a constrained Delaunay triangulation of the
// walkable ground, answering shortest-path queries for a disc of any radius,
// with obstacles added and removed by id.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "footfall/model/geometry.hpp"

namespace footfall {

struct NavMeshState;

/// How a path query ended.
enum class PathStatus {
  kFound,         ///< A path with the asked clearance exists and is returned.
  kNoPath,        ///< Start and goal are free, but no path of that clearance joins them.
  kStartBlocked,  ///< The start is closer than the radius to an obstacle.
  kGoalBlocked,   ///< The goal is closer than the radius to an obstacle.
  kOutside,       ///< The start or the goal lies outside the domain.
};

/// The JSON and Python name of a status: "found", "no_path", "start_blocked",
/// "goal_blocked", "outside".
const char* to_string(PathStatus status);

/// What a path query returns.
struct PathResult {
  PathStatus status = PathStatus::kNoPath;  ///< How the query ended.
  /// Polyline from start to goal; arcs around corners are sampled so that every
  /// chord stays outside the corner's circle. Empty unless found. [m]
  std::vector<Vec2> points;
  double length = 0.0;         ///< Length of the polyline. [m] [>= 0]
  double min_clearance = 0.0;  ///< Smallest distance from the polyline to an obstacle. [m]
  /// Per point, the ground's height under it, for a way over a scenario's
  /// ground (LayeredNavigation); empty otherwise. [m]
  std::vector<double> heights;
};

/// One triangle of the mesh, for drawing.
struct NavTriangle {
  std::array<Vec2, 3> corners;  ///< Counter-clockwise corners. [m]
  bool walkable = false;        ///< Inside the domain and outside every obstacle.
  /// Per corner i: the largest radius that may pass around corner i, from the
  /// edge before it to the edge after it; 0 where the triangle is not walkable. [m]
  std::array<double, 3> corner_clearance{};
  /// Per edge i (opposite corner i): true if it lies on an obstacle or the boundary.
  std::array<bool, 3> constrained{};
};

/// Settings of one path query.
struct PathQuery {
  Vec2 from;                   ///< Start point. [m]
  Vec2 to;                     ///< Goal point. [m]
  double radius = 0.25;        ///< Radius of the disc that walks the path. [m] [>= 0]
  double arc_tolerance = 0.01; ///< Largest gap between a sampled arc and its circle. [m] [> 0]
};

/// A triangulated walkable domain with dynamic obstacles.
///
/// The domain is an axis-aligned rectangle; obstacles are polygons (either
/// winding, touching, overlapping, nested or self-intersecting: a point is
/// blocked when it is inside any of them, by the non-zero rule) and isolated
/// points. Each obstacle gets an id; removing it repairs the mesh locally.
/// Queries are const and may run in parallel; updates may not overlap them.
class NavMesh {
 public:
  /// A mesh of the empty rectangle [min_corner, max_corner].
  /// Throws std::invalid_argument if the corners are not finite or the
  /// rectangle is empty.
  NavMesh(Vec2 min_corner, Vec2 max_corner);
  ~NavMesh();
  NavMesh(NavMesh&&) noexcept;
  NavMesh& operator=(NavMesh&&) noexcept;

  /// Adds a polygon obstacle (at least one vertex; repeated vertices are
  /// dropped; fewer than three distinct ones make a segment or a point) and
  /// returns its id. The part outside the domain is clipped away (an obstacle
  /// wholly outside blocks nothing but keeps its id). Throws
  /// std::invalid_argument naming `name` (or "polygon") and the vertex if a
  /// coordinate is NaN, infinite or beyond kMaxCoordinate.
  int add_polygon(const std::vector<Vec2>& polygon, const std::string& name = "");
  /// Adds a region as one obstacle and returns its id: the area inside its
  /// `outlines` (polygons as add_polygon takes them; a detailed one enters
  /// simplified) and outside its `holes` (as they are; a hole is open to
  /// whatever lies in it). Those of fewer than three distinct vertices in
  /// the domain are left out. Throws like add_polygon.
  int add_region(const std::vector<std::vector<Vec2>>& outlines, const std::vector<std::vector<Vec2>>& holes,
                 const std::string& name = "");
  /// Adds a point obstacle and returns its id (outside the domain it blocks
  /// nothing). Throws like add_polygon.
  int add_point(Vec2 point, const std::string& name = "");
  /// Adds an obstacle that blocks nothing (one with no footprint, such as an
  /// obstacle wholly above the head) and returns its id.
  int add_empty();
  /// Removes the obstacle with this id. Throws std::out_of_range if there is none.
  void remove(int id);
  /// True if an obstacle has this id.
  bool contains(int id) const;

  /// Shortest path for a disc of `query.radius`. Throws std::invalid_argument
  /// for a negative or non-finite radius or tolerance, or non-finite points.
  PathResult find_path(const PathQuery& query) const;
  /// Distance from `point` to the nearest obstacle or boundary; 0 when the
  /// point is blocked or outside the domain. [m]
  double clearance(Vec2 point) const;
  /// Distance from the segment [a, b] to the nearest obstacle or boundary, up
  /// to `limit` (the walk stops there: a small limit makes this a cheap line of
  /// sight test); 0 when the segment crosses an obstacle or leaves the domain. [m]
  double clearance_between(Vec2 a, Vec2 b,
                           double limit = std::numeric_limits<double>::infinity()) const;
  /// True if the segment [a, b] lies in the walkable domain and crosses no
  /// obstacle, passing none nearer than 1e-9 m: the line of sight. For points
  /// that far from every obstacle, clearance_between(a, b, 1e-9) >= 1e-9,
  /// found by walking only the triangles the segment crosses.
  bool line_of_sight(Vec2 a, Vec2 b) const;
  /// line_of_sight(from, p) for every p of `to` (`from` is located once).
  std::vector<char> lines_of_sight(Vec2 from, const std::vector<Vec2>& to) const;

  /// Every finite triangle, for drawing.
  std::vector<NavTriangle> triangles() const;
  /// Number of finite triangles.
  std::size_t triangle_count() const;
  /// The domain's corners. [m]
  Vec2 min_corner() const;
  Vec2 max_corner() const;

 private:
  std::unique_ptr<NavMeshState> impl_;
};

}  // namespace footfall
