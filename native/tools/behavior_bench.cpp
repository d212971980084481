// footfall bench --behaviors: the full-body planner on the paper's random
// environments (section 4.2), normal and dense, goals at 6 and 10 steps.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <vector>

#include "bench_command.hpp"
#include "footfall/fullbody/behavioral_planner.hpp"
#include "footfall/scenes/behavior_scenes.hpp"

namespace footfall::tools {

void run_behavior_bench(int repeat, std::ostream& out) {
  out << std::left << std::setw(18) << "environment" << std::right << std::setw(7) << "goals"
      << std::setw(7) << "found" << std::setw(10) << "narrower" << std::setw(10) << "mean ms"
      << std::setw(9) << "sd ms" << std::setw(11) << "median ms" << std::setw(9) << "max ms"
      << std::setw(9) << "points" << std::setw(9) << "poses"
      << "\n";
  for (const char* name : {"random_normal_6", "random_normal_10", "random_dense_6",
                           "random_dense_10"}) {
    const BehaviorScene scene = behavior_scene(name);
    NavMesh mesh = navmesh_of(scene.scenario);
    const CollisionScene obstacles(scene.scenario.obstacles);
    const BodyModel body(scene.scenario.character);
    BehavioralPlanner planner(mesh, obstacles, body, scene.scenario.planner);
    std::vector<double> ms;
    int found = 0, narrower = 0;
    double points = 0, poses = 0;
    for (const Vec2 goal : scene.goals) {
      double fastest = INFINITY;
      BehaviorPath path;
      for (int r = 0; r < repeat; ++r) {
        const auto begin = std::chrono::steady_clock::now();
        path = planner.plan(scene.start, goal);
        fastest = std::min(fastest, std::chrono::duration<double, std::milli>(
                                        std::chrono::steady_clock::now() - begin)
                                        .count());
      }
      ms.push_back(fastest);
      found += path.status == BehaviorPathStatus::kFound ? 1 : 0;
      narrower += std::any_of(path.sections.begin(), path.sections.end(),
                              [](const BehaviorSection& s) { return s.behavior != Behavior::kWalk; });
      points += path.point_obstacles;
      poses += static_cast<double>(path.poses_tested);
    }
    const double n = static_cast<double>(ms.size());
    const double mean = std::accumulate(ms.begin(), ms.end(), 0.0) / n;
    double variance = 0;
    for (const double m : ms) variance += (m - mean) * (m - mean) / n;
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    out << std::left << std::setw(18) << name << std::right << std::setw(7) << ms.size()
        << std::setw(7) << found << std::setw(10) << narrower << std::fixed << std::setprecision(3)
        << std::setw(10) << mean << std::setw(9) << std::sqrt(variance) << std::setw(11)
        << sorted[sorted.size() / 2] << std::setw(9) << sorted.back() << std::setprecision(1)
        << std::setw(9) << points / n << std::setw(9) << poses / n << "\n";
  }
  out << "(fastest of " << repeat
      << " runs per goal; one core; narrower: paths with a section other than walk;\n"
         " points: point obstacles inserted, poses: body poses tested, per query)\n";
}

}  // namespace footfall::tools
