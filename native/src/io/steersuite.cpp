#include "footfall/io/steersuite.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <pugixml.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "footfall/model/footstep.hpp"
#include "footfall/planner/planner.hpp"
#include "io/json_reader.hpp"
#include "util/seeded_random.hpp"
#include "util/quoted.hpp"

namespace footfall {
namespace {

constexpr int kCircleSides = 16;
constexpr int kPlacementTries = 10000;

using detail::fail;
using detail::user_text;

// A SteerSuite ground point (x, z) in Footfall's frame.
Vec2 ground(double x, double z) { return {x, -z}; }

struct Bounds {
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0, zmin = 0, zmax = 0;
};

class Reader {
 public:
  Reader(std::uint64_t seed) : random_(seed) {}

  Scenario read(const pugi::xml_node& root) {
    world_ = root.child("header").child("worldBounds")
                 ? bounds(root.child("header").child("worldBounds"), "header.worldBounds")
                 : Bounds{-100, 100, 0, 0, -100, 100};
    // Obstacles first, so that random agents and targets can keep clear of them.
    int index = 0;
    for (const pugi::xml_node& node : root.children()) {
      const std::string name = node.name();
      const std::string where = name + "[" + std::to_string(index++) + "]";
      if (name == "obstacle") {
        const Bounds b = bounds(node, where);
        add_box({ground(b.xmin, b.zmax), ground(b.xmax, b.zmax), ground(b.xmax, b.zmin),
                 ground(b.xmin, b.zmin)},
                b.ymax - b.ymin);
      } else if (name == "obstacleRegion") {
        obstacle_region(node, where);
      } else if (name == "circleObstacle") {
        circle(node, where);
      } else if (name == "orientedBoxObstacle") {
        oriented_box(node, where);
      } else if (name != "agent" && name != "agentRegion" && name != "header" &&
                 name != "suggestedCameraView") {
        fail(where, "not an element of a SteerSuite test case");
      }
    }
    map_ = ObstacleMap(scenario_.obstacles);
    planner_.emplace(scenario_.character, scenario_.planner, map_);
    index = 0;
    for (const pugi::xml_node& node : root.children()) {
      const std::string name = node.name();
      const std::string where = name + "[" + std::to_string(index++) + "]";
      if (name == "agent") {
        agent(node, where, nullptr, scenario_.agents.size());
      } else if (name == "agentRegion") {
        const Bounds region = bounds(node.child("regionBounds"), where + ".regionBounds");
        const long count = integer(node.child("numAgents"), where + ".numAgents");
        for (long i = 0; i < count; ++i) agent(node, where, &region, static_cast<size_t>(i));
      }
    }
    return std::move(scenario_);
  }

 private:
  double number(const pugi::xml_node& node, const std::string& where) {
    if (!node) fail(where, "missing");
    const std::string text = node.text().get();
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    while (end != nullptr && *end != '\0' && std::isspace(static_cast<unsigned char>(*end))) ++end;
    if (text.empty() || end == nullptr || *end != '\0')
      fail(where, "expected a number, got " + user_text(text));
    if (!std::isfinite(value)) fail(where, "must be a finite number");
    return value;
  }

  long integer(const pugi::xml_node& node, const std::string& where) {
    const double value = number(node, where);
    if (value < 0 || value > 100000 || value != std::floor(value)) {
      fail(where, "expected a whole number from 0 to 100000");
    }
    return static_cast<long>(value);
  }

  static bool is_random(const pugi::xml_node& node) {
    return std::string(node.child("random").text().get()) == "true";
  }

  Bounds bounds(const pugi::xml_node& node, const std::string& where) {
    if (!node) fail(where, "missing");
    // The box between the two values of each pair: some test cases swap them.
    const auto range = [&](const char* axis, double& lo, double& hi) {
      const std::string name(axis);
      lo = number(node.child((name + "min").c_str()), where + "." + name + "min");
      hi = number(node.child((name + "max").c_str()), where + "." + name + "max");
      if (lo > hi) std::swap(lo, hi);
    };
    Bounds b;
    range("x", b.xmin, b.xmax);
    range("y", b.ymin, b.ymax);
    range("z", b.zmin, b.zmax);
    return b;
  }

  // The ground point of an <x> <y> <z> tuple.
  Vec2 point(const pugi::xml_node& node, const std::string& where) {
    if (!node) fail(where, "missing");
    return ground(number(node.child("x"), where + ".x"), number(node.child("z"), where + ".z"));
  }

  Vec2 random_in(const Bounds& b) {
    return ground(random_.uniform(b.xmin, b.xmax), random_.uniform(b.zmin, b.zmax));
  }

  void add_box(std::vector<Vec2> polygon, double height) {
    scenario_.obstacles.push_back(prism(std::move(polygon), height > 0.0 ? height : 1.0));
  }

  void obstacle_region(const pugi::xml_node& node, const std::string& where) {
    const long count = integer(node.child("numObstacles"), where + ".numObstacles");
    const double size = number(node.child("obstacleSize"), where + ".obstacleSize");
    const double height = number(node.child("obstacleHeight"), where + ".obstacleHeight");
    const Bounds region = bounds(node.child("regionBounds"), where + ".regionBounds");
    if (!(size > 0.0)) fail(where + ".obstacleSize", "must be positive");
    for (long i = 0; i < count; ++i) {
      const Vec2 corner = random_in(region);
      add_box({corner, corner + Vec2{size, 0}, corner + Vec2{size, size}, corner + Vec2{0, size}},
              height);
    }
  }

  void circle(const pugi::xml_node& node, const std::string& where) {
    const double radius = number(node.child("radius"), where + ".radius");
    if (!(radius > 0.0)) fail(where + ".radius", "must be positive");
    const Vec2 center = point(node.child("position"), where + ".position");
    // Circumscribed: the polygon holds the whole circle.
    const double reach = radius / std::cos(kPi / kCircleSides);
    std::vector<Vec2> polygon;
    for (int k = 0; k < kCircleSides; ++k)
      polygon.push_back(center + reach * unit(2.0 * kPi * k / kCircleSides));
    add_box(std::move(polygon), number(node.child("height"), where + ".height"));
  }

  void oriented_box(const pugi::xml_node& node, const std::string& where) {
    const double theta = number(node.child("thetaY"), where + ".thetaY") * kPi / 180.0;
    const pugi::xml_node size = node.child("size");
    const double sx = number(size.child("x"), where + ".size.x"),
                 sz = number(size.child("z"), where + ".size.z");
    const Vec2 center = point(node.child("position"), where + ".position");
    std::vector<Vec2> polygon;
    for (const Vec2 corner : {Vec2{-0.5, -0.5}, Vec2{0.5, -0.5}, Vec2{0.5, 0.5}, Vec2{-0.5, 0.5}}) {
      polygon.push_back(center + rotate(Vec2{corner.x * sx, corner.y * sz}, theta));
    }
    add_box(std::move(polygon), number(size.child("y"), where + ".size.y"));
  }

  // True if an agent facing `facing` can stand at `position`, clear of
  // obstacles and free to set off from there (wedged against a tree, one
  // could never step), and clear of the agents placed so far (their radii
  // apart).
  bool free(Vec2 position, double facing, double radius) const {
    const FootstepState standing = standing_state(position, facing, scenario_.character);
    if (planner_->validity().collides(standing) || !planner_->validity().free_to_set_off(standing))
      return false;
    for (size_t i = 0; i < scenario_.agents.size(); ++i) {
      if (distance(position, scenario_.agents[i].position) < radius + radii_[i]) return false;
    }
    return true;
  }

  void agent(const pugi::xml_node& node, const std::string& where, const Bounds* region,
             size_t number_in) {
    const pugi::xml_node initial = node.child("initialConditions");
    AgentSpec agent;
    agent.name = region ? where + "-" + std::to_string(number_in)
                        : std::string(node.child("name").text().get());
    if (agent.name.empty()) agent.name = "agent" + std::to_string(scenario_.agents.size());
    const std::string who = "agent " + user_text(agent.name) + " (" + where + ")";
    const double radius =
        initial.child("radius") ? number(initial.child("radius"), who + ": radius") : 0.5;
    // The facing first: where an agent fits depends on how its shoulders turn.
    const pugi::xml_node direction = initial.child("direction");
    if (!direction || is_random(direction)) {
      agent.facing = random_.uniform(-kPi, kPi);
    } else {
      const Vec2 d = point(direction, who + ": initialConditions.direction");
      agent.facing = length(d) > 0.0 ? angle_of(d) : 0.0;
    }
    const pugi::xml_node position = initial.child("position");
    if (region != nullptr || is_random(position)) {
      const Bounds& area = region ? *region : world_;
      int tries = 0;
      do {
        agent.position = random_in(area);
      } while (!free(agent.position, agent.facing, radius) && ++tries < kPlacementTries);
      if (tries == kPlacementTries) fail(who, "no free place to stand in its region");
    } else {
      agent.position = point(position, who + ": initialConditions.position");
    }
    // Each goal's timeDuration adds to the agent's time budget; cases give
    // absurd ones (3e33 s), which the longest limit caps.
    double budget = 0.0;
    bool timed = false;
    for (const pugi::xml_node& goal : node.child("goalSequence").children()) {
      const std::string type = goal.name();
      if (type != "seekStaticTarget")
        fail(who, "goal type " + user_text(type) + " is not supported (only seekStaticTarget)");
      if (const pugi::xml_node duration = goal.child("timeDuration")) {
        const double seconds = number(duration, who + ": goalSequence." + type + ".timeDuration");
        if (seconds <= 0.0) fail(who + ": goalSequence." + type + ".timeDuration", "must be positive");
        budget += seconds;
        timed = true;
      }
      const pugi::xml_node target = goal.child("targetLocation");
      if (is_random(goal) || is_random(target)) {
        Vec2 point_in;
        int tries = 0;
        do {
          point_in = random_in(world_);
        } while (map_.overlaps({point_in, 0.5}) && ++tries < kPlacementTries);
        agent.goals.push_back(point_in);
      } else {
        agent.goals.push_back(point(target, who + ": goalSequence." + type + ".targetLocation"));
      }
    }
    if (agent.goals.empty()) fail(who, "has no goals");
    if (timed) agent.time_limit = std::min(budget, kMaxTimeLimit);
    agent.leave_at_goal = true;  // SteerSuite removes an agent that reaches its last goal
    scenario_.agents.push_back(std::move(agent));
    radii_.push_back(radius);
  }

  SeededRandom random_;
  Scenario scenario_;
  Bounds world_;
  ObstacleMap map_;
  std::optional<FootstepPlanner> planner_;
  std::vector<double> radii_;
};

}  // namespace

Scenario parse_steersuite(const std::string& text, const std::string& source, std::uint64_t seed) {
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_string(text.c_str());
  if (!parsed) {
    size_t line = 1, column = 1;
    for (std::ptrdiff_t i = 0; i < parsed.offset && i < static_cast<std::ptrdiff_t>(text.size());
         ++i) {
      column = text[static_cast<size_t>(i)] == '\n' ? (++line, 1) : column + 1;
    }
    throw std::invalid_argument(source + ": not valid XML: " + parsed.description() + " at line " +
                                std::to_string(line) + ", column " + std::to_string(column));
  }
  const pugi::xml_node root = document.child("SteerBenchTestCase");
  if (!root)
    throw std::invalid_argument(source +
                                ": not a SteerSuite test case (no SteerBenchTestCase element)");
  try {
    Scenario scenario = Reader(seed).read(root);
    validate(scenario);
    return scenario;
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
}

Scenario load_steersuite(const std::string& path, std::uint64_t seed) {
  return parse_steersuite(detail::read_file(path), path, seed);
}

}  // namespace footfall
