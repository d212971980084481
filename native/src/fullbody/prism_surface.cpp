// Footfall — prism surfaces.
#include "fullbody/prism_surface.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <queue>

namespace footfall::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Kernel, CGAL::Triangulation_face_base_with_info_2<int, Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<Kernel>, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

}  // namespace

std::vector<std::array<Vec2, 3>> triangulate_polygon(const std::vector<Vec2>& polygon) {
  Cdt cdt;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    if (!(a == b)) cdt.insert_constraint(Cdt::Point(a.x, a.y), Cdt::Point(b.x, b.y));
  }
  // Each face's depth: how many outline edges lie between it and the outside.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::queue<Cdt::Face_handle> now, deeper;
  cdt.infinite_face()->info() = 0;
  now.push(cdt.infinite_face());
  for (int depth = 0; !now.empty(); ++depth) {
    while (!now.empty()) {
      const Cdt::Face_handle f = now.front();
      now.pop();
      for (int e = 0; e < 3; ++e) {
        const Cdt::Face_handle next = f->neighbor(e);
        if (next->info() >= 0) continue;
        if (cdt.is_constrained({f, e})) {
          deeper.push(next);
        } else {
          next->info() = depth;
          now.push(next);
        }
      }
    }
    while (!deeper.empty()) {
      const Cdt::Face_handle f = deeper.front();
      deeper.pop();
      if (f->info() >= 0) continue;
      f->info() = depth + 1;
      now.push(f);
    }
  }
  std::vector<std::array<Vec2, 3>> result;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    std::array<Vec2, 3> corners;
    for (int k = 0; k < 3; ++k) corners[k] = {f->vertex(k)->point().x(), f->vertex(k)->point().y()};
    result.push_back(corners);
  }
  return result;
}

std::vector<std::array<Vec3, 3>> prism_surface(const Obstacle& prism) {
  const std::vector<Vec2>& polygon = prism.polygon;
  const auto at = [](Vec2 p, double z) { return Vec3{p.x, p.y, z}; };
  std::vector<std::array<Vec3, 3>> result;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % n];
    result.push_back({at(a, prism.base), at(b, prism.base), at(b, prism.height)});
    result.push_back({at(a, prism.base), at(b, prism.height), at(a, prism.height)});
  }
  for (const auto& t : triangulate_polygon(polygon)) {
    result.push_back({at(t[0], prism.base), at(t[1], prism.base), at(t[2], prism.base)});
    result.push_back({at(t[0], prism.height), at(t[1], prism.height), at(t[2], prism.height)});
  }
  return result;
}

}  // namespace footfall::detail
