// Scenario and plan files: every bad input named by file and field path.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "footfall/crowd/scenario.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/io/scenario_file.hpp"
#include "footfall/scenes/scenes.hpp"

namespace footfall {
namespace {

std::string scene_error(const std::string& text) {
  try {
    parse_scenario(text, "scene.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

const char* const kHeader = R"("format": "footfall-scenario", "version": 1)";

std::string scenario_text(const std::string& body) {
  return std::string("{") + kHeader + ", " + body + "}";
}

TEST(ScenarioFile, ReadsEveryPartAndItsOverrides) {
  const Scenario s = parse_scenario(scenario_text(R"(
    "obstacles": [{"polygon": [[2, -1], [3, -1], [3, 1], [2, 1]], "height": 0.8}],
    "agents": [{"name": "ann", "position": [0, 0], "facing": 0.5, "goals": [[5, 0], [6, 1]],
                "leave_at_goal": true},
               {"position": [0, 3], "goals": [[0, 6]]}],
    "character": {"mass": 60, "max_speed": 2.0, "left": {"max_speed": 1.0}},
    "planner": {"max_expansions": 200, "stall_expansions": 0, "gaits": [{"speed": 1.0, "duration": 0.5}], "turn_angles": [0.1, 0.5]}
  )"));
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_DOUBLE_EQ(s.obstacles[0].height, 0.8);
  ASSERT_EQ(s.agents.size(), 2u);
  EXPECT_EQ(s.agents[0].name, "ann");
  EXPECT_DOUBLE_EQ(s.agents[0].facing, 0.5);
  EXPECT_EQ(s.agents[0].goals.size(), 2u);
  EXPECT_TRUE(s.agents[0].leave_at_goal);
  EXPECT_FALSE(s.agents[1].leave_at_goal);
  EXPECT_EQ(s.agents[1].name, "agent1");
  EXPECT_NEAR(s.agents[1].facing, 3.14159265358979 / 2, 1e-12);  // toward its first goal
  EXPECT_DOUBLE_EQ(s.character.mass, 60);
  EXPECT_DOUBLE_EQ(s.character.left.max_speed, 1.0);  // the per-foot object wins
  EXPECT_DOUBLE_EQ(s.character.right.max_speed, 2.0);
  EXPECT_EQ(s.planner.max_expansions, 200);
  EXPECT_EQ(s.planner.stall_expansions, 0);
  EXPECT_EQ(s.planner.gaits.size(), 1u);
  EXPECT_EQ(s.planner.turn_angles.size(), 2u);
}

TEST(ScenarioFile, AScenarioWithoutAgentsIsValid) {
  EXPECT_TRUE(parse_scenario(scenario_text(R"("obstacles": [])")).agents.empty());
}

TEST(ScenarioFile, BadInputIsNamedByFileAndField) {
  const std::string agent = R"("agents": [{"position": [0, 0], "goals": [[5, 0]]}])";
  EXPECT_EQ(scene_error("{\"format\": "),
            "scene.json: not valid JSON: parse error at line 1, column 12: "
            "syntax error while parsing value - unexpected end of input; expected "
            "'[', '{', or a literal");
  EXPECT_EQ(scene_error(scenario_text(R"("agents": [{"position": [0, "x"], "goals": [[5, 0]]}])")),
            "scene.json: agents[0].position[1]: expected a number, got string");
  EXPECT_EQ(scene_error(scenario_text(R"("agents": [{"position": [NaN, 0], "goals": [[5, 0]]}])")),
            "scene.json: agents[0].position[0]: must be a finite number, got NaN");
  EXPECT_EQ(
      scene_error(scenario_text(R"("agents": [{"position": [0, 0], "goals": [[-Infinity, 0]]}])")),
      "scene.json: agents[0].goals[0][0]: must be a finite number, got -Infinity");
  EXPECT_EQ(scene_error(scenario_text(R"("obstacles": [{"polygon": [[0, 0], [1, 0]]}])")),
            "scene.json: obstacles[0].polygon: needs at least 3 points, got 2");
  EXPECT_EQ(scene_error(scenario_text(
                R"("obstacles": [{"polygon": [[-1, -1], [1, -1], [1, 1]]}], )" + agent)),
            "scene.json: agents[0].position: the standing agent overlaps obstacles[0]");
  EXPECT_EQ(scene_error(scenario_text(
                R"("obstacles": [{"polygon": [[4, -1], [6, -1], [6, 1], [4, 1]]}], )" + agent)),
            "scene.json: agents[0].goals[0]: inside obstacles[0]");
  EXPECT_EQ(scene_error(scenario_text(R"("character": {"speed": 1.0})")),
            "scene.json: character.speed: unknown field");
  EXPECT_EQ(scene_error(scenario_text(R"("planner": {"horizon": 10})")),
            "scene.json: planner.horizon: unknown field");
  EXPECT_EQ(scene_error(scenario_text(R"("character": {"mass": -3})")),
            "scene.json: character.mass: must be in (0, 500], got -3");
  EXPECT_EQ(scene_error(scenario_text(R"("agents": [{"position": [0, 0], "goals": []}])")),
            "scene.json: agents[0].goals: needs at least one goal");
  EXPECT_EQ(scene_error(scenario_text(
                R"("agents": [{"position": [0, 0], "goals": [[5, 0]], "leave_at_goal": 1}])")),
            "scene.json: agents[0].leave_at_goal: expected true or false, got number");
  EXPECT_EQ(scene_error(scenario_text(R"("agents": [{"position": [0, 0]}])")),
            "scene.json: agents[0].goals: missing");
  EXPECT_EQ(scene_error(R"({"format": "footfall-plan", "version": 1})"),
            "scene.json: format: expected \"footfall-scenario\", got 'footfall-plan'");
  EXPECT_EQ(scene_error(R"({"format": "footfall-scenario", "version": 2})"),
            "scene.json: version: unsupported version 2 (this Footfall reads version 1)");
  EXPECT_EQ(scene_error(scenario_text(R"("agents": {})")),
            "scene.json: agents: expected an array, got object");
  EXPECT_EQ(scene_error(scenario_text(R"("extra": 1)")), "scene.json: extra: unknown field");
  EXPECT_EQ(scene_error(scenario_text(R"("planner": {"max_expansions": 18446744073709551615})")),
            "scene.json: planner.max_expansions: too large");
  EXPECT_EQ(scene_error(scenario_text(R"("planner": {"stall_expansions": -1})")),
            "scene.json: planner.stall_expansions: must be in [0, 1000000], got -1");
  // A NaN before a syntax error does not move the error's reported position.
  const std::string plain = scene_error("{\"a\": [1, 2,\n  1 2]}");
  const std::string with_nan = scene_error("{\"a\": [NaN, 2,\n  1 2]}");
  EXPECT_NE(plain.find("line 2, column 5"), std::string::npos) << plain;
  EXPECT_NE(with_nan.find("line 2, column 5"), std::string::npos) << with_nan;
  EXPECT_EQ(scene_error(
                scenario_text(R"("obstacles": [{"polygon": [[0, 0], [1e300, 0], [0, 1]]}])")),
            "scene.json: obstacles[0].polygon[1]: coordinates must be finite numbers within 1e9 m "
            "of the origin");
  EXPECT_EQ(scene_error(scenario_text(R"("agents": [{"position": [0, 0], "goals": [[0, -2e9]]}])")),
            "scene.json: agents[0].goals[0]: must be finite and within 1e9 m of the origin");
}

// A box from (x0, y0, z0) to (x1, y1, z1) as a mesh, in JSON.
std::string mesh_box(double x0, double y0, double z0, double x1, double y1, double z1) {
  std::string v;
  for (int k = 0; k < 8; ++k) {
    v += (k ? ", [" : "[") + std::to_string(k & 1 ? x1 : x0) + ", " +
         std::to_string(k & 2 ? y1 : y0) + ", " + std::to_string(k & 4 ? z1 : z0) + "]";
  }
  return R"({"mesh": {"vertices": [)" + v + R"(], "triangles": [[0, 1, 3], [0, 3, 2], [4, 7, 5],
      [4, 6, 7], [0, 5, 1], [0, 4, 5], [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7],
      [1, 7, 3]]}})";
}

TEST(ScenarioFile, ObstaclesHaveABaseOrAMesh) {
  const Scenario s = parse_scenario(scenario_text(
      R"("obstacles": [{"polygon": [[2, -1], [3, -1], [3, 1], [2, 1]], "base": 0.7, "height": 0.8}, )" +
      mesh_box(4, -1, 0, 5, 1, 1) + "]"));
  ASSERT_EQ(s.obstacles.size(), 2u);
  EXPECT_DOUBLE_EQ(s.obstacles[0].base, 0.7);
  ASSERT_TRUE(s.obstacles[1].is_mesh());
  EXPECT_EQ(s.obstacles[1].mesh.triangles.size(), 12u);
  // The mesh's footprint blocks the navigation mesh like the box it is.
  const NavMesh mesh = navmesh_of(s);
  EXPECT_EQ(mesh.clearance({4.5, 0}), 0.0);
  EXPECT_NEAR(mesh.clearance({4.5, 1.5}), 0.5, 1e-9);
  // The plan file keeps both.
  Plan plan;
  plan.obstacles = s.obstacles;
  const Plan back = parse_plan(plan_to_json(plan), "plan.json");
  EXPECT_DOUBLE_EQ(back.obstacles[0].base, 0.7);
  EXPECT_EQ(back.obstacles[1].mesh.vertices.size(), 8u);
}

TEST(ScenarioFile, BadThreeDimensionalObstaclesAreNamed) {
  const auto obstacle = [](const std::string& json) {
    return scene_error(scenario_text(R"("obstacles": [)" + json + "]"));
  };
  EXPECT_EQ(obstacle(R"({"polygon": [[0, 0], [1, 0], [1, 1]], "base": 2, "height": 1})"),
            "scene.json: obstacles[0].base: must be in [0, height) = [0, 1.000000), got 2.000000");
  EXPECT_EQ(obstacle(R"({"mesh": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 3]]}})"),
            "scene.json: obstacles[0].mesh.triangles[0][2]: vertex index 3 is not in [0, 3)");
  EXPECT_EQ(obstacle(R"({"mesh": {"vertices": [[0, 0, 0], [1, 0, NaN], [0, 1, 0]], "triangles": [[0, 1, 2]]}})"),
            "scene.json: obstacles[0].mesh.vertices[1][2]: must be a finite number, got NaN");
  EXPECT_EQ(obstacle(R"({"mesh": {"vertices": [], "triangles": []}})"),
            "scene.json: obstacles[0].mesh.triangles: needs at least one triangle");
  EXPECT_EQ(obstacle(R"({"mesh": {"vertices": [[0, 0]], "triangles": []}})"),
            "scene.json: obstacles[0].mesh.vertices[0]: expected [x, y, z], got 2 items");
  EXPECT_EQ(obstacle(R"({"polygon": [[0, 0], [1, 0], [1, 1]], "mesh": {"vertices": [], "triangles": []}})"),
            "scene.json: obstacles[0].polygon: not with \"mesh\": a mesh gives its own shape");
}

TEST(ScenarioFile, MissingFileIsNamed) {
  try {
    load_scenario("/nonexistent/scene.json");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/scene.json: cannot open the file for reading");
  }
}

TEST(PlanFile, RoundTripsBitForBit) {
  const Plan plan = plan_scenario(demo_scenario());
  const std::string text = plan_to_json(plan);
  EXPECT_EQ(plan_to_json(parse_plan(text)), text);
}

TEST(PlanFile, AnAgentThatLeavesSaysSo) {
  Scenario scenario;
  scenario.agents.push_back({"stays", {0, 0}, 0, {{3, 0}}});
  scenario.agents.push_back({"goes", {0, 2}, 0, {{3, 2}}, true});
  const Plan plan = plan_scenario(scenario);
  const std::string text = plan_to_json(plan);
  EXPECT_EQ(text.find("\"leaves\""), text.rfind("\"leaves\""));  // written once: for "goes"
  const Plan back = parse_plan(text);
  EXPECT_FALSE(back.agents[0].leaves);
  EXPECT_TRUE(back.agents[1].leaves);
  EXPECT_EQ(plan_to_json(back), text);
}

TEST(PlanFile, ReadsAHandWrittenPlanWithBehaviours) {
  const Plan plan = parse_plan(R"({"format": "footfall-plan", "version": 1, "agents": [{
    "name": "p", "status": "partial", "footsteps": [
      {"foot": "left", "start_time": 0, "end_time": 0.5, "foot_position": [0.3, 0.1], "foot_orientation": 0,
       "com_start": [0, 0], "com_end": [0.6, 0], "com_velocity_start": [1.2, 0.1], "com_velocity_end": [1.2, -0.1],
       "behavior": "side_step", "cost": 90},
      {"foot": "right", "start_time": 0.5, "end_time": 1.0, "foot_position": [0.9, -0.1], "foot_orientation": 0,
       "com_start": [0.6, 0], "com_end": [1.2, 0], "com_velocity_start": [1.2, -0.1], "com_velocity_end": [1.2, 0.1],
       "behavior": "arms_in", "cost": 90}]}]})");
  ASSERT_EQ(plan.agents.size(), 1u);
  const AgentPlan& agent = plan.agents[0];
  EXPECT_EQ(agent.footsteps[0].behavior, Behavior::kSideStep);
  EXPECT_EQ(agent.footsteps[1].behavior, Behavior::kArmsIn);
  EXPECT_DOUBLE_EQ(agent.footsteps[1].cost.total(), 90);
  EXPECT_EQ(agent.start.com, (Vec2{0, 0}));
  EXPECT_NEAR(com_at(agent, 0.75).position.x, 0.9, 0.05);
}

TEST(PlanFile, BadPlansAreNamedByField) {
  try {
    parse_plan(
        R"({"format": "footfall-plan", "version": 1, "agents": [{"name": "p", "status": "lost", "footsteps": []}]})",
        "p.json");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "p.json: agents[0].status: 'lost' is not one of \"reached\", \"partial\"");
  }
}

TEST(PlanFile, FailedWriteLeavesNothing) {
  const Plan plan = plan_scenario(demo_scenario());
  EXPECT_THROW(write_plan_file(plan, "/nonexistent-dir/plan.json"), Error);
  const auto path = std::filesystem::temp_directory_path() / "footfall-test-plan.json";
  write_plan_file(plan, path.string());
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".partial"));
  EXPECT_EQ(plan_to_json(load_plan(path.string())), plan_to_json(plan));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace footfall
