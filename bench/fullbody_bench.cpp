// Footfall — full-body collision benchmarks (Google Benchmark): one body pose
// (14 capsules) tested against a scene of 10,008 triangles (834 boxes of
// random sizes and heights, tables among them, in a 60 x 60 m hall), at
// places among the clutter; the deepest contact; building the scene. Run:
// build/bench/footfall_fullbody_bench
#include <benchmark/benchmark.h>

#include <vector>

#include "footfall/fullbody/body_model.hpp"
#include "footfall/fullbody/collision_scene.hpp"
#include "footfall/scenes/scenes.hpp"
#include "util/seeded_random.hpp"

namespace footfall {
namespace {

struct Clutter {
  std::vector<Obstacle> obstacles;
  std::vector<GroundPlacement> places;  // where poses are tested
};

const Clutter& clutter() {
  static const Clutter scene = [] {
    Clutter c;
    c.obstacles = box_field(834, 60.0, 3);
    SeededRandom random(4);
    for (Obstacle& o : c.obstacles) {
      o.height = random.uniform(0.4, 2.2);
      if (random.uniform(0, 1) < 0.2) o.base = random.uniform(0.3 * o.height, 0.9 * o.height);
    }
    for (int i = 0; i < 4096; ++i)
      c.places.push_back({{random.uniform(-29, 29), random.uniform(-29, 29)},
                          random.uniform(-3.14, 3.14)});
    return c;
  }();
  return scene;
}

// state.range(0): 1 tests places where the pose touches something (the test
// stops at the first limb that does), 0 places where it touches nothing
// (every limb is tested against the triangles near the body).
void BM_PoseTest(benchmark::State& state) {
  const Clutter& c = clutter();
  const CollisionScene scene(c.obstacles);
  const BodyModel body{CharacterParams{}};
  BodyPose pose;
  body.pose_at(Behavior::kWalk, 0.25, pose);
  std::vector<GroundPlacement> places;
  for (const GroundPlacement& p : c.places)
    if (static_cast<bool>(scene.test(pose, p)) == (state.range(0) == 1)) places.push_back(p);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(scene.test(pose, places[i++ % places.size()]));
  state.counters["triangles"] = static_cast<double>(scene.triangle_count());
  state.counters["places"] = static_cast<double>(places.size());
}
BENCHMARK(BM_PoseTest)->Arg(0)->Arg(1);

void BM_DeepestContact(benchmark::State& state) {
  const Clutter& c = clutter();
  const CollisionScene scene(c.obstacles);
  const BodyModel body{CharacterParams{}};
  BodyPose pose;
  body.pose_at(Behavior::kWalk, 0.25, pose);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(scene.test(pose, c.places[i++ & 4095], true));
}
BENCHMARK(BM_DeepestContact);

void BM_BuildScene(benchmark::State& state) {
  const Clutter& c = clutter();
  for (auto _ : state) benchmark::DoNotOptimize(CollisionScene(c.obstacles));
}
BENCHMARK(BM_BuildScene)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace footfall

BENCHMARK_MAIN();
