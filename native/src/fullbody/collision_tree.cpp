// Footfall — building the bounding-volume hierarchy: split at the median
// centre along the longest axis, down to leaves of kLeafSize triangles.
#include "fullbody/collision_tree.hpp"

#include <algorithm>
#include <numeric>

namespace footfall {
namespace {

constexpr std::uint32_t kLeafSize = 4;

Box3 box_of(const SceneTriangle& t) {
  Box3 box;
  for (const Vec3& c : t.corners) box.take_in(c);
  return box;
}

double axis_value(Vec3 v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }

}  // namespace

CollisionTree::CollisionTree(std::vector<SceneTriangle> input) : triangles(std::move(input)) {
  if (triangles.empty()) return;
  std::vector<Box3> boxes;
  std::vector<Vec3> centres;
  boxes.reserve(triangles.size());
  centres.reserve(triangles.size());
  for (SceneTriangle& t : triangles) {
    const Vec3 n = cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]);
    const double area = length(n);
    t.normal = area > 0 ? (1.0 / area) * n : Vec3{};
    t.offset = dot(t.normal, t.corners[0]);
    t.box = box_of(t);
    boxes.push_back(t.box);
    centres.push_back((1.0 / 3.0) * (t.corners[0] + t.corners[1] + t.corners[2]));
  }
  nodes.reserve(2 * triangles.size() / kLeafSize + 2);
  build(boxes, centres, 0, static_cast<std::uint32_t>(triangles.size()));
}

std::uint32_t CollisionTree::build(std::vector<Box3>& boxes, std::vector<Vec3>& centres,
                                   std::uint32_t first, std::uint32_t count) {
  const std::uint32_t index = static_cast<std::uint32_t>(nodes.size());
  nodes.emplace_back();
  Box3 box, centre_box;
  for (std::uint32_t i = first; i < first + count; ++i) {
    box.take_in(boxes[i]);
    centre_box.take_in(centres[i]);
  }
  nodes[index].box = box;
  if (count <= kLeafSize) {
    nodes[index].first = first;
    nodes[index].count = count;
    return index;
  }
  const Vec3 extent = centre_box.max - centre_box.min;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  // Sort the range's triangles by centre along the axis (an index permutation
  // applied to the three parallel arrays).
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), first);
  const std::uint32_t half = count / 2;
  std::nth_element(order.begin(), order.begin() + half, order.end(),
                   [&](std::uint32_t a, std::uint32_t b) {
                     return axis_value(centres[a], axis) < axis_value(centres[b], axis);
                   });
  std::vector<SceneTriangle> t(count);
  std::vector<Box3> b(count);
  std::vector<Vec3> c(count);
  for (std::uint32_t k = 0; k < count; ++k) {
    t[k] = triangles[order[k]];
    b[k] = boxes[order[k]];
    c[k] = centres[order[k]];
  }
  std::copy(t.begin(), t.end(), triangles.begin() + first);
  std::copy(b.begin(), b.end(), boxes.begin() + first);
  std::copy(c.begin(), c.end(), centres.begin() + first);
  build(boxes, centres, first, half);
  const std::uint32_t second = build(boxes, centres, first + half, count - half);
  nodes[index].second = second;
  return index;
}

}  // namespace footfall
