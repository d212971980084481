// The full-body planner in Python: a scenario's annotated paths, and the
// body model's clearances.
#include "bindings.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/fullbody/behavioral_planner.hpp"
#include "footfall/fullbody/body_check.hpp"
#include "footfall/fullbody/body_sweep.hpp"
#include "footfall/scenes/behavior_scenes.hpp"

namespace py = pybind11;

namespace footfall::bindings {
namespace {

Behavior behavior_named(const std::string& name) {
  for (Behavior b : {Behavior::kWalk, Behavior::kArmsIn, Behavior::kSideStep})
    if (name == to_string(b)) return b;
  throw std::invalid_argument("behavior: expected walk, arms_in or side_step, got \"" + name +
                              "\"");
}

// The scenario's navigation mesh, once the scenario is known to be valid.
NavMesh checked_mesh(const Scenario& scenario) {
  validate(scenario);
  return navmesh_of(scenario);
}

// Everything a query needs, built once from a scenario.
struct ScenarioBehaviors {
  explicit ScenarioBehaviors(const Scenario& scenario)
      : params(scenario.planner),
        mesh(checked_mesh(scenario)),
        scene(scenario.obstacles),
        body(scenario.character),
        planner(mesh, scene, body, params) {}
  PlannerParams params;
  NavMesh mesh;
  CollisionScene scene;
  BodyModel body;
  BehavioralPlanner planner;
};

}  // namespace

void bind_fullbody(py::module_& m) {
  py::enum_<BehaviorPathStatus>(m, "BehaviorPathStatus")
      .value("found", BehaviorPathStatus::kFound)
      .value("horizon", BehaviorPathStatus::kHorizon)
      .value("time_limit", BehaviorPathStatus::kTimeLimit)
      .value("no_path", BehaviorPathStatus::kNoPath)
      .value("start_blocked", BehaviorPathStatus::kStartBlocked)
      .value("goal_blocked", BehaviorPathStatus::kGoalBlocked)
      .value("outside", BehaviorPathStatus::kOutside);

  py::class_<BehaviorSection>(m, "BehaviorSection", "One section of an annotated path.")
      .def_property_readonly("behavior",
                             [](const BehaviorSection& s) { return to_string(s.behavior); })
      .def_readonly("clearance", &BehaviorSection::clearance)
      .def_readonly("points", &BehaviorSection::points)
      .def_readonly("length", &BehaviorSection::length);

  py::class_<BehaviorPath>(m, "BehaviorPath", "An annotated path (docs/full-body.md).")
      .def_property_readonly("status", [](const BehaviorPath& p) { return to_string(p.status); })
      .def_readonly("sections", &BehaviorPath::sections)
      .def_readonly("length", &BehaviorPath::length)
      .def_readonly("min_clearance", &BehaviorPath::min_clearance)
      .def_readonly("point_obstacles", &BehaviorPath::point_obstacles)
      .def_readonly("poses_tested", &BehaviorPath::poses_tested)
      .def_readonly("path_queries", &BehaviorPath::path_queries)
      .def_readonly("reason", &BehaviorPath::reason);

  py::class_<ScenarioBehaviors>(
      m, "BehavioralPlanner",
      "The full-body behavioural planner on a scenario's obstacles, character and planner "
      "parameters (ValueError for a bad scenario). One query at a time per planner: a query "
      "puts point obstacles into its navigation mesh and takes them out again.")
      .def(py::init<const Scenario&>(), py::arg("scenario"))
      .def(
          "plan",
          [](ScenarioBehaviors& s, Vec2 from, Vec2 to) { return s.planner.plan(from, to); },
          py::arg("start"), py::arg("goal"), py::call_guard<py::gil_scoped_release>(),
          "The annotated path from start to goal: sections of walk, arms_in and side_step.")
      .def(
          "clearance",
          [](const ScenarioBehaviors& s, const std::string& behavior) {
            return s.body.clearance(behavior_named(behavior));
          },
          py::arg("behavior"), "The clearance the planner keeps for a behaviour [m].")
      .def(
          "test_collision",
          [](const ScenarioBehaviors& s, const std::vector<Vec2>& points,
             const std::string& behavior) -> py::object {
            if (points.size() < 2) throw std::invalid_argument("points: needs at least 2");
            const BodyCollision hit = sweep_body(s.scene, s.body, behavior_named(behavior),
                                                 points, s.params.pose_rate);
            if (!hit.hit) return py::none();
            py::dict d;
            d["limb"] = to_string(static_cast<Limb>(hit.contact.limb));
            d["point"] = py::make_tuple(hit.contact.point.x, hit.contact.point.y,
                                        hit.contact.point.z);
            d["root"] = hit.root;
            d["time"] = hit.time;
            d["along"] = hit.along;
            d["obstacle"] = hit.contact.obstacle;
            return d;
          },
          py::arg("points"), py::arg("behavior"),
          "TESTCOLLISION: the first pose of the behaviour along the points that meets an "
          "obstacle, as {limb, point, root, time, along, obstacle}, or None.");

  py::class_<AgentBodyCheck>(m, "AgentBodyCheck", "One agent's full-body check.")
      .def_readonly("poses", &AgentBodyCheck::poses)
      .def_readonly("penetrations", &AgentBodyCheck::penetrations)
      .def_readonly("deepest", &AgentBodyCheck::deepest);
  py::class_<BodyCheck>(m, "BodyCheck", "A plan's full-body check (body_check.hpp).")
      .def_readonly("agents", &BodyCheck::agents)
      .def_readonly("poses", &BodyCheck::poses)
      .def_readonly("penetrations", &BodyCheck::penetrations)
      .def_readonly("deepest", &BodyCheck::deepest);
  m.def("check_body", &check_body, py::arg("plan"), py::arg("pose_rate") = 30.0,
        py::call_guard<py::gil_scoped_release>(),
        "Sweeps every agent's body, in each step's behaviour and phase, along its planned COM "
        "path: the poses with a limb deeper than 1 mm in an obstacle, and the deepest.");

  m.def(
      "behavior_scene",
      [](const std::string& name) {
        BehaviorScene scene = behavior_scene(name);
        return py::make_tuple(scene.scenario, scene.start, scene.goals);
      },
      py::arg("name"),
      "A built-in scene of the full-body planner as (scenario, start, goals): "
      "door, corridor, gap, open_field, random_{normal,dense}_{6,10}.");
}

}  // namespace footfall::bindings
