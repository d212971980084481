// Fuzz target: the navigation mesh's updates. The input is a sequence of
// obstacles added, moved and removed on a small grid (coordinates that fall
// on each other, as degenerate as a scene can be); afterwards the mesh must
// answer as one built from scratch from the obstacles that remain: the same
// clearances and lines of sight, the same path statuses, path lengths within
// the queries' documented tolerance.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "footfall/navmesh/navmesh.hpp"
#include "properties.hpp"

namespace {

using footfall::NavMesh;
using footfall::Vec2;
using footfall::fuzz::require;

constexpr double kCell = 0.5;  // [m] the grid that coordinates fall on
constexpr Vec2 kLow{0.0, 0.0}, kHigh{8.0, 8.0};

// An obstacle from 3 bytes: a point, or a box of 1-4 cells a side.
std::vector<Vec2> obstacle_of(std::uint8_t kind, std::uint8_t at, std::uint8_t size) {
  const Vec2 corner{kCell * (at % 16), kCell * (at / 16)};
  if (kind % 4 == 0) return {corner};
  const double w = kCell * (1 + size % 4), h = kCell * (1 + (size / 4) % 4);
  return {corner, corner + Vec2{w, 0.0}, corner + Vec2{w, h}, corner + Vec2{0.0, h}};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  NavMesh mesh(kLow, kHigh);
  std::map<int, std::vector<Vec2>> present;  // by id
  for (std::size_t i = 0; i + 3 <= size && i < 3 * 64; i += 3) {
    const std::uint8_t op = data[i];
    if (op % 3 == 2 && !present.empty()) {  // remove (or, every other time, move) one
      auto it = present.begin();
      std::advance(it, data[i + 1] % present.size());
      mesh.remove(it->first);
      const std::vector<Vec2> polygon = it->second;
      present.erase(it);
      if (op & 8) {
        std::vector<Vec2> moved = polygon;
        for (Vec2& p : moved) p = p + Vec2{kCell * (data[i + 2] % 3) - kCell, 0.0};
        present[mesh.add_polygon(moved)] = moved;
      }
    } else {
      const std::vector<Vec2> polygon = obstacle_of(op, data[i + 1], data[i + 2]);
      present[mesh.add_polygon(polygon)] = polygon;
    }
  }
  NavMesh rebuilt(kLow, kHigh);
  for (const auto& [id, polygon] : present) rebuilt.add_polygon(polygon);

  for (double x = 0.25; x < kHigh.x; x += 1.0) {
    for (double y = 0.25; y < kHigh.y; y += 1.0) {
      const Vec2 p{x, y};
      require(std::fabs(mesh.clearance(p) - rebuilt.clearance(p)) <= 1e-9,
              "updated mesh as rebuilt: clearance");
      const Vec2 q{kHigh.x - y, x};
      require(mesh.line_of_sight(p, q) == rebuilt.line_of_sight(p, q),
              "updated mesh as rebuilt: line of sight");
    }
  }
  for (const double radius : {0.1, 0.3}) {
    const footfall::PathQuery query{{0.25, 0.25}, {7.75, 7.6}, radius};
    const footfall::PathResult a = mesh.find_path(query), b = rebuilt.find_path(query);
    require(a.status == b.status, "updated mesh as rebuilt: path status");
    if (a.status == footfall::PathStatus::kFound)
      require(std::fabs(a.length - b.length) <= 0.01 * b.length + 1e-9,
              "updated mesh as rebuilt: path length");
  }
  return 0;
}
