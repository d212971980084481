#include "navmesh/outline_union.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_set_2.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace footfall {

namespace {

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Exact>;

std::vector<Vec2> to_outline(const ExactPolygon& polygon) {
  std::vector<Vec2> outline;
  for (auto v = polygon.vertices_begin(); v != polygon.vertices_end(); ++v)
    outline.push_back({CGAL::to_double(v->x()), CGAL::to_double(v->y())});
  return outline;
}

struct Bounds {
  double x0, y0, x1, y1;
};

int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

std::vector<OverlapGroup> overlapping_groups(const std::vector<std::vector<Vec2>>& outlines) {
  const int n = static_cast<int>(outlines.size());
  std::vector<ExactPolygon> exact(n);
  std::vector<Bounds> boxes(n);
  std::vector<int> candidates;
  for (int i = 0; i < n; ++i) {
    if (outlines[i].size() < 3) continue;
    ExactPolygon& polygon = exact[i];
    for (Vec2 p : outlines[i]) polygon.push_back({p.x, p.y});
    if (!polygon.is_simple()) continue;
    if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
    const auto box = polygon.bbox();
    boxes[i] = {box.xmin(), box.ymin(), box.xmax(), box.ymax()};
    candidates.push_back(i);
  }
  // Pairs whose boxes meet, swept along x; tested exactly unless already joined.
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  std::sort(candidates.begin(), candidates.end(), [&](int a, int b) { return boxes[a].x0 < boxes[b].x0; });
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const int a = candidates[k];
    for (std::size_t l = k + 1; l < candidates.size() && boxes[candidates[l]].x0 <= boxes[a].x1; ++l) {
      const int b = candidates[l];
      if (boxes[b].y0 > boxes[a].y1 || boxes[b].y1 < boxes[a].y0) continue;
      const int ra = root(parent, a), rb = root(parent, b);
      if (ra == rb || !CGAL::do_intersect(exact[a], exact[b])) continue;
      parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  }
  std::map<int, std::vector<int>> members;  // by the group's first member
  for (int i : candidates) members[root(parent, i)].push_back(i);
  std::vector<OverlapGroup> groups;
  for (auto& [first, group] : members) {
    if (group.size() < 2) continue;
    std::sort(group.begin(), group.end());
    std::vector<ExactPolygon> polygons;
    for (int i : group) polygons.push_back(exact[i]);
    CGAL::Polygon_set_2<Exact> covered;
    covered.join(polygons.begin(), polygons.end());
    std::vector<CGAL::Polygon_with_holes_2<Exact>> parts;
    covered.polygons_with_holes(std::back_inserter(parts));
    OverlapGroup result;
    result.members = group;
    for (const auto& part : parts) {
      result.region.outlines.push_back(to_outline(part.outer_boundary()));
      for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole)
        result.region.holes.push_back(to_outline(*hole));
    }
    groups.push_back(std::move(result));
  }
  return groups;
}

}  // namespace footfall
