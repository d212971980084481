#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/io/plan_file.hpp"
#include "footfall/io/scenario_file.hpp"
#include "footfall/io/steersuite.hpp"
#include "footfall/plan/metrics.hpp"
#include "footfall/plan/motion_check.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/scenes/scenes.hpp"

namespace py = pybind11;

namespace footfall::bindings {
namespace {

// A flag that another Python thread sets to stop a running plan_scenario.
struct CancelFlag {
  std::atomic<bool> flag{false};
};

// Runs `run` (plan_scenario or replan_agents) without the GIL; the progress
// callback takes it back. An exception raised by the callback cancels the
// run and is re-raised.
Plan plan_with_callbacks(const std::function<Plan(const RunControl&)>& run,
                         const py::object& progress, CancelFlag* cancel, int threads) {
  CancelFlag own;
  CancelFlag& flag = cancel != nullptr ? *cancel : own;
  std::optional<py::error_already_set> error;
  RunControl control;
  control.cancel = &flag.flag;
  control.threads = threads;
  if (!progress.is_none()) {
    control.progress = [&](double fraction) {
      py::gil_scoped_acquire gil;
      if (error) return;
      try {
        progress(fraction);
      } catch (py::error_already_set& e) {
        error.emplace(std::move(e));
        flag.flag = true;
      }
    };
  }
  Plan plan;
  {
    py::gil_scoped_release release;
    plan = run(control);
  }
  if (error) throw *error;
  return plan;
}

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<Scenario>(m, "Scenario", "Obstacles, agents and parameters: plain data.")
      .def(py::init<>())
      .def_readwrite("obstacles", &Scenario::obstacles)
      .def_readwrite("ground", &Scenario::ground,
                     "The walkable ground (prisms and meshes, as obstacles); empty: z = 0.")
      .def_readwrite("agents", &Scenario::agents)
      .def_readwrite("character", &Scenario::character)
      .def_readwrite("planner", &Scenario::planner);
  py::class_<Ground>(m, "Ground", "A scenario's or a plan's ground, indexed (ground/ground.hpp): build it once.")
      .def(py::init<std::vector<GroundSurface>>(), py::arg("surfaces"))
      .def("empty", &Ground::empty, "True without ground: the plane z = 0 is the floor.")
      .def(
          "standing_height",
          [](const Ground& ground, double x, double y, double headroom,
             std::optional<double> near) -> std::optional<double> {
            const auto point = near ? ground.standable_near({x, y}, *near, headroom)
                                    : ground.standing_on({x, y}, headroom);
            if (point) return point->z;
            return std::nullopt;
          },
          py::arg("x"), py::arg("y"), py::arg("headroom"), py::arg("near") = py::none(),
          "The height of the ground a body `headroom` tall stands on at (x, y) [m]: of its levels "
          "(a street and a bridge's deck over it), the nearest `near` [m] where given, else the "
          "lowest; None where there is none.")
      .def(
          "standing_problem",
          [](const Ground& ground, const CharacterParams& character, double x, double y, double facing,
             std::optional<double> height) {
            return standing_problem(ground, character, {x, y}, facing, height);
          },
          py::arg("character"), py::arg("x"), py::arg("y"), py::arg("facing"), py::arg("height") = py::none(),
          "Why a body of `character` cannot stand at (x, y) facing `facing` [rad] (at `height` [m], where "
          "given), as a scenario's agent would be refused; None if it can.");
  m.def("validate", py::overload_cast<const Scenario&>(&validate), py::arg("scenario"),
        "Raises ValueError with the field path of the first problem.");
  m.def("parse_scenario", &parse_scenario, py::arg("text"), py::arg("source") = "<string>",
        "Parses and validates scenario JSON; ValueError 'SOURCE: FIELD.PATH: problem'.");
  m.def("load_scenario", &load_scenario, py::arg("path"));
  m.def("parse_steersuite", &parse_steersuite, py::arg("text"), py::arg("source") = "<string>",
        py::arg("seed") = 1, "Reads a SteerSuite test case (XML, Y-up) as a scenario.");
  m.def("load_steersuite", &load_steersuite, py::arg("path"), py::arg("seed") = 1);
  m.def("load_scenario_file", &load_scenario_file, py::arg("path"),
        "A scenario file of either kind: SteerSuite XML for .xml, Footfall JSON otherwise.");
  m.def("demo_scenario", &demo_scenario, "The built-in demo: a doorway into a cluttered room, and two narrow gaps (arms in, side step).");
  m.def("box_obstacle", &box_obstacle, py::arg("center"), py::arg("size"), py::arg("height") = 1.0);
  m.def("wall_with_door", &wall_with_door, py::arg("x"), py::arg("door_width"),
        py::arg("door_center") = 0.0, py::arg("half_length") = 6.0, py::arg("thickness") = 0.2);
  m.def("city_scenario", &city_scenario, py::arg("agents"), py::arg("size"), py::arg("seed"),
        "A busy city: agents crossing a grid of 6 m blocks and 4 m streets of side `size`.");

  py::class_<CancelFlag>(m, "CancelFlag", "Set it from another thread to stop plan_scenario.")
      .def(py::init<>())
      .def("set", [](CancelFlag& c) { c.flag = true; })
      .def("is_set", [](const CancelFlag& c) { return c.flag.load(); });

  py::class_<Plan>(m, "Plan", "Every agent's footsteps.")
      .def_readonly("agents", &Plan::agents)
      .def_readonly("character", &Plan::character)
      .def_readonly("ground", &Plan::ground)
      .def_readonly("status", &Plan::status);
  m.def(
      "plan_scenario",
      [](const Scenario& scenario, const py::object& progress, CancelFlag* cancel, int threads) {
        return plan_with_callbacks([&](const RunControl& c) { return plan_scenario(scenario, c); },
                                   progress, cancel, threads);
      },
      py::arg("scenario"), py::arg("progress") = py::none(), py::arg("cancel") = nullptr,
      py::arg("threads") = 1,
      "Plans every agent together, without holding the GIL, on `threads` threads (1-64; the "
      "plan is the same for any number). progress(fraction) is called at most a few times a "
      "second; a set CancelFlag stops the run (status CANCELLED).");
  m.def(
      "replan_agents",
      [](const Scenario& scenario, const Plan& fixed, const std::vector<std::string>& names,
         const py::object& progress, CancelFlag* cancel, int threads) {
        return plan_with_callbacks(
            [&](const RunControl& c) { return replan_agents(scenario, fixed, names, c); }, progress,
            cancel, threads);
      },
      py::arg("scenario"), py::arg("fixed"), py::arg("names"), py::arg("progress") = py::none(),
      py::arg("cancel") = nullptr, py::arg("threads") = 1,
      "Plans the agents named again among the others, which keep their plans in `fixed` (by "
      "name); the plan lists every agent of the scenario. ValueError 'agents: ...' or 'fixed: "
      "...' for no names, an unknown name, or an agent neither named nor in `fixed`. Otherwise "
      "as plan_scenario.");
  m.def("plan_to_json", &plan_to_json, py::arg("plan"));

  py::class_<AgentMetrics>(m, "AgentMetrics", "One agent's figures (see metrics.hpp).")
      .def_readonly("name", &AgentMetrics::name)
      .def_readonly("reached", &AgentMetrics::reached)
      .def_readonly("time", &AgentMetrics::time)
      .def_readonly("path_length", &AgentMetrics::path_length)
      .def_readonly("effort", &AgentMetrics::effort)
      .def_readonly("overlaps", &AgentMetrics::overlaps)
      .def_readonly("collision_episodes", &AgentMetrics::collision_episodes)
      .def_readonly("energy", &AgentMetrics::energy)
      .def_readonly("acceleration", &AgentMetrics::acceleration);
  py::class_<PlanMetrics>(m, "PlanMetrics", "A plan's figures, SteerBench's composites among them.")
      .def_readonly("agents", &PlanMetrics::agents)
      .def_readonly("rate", &PlanMetrics::rate)
      .def_readonly("composite01", &PlanMetrics::composite01)
      .def_readonly("composite02", &PlanMetrics::composite02)
      .def_readonly("overlaps", &PlanMetrics::overlaps);
  m.def("measure_plan", &measure_plan, py::arg("plan"), py::arg("rate") = 20.0,
        py::call_guard<py::gil_scoped_release>(),
        "Our figures and SteerBench's, sampled at `rate` Hz.");
  py::class_<MotionCheck>(m, "MotionCheck", "How smoothly one agent's plan moves.")
      .def_readonly("velocity_jump", &MotionCheck::velocity_jump)
      .def_readonly("top_speed", &MotionCheck::top_speed)
      .def_readonly("stance_slide", &MotionCheck::stance_slide)
      .def_readonly("worst_jump_step", &MotionCheck::worst_jump_step)
      .def_readonly("worst_slide_step", &MotionCheck::worst_slide_step);
  m.def("check_motion", &check_motion, py::arg("agent"), py::arg("rate") = 500.0,
        py::call_guard<py::gil_scoped_release>(),
        "Velocity jumps at step boundaries, top COM speed and stance-foot slide of one agent's plan.");
  m.def("parse_plan", &parse_plan, py::arg("text"), py::arg("source") = "<string>");
  m.def("load_plan", &load_plan, py::arg("path"));
  m.def("write_plan_file", &write_plan_file, py::arg("plan"), py::arg("path"),
        "Writes atomically: a failure leaves no half-written file.");
}

}  // namespace footfall::bindings
