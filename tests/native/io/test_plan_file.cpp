// The plan file's version 2 (compact, footsteps as columns, written as a
// stream): plans read back the same to the bit, version 1 files still read,
// and bad version 2 files are named by field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "footfall/crowd/scenario.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/io/scenario_file.hpp"
#include "footfall/io/steersuite.hpp"
#include "footfall/scenes/scenes.hpp"
#include "io/json_reader.hpp"
#include "io/param_json.hpp"

namespace footfall {
namespace {

using detail::Json;

const std::filesystem::path kData = std::filesystem::path(FOOTFALL_STEERSUITE_DIR).parent_path();

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same(Vec2 a, Vec2 b) { return same(a.x, b.x) && same(a.y, b.y); }
bool same(OrientationInterval a, OrientationInterval b) {
  return same(a.inner, b.inner) && same(a.outer, b.outer);
}

// Every field of two plans, doubles to the bit; `what` names the plans.
void expect_same_plan(const Plan& a, const Plan& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.status, b.status);
  // As the file holds them: a flat plan's without the fields only ground uses.
  const bool ground = !a.ground.empty();
  EXPECT_EQ(detail::character_to_json(a.character, ground),
            detail::character_to_json(b.character, ground));
  ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
  for (std::size_t i = 0; i < a.obstacles.size(); ++i)
    EXPECT_EQ(detail::obstacle_to_json(a.obstacles[i]), detail::obstacle_to_json(b.obstacles[i]));
  ASSERT_EQ(a.agents.size(), b.agents.size());
  for (std::size_t n = 0; n < a.agents.size(); ++n) {
    const AgentPlan &p = a.agents[n], &q = b.agents[n];
    SCOPED_TRACE("agent " + p.name);
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.status, q.status);
    EXPECT_EQ(p.reason, q.reason);
    if (p.status == AgentStatus::kPartial) {  // else not kept
      EXPECT_TRUE(same(p.stuck_at, q.stuck_at));
    }
    EXPECT_EQ(p.goals_reached, q.goals_reached);
    EXPECT_EQ(p.leaves, q.leaves);
    EXPECT_EQ(p.searches, q.searches);
    EXPECT_EQ(p.nodes_generated, q.nodes_generated);
    EXPECT_EQ(p.nodes_expanded, q.nodes_expanded);
    EXPECT_TRUE(same(p.scale, q.scale));
    ASSERT_EQ(p.character == nullptr, q.character == nullptr);
    if (p.character) {
      EXPECT_EQ(detail::character_to_json(*p.character, ground),
                detail::character_to_json(*q.character, ground));
    }
    const FootstepState &s = p.start, &t = q.start;
    EXPECT_TRUE(same(s.com, t.com) && same(s.com_velocity, t.com_velocity) &&
                same(s.facing, t.facing) && same(s.time, t.time));
    EXPECT_TRUE(same(s.feet[0], t.feet[0]) && same(s.feet[1], t.feet[1]));
    EXPECT_TRUE(same(s.foot_orientation[0], t.foot_orientation[0]) &&
                same(s.foot_orientation[1], t.foot_orientation[1]));
    EXPECT_EQ(s.last_foot, t.last_foot);
    EXPECT_EQ(s.before_first_step, t.before_first_step);
    ASSERT_EQ(p.sections.size(), q.sections.size());
    for (std::size_t i = 0; i < p.sections.size(); ++i) {
      const BehaviorSection &u = p.sections[i], &v = q.sections[i];
      EXPECT_EQ(u.behavior, v.behavior) << "section " << i;
      EXPECT_TRUE(same(u.clearance, v.clearance) && same(u.length, v.length)) << "section " << i;
      ASSERT_EQ(u.points.size(), v.points.size()) << "section " << i;
      for (std::size_t k = 0; k < u.points.size(); ++k)
        EXPECT_TRUE(same(u.points[k], v.points[k])) << "section " << i << " point " << k;
    }
    ASSERT_EQ(p.footsteps.size(), q.footsteps.size());
    for (std::size_t i = 0; i < p.footsteps.size(); ++i) {
      const Footstep &u = p.footsteps[i], &v = q.footsteps[i];
      SCOPED_TRACE("footstep " + std::to_string(i));
      EXPECT_EQ(u.foot, v.foot);
      EXPECT_EQ(u.kind, v.kind);
      EXPECT_EQ(u.behavior, v.behavior);
      EXPECT_TRUE(same(u.start_time, v.start_time) && same(u.end_time, v.end_time));
      EXPECT_TRUE(same(u.foot_position, v.foot_position));
      EXPECT_TRUE(same(u.orientation_interval, v.orientation_interval));
      EXPECT_TRUE(same(u.foot_orientation, v.foot_orientation));
      EXPECT_TRUE(same(u.com_start, v.com_start) && same(u.com_end, v.com_end));
      EXPECT_TRUE(same(u.com_velocity_start, v.com_velocity_start) &&
                  same(u.com_velocity_end, v.com_velocity_end));
      EXPECT_TRUE(same(u.phi, v.phi) && same(u.speed, v.speed) && same(u.alpha, v.alpha));
      EXPECT_TRUE(same(u.cost.fixed_rate, v.cost.fixed_rate) &&
                  same(u.cost.speed_change, v.cost.speed_change) &&
                  same(u.cost.curvature, v.cost.curvature));
    }
  }
}

std::size_t footsteps(const Plan& plan) {
  std::size_t count = 0;
  for (const AgentPlan& agent : plan.agents) count += agent.footsteps.size();
  return count;
}

// A crowd of four with what plans hold beyond walking: goals with a wait and
// an end facing, an agent that leaves, one scaled, one with its own
// character, one that runs out of time; prisms, a table and a mesh.
const char* const kFeatures = R"({"format": "footfall-scenario", "version": 1,
  "obstacles": [
    {"polygon": [[2, 1.2], [2.6, 1.2], [2.6, 1.8], [2, 1.8]], "height": 1.0},
    {"polygon": [[4, -2.5], [5, -2.5], [5, -1.9], [4, -1.9]], "base": 0.7, "height": 0.8},
    {"mesh": {"vertices": [[6, 2, 0], [6.5, 2, 0], [6, 2.5, 0], [6, 2, 1.5]],
              "triangles": [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]}}],
  "agents": [
    {"name": "ann", "position": [0, 0], "goals": [[2.5, 0], [4, 0.5]], "goal_wait": 0.4,
     "end_facing": 1.5},
    {"name": "bo", "position": [0, 1.5], "goals": [[4, 1.5]], "leave_at_goal": true, "scale": 0.8},
    {"name": "cy \"the third\"", "position": [0, -1.2], "goals": [[6, -1.2]], "start_delay": 0.3,
     "character": {"mass": 60}},
    {"name": "dee", "position": [0, -3], "goals": [[12, -3]], "time_limit": 1.5}]})";

TEST(PlanFileV2, CrowdPlansReadBackTheSameToTheBit) {
  const std::pair<const char*, Scenario> scenarios[] = {
      {"demo", demo_scenario()},
      {"circle-20", load_steersuite((kData / "steersuite" / "circle-20.xml").string())},
      {"features", parse_scenario(kFeatures)}};
  for (const auto& [name, scenario] : scenarios) {
    const Plan plan = plan_scenario(scenario);
    const std::string text = plan_to_json(plan);
    const Plan back = parse_plan(text);
    expect_same_plan(plan, back, name);
    EXPECT_EQ(plan_to_json(back), text) << name;
  }
}

TEST(PlanFileV2, IsCompact) {
  for (const char* name : {"circle-20", "4-way-oncomming"}) {
    const std::string path = (kData / "steersuite" / name).string() + ".xml";
    const Plan plan = plan_scenario(load_steersuite(path));
    const std::string text = plan_to_json(plan);
    EXPECT_LT(double(text.size()) / double(footsteps(plan)), 250.0) << name;
    EXPECT_EQ(text.find('\n'), text.size() - 1) << name;  // one line
  }
  // The demo, a small plan its obstacles and character weigh on, on the
  // flat; on its ground it carries two more columns (foot_height, terrain).
  Scenario flat = demo_scenario();
  flat.ground.clear();
  const Plan demo = plan_scenario(flat);
  EXPECT_LT(double(plan_to_json(demo).size()) / double(footsteps(demo)), 250.0);
  const Plan on_ground = plan_scenario(demo_scenario());
  EXPECT_LT(double(plan_to_json(on_ground).size()) / double(footsteps(on_ground)), 260.0);
}

// Version 1 (written by Footfall before version 2, pretty-printed) reads as
// it did: each field as the file holds it, and written again the same plan.
TEST(PlanFileV2, AVersionOneFileStillReads) {
  const std::string path = (kData / "plan-v1-small.json").string();
  const Plan plan = load_plan(path);
  std::ifstream in(path);
  const Json file = Json::parse(in);
  ASSERT_EQ(file["version"], 1);
  ASSERT_EQ(plan.agents.size(), file["agents"].size());
  const auto xy = [](const Json& json) {
    return Vec2{json[0].get<double>(), json[1].get<double>()};
  };
  for (std::size_t n = 0; n < plan.agents.size(); ++n) {
    const AgentPlan& agent = plan.agents[n];
    const Json& written = file["agents"][n];
    SCOPED_TRACE(agent.name);
    EXPECT_EQ(agent.name, written["name"]);
    EXPECT_EQ(to_string(agent.status), written["status"]);
    EXPECT_TRUE(same(agent.start.com, xy(written["start"]["position"])));
    EXPECT_TRUE(same(agent.start.facing, written["start"]["facing"].get<double>()));
    EXPECT_TRUE(same(agent.start.feet[0], xy(written["start"]["left_foot"])));
    EXPECT_TRUE(same(agent.start.feet[1], xy(written["start"]["right_foot"])));
    EXPECT_EQ(agent.goals_reached, written["stats"]["goals_reached"]);
    EXPECT_EQ(agent.nodes_expanded, written["stats"]["nodes_expanded"]);
    EXPECT_EQ(agent.sections.size(), written["sections"].size());
    ASSERT_EQ(agent.footsteps.size(), written["footsteps"].size());
    for (std::size_t i = 0; i < agent.footsteps.size(); ++i) {
      const Footstep& step = agent.footsteps[i];
      const Json& json = written["footsteps"][i];
      SCOPED_TRACE("footstep " + std::to_string(i));
      EXPECT_EQ(to_string(step.foot), json["foot"]);
      EXPECT_EQ(to_string(step.kind), json["kind"]);
      EXPECT_EQ(to_string(step.behavior), json["behavior"]);
      for (const auto& [value, key] :
           {std::pair{step.start_time, "start_time"}, {step.end_time, "end_time"},
            {step.foot_orientation, "foot_orientation"}, {step.phi, "phi"},
            {step.speed, "speed"}, {step.alpha, "alpha"}, {step.cost.total(), "cost"}})
        EXPECT_TRUE(same(value, json[key].get<double>())) << key;
      for (const auto& [value, key] :
           {std::pair{step.foot_position, "foot_position"}, {step.com_start, "com_start"},
            {step.com_end, "com_end"}, {step.com_velocity_start, "com_velocity_start"},
            {step.com_velocity_end, "com_velocity_end"},
            {Vec2{step.orientation_interval.inner, step.orientation_interval.outer},
             "orientation_interval"}})
        EXPECT_TRUE(same(value, xy(json[key]))) << key;
      EXPECT_TRUE(same(step.cost.curvature, json["cost_terms"]["curvature"].get<double>()));
    }
  }
  ASSERT_TRUE(plan.agents[1].leaves && plan.agents[1].scale == 0.8);
  ASSERT_TRUE(plan.agents[2].character && plan.agents[3].status == AgentStatus::kPartial);
  expect_same_plan(plan, parse_plan(plan_to_json(plan)), "version 1 written as version 2");
}

// A step that does not start where the one before ended keeps its start,
// and zeros keep their sign.
TEST(PlanFileV2, StepsKeepStartsThatAreNotTheEndBefore) {
  Plan plan = plan_scenario(demo_scenario());
  std::vector<Footstep>& steps = plan.agents[0].footsteps;
  steps[3].start_time += 0.25;  // a pause
  steps[5].com_start.x = std::nextafter(steps[5].com_start.x, 100.0);
  steps[0].com_velocity_start.y = -0.0;
  steps[7].alpha = -0.0;
  const std::string text = plan_to_json(plan);
  EXPECT_NE(text.find(R"("starts":[{"step":0,)"), std::string::npos);
  expect_same_plan(plan, parse_plan(text), "starts");
  EXPECT_TRUE(std::signbit(parse_plan(text).agents[0].footsteps[7].alpha));
}

// A write that fails part way (a name that is not UTF-8) leaves no file.
TEST(PlanFileV2, AWriteThatFailsMidwayLeavesNoFile) {
  Plan plan = plan_scenario(demo_scenario());
  plan.agents[3].name = "bad \xff";
  const auto folder = std::filesystem::temp_directory_path() / "footfall-test-plan-midway";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directory(folder);
  EXPECT_ANY_THROW(write_plan_file(plan, (folder / "plan.json").string()));
  EXPECT_TRUE(std::filesystem::is_empty(folder));
  std::filesystem::remove_all(folder);
}

std::string plan_error(const std::string& text) {
  try {
    parse_plan(text, "p.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// A plan of one agent and two steps with its version 2 footsteps `columns`.
std::string two_steps(const std::string& columns) {
  return R"({"format": "footfall-plan", "version": 2, "agents": [{"name": "p", "status": "reached",
    "start": {"position": [0, 0], "facing": 0, "left_foot": [0, 0.1], "right_foot": [0, -0.1]},
    "footsteps": {)" +
         columns + "}}]}";
}

// Every column but those in `changed`, which replace them.
std::string columns(const std::map<std::string, std::string>& changed) {
  std::map<std::string, std::string> all{
      {"count", "2"},
      {"foot", R"("lr")"},
      {"kind", R"("ww")"},
      {"behavior", R"("wa")"},
      {"end_time", "[0.5, 1]"},
      {"foot_position", "[[0.3, 0.1], [0.9, -0.1]]"},
      {"com_end", "[[0.6, 0], [1.2, 0]]"},
      {"com_velocity_end", "[[1.2, -0.1], [1.2, 0.1]]"},
      {"values", "[0, 1.2, 0.1, 40, 50]"},
      {"phi", "[0, 0]"},
      {"foot_orientation", "[0, 0]"},
      {"orientation_interval", "[[0, 0], [0, 0]]"},
      {"speed", "[1, 1]"},
      {"alpha", "[2, 2]"},
      {"fixed_rate", "[3, 3]"},
      {"speed_change", "[4, 0]"},
      {"curvature", "[0, 0]"}};
  for (const auto& [key, value] : changed) {
    if (value.empty()) {
      all.erase(key);
    } else {
      all[key] = value;
    }
  }
  std::string text;
  for (const auto& [key, value] : all)
    text += (text.empty() ? "\"" : ", \"") + key + "\": " + value;
  return text;
}

TEST(PlanFileV2, ReadsAHandWrittenPlan) {
  const Plan plan = parse_plan(two_steps(columns({})));
  const std::vector<Footstep>& steps = plan.agents[0].footsteps;
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[1].foot, Foot::kRight);
  EXPECT_EQ(steps[1].behavior, Behavior::kArmsIn);
  EXPECT_EQ(steps[1].start_time, 0.5);
  EXPECT_EQ(steps[1].com_start, (Vec2{0.6, 0}));
  EXPECT_EQ(steps[1].com_velocity_start, (Vec2{1.2, -0.1}));
  EXPECT_EQ(steps[0].com_velocity_start, (Vec2{0, 0}));
  EXPECT_EQ(steps[0].cost.total(), 40 + 50);
  EXPECT_EQ(steps[1].speed, 1.2);
}

TEST(PlanFileV2, BadFilesAreNamedByField) {
  const auto error = [](const std::map<std::string, std::string>& changed) {
    return plan_error(two_steps(columns(changed)));
  };
  const std::string at = "p.json: agents[0].footsteps.";
  EXPECT_EQ(error({{"com_end", "[[0.6, 0]]"}}), at + "com_end: expected 2 items (count), got 1");
  EXPECT_EQ(error({{"foot", R"("lrl")"}}), at + "foot: expected 2 letters (count), got 3");
  EXPECT_EQ(error({{"kind", R"("wq")"}}),
            at + "kind[1]: 'q' is not one of 'w' (walk), 's' (stop), 'x' (side_step), 't' (start)");
  EXPECT_EQ(error({{"end_time", R"([0.5, "1"])"}}),
            at + "end_time[1]: expected a number, got string");
  EXPECT_EQ(error({{"values", "[0, 1.2, NaN, 40, 50]"}}),
            at + "values[2]: must be a finite number, got NaN");
  EXPECT_EQ(error({{"alpha", "[2, 5]"}}), at + "alpha[1]: index 5 is not in [0, 5) of values");
  EXPECT_EQ(error({{"orientation_interval", "[[0, 0], [0]]"}}),
            at + "orientation_interval[1]: expected [inner, outer], two indexes into values");
  EXPECT_EQ(error({{"phi", "[0, 0.5]"}}), at + "phi[1]: expected an integer, got number");
  EXPECT_EQ(error({{"end_time", "[0.5, 0.5]"}}), at + "end_time[1]: must be after start_time");
  EXPECT_EQ(error({{"end_time", "[0.5, 1e9]"}}),
            at + "end_time[1]: must be in [0, 200000] s, got 1000000000.000000");
  EXPECT_EQ(error({{"count", "-1"}}), at + "count: must be at least 0, got -1");
  EXPECT_EQ(error({{"curvature", ""}}), at + "curvature: missing");
  EXPECT_EQ(error({{"cost", "[1, 1]"}}), at + "cost: unknown field");
  EXPECT_EQ(error({{"starts", R"([{"step": 1, "start_time": 0.4, "com_start": [0.6, 0],
                                  "com_velocity_start": [0, 0]}])"}}),
            at + "starts[0].start_time: starts before the previous step ends");
  EXPECT_EQ(error({{"starts", R"([{"step": 1, "start_time": 0.5, "com_start": [0.6, 0],
                                  "com_velocity_start": [0, 0]}, {"step": 1}])"}}),
            at + "starts[1].step: must be in [2, 2) (after the entry before), got 1");
  EXPECT_EQ(plan_error(R"({"format": "footfall-plan", "version": 3, "agents": []})"),
            "p.json: version: unsupported version 3 (this Footfall reads versions 1 and 2)");
  // Cut short, as by a full disk: the place is named.
  const std::string text = plan_to_json(plan_scenario(demo_scenario()));
  EXPECT_EQ(plan_error(text.substr(0, text.size() / 2)).rfind("p.json: not valid JSON: ", 0), 0u);
  // Without its start, a version 2 agent has no first step.
  std::string startless = two_steps(columns({}));
  const std::size_t start = startless.find("\"start\"");
  startless.erase(start, startless.find("\"footsteps\"") - start);
  EXPECT_EQ(plan_error(startless), "p.json: agents[0].start: missing");
}

}  // namespace
}  // namespace footfall
