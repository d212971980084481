// Footfall — navigation mesh benchmarks (Google Benchmark): the issue's
// 1000 x 1000 m scenes with 2,000 and 10,000 random boxes of 1-6 m, and a
// room-scale scene. Build, path queries over the whole domain at radii
// 0.25-3 m, the funnel alone, point obstacles inserted and removed, and boxes
// moved; and the hostile cases: one polygon of many vertices, and many
// overlapping boxes. Run: build/bench/footfall_navmesh_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "footfall/crowd/scenario.hpp"
#include "footfall/scenes/box_scenes.hpp"
#include "navmesh/channel_funnel.hpp"
#include "footfall/navmesh/navmesh.hpp"

namespace footfall {
namespace {

using bench::box_scene;
using bench::BoxScene;
using bench::build;
using bench::queries;

/// The scenes are built once per process; benchmarks share them.
const BoxScene& scene_of(int boxes) {
  static const BoxScene two_thousand = box_scene(2000, 1000.0, 1);
  static const BoxScene ten_thousand = box_scene(10000, 1000.0, 2);
  static const BoxScene room = box_scene(60, 30.0, 3);
  return boxes == 2000 ? two_thousand : boxes == 10000 ? ten_thousand : room;
}

const NavMesh& mesh_of(int boxes) {
  static const std::unique_ptr<NavMesh> two_thousand = build(scene_of(2000));
  static const std::unique_ptr<NavMesh> ten_thousand = build(scene_of(10000));
  static const std::unique_ptr<NavMesh> room = build(scene_of(60));
  return boxes == 2000 ? *two_thousand : boxes == 10000 ? *ten_thousand : *room;
}

void BM_Build(benchmark::State& state) {
  const BoxScene& scene = scene_of(static_cast<int>(state.range(0)));
  std::size_t triangles = 0;
  for (auto _ : state) {
    const auto mesh = build(scene);
    triangles = mesh->triangle_count();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_Build)->Arg(60)->Arg(2000)->Arg(10000)->Unit(benchmark::kMillisecond);

/// Path queries; range(1) is the radius in centimetres.
void BM_Query(benchmark::State& state) {
  const NavMesh& mesh = mesh_of(static_cast<int>(state.range(0)));
  const std::vector<PathQuery> all =
      queries(mesh, static_cast<double>(state.range(1)) / 100.0, 200, 7);
  std::size_t i = 0, found = 0, asked = 0;
  for (auto _ : state) {
    const PathResult result = mesh.find_path(all[i]);
    found += result.status == PathStatus::kFound;
    ++asked;
    i = (i + 1) % all.size();
  }
  state.counters["found"] = static_cast<double>(found) / static_cast<double>(asked);
  state.counters["triangles"] = static_cast<double>(mesh.triangle_count());
}
BENCHMARK(BM_Query)
    ->ArgsProduct({{60}, {25, 100}})
    ->ArgsProduct({{2000, 10000}, {25, 100, 300}})
    ->Unit(benchmark::kMicrosecond);

/// The funnel alone through a winding corridor of `range(0)` portals, 3 m wide.
void BM_Funnel(benchmark::State& state) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> bend(-0.6, 0.6);
  std::vector<Portal> portals;
  Vec2 at{0, 0};
  double heading = 0.0;
  for (int i = 0; i < state.range(0); ++i) {
    heading += bend(rng);
    at = at + 1.5 * unit(heading);
    const Vec2 across = 1.5 * perp(unit(heading));
    portals.push_back({at + across, at - across});
  }
  const Vec2 start{-1.0, 0.0};
  const Vec2 goal = at + 1.5 * unit(heading);
  std::size_t points = 0;
  for (auto _ : state) {
    const FunnelPath path = funnel(start, goal, portals, 0.25, 0.01);
    points = path.points.size();
    benchmark::DoNotOptimize(points);
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_Funnel)->Arg(16)->Arg(64)->Unit(benchmark::kMicrosecond);

/// A point obstacle inserted and removed again (repair included): the time
/// of one such pair.
void BM_PointInsertRemove(benchmark::State& state) {
  auto mesh = build(scene_of(static_cast<int>(state.range(0))));
  const std::vector<PathQuery> spots = queries(*mesh, 0.5, 256, 9);
  std::size_t i = 0;
  for (auto _ : state) {
    const int id = mesh->add_point(spots[i].from);
    mesh->remove(id);
    i = (i + 1) % spots.size();
  }
}
BENCHMARK(BM_PointInsertRemove)->Arg(2000)->Arg(10000)->Unit(benchmark::kMicrosecond);

/// One box moved by 0.5 m: removed and inserted at its new place.
void BM_MoveBox(benchmark::State& state) {
  const BoxScene& scene = scene_of(static_cast<int>(state.range(0)));
  auto mesh = std::make_unique<NavMesh>(scene.min_corner, scene.max_corner);
  std::vector<int> ids;
  for (const auto& box : scene.boxes) ids.push_back(mesh->add_polygon(box));
  std::vector<std::vector<Vec2>> boxes = scene.boxes;
  std::size_t i = 0;
  double step = 0.5;
  for (auto _ : state) {
    for (Vec2& corner : boxes[i]) corner.x += step;
    mesh->remove(ids[i]);
    ids[i] = mesh->add_polygon(boxes[i]);
    i = (i + 1) % boxes.size();
    if (i == 0) step = -step;  // back and forth, so the scene stays the same
  }
}
BENCHMARK(BM_MoveBox)->Arg(2000)->Arg(10000)->Unit(benchmark::kMicrosecond);

/// A circle of radius 20 m as one polygon of `range(0)` vertices (a
/// footprint read from a fine mesh), in a 100 m square: the mesh built.
std::vector<Vec2> fine_circle(int vertices) {
  std::vector<Vec2> circle;
  for (int k = 0; k < vertices; ++k) circle.push_back(20.0 * unit(2 * kPi * k / vertices));
  return circle;
}

void BM_BuildOnePolygon(benchmark::State& state) {
  const std::vector<Vec2> circle = fine_circle(static_cast<int>(state.range(0)));
  std::size_t triangles = 0;
  for (auto _ : state) {
    NavMesh mesh({-50, -50}, {50, 50});
    mesh.add_polygon(circle);
    triangles = mesh.triangle_count();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_BuildOnePolygon)->Arg(1000)->Arg(4000)->Arg(16000)->Arg(64000)->Unit(benchmark::kMillisecond);

/// A path past that circle for a disc of 0.3 m, from one side to the other.
void BM_PathRoundOnePolygon(benchmark::State& state) {
  NavMesh mesh({-50, -50}, {50, 50});
  mesh.add_polygon(fine_circle(static_cast<int>(state.range(0))));
  const PathQuery query{{-40, 0.5}, {40, -0.5}, 0.3, 0.01};
  double length = 0;
  for (auto _ : state) {
    length = mesh.find_path(query).length;
    benchmark::DoNotOptimize(length);
  }
  state.counters["length"] = length;
}
BENCHMARK(BM_PathRoundOnePolygon)->Arg(1000)->Arg(4000)->Arg(16000)->Arg(64000)->Unit(benchmark::kMillisecond);

/// A scenario's mesh (navmesh_of) of `range(0)` boxes of 5 m placed at
/// random in a square of `range(1)` m, most overlapping others (as one
/// SteerSuite obstacleRegion makes them).
void BM_BuildOverlappingBoxes(benchmark::State& state) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(0.0, static_cast<double>(state.range(1)) - 5.0);
  Scenario scenario;
  for (int i = 0; i < state.range(0); ++i) {
    const Vec2 low{at(rng), at(rng)};
    scenario.obstacles.push_back({{low, low + Vec2{5, 0}, low + Vec2{5, 5}, low + Vec2{0, 5}}, 2.0, 0.0, {}});
  }
  std::size_t triangles = 0;
  for (auto _ : state) {
    const NavMesh mesh = navmesh_of(scenario);
    triangles = mesh.triangle_count();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_BuildOverlappingBoxes)
    ->ArgsProduct({{250, 500, 2000}, {11, 20, 40}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace footfall

BENCHMARK_MAIN();
