// Footfall — the ground's walls (the edges a walker cannot step across),
// found by sampling the walkable faces' edges.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "footfall/ground/ground.hpp"
#include "ground/walkable_edges.hpp"

namespace footfall {
namespace {

constexpr double kOwnLevel = 0.02;  // [m] a level this near the edge's height is the face's own

bool any_within(const std::vector<GroundPoint>& levels, double z, double reach) {
  return std::any_of(levels.begin(), levels.end(),
                     [&](const GroundPoint& level) { return std::fabs(level.z - z) <= reach; });
}

}  // namespace

std::vector<GroundWall> Ground::walls(double max_step, double headroom,
                                      double min_normal_z) const {
  std::vector<GroundWall> walls;
  const auto standable = [&](Vec2 p) {
    return not_too_steep(standable_at(p, headroom), min_normal_z);
  };
  const auto steep = [&](int f) { return faces_[f].normal.z < min_normal_z; };
  visit_walkable_edges([&](Vec2 a, Vec2 b, double za, double zb, Vec2 outward) {
    const int samples = std::max(1, static_cast<int>(std::ceil(length(b - a) / kEdgeSpacing)));
    int run = -1;  // the first sample of the current run of wall samples
    for (int i = 0; i <= samples; ++i) {
      bool wall = false;
      if (i < samples) {
        const double t = (i + 0.5) / samples;
        const Vec2 s = a + t * (b - a);
        const double z = za + t * (zb - za);
        // Only where the face itself is stood on; beyond the step, nothing to stand on.
        wall = any_within(standable(s - kEdgeBeside * outward), z, kOwnLevel) &&
               !any_within(standable(s + kEdgeBeside * outward), z, max_step);
      }
      if (wall && run < 0) run = i;
      if (!wall && run >= 0) {
        walls.push_back({a + (static_cast<double>(run) / samples) * (b - a),
                         a + (static_cast<double>(i) / samples) * (b - a)});
        run = -1;
      }
    }
  }, [&](int f, int g) { return steep(f) != steep(g); });
  return walls;
}

}  // namespace footfall
