// footfall — the command-line program: plan scenarios, run the demo and the
// benchmarks. Exit codes: 0 success, 2 bad input or usage, 1 other failure.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "animate_command.hpp"
#include "bench_command.hpp"
#include "footfall/crowd/navigation.hpp"
#include "footfall/fullbody/body_check.hpp"
#include "footfall/io/path_json.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/io/scenario_file.hpp"
#include "footfall/io/steersuite.hpp"
#include "footfall/navmesh/navmesh.hpp"
#include "footfall/plan/ground_check.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/scenes/scenes.hpp"
#include "util/pending_files.hpp"
#include "util/quoted.hpp"

namespace {

using footfall::detail::user_text;

constexpr int kExitBadInput = 2;

// The usage keeps its columns.
// clang-format off
const char* const kUsage =
    "usage: footfall plan SCENARIO -o PLAN [--threads N] [--glb CROWD --rig RIG]\n"
    "                                         plan every agent of a scenario (JSON, or SteerSuite\n"
    "                                         .xml) on N threads (default 1; same plan either way);\n"
    "                                         with --glb, also the crowd animated as in animate\n"
    "       footfall plan SCENARIO --fixed PLAN --agents NAME,NAME -o OUT [--threads N] ...\n"
    "                                         plan the named agents again among the others, which\n"
    "                                         keep their plans in PLAN; OUT has every agent\n"
    "       footfall demo [-o PLAN] [--threads N] [--glb CROWD --rig RIG]\n"
    "                                         the built-in demo (default out/demo-plan.json)\n"
    "       footfall animate PLAN --rig RIG -o CROWD [--profile PROFILE] [--fps N]\n"
    "                                         every agent animated on a rig (.glb or .gltf; its\n"
    "                                         profile beside it by default, RIG.json) as one\n"
    "                                         animated .glb, N keys a second (default 24)\n"
    "       footfall metrics PLAN             our figures and SteerBench's, per agent, at 20 Hz,\n"
    "                                         and the full-body check of limbs against obstacles\n"
    "       footfall path SCENARIO --from X,Y[,Z] --to X,Y[,Z] --radius R\n"
    "                                         shortest path for a disc of radius R, as JSON; on\n"
    "                                         ground, Z picks the level where several lie over\n"
    "                                         a point, and each point has its height\n"
    "       footfall path SCENARIO --from X,Y[,Z] --to X,Y[,Z] --behaviors\n"
    "                                         the full-body planner's path, in sections of walk,\n"
    "                                         arms_in and side_step, as JSON\n"
    "       footfall bench [--repeat N]       time the planner on the standard workloads\n"
    "       footfall bench --crowds [--threads N] [--repeat N]\n"
    "                                         plan the crowd workloads of the paper's table 1\n"
    "                                         (the fastest of N runs each; default 1)\n"
    "       footfall bench --box-seeds FIRST-LAST [--threads N] [-o PLAN]\n"
    "                                         plan the 500 among 700 boxes for each seed and\n"
    "                                         list the agents that do not reach their goals\n"
    "       footfall bench --city AGENTS,SIZE [--seeds FIRST-LAST] [--threads N] [-o PLAN]\n"
    "                                         plan AGENTS crossing a city of SIZE m (6 m blocks,\n"
    "                                         4 m streets) for each seed (default 1-1): reached,\n"
    "                                         overlaps, travel time over alone, who is short\n"
    "                                         (-o: the last seed's plan, here and --box-seeds)\n"
    "       footfall bench --behaviors [--repeat N]\n"
    "                                         time the full-body planner in the random\n"
    "                                         environments (the fastest of N runs; default 5)\n"
    "       footfall --version | --help\n";
// clang-format on

struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Width of a left-aligned text column: at least `minimum`, and two more than
/// its longest entry, so that long agent names never run into the next column.
template <typename Range, typename Text>
int column_width(const Range& rows, int minimum, Text text) {
  std::size_t widest = 0;
  for (const auto& row : rows) widest = std::max(widest, std::string(text(row)).size());
  return std::max(minimum, static_cast<int>(widest) + 2);
}

std::string status_of(const footfall::AgentPlan& agent) {
  const std::string status = footfall::to_string(agent.status);
  return agent.reason.empty() ? status : status + " (" + agent.reason + ")";
}

void print_table(const footfall::Plan& plan, std::ostream& out) {
  const int name_width =
      column_width(plan.agents, 14, [](const footfall::AgentPlan& a) { return a.name; });
  const int status_width = column_width(plan.agents, 10, status_of);
  out << std::left << std::setw(name_width) << "agent" << std::setw(status_width) << "status"
      << std::right << std::setw(7) << "steps" << std::setw(10) << "time [s]" << std::setw(11)
      << "cost [J]" << std::setw(10) << "searches" << std::setw(10) << "expanded"
      << "\n";
  for (const footfall::AgentPlan& agent : plan.agents) {
    out << std::left << std::setw(name_width) << agent.name << std::setw(status_width)
        << status_of(agent) << std::right << std::setw(7) << agent.footsteps.size() << std::setw(10)
        << std::fixed << std::setprecision(2) << agent.end_time() << std::setw(11)
        << std::setprecision(1) << agent.total_cost() << std::setw(10) << agent.searches
        << std::setw(10) << agent.nodes_expanded << "\n";
  }
}

void print_metrics(const footfall::PlanMetrics& metrics, const footfall::BodyCheck& body,
                   const footfall::GroundCheck& ground, std::ostream& out) {
  const int name_width =
      column_width(metrics.agents, 14, [](const footfall::AgentMetrics& m) { return m.name; });
  out << std::left << std::setw(name_width) << "agent" << std::setw(9) << "reached" << std::right
      << std::setw(9) << "time [s]" << std::setw(10) << "path [m]" << std::setw(11) << "effort [J]"
      << std::setw(10) << "overlaps" << std::setw(11) << "episodes" << std::setw(10) << "energy"
      << std::setw(13) << "acceleration" << std::setw(12) << "limb hits"
      << "\n";
  for (std::size_t i = 0; i < metrics.agents.size(); ++i) {
    const footfall::AgentMetrics& m = metrics.agents[i];
    out << std::left << std::setw(name_width) << m.name << std::setw(9)
        << (m.reached ? "yes" : "no") << std::right << std::fixed << std::setprecision(2)
        << std::setw(9) << m.time << std::setw(10) << m.path_length << std::setprecision(1)
        << std::setw(11) << m.effort << std::setw(10) << m.overlaps << std::setw(11)
        << m.collision_episodes << std::setw(10) << m.energy << std::setw(13) << m.acceleration
        << std::setw(12) << body.agents[i].penetrations << "\n";
  }
  out << std::setprecision(2) << "five-circle overlaps: " << metrics.overlaps << "\n"
      << "full body (30 poses/s): " << body.penetrations << " poses with a limb in an obstacle of "
      << body.poses << ", deepest " << std::setprecision(3) << body.deepest << " m\n"
      << std::setprecision(2)
      << "SteerBench (" << metrics.rate << " Hz): composite01 " << metrics.composite01
      << ", composite02 " << metrics.composite02 << "\n";
  if (ground.footholds > 0)
    out << "ground: " << ground.footholds << " footholds; off the ground " << ground.off_ground
        << ", soles unsupported " << ground.unsupported << ", rises over the limit "
        << ground.over_rise << ", swing feet through the ground " << ground.swing << "\n";
}

// The options after the verb: "-o PATH", "--threads N", plan's "--fixed
// PLAN" and "--agents NAME,NAME", and the crowd's "--glb PATH", "--rig RIG",
// "--profile PROFILE", "--fps N".
struct Options {
  std::string output;
  int threads = 1;
  std::string fixed;
  std::vector<std::string> agents;
  std::string glb;
  footfall::tools::AnimateArguments animate;
  bool animate_given = false;  ///< any of --rig, --profile, --fps
};

// Names the agents planned again (`names`) whose plans overlap others or
// obstacles: the fixed agents make way for no one, and in a dense crowd one
// planned again may have to stand where they walk.
void warn_of_overlaps(const footfall::Plan& plan, const std::vector<std::string>& names,
                      std::ostream& out) {
  const footfall::PlanMetrics metrics = footfall::measure_plan(plan);
  for (const footfall::AgentMetrics& agent : metrics.agents) {
    if (agent.overlaps == 0 || std::find(names.begin(), names.end(), agent.name) == names.end())
      continue;
    out << "footfall: warning: agent " << user_text(agent.name) << " planned again overlaps "
        << "others or obstacles at " << agent.overlaps << " samples (" << metrics.rate
        << " Hz): the fixed agents make way for no one; plan every agent\n";
  }
}

// Names the agents that stand short of their goals, where and why: a way
// too narrow for their bodies, walled in by others until their time limits...
void warn_of_short(const footfall::Plan& plan, std::ostream& out) {
  for (const footfall::AgentPlan& agent : plan.agents)
    if (agent.status != footfall::AgentStatus::kReached)
      out << "footfall: " << user_text(agent.name) << " " << short_of_goal_text(agent) << "\n";
}

// The named agents planned again among the others' plans in `fixed` (read
// from --fixed); the core's "fixed" and "agents" fields are named as the
// file and the flag.
footfall::Plan replan(const footfall::Scenario& scenario, const footfall::Plan& fixed,
                      const Options& options, const footfall::RunControl& control) {
  try {
    return footfall::replan_agents(scenario, fixed, options.agents, control);
  } catch (const std::invalid_argument& error) {
    const std::string what = error.what();
    for (const auto& [field, shown] : {std::pair<std::string, std::string>{"fixed: ", options.fixed + ": "},
                                       {"agents: ", "--agents: "}})
      if (what.rfind(field, 0) == 0) throw std::invalid_argument(shown + what.substr(field.size()));
    throw;
  }
}

// Plans (showing progress when standard error is a terminal), writes the plan
// atomically (creating the folder), prints the table; with --glb, writes the
// animated crowd too.
int plan_and_write(const footfall::Scenario& scenario, const Options& options) {
  const std::string& output = options.output;
  const int threads = options.threads;
  footfall::RunControl control;
  control.threads = threads;
  const bool terminal = isatty(STDERR_FILENO) == 1;
  if (terminal) {
    control.progress = [](double fraction) {
      std::cerr << "\rplanning " << std::setw(3) << static_cast<int>(100 * fraction) << "%"
                << std::flush;
    };
  }
  double search_seconds = 0.0;
  control.search_seconds = &search_seconds;
  const footfall::Plan fixed =
      options.fixed.empty() ? footfall::Plan{} : footfall::load_plan(options.fixed);
  const auto begin = std::chrono::steady_clock::now();
  const footfall::Plan plan = options.fixed.empty() ? footfall::plan_scenario(scenario, control)
                                                    : replan(scenario, fixed, options, control);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  if (terminal) std::cerr << "\r             \r" << std::flush;
  const std::filesystem::path folder = std::filesystem::path(output).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder);
  footfall::write_plan_file(plan, output);
  print_table(plan, std::cout);
  long searches = 0;
  for (const footfall::AgentPlan& agent : plan.agents) searches += agent.searches;
  std::cout << std::setprecision(3) << "planned in " << wall << " s on " << threads
            << " thread(s): " << searches << " searches, "
            << 1000.0 * search_seconds / static_cast<double>(std::max(1L, searches))
            << " ms each\n";
  std::cout << "plan written to " << output << "\n";
  if (!options.fixed.empty()) warn_of_overlaps(plan, options.agents, std::cerr);
  warn_of_short(plan, std::cerr);
  if (!options.glb.empty()) footfall::tools::animate_and_write(plan, options.animate, options.glb, std::cout);
  return 0;
}

// plan's and demo's --glb needs --rig; --rig, --profile and --fps need --glb.
void check_crowd_options(const Options& options, const std::string& verb) {
  if (!options.glb.empty() && options.animate.rig.empty())
    throw UsageError(verb + ": --glb needs --rig RIG");
  if (options.glb.empty() && options.animate_given)
    throw UsageError(verb + ": --rig, --profile and --fps go with --glb CROWD");
}

// A whole number from lo to hi, or a usage error naming the flag.
int parse_whole(const std::string& flag, const std::string& text, int lo, int hi) {
  const bool digits = !text.empty() && text.size() <= 9 &&
                      text.find_first_not_of("0123456789") == std::string::npos;
  const int n = digits ? std::atoi(text.c_str()) : -1;
  if (n < lo || n > hi)
    throw UsageError(flag + ": expected a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi) + ", got " + user_text(text));
  return n;
}

// A finite number, or a usage error naming the flag. (strtod, not stod: a
// number too small for a normal double is still a number.)
double parse_number(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const bool whole = !text.empty() && !std::isspace(static_cast<unsigned char>(text[0])) &&
                     end == text.c_str() + text.size();
  if (!whole || !std::isfinite(value))
    throw UsageError(flag + ": expected a finite number, got " + user_text(text));
  return value;
}

// Names separated by commas, none empty, or a usage error naming the flag.
std::vector<std::string> parse_names(const std::string& flag, const std::string& text) {
  std::vector<std::string> names;
  std::size_t from = 0;
  for (std::size_t comma = text.find(','); ; comma = text.find(',', from)) {
    names.push_back(text.substr(from, comma == std::string::npos ? comma : comma - from));
    if (names.back().empty()) throw UsageError(flag + ": an empty name in " + user_text(text));
    if (comma == std::string::npos) return names;
    from = comma + 1;
  }
}

// Reads the options after the verb; returns the positional arguments.
std::vector<std::string> parse_arguments(int argc, char** argv, Options& options) {
  std::vector<std::string> positional;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o" || arg == "--output") {
      if (i + 1 >= argc) throw UsageError(arg + " needs a file name");
      options.output = argv[++i];
    } else if (arg == "--threads") {
      if (i + 1 >= argc) throw UsageError("--threads needs a number");
      options.threads = parse_whole(arg, argv[++i], 1, 64);
    } else if (arg == "--fixed") {
      if (i + 1 >= argc) throw UsageError("--fixed needs a plan file");
      options.fixed = argv[++i];
    } else if (arg == "--agents") {
      if (i + 1 >= argc) throw UsageError("--agents needs agent names, separated by commas");
      options.agents = parse_names(arg, argv[++i]);
    } else if (arg == "--glb" || arg == "--rig" || arg == "--profile") {
      if (i + 1 >= argc) throw UsageError(arg + " needs a file name");
      std::string& value = arg == "--glb" ? options.glb : arg == "--rig" ? options.animate.rig : options.animate.profile;
      value = argv[++i];
      options.animate_given = options.animate_given || arg != "--glb";
    } else if (arg == "--fps") {
      if (i + 1 >= argc) throw UsageError("--fps needs a number");
      options.animate.fps = parse_number(arg, argv[++i]);
      if (options.animate.fps < 1 || options.animate.fps > 240)
        throw UsageError("--fps: expected a number from 1 to 240, got " + user_text(argv[i]));
      options.animate_given = true;
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option " + user_text(arg));
    } else {
      positional.push_back(arg);
    }
  }
  return positional;
}

/// A point X,Y or X,Y,Z: its plan position, and its height if given.
struct ParsedPoint {
  footfall::Vec2 at;
  std::optional<double> z;
};

ParsedPoint parse_point(const std::string& flag, const std::string& text) {
  std::vector<std::string> parts{""};
  for (const char c : text) {
    if (c == ',')
      parts.emplace_back();
    else
      parts.back() += c;
  }
  if (parts.size() < 2 || parts.size() > 3)
    throw UsageError(flag + ": expected X,Y or X,Y,Z, got " + user_text(text));
  ParsedPoint point{{parse_number(flag, parts[0]), parse_number(flag, parts[1])}, std::nullopt};
  if (parts.size() == 3) point.z = parse_number(flag, parts[2]);
  if (!footfall::in_world(point.at) || (point.z && std::fabs(*point.z) > 1e9))
    throw UsageError(flag + ": must be within 1e9 m of the origin, got " + user_text(text));
  return point;
}

// footfall path SCENARIO --from X,Y[,Z] --to X,Y[,Z] (--radius R | --behaviors)
int print_path(int argc, char** argv) {
  std::string scenario;
  footfall::PathQuery query;
  std::optional<double> from_z, to_z;
  bool from = false, to = false, radius = false, behaviors = false;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--from" && has_value) {
      const ParsedPoint point = parse_point(arg, argv[++i]);
      query.from = point.at;
      from_z = point.z;
      from = true;
    } else if (arg == "--to" && has_value) {
      const ParsedPoint point = parse_point(arg, argv[++i]);
      query.to = point.at;
      to_z = point.z;
      to = true;
    } else if (arg == "--radius" && has_value) {
      query.radius = parse_number(arg, argv[++i]);
      if (query.radius < 0) throw UsageError("--radius: must be >= 0, got " + user_text(argv[i]));
      radius = true;
    } else if (arg == "--behaviors") {
      behaviors = true;
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("path: unknown option or missing value: " + user_text(arg));
    } else if (scenario.empty()) {
      scenario = arg;
    } else {
      throw UsageError("path takes one scenario file");
    }
  }
  if (scenario.empty() || !from || !to || radius == behaviors)
    throw UsageError("path needs SCENARIO, --from X,Y, --to X,Y and one of --radius R, --behaviors");
  const footfall::Scenario loaded = footfall::load_scenario_file(scenario);
  const footfall::LayeredNavigation navigation(loaded);
  const int from_layer = navigation.layer_at(query.from, from_z, "--from");
  const int to_layer = navigation.layer_at(query.to, to_z, "--to");
  if (!behaviors) {
    std::cout << footfall::to_json(navigation.find_path(query, from_layer, to_layer)) << "\n";
    return 0;
  }
  if (navigation.layers() > 1)
    throw std::invalid_argument(
        "--behaviors: the full-body planner does not yet find ways on ground with levels above "
        "one another");
  footfall::NavMesh mesh = footfall::navmesh_of(loaded);
  const footfall::CollisionScene scene(loaded.obstacles);
  const footfall::BodyModel body(loaded.character);
  footfall::BehavioralPlanner planner(mesh, scene, body, loaded.planner);
  std::cout << footfall::to_json(planner.plan(query.from, query.to)) << "\n";
  return 0;
}

int run(int argc, char** argv) {
  if (argc < 2) throw UsageError("missing command");
  const std::string verb = argv[1];
  if (verb == "--help" || verb == "-h") {
    std::cout << kUsage;
    return 0;
  }
  if (verb == "--version") {
    std::cout << "footfall " << FOOTFALL_VERSION << "\n";
    return 0;
  }
  if (verb == "plan") {
    Options options;
    const auto positional = parse_arguments(argc, argv, options);
    if (positional.size() != 1) throw UsageError("plan takes one scenario file");
    if (options.output.empty()) throw UsageError("plan needs -o PLAN");
    check_crowd_options(options, "plan");
    if (options.fixed.empty() != options.agents.empty())
      throw UsageError("plan: --fixed PLAN and --agents NAME,NAME go together");
    return plan_and_write(footfall::load_scenario_file(positional[0]), options);
  }
  if (verb == "demo") {
    Options options;
    options.output = "out/demo-plan.json";
    if (!parse_arguments(argc, argv, options).empty()) throw UsageError("demo takes no file");
    if (!options.fixed.empty() || !options.agents.empty())
      throw UsageError("demo: --fixed and --agents are plan's");
    check_crowd_options(options, "demo");
    return plan_and_write(footfall::demo_scenario(), options);
  }
  if (verb == "metrics") {
    Options options;
    const auto positional = parse_arguments(argc, argv, options);
    if (positional.size() != 1 || !options.output.empty() || !options.glb.empty() ||
        options.animate_given || !options.fixed.empty() || !options.agents.empty())
      throw UsageError("metrics takes one plan file");
    const footfall::Plan plan = footfall::load_plan(positional[0]);
    print_metrics(footfall::measure_plan(plan), footfall::check_body(plan),
                  footfall::check_ground(plan), std::cout);
    return 0;
  }
  if (verb == "animate") {
    Options options;
    const auto positional = parse_arguments(argc, argv, options);
    if (positional.size() != 1) throw UsageError("animate takes one plan file");
    if (options.output.empty() || options.animate.rig.empty())
      throw UsageError("animate needs --rig RIG and -o CROWD");
    if (!options.glb.empty()) throw UsageError("animate writes -o CROWD; --glb is plan's");
    if (!options.fixed.empty() || !options.agents.empty())
      throw UsageError("animate: --fixed and --agents are plan's");
    footfall::tools::animate_and_write(footfall::load_plan(positional[0]), options.animate,
                                       options.output, std::cout);
    return 0;
  }
  if (verb == "path") return print_path(argc, argv);
  if (verb == "bench") {
    int repeat = 0, threads = 1;  // repeat 0: each kind's default
    bool crowds = false, behaviors = false;
    std::optional<std::pair<int, int>> box_seeds, seeds;
    std::optional<std::pair<int, double>> city;
    std::string plan_path;  // the last seed's plan, for --box-seeds and --city
    const auto seed_range = [](const std::string& flag, const std::string& range) {
      const std::size_t dash = range.find('-');
      if (dash == std::string::npos)
        throw UsageError(flag + ": give FIRST-LAST, as 1-200, not " + user_text(range));
      const std::pair<int, int> out{parse_whole(flag, range.substr(0, dash), 0, 1000000000),
                                    parse_whole(flag, range.substr(dash + 1), 0, 1000000000)};
      if (out.first > out.second)
        throw UsageError(flag + ": the first seed is after the last: " + user_text(range));
      return out;
    };
    for (int i = 2; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--repeat" && i + 1 < argc) {
        repeat = parse_whole(arg, argv[++i], 1, 1000000);
      } else if (arg == "--threads" && i + 1 < argc) {
        threads = parse_whole(arg, argv[++i], 1, 64);
      } else if (arg == "--crowds") {
        crowds = true;
      } else if (arg == "--behaviors") {
        behaviors = true;
      } else if (arg == "--box-seeds" && i + 1 < argc) {
        box_seeds = seed_range(arg, argv[++i]);
      } else if (arg == "-o" && i + 1 < argc) {
        plan_path = argv[++i];
      } else if (arg == "--seeds" && i + 1 < argc) {
        seeds = seed_range(arg, argv[++i]);
      } else if (arg == "--city" && i + 1 < argc) {
        const std::string value = argv[++i];
        const std::size_t comma = value.find(',');
        if (comma == std::string::npos)
          throw UsageError("--city: give AGENTS,SIZE, as 1000,60, not " + user_text(value));
        city = std::pair{parse_whole(arg, value.substr(0, comma), 1, 100000),
                         parse_number(arg, value.substr(comma + 1))};
      } else {
        throw UsageError("unknown option or missing value: " + user_text(arg));
      }
    }
    const int kinds = static_cast<int>(crowds) + static_cast<int>(behaviors) +
                      static_cast<int>(box_seeds.has_value()) + static_cast<int>(city.has_value());
    if (kinds > 1)
      throw UsageError("bench: one of --crowds, --behaviors, --box-seeds and --city");
    if (seeds && !city) throw UsageError("bench: --seeds goes with --city");
    if (!plan_path.empty() && !city && !box_seeds)
      throw UsageError("bench: -o goes with --city or --box-seeds");
    if (box_seeds) {
      footfall::tools::run_crowd_seeds(
          [](std::uint64_t seed) { return footfall::box_field_crowd_scenario(500, 700, seed); },
          box_seeds->first, box_seeds->second, threads, plan_path, std::cout);
    } else if (city) {
      const auto [agents, size] = *city;
      try {  // a size out of range is a usage error, before any plan
        footfall::city_blocks(size);
      } catch (const std::invalid_argument& error) {
        throw UsageError(std::string("--city: ") + error.what());
      }
      const auto range = seeds.value_or(std::pair{1, 1});
      footfall::tools::run_crowd_seeds(
          [&](std::uint64_t seed) { return footfall::city_scenario(agents, size, seed); },
          range.first, range.second, threads, plan_path, std::cout);
    } else if (behaviors) {
      footfall::tools::run_behavior_bench(repeat > 0 ? repeat : 5, std::cout);
    } else if (crowds) {
      footfall::tools::run_crowd_bench(threads, repeat > 0 ? repeat : 1, std::cout);
    } else {
      footfall::tools::run_bench(repeat > 0 ? repeat : 20, std::cout);
    }
    return 0;
  }
  throw UsageError("unknown command " + user_text(verb));
}

}  // namespace

// Stopped while writing a plan: no half-written file is left behind.
extern "C" void remove_pending_and_stop(int signal_number) {
  footfall::detail::remove_pending_files();
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

int main(int argc, char** argv) {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP})
    std::signal(signal_number, remove_pending_and_stop);
  try {
    return run(argc, argv);
  } catch (const UsageError& error) {
    std::cerr << "footfall: " << error.what() << " (footfall --help shows the usage)\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& error) {
    std::cerr << "footfall: " << error.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& error) {
    std::cerr << "footfall: " << error.what() << "\n";
    return 1;
  }
}
