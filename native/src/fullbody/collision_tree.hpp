// Footfall — the bounding-volume hierarchy over the scene's triangles.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "footfall/model/geometry3.hpp"

namespace footfall {

/// An axis-aligned box in space.
struct Box3 {
  Vec3 min{INFINITY, INFINITY, INFINITY};
  Vec3 max{-INFINITY, -INFINITY, -INFINITY};

  void take_in(Vec3 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
  }
  void take_in(const Box3& b) {
    take_in(b.min);
    take_in(b.max);
  }
  bool meets(const Box3& b) const {
    return min.x <= b.max.x && b.min.x <= max.x && min.y <= b.max.y && b.min.y <= max.y &&
           min.z <= b.max.z && b.min.z <= max.z;
  }
};

/// One triangle, the obstacle it belongs to, and its plane (unit normal and
/// offset; a zero normal for a degenerate triangle) for a quick rejection.
struct SceneTriangle {
  std::array<Vec3, 3> corners;
  int obstacle = 0;
  Vec3 normal;
  double offset = 0;
  Box3 box;
};

/// A binary tree of boxes; leaves hold a few triangles. Nodes are stored
/// depth first: a node's first child follows it, `second` is the other.
struct CollisionTree {
  struct Node {
    Box3 box;
    std::uint32_t second = 0;  ///< Inner node: index of the second child.
    std::uint32_t first = 0;   ///< Leaf: first triangle.
    std::uint32_t count = 0;   ///< Leaf: number of triangles; 0 for an inner node.
  };
  std::vector<Node> nodes;
  std::vector<SceneTriangle> triangles;  ///< Reordered so that each leaf's are adjacent.

  /// Builds the tree over `triangles`.
  explicit CollisionTree(std::vector<SceneTriangle> triangles);

  /// Calls visit(triangle) for every triangle whose box meets `box`, until
  /// visit returns true; returns whether it did.
  template <typename Visit>
  bool visit(const Box3& box, Visit visit) const {
    if (nodes.empty()) return false;
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const std::uint32_t index = stack[--top];
      const Node& node = nodes[index];
      if (!node.box.meets(box)) continue;
      if (node.count > 0) {
        for (std::uint32_t t = node.first; t < node.first + node.count; ++t)
          if (visit(triangles[t])) return true;
      } else {
        stack[top++] = node.second;
        stack[top++] = index + 1;
      }
    }
    return false;
  }

 private:
  std::uint32_t build(std::vector<Box3>& boxes, std::vector<Vec3>& centres, std::uint32_t first,
                      std::uint32_t count);
};

}  // namespace footfall
