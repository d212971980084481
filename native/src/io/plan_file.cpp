#include "footfall/io/plan_file.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include "footfall/ground/ground.hpp"
#include "io/atomic_file.hpp"
#include "io/json_reader.hpp"
#include "io/json_writer.hpp"
#include "io/param_json.hpp"
#include "util/quoted.hpp"

namespace footfall {

using namespace detail;

namespace {

// Version 2 writes a footstep's enumerations as one letter each, indexed
// by the enumerator: Foot "lr", StepKind "wsxt", Behavior "was".
constexpr std::string_view kFootLetters = "lr", kKindLetters = "wsxt", kBehaviorLetters = "was";
static_assert(static_cast<int>(Foot::kRight) == 1 && static_cast<int>(StepKind::kStart) == 3 &&
              static_cast<int>(Behavior::kSideStep) == 2);

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Where a step starts unless version 2's "starts" says otherwise: where the
// step before ended; the first at time 0, standing at the agent's start.
struct StepStart {
  double time = 0.0;
  Vec2 com, velocity;
};
StepStart start_after(const std::vector<Footstep>& steps, std::size_t i, Vec2 start_com) {
  if (i == 0) return {0.0, start_com, {}};
  const Footstep& previous = steps[i - 1];
  return {previous.end_time, previous.com_end, previous.com_velocity_end};
}

// The numbers of the footstep fields written as indexes (angles, speeds,
// costs: they repeat from step to step), each distinct one listed once, in
// the order first met. Told apart by their bits: -0.0 is not 0.0.
class ValueTable {
 public:
  void add(double value) {
    if (index_.emplace(bits(value), values_.size()).second) values_.push_back(value);
  }
  std::size_t index(double value) const { return index_.at(bits(value)); }
  const std::vector<double>& values() const { return values_; }

 private:
  static std::uint64_t bits(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
  }
  std::vector<double> values_;
  std::unordered_map<std::uint64_t, std::size_t> index_;
};

void write_point(JsonWriter& out, Vec2 p) { out.begin_array().number(p.x).number(p.y).end_array(); }

// One agent's footsteps as version 2's columns (docs/file-formats.md).
void write_footsteps(JsonWriter& out, const AgentPlan& agent, bool ground) {
  const std::vector<Footstep>& steps = agent.footsteps;
  ValueTable table;
  for (const Footstep& s : steps) {
    for (const double value : {s.phi, s.foot_orientation, s.orientation_interval.inner,
                               s.orientation_interval.outer, s.speed, s.alpha, s.cost.fixed_rate,
                               s.cost.speed_change, s.cost.curvature})
      table.add(value);
    if (ground) table.add(s.cost.terrain);
  }
  const auto column = [&](const char* name, auto write_item) {
    out.key(name).begin_array();
    for (const Footstep& step : steps) write_item(step);
    out.end_array();
  };
  const auto letters = [&](const char* name, auto letter) {
    std::string text;
    for (const Footstep& step : steps) text += letter(step);
    out.key(name).string(text);
  };
  const auto index = [&](double value) { out.integer(static_cast<long long>(table.index(value))); };
  out.begin_object().key("count").integer(static_cast<long long>(steps.size()));
  letters("foot", [](const Footstep& s) { return kFootLetters[static_cast<int>(s.foot)]; });
  letters("kind", [](const Footstep& s) { return kKindLetters[static_cast<int>(s.kind)]; });
  letters("behavior",
          [](const Footstep& s) { return kBehaviorLetters[static_cast<int>(s.behavior)]; });
  column("end_time", [&](const Footstep& s) { out.number(s.end_time); });
  column("foot_position", [&](const Footstep& s) { write_point(out, s.foot_position); });
  column("com_end", [&](const Footstep& s) { write_point(out, s.com_end); });
  column("com_velocity_end", [&](const Footstep& s) { write_point(out, s.com_velocity_end); });
  if (ground) column("foot_height", [&](const Footstep& s) { out.number(s.foot_height); });
  out.key("values").begin_array();
  for (const double value : table.values()) out.number(value);
  out.end_array();
  column("phi", [&](const Footstep& s) { index(s.phi); });
  column("foot_orientation", [&](const Footstep& s) { index(s.foot_orientation); });
  column("orientation_interval", [&](const Footstep& s) {
    out.begin_array();
    index(s.orientation_interval.inner);
    index(s.orientation_interval.outer);
    out.end_array();
  });
  column("speed", [&](const Footstep& s) { index(s.speed); });
  column("alpha", [&](const Footstep& s) { index(s.alpha); });
  column("fixed_rate", [&](const Footstep& s) { index(s.cost.fixed_rate); });
  column("speed_change", [&](const Footstep& s) { index(s.cost.speed_change); });
  column("curvature", [&](const Footstep& s) { index(s.cost.curvature); });
  if (ground) column("terrain", [&](const Footstep& s) { index(s.cost.terrain); });
  // Only the steps that do not start where start_after says, to the bit.
  bool any = false;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const Footstep& step = steps[i];
    const StepStart expected = start_after(steps, i, agent.start.com);
    if (same_bits(step.start_time, expected.time) && same_bits(step.com_start.x, expected.com.x) &&
        same_bits(step.com_start.y, expected.com.y) &&
        same_bits(step.com_velocity_start.x, expected.velocity.x) &&
        same_bits(step.com_velocity_start.y, expected.velocity.y))
      continue;
    if (!any) out.key("starts").begin_array();
    any = true;
    out.begin_object().key("step").integer(static_cast<long long>(i));
    out.key("start_time").number(step.start_time).key("com_start");
    write_point(out, step.com_start);
    out.key("com_velocity_start");
    write_point(out, step.com_velocity_start);
    out.end_object();
  }
  if (any) out.end_array();
  out.end_object();
}

void write_agent(JsonWriter& out, const AgentPlan& agent, bool ground) {
  out.begin_object().key("name").string(agent.name);
  out.key("status").string(to_string(agent.status));
  if (agent.status != AgentStatus::kReached) {
    out.key("reason").string(agent.reason).key("stopped_at");
    write_point(out, agent.stuck_at);
  }
  if (agent.narrowest) {
    const Narrowest& narrowest = *agent.narrowest;
    out.key("narrowest").begin_object().key("at");
    write_point(out, narrowest.at);
    out.key("width").number(narrowest.width).key("needs").number(narrowest.needs);
    out.key("behavior").string(to_string(narrowest.behavior)).end_object();
  }
  if (agent.leaves) out.key("leaves").value(true);
  if (agent.scale != 1.0) out.key("scale").number(agent.scale);
  if (agent.character) out.key("character").value(character_to_json(*agent.character, ground));
  out.key("start").begin_object().key("position");
  write_point(out, agent.start.com);
  out.key("facing").number(agent.start.facing).key("left_foot");
  write_point(out, agent.start.feet[0]);
  out.key("right_foot");
  write_point(out, agent.start.feet[1]);
  if (ground) {
    out.key("foot_heights").begin_array();
    for (const double height : agent.start.foot_heights) out.number(height);
    out.end_array();
  }
  out.end_object();
  if (!agent.sections.empty()) {
    out.key("sections").begin_array();
    for (const BehaviorSection& section : agent.sections) {
      out.begin_object().key("behavior").string(to_string(section.behavior));
      out.key("clearance").number(section.clearance).key("points").begin_array();
      for (const Vec2 p : section.points) write_point(out, p);
      out.end_array().key("length").number(section.length).end_object();
    }
    out.end_array();
  }
  out.key("stats").begin_object();
  out.key("goals_reached").integer(agent.goals_reached).key("searches").integer(agent.searches);
  out.key("nodes_generated").integer(agent.nodes_generated);
  out.key("nodes_expanded").integer(agent.nodes_expanded);
  out.key("total_cost").number(agent.total_cost()).key("end_time").number(agent.end_time());
  out.end_object().key("footsteps");
  write_footsteps(out, agent, ground);
  out.end_object();
}

// The plan as version 2 JSON, agent by agent.
void write_plan(const Plan& plan, std::ostream& stream) {
  long long footsteps = 0, searches = 0, generated = 0, expanded = 0, reached = 0;
  for (const AgentPlan& agent : plan.agents) {
    footsteps += static_cast<long long>(agent.footsteps.size());
    searches += agent.searches;
    generated += agent.nodes_generated;
    expanded += agent.nodes_expanded;
    reached += agent.status == AgentStatus::kReached ? 1 : 0;
  }
  JsonWriter out(stream);
  out.begin_object().key("format").string("footfall-plan").key("version").integer(2);
  const bool ground = !plan.ground.empty();
  out.key("character").value(character_to_json(plan.character, ground));
  out.key("obstacles").begin_array();
  for (const Obstacle& obstacle : plan.obstacles) out.value(obstacle_to_json(obstacle));
  out.end_array();
  if (ground) {
    out.key("ground").begin_array();
    for (const Obstacle& surface : plan.ground) out.value(obstacle_to_json(surface));
    out.end_array();
  }
  out.key("stats").begin_object();
  out.key("status").string(to_string(plan.status));
  out.key("agents").integer(static_cast<long long>(plan.agents.size()));
  out.key("agents_reached").integer(reached).key("footsteps").integer(footsteps);
  out.key("searches").integer(searches).key("nodes_generated").integer(generated);
  out.key("nodes_expanded").integer(expanded).end_object();
  out.key("agents").begin_array();
  for (const AgentPlan& agent : plan.agents) write_agent(out, agent, ground);
  out.end_array().end_object();
  out.flush();
  stream << '\n';
}

// Reads an enum by its to_string name.
template <typename Enum, size_t N>
Enum read_enum(const Json& value, const std::string& path, const Enum (&choices)[N]) {
  const std::string name = string(value, path);
  std::string expected;
  for (const Enum choice : choices) {
    if (name == to_string(choice)) return choice;
    expected += std::string(expected.empty() ? "" : ", ") + "\"" + to_string(choice) + "\"";
  }
  fail(path, user_text(name) + " is not one of " + expected);
}

// A step's time must lie in [0, kMaxPlanTime].
void check_time(double time, const std::string& path) {
  if (time < 0.0 || time > kMaxPlanTime)
    fail(path, "must be in [0, " + std::to_string(std::lround(kMaxPlanTime)) + "] s, got " +
                   std::to_string(time));
}

Footstep read_footstep(const Json& json, const std::string& path) {
  expect_object(json, path,
                {"foot", "kind", "start_time", "end_time", "foot_position", "foot_orientation",
                 "orientation_interval", "com_start", "com_end", "com_velocity_start",
                 "com_velocity_end", "phi", "speed", "alpha", "behavior", "cost", "cost_terms"});
  const auto field = [&](const char* key) -> const Json& { return require(json, path, key); };
  Footstep step;
  step.foot = read_enum(field("foot"), child(path, "foot"), {Foot::kLeft, Foot::kRight});
  if (json.contains("kind"))
    step.kind =
        read_enum(json["kind"], child(path, "kind"),
                  {StepKind::kWalk, StepKind::kStop, StepKind::kSideStep, StepKind::kStart});
  step.start_time = number(field("start_time"), child(path, "start_time"));
  step.end_time = number(field("end_time"), child(path, "end_time"));
  if (!(step.end_time > step.start_time)) fail(child(path, "end_time"), "must be after start_time");
  check_time(step.start_time, child(path, "start_time"));
  check_time(step.end_time, child(path, "end_time"));
  step.foot_position = point(field("foot_position"), child(path, "foot_position"));
  step.foot_orientation = number(field("foot_orientation"), child(path, "foot_orientation"));
  step.orientation_interval = {step.foot_orientation, step.foot_orientation};
  if (json.contains("orientation_interval")) {
    const Vec2 bounds = point(json["orientation_interval"], child(path, "orientation_interval"));
    step.orientation_interval = {bounds.x, bounds.y};
  }
  step.com_start = point(field("com_start"), child(path, "com_start"));
  step.com_end = point(field("com_end"), child(path, "com_end"));
  step.com_velocity_start = point(field("com_velocity_start"), child(path, "com_velocity_start"));
  step.com_velocity_end = point(field("com_velocity_end"), child(path, "com_velocity_end"));
  // The torso faces along the COM chord unless phi says otherwise.
  step.phi = json.contains("phi") ? number(json["phi"], child(path, "phi"))
                                  : angle_of(step.com_end - step.com_start);
  if (json.contains("speed")) step.speed = number(json["speed"], child(path, "speed"));
  if (json.contains("alpha")) step.alpha = number(json["alpha"], child(path, "alpha"));
  step.behavior = read_enum(field("behavior"), child(path, "behavior"),
                            {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep});
  // The total is what the file states; the terms are kept when given.
  const double cost = number(field("cost"), child(path, "cost"));
  if (json.contains("cost_terms")) {
    const std::string terms_path = child(path, "cost_terms");
    const Json& terms = json["cost_terms"];
    expect_object(terms, terms_path, {"fixed_rate", "speed_change", "curvature"});
    step.cost.fixed_rate =
        number(require(terms, terms_path, "fixed_rate"), child(terms_path, "fixed_rate"));
    step.cost.speed_change =
        number(require(terms, terms_path, "speed_change"), child(terms_path, "speed_change"));
    step.cost.curvature =
        number(require(terms, terms_path, "curvature"), child(terms_path, "curvature"));
  } else {
    step.cost.fixed_rate = cost;
  }
  return step;
}

// Version 2's footstep columns of one agent: each holds one item per step.
class FootstepColumns {
 public:
  FootstepColumns(const Json& json, std::string path) : json_(json), path_(std::move(path)) {
    expect_object(json, path_,
                  {"count", "foot", "kind", "behavior", "end_time", "foot_position", "com_end",
                   "com_velocity_end", "foot_height", "terrain", "values", "phi",
                   "foot_orientation", "orientation_interval",
                   "speed", "alpha", "fixed_rate", "speed_change", "curvature", "starts"});
    const long long count = integer(require(json, path_, "count"), child(path_, "count"));
    if (count < 0) fail(child(path_, "count"), "must be at least 0, got " + std::to_string(count));
    count_ = static_cast<std::size_t>(count);
    const std::string values_path = child(path_, "values");
    const Json& values = array(require(json, path_, "values"), values_path);
    for (std::size_t k = 0; k < values.size(); ++k)
      values_.push_back(number(values[k], item(values_path, k)));
  }

  std::size_t count() const { return count_; }
  std::string path(const char* name) const { return child(path_, name); }

  // The array `name`, of count() items.
  const Json& items(const char* name) const {
    const Json& column = array(require(json_, path_, name), path(name));
    if (column.size() != count_) fail(path(name), size_error(column.size(), "items"));
    return column;
  }

  // The string of letters `name`, one per step, as enumerators: their index in `letters`.
  template <typename Enum>
  void read_letters(const char* name, std::string_view letters, std::vector<Footstep>& steps,
                    Enum Footstep::*member) const {
    const std::string text = string(require(json_, path_, name), path(name));
    if (text.size() != count_) fail(path(name), size_error(text.size(), "letters"));
    for (std::size_t i = 0; i < count_; ++i) {
      const std::size_t k = letters.find(text[i]);
      if (k == std::string_view::npos) {
        std::string expected;
        for (std::size_t e = 0; e < letters.size(); ++e)
          expected += std::string(e == 0 ? "" : ", ") + "'" + letters[e] + "' (" +
                      to_string(static_cast<Enum>(e)) + ")";
        fail(item(path(name), i),
             user_text(std::string(1, text[i])) + " is not one of " + expected);
      }
      steps[i].*member = static_cast<Enum>(k);
    }
  }

  // The number that `index` (at `at`) names in "values".
  double value(const Json& index, const std::string& at) const {
    const long long k = integer(index, at);
    if (k < 0 || static_cast<std::size_t>(k) >= values_.size())
      fail(at, "index " + std::to_string(k) + " is not in [0, " + std::to_string(values_.size()) +
                   ") of values");
    return values_[static_cast<std::size_t>(k)];
  }

  // The column `name` of indexes into "values", each number set by `set`.
  template <typename Set>
  void read_indexed(const char* name, std::vector<Footstep>& steps, Set set) const {
    const Json& column = items(name);
    for (std::size_t i = 0; i < count_; ++i) set(steps[i], value(column[i], item(path(name), i)));
  }

 private:
  std::string size_error(std::size_t size, const char* what) const {
    return "expected " + std::to_string(count_) + " " + what + " (count), got " +
           std::to_string(size);
  }

  const Json& json_;
  std::string path_;
  std::size_t count_ = 0;
  std::vector<double> values_;
};

// The steps whose start "starts" gives, by step, each after the one before.
std::map<std::size_t, std::size_t> read_start_steps(const Json& starts, const std::string& path,
                                                    std::size_t count) {
  std::map<std::size_t, std::size_t> entries;
  long long least = 0;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const std::string at = item(path, k);
    expect_object(starts[k], at, {"step", "start_time", "com_start", "com_velocity_start"});
    const long long step = integer(require(starts[k], at, "step"), child(at, "step"));
    if (step < least || step >= static_cast<long long>(count))
      fail(child(at, "step"), "must be in [" + std::to_string(least) + ", " +
                                  std::to_string(count) + ") (after the entry before), got " +
                                  std::to_string(step));
    entries[static_cast<std::size_t>(step)] = k;
    least = step + 1;
  }
  return entries;
}

// One agent's footsteps from version 2's columns (docs/file-formats.md).
std::vector<Footstep> read_footstep_columns(const Json& json, const std::string& path,
                                            Vec2 start_com) {
  const FootstepColumns columns(json, path);
  const std::size_t count = columns.count();
  const Json& ends = columns.items("end_time");  // first: count is now that of a column
  std::vector<Footstep> steps(count);
  columns.read_letters("foot", kFootLetters, steps, &Footstep::foot);
  columns.read_letters("kind", kKindLetters, steps, &Footstep::kind);
  columns.read_letters("behavior", kBehaviorLetters, steps, &Footstep::behavior);
  for (const auto& [name, member] :
       {std::pair{"foot_position", &Footstep::foot_position}, {"com_end", &Footstep::com_end},
        {"com_velocity_end", &Footstep::com_velocity_end}}) {
    const Json& column = columns.items(name);
    for (std::size_t i = 0; i < count; ++i)
      steps[i].*member = point(column[i], item(columns.path(name), i));
  }
  if (json.contains("foot_height")) {
    const Json& column = columns.items("foot_height");
    for (std::size_t i = 0; i < count; ++i)
      steps[i].foot_height = number(column[i], item(columns.path("foot_height"), i));
  }
  columns.read_indexed("phi", steps, [](Footstep& s, double v) { s.phi = v; });
  columns.read_indexed("foot_orientation", steps,
                       [](Footstep& s, double v) { s.foot_orientation = v; });
  const Json& intervals = columns.items("orientation_interval");
  for (std::size_t i = 0; i < count; ++i) {
    const std::string at = item(columns.path("orientation_interval"), i);
    if (!intervals[i].is_array() || intervals[i].size() != 2)
      fail(at, "expected [inner, outer], two indexes into values");
    steps[i].orientation_interval = {columns.value(intervals[i][0], item(at, 0)),
                                     columns.value(intervals[i][1], item(at, 1))};
  }
  columns.read_indexed("speed", steps, [](Footstep& s, double v) { s.speed = v; });
  columns.read_indexed("alpha", steps, [](Footstep& s, double v) { s.alpha = v; });
  columns.read_indexed("fixed_rate", steps, [](Footstep& s, double v) { s.cost.fixed_rate = v; });
  columns.read_indexed("speed_change", steps,
                       [](Footstep& s, double v) { s.cost.speed_change = v; });
  columns.read_indexed("curvature", steps, [](Footstep& s, double v) { s.cost.curvature = v; });
  if (json.contains("terrain"))
    columns.read_indexed("terrain", steps, [](Footstep& s, double v) { s.cost.terrain = v; });

  // The times, and the starts: where start_after says, but for the steps in "starts".
  const Json none = Json::array();
  const std::string starts_path = columns.path("starts");
  const Json& starts = json.contains("starts") ? array(json["starts"], starts_path) : none;
  const auto given = read_start_steps(starts, starts_path, count);
  for (std::size_t i = 0; i < count; ++i) {
    Footstep& step = steps[i];
    const StepStart start = start_after(steps, i, start_com);
    step.start_time = start.time;
    step.com_start = start.com;
    step.com_velocity_start = start.velocity;
    std::string start_time_path;  // where the start time was written, if it was
    if (const auto entry = given.find(i); entry != given.end()) {
      const std::string at = item(starts_path, entry->second);
      const Json& written = starts[entry->second];
      start_time_path = child(at, "start_time");
      step.start_time = number(require(written, at, "start_time"), start_time_path);
      step.com_start = point(require(written, at, "com_start"), child(at, "com_start"));
      step.com_velocity_start =
          point(require(written, at, "com_velocity_start"), child(at, "com_velocity_start"));
    }
    const std::string end_path = item(columns.path("end_time"), i);
    step.end_time = number(ends[i], end_path);
    if (!(step.end_time > step.start_time)) fail(end_path, "must be after start_time");
    if (!start_time_path.empty()) check_time(step.start_time, start_time_path);
    check_time(step.end_time, end_path);
    if (!start_time_path.empty() && i > 0 && step.start_time < steps[i - 1].end_time - 1e-9)
      fail(start_time_path, "starts before the previous step ends");
  }
  return steps;
}

// Agents' own characters by their JSON text: those with the same share one.
using Characters = std::map<std::string, std::shared_ptr<const CharacterParams>>;

// The standing start as written.
FootstepState read_start(const Json& start, const std::string& path,
                         const CharacterParams& character) {
  expect_object(start, path, {"position", "facing", "left_foot", "right_foot", "foot_heights"});
  FootstepState state =
      standing_state(point(require(start, path, "position"), child(path, "position")),
                     number(require(start, path, "facing"), child(path, "facing")), character);
  if (start.contains("left_foot"))
    state.feet[0] = point(start["left_foot"], child(path, "left_foot"));
  if (start.contains("right_foot"))
    state.feet[1] = point(start["right_foot"], child(path, "right_foot"));
  if (start.contains("foot_heights")) {
    const std::string heights_path = child(path, "foot_heights");
    const Json& heights = array(start["foot_heights"], heights_path);
    if (heights.size() != 2) fail(heights_path, "needs 2 heights, the left foot's and the right's");
    for (int f = 0; f < 2; ++f)
      state.foot_heights[f] = number(heights[f], item(heights_path, static_cast<std::size_t>(f)));
  }
  return state;
}

Narrowest read_narrowest(const Json& json, const std::string& path) {
  expect_object(json, path, {"at", "width", "needs", "behavior"});
  Narrowest narrowest;
  narrowest.at = point(require(json, path, "at"), child(path, "at"));
  narrowest.width = number(require(json, path, "width"), child(path, "width"));
  narrowest.needs = number(require(json, path, "needs"), child(path, "needs"));
  if (!(narrowest.width >= 0.0)) fail(child(path, "width"), "must be >= 0");
  if (!(narrowest.needs > 0.0)) fail(child(path, "needs"), "must be > 0");
  narrowest.behavior = read_enum(require(json, path, "behavior"), child(path, "behavior"),
                                 {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep});
  return narrowest;
}

AgentPlan read_agent(const Json& json, const std::string& path, int version,
                     const CharacterParams& shared, Characters& characters) {
  expect_object(
      json, path,
      {"name", "status", "leaves", "reason", "stopped_at", "narrowest", "start", "footsteps",
       "sections", "stats", "character", "scale"});
  AgentPlan agent;
  if (json.contains("character")) {
    auto& own = characters[json["character"].dump()];
    if (!own) {
      CharacterParams read = shared;
      read_character(json["character"], child(path, "character"), read);
      validate(read, child(path, "character"));
      own = std::make_shared<const CharacterParams>(std::move(read));
    }
    agent.character = own;
  }
  const CharacterParams& character = character_of(agent, shared);
  agent.name = string(require(json, path, "name"), child(path, "name"));
  agent.status = read_enum(require(json, path, "status"), child(path, "status"),
                           {AgentStatus::kReached, AgentStatus::kPartial});
  if (json.contains("leaves")) agent.leaves = boolean(json["leaves"], child(path, "leaves"));
  if (json.contains("scale")) {
    agent.scale = number(json["scale"], child(path, "scale"));
    if (!in_scale_range(agent.scale))
      fail(child(path, "scale"), kScaleRange);
  }
  if (json.contains("reason")) agent.reason = string(json["reason"], child(path, "reason"));
  if (json.contains("stopped_at"))
    agent.stuck_at = point(json["stopped_at"], child(path, "stopped_at"));
  if (json.contains("narrowest"))
    agent.narrowest = read_narrowest(json["narrowest"], child(path, "narrowest"));
  const std::string steps_path = child(path, "footsteps");
  if (version == 2) {
    // Version 2's first step starts from the start: read before.
    agent.start = read_start(require(json, path, "start"), child(path, "start"), character);
    agent.footsteps =
        read_footstep_columns(require(json, path, "footsteps"), steps_path, agent.start.com);
  } else {
    const Json& steps = array(require(json, path, "footsteps"), steps_path);
    for (size_t i = 0; i < steps.size(); ++i) {
      agent.footsteps.push_back(read_footstep(steps[i], item(steps_path, i)));
      if (i > 0 && agent.footsteps[i].start_time < agent.footsteps[i - 1].end_time - 1e-9) {
        fail(child(item(steps_path, i), "start_time"), "starts before the previous step ends");
      }
    }
  }
  if (json.contains("sections")) {
    const std::string sections_path = child(path, "sections");
    const Json& sections = array(json["sections"], sections_path);
    for (std::size_t i = 0; i < sections.size(); ++i) {
      const std::string at = item(sections_path, i);
      expect_object(sections[i], at, {"behavior", "clearance", "points", "length"});
      BehaviorSection section;
      section.behavior = read_enum(require(sections[i], at, "behavior"), child(at, "behavior"),
                                   {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep});
      section.clearance = number(require(sections[i], at, "clearance"), child(at, "clearance"));
      const std::string points_path = child(at, "points");
      const Json& points = array(require(sections[i], at, "points"), points_path);
      for (std::size_t k = 0; k < points.size(); ++k)
        section.points.push_back(point(points[k], item(points_path, k)));
      if (section.points.size() < 2) fail(points_path, "needs at least 2 points");
      section.length = number(require(sections[i], at, "length"), child(at, "length"));
      agent.sections.push_back(std::move(section));
    }
  }
  // Version 1's start: as written, or standing where the first step begins.
  if (version == 1) {
    if (json.contains("start")) {
      agent.start = read_start(json["start"], child(path, "start"), character);
    } else if (!agent.footsteps.empty()) {
      const Footstep& first = agent.footsteps.front();
      agent.start = standing_state(first.com_start, first.phi, character);
    } else {
      fail(child(path, "start"), "missing (needed when there are no footsteps)");
    }
  }
  // A start written before its heights were: on the first step's ground.
  const bool heights_given = json.contains("start") && json["start"].is_object() &&
                             json["start"].contains("foot_heights");
  if (!heights_given && !agent.footsteps.empty())
    agent.start.foot_heights.fill(agent.footsteps.front().foot_height);
  if (json.contains("stats")) {
    const Json& stats = json["stats"];
    const std::string stats_path = child(path, "stats");
    if (!stats.is_object()) fail(stats_path, "expected an object, got " + type_name(stats));
    if (stats.contains("goals_reached"))
      agent.goals_reached =
          int(integer(stats["goals_reached"], child(stats_path, "goals_reached")));
    if (stats.contains("searches"))
      agent.searches = int(integer(stats["searches"], child(stats_path, "searches")));
    if (stats.contains("nodes_generated"))
      agent.nodes_generated =
          integer(stats["nodes_generated"], child(stats_path, "nodes_generated"));
    if (stats.contains("nodes_expanded"))
      agent.nodes_expanded = integer(stats["nodes_expanded"], child(stats_path, "nodes_expanded"));
  }
  return agent;
}

// Checks the header as expect_header does, for either version; returns it.
int read_version(const Json& root) {
  if (!root.is_object()) fail("(top level)", "expected an object, got " + type_name(root));
  const std::string format = string(require(root, "", "format"), "format");
  if (format != "footfall-plan")
    fail("format", "expected \"footfall-plan\", got " + user_text(format));
  const long long version = integer(require(root, "", "version"), "version");
  if (version != 1 && version != 2)
    fail("version", "unsupported version " + std::to_string(version) +
                        " (this Footfall reads versions 1 and 2)");
  return static_cast<int>(version);
}

Plan read_plan(const Json& root) {
  const int version = read_version(root);
  expect_object(root, "",
                {"format", "version", "character", "obstacles", "ground", "agents", "stats"});
  Plan plan;
  if (root.contains("obstacles")) {
    plan.obstacles = read_obstacles(root["obstacles"]);
    ObstacleMap checked(plan.obstacles);  // the same checks as a scenario's obstacles
  }
  if (root.contains("ground")) {
    plan.ground = read_ground(root["ground"]);
    const Ground checked(plan.ground);  // as a scenario's
  }
  if (root.contains("character")) read_character(root["character"], "character", plan.character);
  validate(plan.character, "character");
  // The top-level stats are derived when writing; read, they must only be an object.
  if (root.contains("stats") && !root["stats"].is_object())
    fail("stats", "expected an object, got " + type_name(root["stats"]));
  const Json& agents = array(require(root, "", "agents"), "agents");
  Characters characters;
  for (size_t i = 0; i < agents.size(); ++i)
    plan.agents.push_back(
        read_agent(agents[i], item("agents", i), version, plan.character, characters));
  return plan;
}

}  // namespace

std::string plan_to_json(const Plan& plan) {
  std::ostringstream out;
  write_plan(plan, out);
  return std::move(out).str();
}

Plan parse_plan(const std::string& text, const std::string& source) {
  const Json root = parse_json(text, source);
  try {
    return read_plan(root);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
}

Plan load_plan(const std::string& path) { return parse_plan(read_file(path), path); }

void write_plan_file(const Plan& plan, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) { write_plan(plan, out); });
}

}  // namespace footfall
