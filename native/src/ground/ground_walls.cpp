// Footfall — the ground's walls (the edges a walker cannot step across) and
// points with levels above one another, found by sampling the walkable faces'
// edges.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "footfall/ground/ground.hpp"

namespace footfall {
namespace {

constexpr double kSpacing = 0.05;  // [m] between samples along an edge
constexpr double kBeside = 0.02;   // [m] from the edge, either side: gaps as wide are closed
constexpr double kOwnLevel = 0.02;  // [m] a level this near the edge's height is the face's own

double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    twice += cross(polygon[j], polygon[i]);
  return 0.5 * twice;
}

bool any_within(const std::vector<GroundPoint>& levels, double z, double reach) {
  return std::any_of(levels.begin(), levels.end(),
                     [&](const GroundPoint& level) { return std::fabs(level.z - z) <= reach; });
}

}  // namespace

template <class Visit>
void Ground::visit_walkable_edges(Visit&& visit) const {
  // Per mesh, how many walkable triangles use each edge (by its vertices).
  std::map<std::pair<int, int>, int> shared;
  int mesh = -1;
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const Face& face = faces_[f];
    if (!face.walkable) continue;
    const GroundSurface& surface = surfaces_[face.surface];
    if (face.triangle < 0) {
      const std::vector<Vec2>& polygon = surface.polygon;
      const double turn = signed_area(polygon) >= 0.0 ? 1.0 : -1.0;
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
      shared.clear();
      for (std::size_t g = f; g < faces_.size() && faces_[g].surface == mesh; ++g) {
        if (!faces_[g].walkable) continue;
        const auto& t = surface.mesh.triangles[faces_[g].triangle];
        for (int c = 0; c < 3; ++c) ++shared[std::minmax(t[c], t[(c + 1) % 3])];
      }
    }
    const auto& t = surface.mesh.triangles[face.triangle];
    for (int c = 0; c < 3; ++c) {
      if (shared[std::minmax(t[c], t[(c + 1) % 3])] > 1) continue;
      const Vec3 a = surface.mesh.vertices[t[c]], b = surface.mesh.vertices[t[(c + 1) % 3]];
      if (ground(a) == ground(b)) continue;
      const Vec2 d = (1.0 / length(ground(b - a))) * ground(b - a);
      visit(ground(a), ground(b), a.z, b.z, Vec2{d.y, -d.x});  // upward faces wind anticlockwise
    }
  }
}

std::vector<GroundWall> Ground::walls(double max_step, double headroom) const {
  std::vector<GroundWall> walls;
  visit_walkable_edges([&](Vec2 a, Vec2 b, double za, double zb, Vec2 outward) {
    const int samples = std::max(1, static_cast<int>(std::ceil(length(b - a) / kSpacing)));
    int run = -1;  // the first sample of the current run of wall samples
    for (int i = 0; i <= samples; ++i) {
      bool wall = false;
      if (i < samples) {
        const double t = (i + 0.5) / samples;
        const Vec2 s = a + t * (b - a);
        const double z = za + t * (zb - za);
        // Only where the face itself is stood on; beyond the step, nothing to stand on.
        wall = any_within(standable_at(s - kBeside * outward, headroom), z, kOwnLevel) &&
               !any_within(standable_at(s + kBeside * outward, headroom), z, max_step);
      }
      if (wall && run < 0) run = i;
      if (!wall && run >= 0) {
        walls.push_back({a + (static_cast<double>(run) / samples) * (b - a),
                         a + (static_cast<double>(i) / samples) * (b - a)});
        run = -1;
      }
    }
  });
  return walls;
}

std::optional<StackedLevels> Ground::stacked_levels(double headroom) const {
  std::optional<StackedLevels> found;
  const auto check = [&](Vec2 p) {
    if (found) return;
    const std::vector<GroundPoint> levels = standable_at(p, headroom);
    if (levels.size() > 1) found = StackedLevels{p, levels[0].z, levels[1].z};
  };
  visit_walkable_edges([&](Vec2 a, Vec2 b, double, double, Vec2 outward) {
    const int samples = std::max(1, static_cast<int>(std::ceil(length(b - a) / kSpacing)));
    for (int i = 0; i <= samples; ++i)
      check(a + (static_cast<double>(i) / samples) * (b - a) - kBeside * outward);
  });
  return found;
}

}  // namespace footfall
