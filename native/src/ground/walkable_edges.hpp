// Footfall — Ground::visit_walkable_edges, shared by the walls and the layers.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "footfall/ground/ground.hpp"

namespace footfall {

/// Edges are sampled this far apart. [m]
constexpr double kEdgeSpacing = 0.05;
/// A sample's two sides lie this far from the edge: gaps as wide are closed. [m]
constexpr double kEdgeBeside = 0.02;
/// For visit_walkable_edges: no edge two walkable triangles of a mesh share.
constexpr auto kNoSharedEdges = [](int, int) { return false; };

/// `levels` without those steeper than a normal's `min_normal_z`: no ground
/// to stand on, for the walls.
inline std::vector<GroundPoint> not_too_steep(std::vector<GroundPoint> levels,
                                              double min_normal_z) {
  levels.erase(std::remove_if(levels.begin(), levels.end(),
                              [&](const GroundPoint& level) {
                                return level.normal.z < min_normal_z;
                              }),
               levels.end());
  return levels;
}

/// Twice the signed area of a polygon: positive when it winds anticlockwise.
inline double twice_signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    twice += cross(polygon[j], polygon[i]);
  return twice;
}

template <class Visit, class KeepShared>
void Ground::visit_walkable_edges(Visit&& visit, KeepShared&& keep_shared) const {
  // Per mesh, the walkable triangles (faces) using each edge (by its
  // vertices): the first two, and how many.
  struct Users {
    std::array<int, 2> faces{-1, -1};
    int count = 0;
  };
  std::map<std::pair<int, int>, Users> users;
  int mesh = -1;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const Face& face = faces_[f];
    if (!face.walkable) continue;
    const GroundSurface& surface = surfaces_[face.surface];
    if (face.triangle < 0) {
      const std::vector<Vec2>& polygon = surface.polygon;
      const double turn = twice_signed_area(polygon) >= 0.0 ? 1.0 : -1.0;
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        if (a == b) continue;
        const Vec2 d = (1.0 / length(b - a)) * (b - a);
        visit(a, b, surface.height, surface.height, turn * Vec2{d.y, -d.x});
      }
      continue;
    }
    if (face.surface != mesh) {  // a mesh's faces come one after another
      mesh = face.surface;
      users.clear();
      for (std::size_t g = f; g < faces_.size() && faces_[g].surface == mesh; ++g) {
        if (!faces_[g].walkable) continue;
        const auto& t = surface.mesh.triangles[faces_[g].triangle];
        for (int c = 0; c < 3; ++c) {
          Users& edge = users[std::minmax(t[c], t[(c + 1) % 3])];
          if (edge.count < 2) edge.faces[edge.count] = static_cast<int>(g);
          ++edge.count;
        }
      }
    }
    const auto& t = surface.mesh.triangles[face.triangle];
    for (int c = 0; c < 3; ++c) {
      const Users& edge = users[std::minmax(t[c], t[(c + 1) % 3])];
      if (edge.count > 1) {
        const int other = edge.faces[0] == static_cast<int>(f) ? edge.faces[1] : edge.faces[0];
        if (!keep_shared(static_cast<int>(f), other)) continue;
      }
      const Vec3 a = surface.mesh.vertices[t[c]], b = surface.mesh.vertices[t[(c + 1) % 3]];
      if (ground(a) == ground(b)) continue;
      const Vec2 d = (1.0 / length(ground(b - a))) * ground(b - a);
      visit(ground(a), ground(b), a.z, b.z, Vec2{d.y, -d.x});  // upward faces wind anticlockwise
    }
  }
}

template <class Visit>
void Ground::visit_inner_edge_samples(Visit&& visit) const {
  visit_walkable_edges(
      [&](Vec2 a, Vec2 b, double, double, Vec2 outward) {
        const int samples =
            std::max(1, static_cast<int>(std::ceil(length(b - a) / kEdgeSpacing)));
        for (int i = 0; i <= samples; ++i)
          visit(a + (static_cast<double>(i) / samples) * (b - a) - kEdgeBeside * outward);
      },
      kNoSharedEdges);
}

}  // namespace footfall
