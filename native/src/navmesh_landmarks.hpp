// Footfall — landmarks for the path search's heuristic (differential
// heuristics: Goldberg and Harrelson 2005, Sturtevant et al. 2009). Distances
// from a few landmarks, measured once for the query's radius, bound the rest
// of a path from any turning point far more tightly than the straight line
// where the disc must go round obstacles.
//
// The metric. For a radius r, m_r is the length of the shortest path that
// crosses from face to face only through gates (portals kept r from both
// ends) of portals at least 2r long: the search's own relaxation without its
// corner-width test. It is a true metric (paths may be joined anywhere,
// since no test depends on how a face is entered and left), and no shorter
// than the disc's path or the search's relaxed length between the same
// points, which pass stricter tests through the same gates.
//
// The bound. For the root R of a node and the goal, the triangle inequality
// gives m_r(R, goal) >= m_r(L, R) - m_r(L, goal) for every landmark L. The
// landmarks keep, per vertex v, the least m_r from L to a point r from v on
// one of its edges (a lower bound on m_r(L, R) for every gate end R at v, and
// for a point p of a face, less r + |v, p|), and per face the length of a
// path from L to its centroid (an upper bound on m_r(L, goal), plus the
// straight line from the centroid to the goal). Both are measured by the
// path search itself, run with no goal from each landmark.
//
// Any change to the obstacles makes them stale: NavMeshState drops them.
#pragma once

#include <cstddef>
#include <memory>
#include <unordered_map>
#include <vector>

#include "navmesh_impl.hpp"

namespace footfall {

/// Distances m_r from a few landmarks, for one radius r.
class Landmarks {
 public:
  /// Landmarks chosen farthest first (each the vertex farthest from those
  /// before it; the first at the vertex nearest the domain's centre), with
  /// their distances. Costs one search of the whole mesh per landmark.
  static std::shared_ptr<const Landmarks> build(const NavMeshState& mesh, double radius);

  double radius() const { return radius_; }
  std::size_t count() const { return count_; }
  /// Node expansions the build took.
  long work() const { return work_; }
  /// Per landmark: at most m_r from it to any point r from `v` along an edge
  /// of `v` (infinite if it reaches none); nullptr for an unknown vertex.
  const double* near_vertex(Vertex v) const { return row(vertex_row_, near_vertex_, v); }
  /// Per landmark: at least m_r from it to the centroid of `f` (infinite if
  /// it does not reach `f`); nullptr for an unknown face.
  const double* to_centroid(Face f) const { return row(face_row_, to_centroid_, f); }

 private:
  template <class Handle>
  const double* row(const std::unordered_map<Handle, std::size_t>& rows, const std::vector<double>& values,
                    Handle h) const {
    const auto found = rows.find(h);
    return found == rows.end() ? nullptr : &values[found->second * count_];
  }

  double radius_ = 0.0;
  std::size_t count_ = 0;
  long work_ = 0;
  std::unordered_map<Vertex, std::size_t> vertex_row_;
  std::vector<double> near_vertex_;  ///< Row per vertex, a column per landmark.
  std::unordered_map<Face, std::size_t> face_row_;
  std::vector<double> to_centroid_;  ///< Row per walkable face, a column per landmark.
};

/// The landmarks' lower bounds on m_r from points to one goal.
class LandmarkHeuristic {
 public:
  /// Bounds to `goal`, in walkable face `goal_face` (none without landmarks).
  LandmarkHeuristic(const Landmarks* landmarks, Face goal_face, Vec2 goal);

  /// Lower bound on m_r from `p`, in walkable face `f`, to the goal (0 if none).
  double from_face(Face f, Vec2 p) const;
  /// Lower bound on m_r from a gate end at `v` (a point r from `v` along one
  /// of its edges) to the goal (0 if none).
  double from_gate_end(Vertex v) const;
  bool empty() const { return used_.empty(); }

 private:
  const Landmarks* landmarks_;
  std::vector<std::size_t> used_;  ///< Landmarks that reach the goal's face.
  std::vector<double> goal_upper_;  ///< Per landmark: m_r from it to the goal is at most this.
};

/// What the path search, run with no goal (NavMeshState::build_landmarks),
/// reports of every node it expands.
class SearchReport {
 public:
  virtual ~SearchReport() = default;
  /// A path of `length` to a point r from `v` along an edge of `v`.
  virtual void gate_end(Vertex v, double length) = 0;
  /// A path of `length` to the centroid of face `f`.
  virtual void centroid(Face f, double length) = 0;
};

/// Runs the path search for radius `radius` from `source`, in walkable face
/// `face`, with no goal and no corner-width test, to the end: every gate
/// end and centroid it reaches is reported, among others with the exact
/// m_r to it. Returns the nodes expanded. Defined in navmesh_query.cpp,
/// beside the search.
long search_everywhere(const NavMeshState& mesh, Face face, Vec2 source, double radius,
                       SearchReport& report);

}  // namespace footfall
