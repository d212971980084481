#include "bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <unistd.h>

#include "footfall/io/plan_file.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/planner/planner.hpp"
#include "footfall/scenes/scenes.hpp"
#include "footfall/ground/ground.hpp"
#include "util/seeded_random.hpp"

namespace footfall::tools {
namespace {


struct Query {
  FootstepState start;
  Vec2 goal;
};

struct Workload {
  std::string name;
  std::vector<Obstacle> obstacles;
  std::vector<Query> queries;
  std::vector<GroundSurface> ground{};  ///< None: the plane z = 0.
};

Query standing_query(Vec2 from, Vec2 to) {
  return {standing_state(from, angle_of(to - from), CharacterParams{}), to};
}

// The table-1 workload for one character: random crossings of 10 m in a field
// of 700 boxes, from standing, between points clear of the boxes.
Workload box_field_workload() {
  Workload workload{"field of 700 boxes", box_field(700, 80.0, 7), {}};
  const ObstacleMap map(workload.obstacles);
  const FootstepPlanner planner(CharacterParams{}, PlannerParams{}, map);
  SeededRandom random(11);
  while (workload.queries.size() < 100) {
    const Vec2 from{random.uniform(-30.0, 30.0), random.uniform(-30.0, 30.0)};
    const Vec2 to = from + 10.0 * unit(random.uniform(-kPi, kPi));
    const Query query = standing_query(from, to);
    if (planner.validity().collides(query.start) ||
        planner.validity().collides(standing_state(to, 0.0, CharacterParams{}))) {
      continue;
    }
    workload.queries.push_back(query);
  }
  return workload;
}

std::vector<Workload> workloads() {
  std::vector<Workload> all;
  all.push_back({"open 10 m", {}, {standing_query({0, 0}, {10, 0})}});
  all.push_back({"around a box", {box_obstacle({4, 0}, {1, 1})}, {standing_query({0, 0}, {8, 0})}});
  all.push_back({"0.7 m door", wall_with_door(4.0, 0.7), {standing_query({0, 0}, {8, 0})}});
  all.push_back(box_field_workload());
  // On ground, each beside the same walk on the flat.
  all.push_back({"8 m up six stairs", {}, {standing_query({-3, 0}, {5, 0})},
                 stairs_scenario(0, 0).ground});
  all.push_back({"8 m on the flat", {}, {standing_query({-3, 0}, {5, 0})}});
  all.push_back({"10 m over a hill", {}, {standing_query({-5, 0.5}, {5, 0.5})},
                 hill_scenario().ground});
  return all;
}

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const size_t index = static_cast<size_t>(p * static_cast<double>(values.size() - 1) + 0.5);
  return values[index];
}

}  // namespace

void run_bench(int repeat, std::ostream& out) {
  out << std::left << std::setw(20) << "workload" << std::right << std::setw(7) << "plans"
      << std::setw(9) << "reached" << std::setw(8) << "steps" << std::setw(11) << "generated"
      << std::setw(10) << "expanded" << std::setw(12) << "median ms" << std::setw(9) << "p90 ms"
      << std::setw(12) << "us / step"
      << "\n";
  for (const Workload& workload : workloads()) {
    const ObstacleMap map(workload.obstacles);
    const Ground ground(workload.ground);
    const FootstepPlanner planner(CharacterParams{}, PlannerParams{}, map, nullptr, &ground);
    std::vector<double> milliseconds;
    double steps = 0, generated = 0, expanded = 0;
    int reached = 0;
    for (const Query& query : workload.queries) {
      for (int r = 0; r < repeat; ++r) {
        const auto begin = std::chrono::steady_clock::now();
        const SearchResult result = planner.plan(query.start, query.goal);
        const auto end = std::chrono::steady_clock::now();
        milliseconds.push_back(std::chrono::duration<double, std::milli>(end - begin).count());
        if (r > 0) continue;
        steps += static_cast<double>(result.footsteps.size());
        generated += result.nodes_generated;
        expanded += result.nodes_expanded;
        reached += result.status == Status::kSuccess ? 1 : 0;
      }
    }
    const double plans = static_cast<double>(workload.queries.size());
    const double median = percentile(milliseconds, 0.5);
    out << std::left << std::setw(20) << workload.name << std::right << std::setw(7)
        << workload.queries.size() << std::setw(9) << reached << std::fixed << std::setprecision(1)
        << std::setw(8) << steps / plans << std::setw(11) << generated / plans << std::setw(10)
        << expanded / plans << std::setprecision(3) << std::setw(12) << median << std::setw(9)
        << percentile(milliseconds, 0.9) << std::setprecision(1) << std::setw(12)
        << 1000.0 * median / std::max(1.0, steps / plans) << "\n";
  }
  out << "(" << repeat << " timed runs per plan; one core; plans start standing)\n";
}

namespace {

/// Mean over the agents that reach of their time to the last goal over the
/// straight line's from their start at the preferred speed.
double mean_travel_over_alone(const Scenario& scenario, const Plan& plan) {
  double sum = 0.0;
  int counted = 0;
  for (std::size_t i = 0; i < plan.agents.size(); ++i) {
    const AgentPlan& agent = plan.agents[i];
    const AgentSpec& spec = scenario.agents[i];
    if (agent.status != AgentStatus::kReached) continue;
    double route = 0.0;
    Vec2 from = spec.position;
    for (const Vec2 goal : spec.goals) route += distance(from, std::exchange(from, goal));
    const double alone = route / character_of(agent, scenario.character).preferred_speed;
    if (alone <= 0.0) continue;
    sum += (agent.end_time() - spec.start_delay) / alone;
    ++counted;
  }
  return counted > 0 ? sum / counted : 0.0;
}

}  // namespace

void run_crowd_seeds(const std::function<Scenario(std::uint64_t)>& crowd, int first, int last,
                     int threads, const std::string& plan_path, std::ostream& out) {
  int short_of_goal = 0, overlapping = 0;
  for (int seed = first; seed <= last; ++seed) {
    RunControl control;
    control.threads = threads;
    // A city of thousands plans for many minutes: show how far it has come.
    const bool terminal = isatty(STDERR_FILENO) == 1;
    if (terminal)
      control.progress = [seed](double fraction) {
        std::cerr << "\rseed " << seed << ": planning " << std::setw(3)
                  << static_cast<int>(100 * fraction) << "%" << std::flush;
      };
    const Scenario scenario = crowd(static_cast<std::uint64_t>(seed));
    const auto begin = std::chrono::steady_clock::now();
    const Plan plan = plan_scenario(scenario, control);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (terminal) std::cerr << "\r                        \r" << std::flush;
    int reached = 0;
    for (const AgentPlan& agent : plan.agents)
      reached += agent.status == AgentStatus::kReached ? 1 : 0;
    const int overlaps = measure_plan(plan).overlaps;
    overlapping += overlaps;
    out << "seed " << seed << ": " << reached << " of " << plan.agents.size() << " reached, "
        << overlaps << " overlap samples, travel " << std::fixed << std::setprecision(2)
        << mean_travel_over_alone(scenario, plan) << " x alone (" << std::setprecision(1)
        << seconds << " s)\n";
    for (const AgentPlan& agent : plan.agents) {
      if (agent.status == AgentStatus::kReached) continue;
      ++short_of_goal;
      out << "  " << agent.name << ": " << agent.reason << " at (" << std::setprecision(2)
          << agent.stuck_at.x << ", " << agent.stuck_at.y << ")\n";
    }
    out.flush();
    if (!plan_path.empty() && seed == last) write_plan_file(plan, plan_path);
  }
  out << short_of_goal << " agent(s) short of their goals and " << overlapping
      << " overlap samples over seeds " << first << "-" << last << "\n";
}

void run_crowd_bench(int threads, int repeat, std::ostream& out) {
  struct CrowdWorkload {
    const char* name;
    Scenario scenario;
  };
  const CrowdWorkload workloads[] = {
      {"egress of 50", egress_scenario(50, 1)},
      {"two-way hall of 200", two_way_hall_scenario(200, 2)},
      {"500 among 700 boxes", box_field_crowd_scenario(500, 700, 7)},
      {"city of 1,000 (60 m)", city_scenario(1000, 60.0, 1)},
  };
  out << std::left << std::setw(22) << "workload" << std::right << std::setw(8) << "agents"
      << std::setw(9) << "reached" << std::setw(10) << "searches" << std::setw(11) << "generated"
      << std::setw(10) << "expanded" << std::setw(10) << "ms/plan" << std::setw(11) << "search ms"
      << std::setw(10) << "sim s" << std::setw(10) << "wall s" << std::setw(16) << "ms/agent/tick"
      << std::setw(12) << "ms/agent-s" << "\n";
  for (const CrowdWorkload& workload : workloads) {
    Plan plan;
    double wall = std::numeric_limits<double>::infinity(), search_seconds = 0.0;
    for (int run = 0; run < repeat; ++run) {
      RunControl control;
      control.threads = threads;
      double searching = 0.0;
      control.search_seconds = &searching;
      const auto begin = std::chrono::steady_clock::now();
      plan = plan_scenario(workload.scenario, control);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      if (seconds < wall) {
        wall = seconds;
        search_seconds = searching;
      }
    }
    long searches = 0;  // an integer: the fixed notation of the row before must not apply
    double generated = 0, expanded = 0, simulated = 0, agent_seconds = 0;
    int reached = 0;
    for (const AgentPlan& agent : plan.agents) {
      searches += agent.searches;
      generated += static_cast<double>(agent.nodes_generated);
      expanded += static_cast<double>(agent.nodes_expanded);
      simulated = std::max(simulated, agent.end_time());
      if (!agent.footsteps.empty())
        agent_seconds += agent.end_time() - agent.footsteps.front().start_time;
      reached += agent.status == AgentStatus::kReached ? 1 : 0;
    }
    const double agents = static_cast<double>(plan.agents.size());
    const auto plans = static_cast<double>(searches);
    const double ticks = std::max(1.0, simulated * 20.0);
    out << std::left << std::setw(22) << workload.name << std::right << std::setw(8)
        << plan.agents.size() << std::setw(9) << reached << std::setw(10) << searches << std::fixed
        << std::setprecision(1) << std::setw(11) << generated / std::max(1.0, plans)
        << std::setw(10) << expanded / std::max(1.0, plans) << std::setprecision(3) << std::setw(10)
        << 1000.0 * wall / std::max(1.0, plans) << std::setw(11)
        << 1000.0 * search_seconds / std::max(1.0, plans) << std::setprecision(1) << std::setw(10)
        << simulated << std::setw(10) << wall << std::setprecision(4) << std::setw(16)
        << 1000.0 * wall / (agents * ticks) << std::setw(12)
        << 1000.0 * wall / std::max(1e-9, agent_seconds) << "\n";
  }
  out << "(the fastest of " << repeat << " run(s) each on " << threads
      << " thread(s); ms/plan, ms/agent/tick and ms/agent-s are the whole run's wall time\n"
         " shared out, the last over the seconds each agent walks or waits, first step to last;\n"
         " search ms is the time in searches alone: way, local goal, search, cut to a rest)\n";
}

}  // namespace footfall::tools
