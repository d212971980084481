// Footfall — the navigation mesh benchmark's scenes, shared with the tests
// that pin down answers the benchmark once showed wrong: random turned boxes
// in a square, and start and goal pairs over the whole domain.
#pragma once

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "footfall/navmesh/navmesh.hpp"

namespace footfall::bench {

/// A box scene: the domain and its boxes, each a turned rectangle.
struct BoxScene {
  Vec2 min_corner, max_corner;
  std::vector<std::vector<Vec2>> boxes;
};

/// The upright rectangle with corners `lo` and `hi`, counter-clockwise.
inline std::vector<Vec2> box_between(Vec2 lo, Vec2 hi) {
  return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
}

/// The rectangle of half sides `half` about `centre`, turned by `angle`. [rad]
inline std::vector<Vec2> box_at(Vec2 centre, Vec2 half, double angle) {
  std::vector<Vec2> out;
  for (Vec2 corner : {Vec2{-half.x, -half.y}, Vec2{half.x, -half.y}, half, Vec2{-half.x, half.y}})
    out.push_back(centre + rotate(corner, angle));
  return out;
}

/// `count` boxes with sides of 1-6 m, turned at random, anywhere in the square
/// of side `size` (they may overlap, as scattered props do).
inline BoxScene box_scene(int count, double size, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> where(0.0, size), side(1.0, 6.0), turn(0.0, kPi);
  BoxScene scene{{0, 0}, {size, size}, {}};
  for (int i = 0; i < count; ++i) {
    const Vec2 centre{where(rng), where(rng)};
    const Vec2 half{0.5 * side(rng), 0.5 * side(rng)};
    scene.boxes.push_back(box_at(centre, half, turn(rng)));
  }
  return scene;
}

inline std::unique_ptr<NavMesh> build(const BoxScene& scene) {
  auto mesh = std::make_unique<NavMesh>(scene.min_corner, scene.max_corner);
  for (const auto& box : scene.boxes) mesh->add_polygon(box);
  return mesh;
}

/// Start and goal pairs spread over the whole domain, both clear by `radius`.
inline std::vector<PathQuery> queries(const NavMesh& mesh, double radius, int count,
                                      std::uint32_t seed) {
  std::mt19937 rng(seed);
  const Vec2 lo = mesh.min_corner(), hi = mesh.max_corner();
  std::uniform_real_distribution<double> x(lo.x, hi.x), y(lo.y, hi.y);
  auto free_point = [&] {
    for (;;) {
      const Vec2 p{x(rng), y(rng)};
      if (mesh.clearance(p) > radius) return p;
    }
  };
  std::vector<PathQuery> out;
  for (int i = 0; i < count; ++i) out.push_back({free_point(), free_point(), radius, 0.01});
  return out;
}

}  // namespace footfall::bench
