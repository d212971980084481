// Footfall — prism surfaces.
#include "fullbody/prism_surface.hpp"

#include <numeric>

namespace footfall::detail {
namespace {

double signed_area(const std::vector<Vec2>& polygon) {
  double area = 0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    area += cross(polygon[j], polygon[i]);
  return 0.5 * area;
}

bool inside_triangle(Vec2 p, Vec2 a, Vec2 b, Vec2 c) {
  return cross(b - a, p - a) >= 0 && cross(c - b, p - b) >= 0 && cross(a - c, p - c) >= 0;
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec2>& polygon) {
  std::vector<std::array<int, 3>> result;
  std::vector<int> left(polygon.size());
  std::iota(left.begin(), left.end(), 0);
  if (signed_area(polygon) < 0) std::reverse(left.begin(), left.end());  // counter-clockwise
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < left.size() && !clipped; ++i) {
      const int a = left[(i + left.size() - 1) % left.size()], b = left[i],
                c = left[(i + 1) % left.size()];
      if (cross(polygon[b] - polygon[a], polygon[c] - polygon[b]) <= 0) continue;  // reflex
      bool ear = true;
      for (const int other : left) {
        if (other == a || other == b || other == c) continue;
        if (inside_triangle(polygon[other], polygon[a], polygon[b], polygon[c])) ear = false;
        if (!ear) break;
      }
      if (!ear) continue;
      result.push_back({a, b, c});
      left.erase(left.begin() + static_cast<long>(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  for (std::size_t i = 1; i + 1 < left.size(); ++i) result.push_back({left[0], left[i], left[i + 1]});
  return result;
}

std::vector<std::array<Vec3, 3>> prism_surface(const Obstacle& prism) {
  const std::vector<Vec2>& polygon = prism.polygon;
  const auto at = [&](int i, double z) { return Vec3{polygon[i].x, polygon[i].y, z}; };
  std::vector<std::array<Vec3, 3>> result;
  const int n = static_cast<int>(polygon.size());
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    result.push_back({at(i, prism.base), at(j, prism.base), at(j, prism.height)});
    result.push_back({at(i, prism.base), at(j, prism.height), at(i, prism.height)});
  }
  for (const auto& t : triangulate_polygon(polygon)) {
    result.push_back({at(t[0], prism.base), at(t[1], prism.base), at(t[2], prism.base)});
    result.push_back({at(t[0], prism.height), at(t[1], prism.height), at(t[2], prism.height)});
  }
  return result;
}

}  // namespace footfall::detail
