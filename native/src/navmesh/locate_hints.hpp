// Footfall — where to start CGAL's point location: a grid over the domain
// keeping one mesh vertex per cell. Without a start CGAL walks from the hull,
// past some sqrt(n) faces, so a local update of a large mesh would cost more
// in finding its place than in changing it, and a query would locate its start
// and goal, and every path it measures, from afar.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <vector>

#include "navmesh/navmesh_cdt.hpp"

namespace footfall {

/// One kept vertex per grid cell, where CGAL's walks start.
class LocateHints {
 public:
  LocateHints(Vec2 lo, Vec2 hi) : lo_(lo), hi_(hi) { cells_.resize(side_ * side_); }

  /// A face near `p`: one of a vertex kept in p's cell or the cells around
  /// it; null (CGAL then starts at the hull) if they are all empty.
  Face near(const Point& p) const {
    const int cx = coordinate(p.x(), lo_.x, hi_.x), cy = coordinate(p.y(), lo_.y, hi_.y);
    for (int ring = 0; ring <= kRings; ++ring)
      for (int y = std::max(cy - ring, 0); y <= std::min(cy + ring, side_ - 1); ++y)
        for (int x = std::max(cx - ring, 0); x <= std::min(cx + ring, side_ - 1); ++x) {
          if (std::max(std::abs(x - cx), std::abs(y - cy)) != ring) continue;
          const Vertex v = cells_[static_cast<std::size_t>(y * side_ + x)];
          if (v != Vertex()) return v->face();
        }
    return Face();
  }

  /// Keeps `v`, a new vertex of `cdt`, as its cell's start. The grid is
  /// refined as the mesh grows: at most two vertices per cell.
  void keep(const Cdt& cdt, Vertex v) {
    if (cdt.number_of_vertices() > 2 * cells_.size()) {
      side_ *= 2;
      cells_.assign(static_cast<std::size_t>(side_ * side_), Vertex());
      for (Vertex w : cdt.finite_vertex_handles()) cells_[cell(w->point())] = w;
    }
    cells_[cell(v->point())] = v;
  }

  /// Forgets `v` before CGAL removes it.
  void forget(Vertex v) {
    Vertex& kept = cells_[cell(v->point())];
    if (kept == v) kept = Vertex();
  }

 private:
  static constexpr int kRings = 2;

  int coordinate(double t, double lo, double hi) const {
    return static_cast<int>(std::clamp((t - lo) / (hi - lo) * side_, 0.0, side_ - 1.0));
  }
  std::size_t cell(const Point& p) const {
    return static_cast<std::size_t>(coordinate(p.y(), lo_.y, hi_.y) * side_ +
                                    coordinate(p.x(), lo_.x, hi_.x));
  }

  Vec2 lo_, hi_;
  int side_ = 8;
  std::vector<Vertex> cells_;
};

}  // namespace footfall
