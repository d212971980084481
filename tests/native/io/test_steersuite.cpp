// SteerSuite test cases read as scenarios: the axis mapping, random regions,
// and every case of tests/data/steersuite.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "footfall/planner/planner.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/io/steersuite.hpp"
#include "oracle/oracle.hpp"

namespace footfall {
namespace {

const std::filesystem::path kCases = FOOTFALL_STEERSUITE_DIR;

std::string case_error(const std::string& text) {
  try {
    parse_steersuite(text, "case.xml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

std::string test_case(const std::string& body) {
  return "<SteerBenchTestCase xmlns=\"http://www.magix.ucla.edu/steerbench\">" + body +
         "</SteerBenchTestCase>";
}

const char* const kAgent =
    "<agent><name>A</name><initialConditions><radius>0.5</radius>"
    "<position><x>-10</x><y>0</y><z>1</z></position><direction><x>1</x><y>0</y><z>0</z></direction>"
    "</initialConditions><goalSequence><seekStaticTarget><targetLocation><x>15</x><y>0</y><z>2</z>"
    "</targetLocation></seekStaticTarget></goalSequence></agent>";

TEST(SteerSuite, MapsYUpToZUp) {
  const Scenario s = parse_steersuite(test_case(
      std::string("<obstacle><xmin>-20</xmin><xmax>20</xmax><ymin>0</ymin><ymax>1.5</ymax>"
                  "<zmin>3</zmin><zmax>5</zmax></obstacle>") +
      kAgent));
  ASSERT_EQ(s.agents.size(), 1u);
  EXPECT_EQ(s.agents[0].name, "A");
  EXPECT_EQ(s.agents[0].position, (Vec2{-10, -1}));  // (x, z) -> (x, -z)
  EXPECT_DOUBLE_EQ(s.agents[0].facing, 0.0);
  EXPECT_EQ(s.agents[0].goals.at(0), (Vec2{15, -2}));
  EXPECT_TRUE(s.agents[0].leave_at_goal);  // SteerSuite removes an agent at its goal
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_DOUBLE_EQ(s.obstacles[0].height, 1.5);
  const ObstacleMap map(s.obstacles);
  EXPECT_TRUE(map.contains(0, {0, -4}));
  EXPECT_FALSE(map.contains(0, {0, 4}));
}

TEST(SteerSuite, OrientedBoxesAndCirclesHoldTheirShapes) {
  const Scenario s = parse_steersuite(test_case(
      std::string(
          "<circleObstacle><radius>1</radius><height>1</height><position><x>5</x><y>0</y><z>5</z>"
          "</position></circleObstacle><orientedBoxObstacle><thetaY>90</thetaY><size><x>4</x><y>1</"
          "y>"
          "<z>1</z></size><position><x>-5</x><y>0</y><z>0</z></position></orientedBoxObstacle>") +
      kAgent));
  const ObstacleMap map(s.obstacles);
  for (int k = 0; k < 32; ++k) {  // the whole circle lies in its polygon
    EXPECT_TRUE(map.contains(0, Vec2{5, -5} + 0.999 * unit(k * 3.14159265358979 / 16)));
  }
  // Turned a quarter turn, the 4 x 1 box runs along y.
  EXPECT_TRUE(map.contains(1, {-5, 1.9}));
  EXPECT_FALSE(map.contains(1, {-6.9, 0}));
}

TEST(SteerSuite, EveryCaseLoadsOrIsRefusedByName) {
  if (!std::filesystem::is_directory(kCases)) GTEST_SKIP() << kCases << " is not there";
  int loaded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kCases)) {
    if (entry.path().extension() != ".xml") continue;
    SCOPED_TRACE(entry.path().filename().string());
    if (entry.path().filename() == "EXAMPLE.xml") {
      try {
        load_steersuite(entry.path().string());
        ADD_FAILURE() << "no error";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "agent 'Agent A' (agent[4]): goal type 'fleeDynamicTarget' is not supported"),
                  std::string::npos)
            << e.what();
      }
      continue;
    }
    const Scenario scenario = load_steersuite(entry.path().string());
    EXPECT_FALSE(scenario.agents.empty());
    ++loaded;
  }
  EXPECT_EQ(loaded, 27);  // every case but EXAMPLE.xml
}

TEST(SteerSuite, GoalDurationsAreTheAgentsTimeBudget) {
  // 3-squeeze: 1000 s for each agent's one goal; circle-20 gives 3e33 s, capped.
  for (const AgentSpec& agent : load_steersuite((kCases / "3-squeeze.xml").string()).agents)
    EXPECT_DOUBLE_EQ(agent.time_limit, 1000.0 * static_cast<double>(agent.goals.size()));
  for (const AgentSpec& agent : load_steersuite((kCases / "circle-20.xml").string()).agents)
    EXPECT_DOUBLE_EQ(agent.time_limit, kMaxTimeLimit);
  EXPECT_DOUBLE_EQ(parse_steersuite(test_case(kAgent), "case.xml").agents[0].time_limit, 0.0);
  std::string timed = kAgent;
  timed.insert(timed.find("</seekStaticTarget>"), "<timeDuration>-5</timeDuration>");
  EXPECT_NE(case_error(test_case(timed)).find("timeDuration: must be positive"), std::string::npos)
      << case_error(test_case(timed));
}

TEST(SteerSuite, RandomRegionsAreSeededAndFree) {
  if (!std::filesystem::is_directory(kCases)) GTEST_SKIP() << kCases << " is not there";
  const std::string path = (kCases / "bottleneck-evacuation.xml").string();
  const Scenario a = load_steersuite(path, 7), b = load_steersuite(path, 7),
                 c = load_steersuite(path, 8);
  ASSERT_EQ(a.agents.size(), 200u);
  bool differs = false;
  for (size_t i = 0; i < a.agents.size(); ++i) {
    EXPECT_EQ(a.agents[i].position, b.agents[i].position);
    differs = differs || !(a.agents[i].position == c.agents[i].position);
  }
  EXPECT_TRUE(differs);
  const ObstacleMap map(a.obstacles);
  const FootstepPlanner planner(a.character, a.planner, map);
  for (size_t i = 0; i < a.agents.size(); ++i) {
    EXPECT_FALSE(
        planner.validity().collides(standing_state(a.agents[i].position, a.agents[i].facing, a.character)));
    for (size_t j = 0; j < i; ++j)
      EXPECT_GE(distance(a.agents[i].position, a.agents[j].position), 1.0);
  }
}

// Random agents among random trees (as SteerSuite's forest, denser): each
// stands free to set off. In forest, one placed facing a tree 0.17 m ahead
// took no step in 363 s.
TEST(SteerSuite, RandomAgentsAmongTreesCanSetOff) {
  const std::string region =
      "<regionBounds><xmin>-15</xmin><xmax>15</xmax><ymin>0</ymin><ymax>0</ymax>"
      "<zmin>-15</zmin><zmax>15</zmax></regionBounds>";
  const std::string text = test_case(
      "<obstacleRegion><numObstacles>250</numObstacles>" + region +
      "<obstacleSize>0.98</obstacleSize><obstacleHeight>1.0</obstacleHeight></obstacleRegion>"
      "<agentRegion><numAgents>200</numAgents>" + region +
      "<initialConditions><direction><random>true</random></direction><radius>0.5</radius>"
      "<speed>0</speed></initialConditions><goalSequence><seekStaticTarget><targetLocation>"
      "<random>true</random></targetLocation></seekStaticTarget></goalSequence></agentRegion>");
  const Scenario scenario = parse_steersuite(text);
  ASSERT_EQ(scenario.agents.size(), 200u);
  const ObstacleMap map(scenario.obstacles);
  const FootstepPlanner planner(scenario.character, scenario.planner, map);
  for (const AgentSpec& agent : scenario.agents)
    EXPECT_TRUE(planner.validity().free_to_set_off(
        standing_state(agent.position, agent.facing, scenario.character)))
        << agent.name << " at " << agent.position.x << ", " << agent.position.y;
}

TEST(SteerSuite, BadInputIsNamed) {
  EXPECT_EQ(case_error("<SteerBenchTestCase><agent>"),
            "case.xml: not valid XML: Start-end tags mismatch at line 1, column 27");
  EXPECT_EQ(case_error("<other/>"),
            "case.xml: not a SteerSuite test case (no SteerBenchTestCase element)");
  std::string bad = kAgent;
  bad.replace(bad.find("<x>-10</x>"), 10, "<x>abc</x>");
  EXPECT_EQ(case_error(test_case(bad)),
            "case.xml: agent 'A' (agent[0]): initialConditions.position.x: expected a number, got "
            "'abc'");
  EXPECT_EQ(case_error(test_case("<sphere/>")),
            "case.xml: sphere[0]: not an element of a SteerSuite test case");
  std::string flee = kAgent;
  flee.replace(flee.find("seekStaticTarget"), 16, "seekDynamicTarget");
  flee.replace(flee.rfind("seekStaticTarget"), 16, "seekDynamicTarget");
  EXPECT_EQ(case_error(test_case(flee)),
            "case.xml: agent 'A' (agent[0]): goal type 'seekDynamicTarget' is not supported (only "
            "seekStaticTarget)");
}

}  // namespace
}  // namespace footfall
