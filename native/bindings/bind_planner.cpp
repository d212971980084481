#include <array>
#include <limits>
#include <memory>
#include <optional>

#include <pybind11/numpy.h>

#include "bindings.hpp"
#include "footfall/crowd/crowd_planner.hpp"
#include "footfall/plan/plan.hpp"
#include "footfall/planner/planner.hpp"

namespace py = pybind11;

namespace footfall::bindings {

void bind_planner(py::module_& m) {
  py::class_<Obstacle>(m, "Obstacle",
                       "A polygon [m] extruded from a base to a height [m], or a triangle mesh.")
      .def(py::init<>())
      .def(py::init([](std::vector<Vec2> polygon, double height, double base) {
             Obstacle obstacle = prism(std::move(polygon), height, base);
             validate(obstacle, "Obstacle");
             return obstacle;
           }),
           py::arg("polygon"), py::arg("height") = 2.0, py::arg("base") = 0.0)
      .def_static(
          "from_mesh",
          [](const std::vector<std::array<double, 3>>& vertices,
             const std::vector<std::array<int, 3>>& triangles) {
            Obstacle obstacle;
            for (const auto& v : vertices) obstacle.mesh.vertices.push_back({v[0], v[1], v[2]});
            obstacle.mesh.triangles = triangles;
            validate(obstacle, "Obstacle");
            return obstacle;
          },
          "An obstacle of any shape: vertices [[x, y, z], ...] [m] and triangles [[i, j, k], "
          "...]. Raises ValueError for a bad index, a non-finite vertex or no triangles.",
          py::arg("vertices"), py::arg("triangles"))
      .def_readwrite("polygon", &Obstacle::polygon)
      .def_readwrite("height", &Obstacle::height)
      .def_readwrite("base", &Obstacle::base)
      .def_property_readonly("is_mesh", &Obstacle::is_mesh)
      .def_property_readonly(
          "mesh_vertices",
          [](const Obstacle& obstacle) {
            std::vector<std::array<double, 3>> vertices;
            vertices.reserve(obstacle.mesh.vertices.size());
            for (const Vec3& v : obstacle.mesh.vertices) vertices.push_back({v.x, v.y, v.z});
            return vertices;
          },
          "A mesh obstacle's vertices [[x, y, z], ...] [m] (empty for a prism).")
      .def_property_readonly(
          "mesh_triangles", [](const Obstacle& obstacle) { return obstacle.mesh.triangles; },
          "A mesh obstacle's triangles [[i, j, k], ...] (empty for a prism).");

  py::class_<ObstacleMap>(m, "ObstacleMap", "Static obstacles indexed for circle queries.")
      .def(py::init<std::vector<Obstacle>, double>(), py::arg("obstacles"),
           py::arg("cut_height") = std::numeric_limits<double>::infinity(),
           "Footprints of the parts of `obstacles` below `cut_height` [m] (all of them by default).")
      .def("first_overlap",
           py::overload_cast<const Circle&>(&ObstacleMap::first_overlap, py::const_),
           py::arg("circle"))
      .def("overlaps", &ObstacleMap::overlaps, py::arg("circle"))
      .def("contains", &ObstacleMap::contains, py::arg("index"), py::arg("point"))
      .def_property_readonly("obstacles", &ObstacleMap::obstacles);

  py::class_<SearchResult>(m, "SearchResult")
      .def_readonly("status", &SearchResult::status)
      .def_readonly("footsteps", &SearchResult::footsteps)
      .def_readonly("end_state", &SearchResult::end_state)
      .def_readonly("nodes_generated", &SearchResult::nodes_generated)
      .def_readonly("nodes_expanded", &SearchResult::nodes_expanded)
      .def_readonly("refused_by", &SearchResult::refused_by,
                    "Indices into `others` of the agents that turned down a step or a rest.");

  py::class_<FootstepPlanner>(m, "FootstepPlanner",
                              "The short-horizon best-first footstep planner.")
      .def(py::init<const CharacterParams&, const PlannerParams&, const ObstacleMap&>(),
           py::arg("character"), py::arg("planner"), py::arg("obstacles"),
           py::keep_alive<1, 4>())  // the planner refers to the obstacle map
      .def(
          "plan",
          [](const FootstepPlanner& planner, const FootstepState& start, Vec2 goal,
             const std::vector<const AgentPlan*>& others, bool leaves, const KeepOut& keep_out,
             double rest_grace) {
            return planner.plan(start, goal, {others.begin(), others.end()},
                                {leaves, keep_out, 0, rest_grace});
          },
          py::arg("start"), py::arg("goal"), py::arg("others") = std::vector<const AgentPlan*>{},
          py::arg("leaves") = false, py::arg("keep_out") = KeepOut{},
          py::arg("rest_grace") = std::numeric_limits<double>::infinity(),
          py::call_guard<py::gil_scoped_release>(),
          "Best-first search; `others`: agent plans to keep clear of as moving obstacles; "
          "`leaves`: the character is gone at the goal, so needs no room to rest there; "
          "`keep_out`: circles its rests keep out of (a way another agent waits to take); "
          "`rest_grace`: seconds a walking other stands where its plan ends (its rest is "
          "provisional); the steps are then cut before the first that runs into it. "
          "ValueError if negative.")
      .def("heuristic", &FootstepPlanner::heuristic, py::arg("state"), py::arg("goal"))
      .def("expected_step_cost", &FootstepPlanner::expected_step_cost)
      .def("expected_step_length", &FootstepPlanner::expected_step_length)
      .def(
          "collides",
          [](const FootstepPlanner& planner, const Footstep& step,
             const std::vector<const AgentPlan*>& others) {
            return planner.validity().collides(step, {others.begin(), others.end()});
          },
          py::arg("step"), py::arg("others") = std::vector<const AgentPlan*>{})
      .def(
          "collides",
          [](const FootstepPlanner& planner, const FootstepState& state) {
            return planner.validity().collides(state);
          },
          py::arg("state"));
  m.def(
      "choose_foot_orientations",
      [](std::vector<Footstep> steps, const std::array<OrientationInterval, 2>& initial,
         const CharacterParams& character) {
        choose_foot_orientations(steps, initial, character);
        return steps;
      },
      py::arg("steps"), py::arg("initial"), py::arg("character"),
      "Returns the steps with exact foot orientations (section 4's post-process).");
  m.def("reachable_orientations", &reachable_orientations, py::arg("interval"), py::arg("foot"),
        py::arg("max_foot_turn"));

  py::class_<AgentSpec>(
      m, "AgentSpec",
      "An agent to plan: name, position [m], facing [rad], goals [m], and whether "
      "it walks through its last goal and leaves there.")
      .def(py::init<>())
      .def(py::init([](std::string name, Vec2 position, double facing, std::vector<Vec2> goals,
                       bool leave_at_goal) {
             return AgentSpec{std::move(name), position, facing, std::move(goals), leave_at_goal};
           }),
           py::arg("name"), py::arg("position"), py::arg("facing"), py::arg("goals"),
           py::arg("leave_at_goal") = false)
      .def_readwrite("name", &AgentSpec::name)
      .def_readwrite("position", &AgentSpec::position)
      .def_readwrite("facing", &AgentSpec::facing)
      .def_readwrite("goals", &AgentSpec::goals)
      .def_readwrite("leave_at_goal", &AgentSpec::leave_at_goal)
      .def_readwrite("start_delay", &AgentSpec::start_delay,
                     "It stands still until this time [s], then sets off.")
      .def_readwrite("goal_wait", &AgentSpec::goal_wait,
                     "It stands this long [s] at each goal but the last.")
      .def_readwrite("end_facing", &AgentSpec::end_facing,
                     "The facing [rad] it turns to at its last goal, where it has room; None: as it arrives.")
      .def_readwrite("goal_facings", &AgentSpec::goal_facings,
                     "Per goal, the facing [rad] it turns to once it stands there, where it has room (None: "
                     "as it arrives): one per goal, or empty. The last goal's may be end_facing instead.")
      .def_readwrite("scale", &AgentSpec::scale,
                     "Its body's size as a share of the scenario's character, [0.5, 1.6] (set its "
                     "character to scaled() of it).")
      .def_readwrite("height", &AgentSpec::height,
                     "The height its position was given with [m] (None: the only ground under it).")
      .def_readwrite("goal_heights", &AgentSpec::goal_heights,
                     "Per goal, the height it was given with [m] (None: the only ground under it); "
                     "one per goal, or empty.")
      .def_readwrite("time_limit", &AgentSpec::time_limit,
                     "Its time budget [s]; 0: the planner's max_time or four times its route's "
                     "walking time, whichever is longer.")
      .def_property(
          "character",
          [](const AgentSpec& a) {
            return a.character ? std::optional<CharacterParams>(*a.character) : std::nullopt;
          },
          [](AgentSpec& a, const std::optional<CharacterParams>& character) {
            a.character = character ? std::make_shared<const CharacterParams>(*character) : nullptr;
          },
          "Its own character (a copy); None: the planner's.");

  py::enum_<AgentStatus>(m, "AgentStatus")
      .value("REACHED", AgentStatus::kReached)
      .value("PARTIAL", AgentStatus::kPartial);

  py::class_<Narrowest>(m, "Narrowest",
                        "Where the way to a goal an agent cannot reach is narrowest (its reason "
                        "'unreachable').")
      .def_readonly("at", &Narrowest::at, "The narrowest point (x, y) [m].")
      .def_readonly("width", &Narrowest::width,
                    "The way's free width there [m]; 0: no way leads there.")
      .def_readonly("needs", &Narrowest::needs, "The width its body needs with `behavior` [m].")
      .def_property_readonly(
          "behavior", [](const Narrowest& n) { return std::string(to_string(n.behavior)); },
          "Its narrowest behaviour: 'side_step'.")
      .def("__str__", &unreachable_text);

  py::class_<AgentPlan>(m, "AgentPlan", "One agent's timed footsteps.")
      .def_readonly("name", &AgentPlan::name)
      .def_readonly("status", &AgentPlan::status)
      .def_readonly("reason", &AgentPlan::reason)
      .def_readonly("narrowest", &AgentPlan::narrowest,
                    "With reason 'unreachable': where its way is too narrow (Narrowest); else "
                    "None.")
      .def_readonly("stuck_at", &AgentPlan::stuck_at)
      .def_readonly("start", &AgentPlan::start)
      .def_readonly("footsteps", &AgentPlan::footsteps)
      .def_readonly("goals_reached", &AgentPlan::goals_reached)
      .def_readonly("leaves", &AgentPlan::leaves)
      .def_readonly("scale", &AgentPlan::scale, "Its body's size as a share of the rig's.")
      .def_readonly("searches", &AgentPlan::searches)
      .def_readonly("nodes_generated", &AgentPlan::nodes_generated)
      .def_readonly("nodes_expanded", &AgentPlan::nodes_expanded)
      .def_readonly("sections", &AgentPlan::sections,
                    "The annotated way (BehaviorSection), joined end to end.")
      .def_property_readonly(
          "character",
          [](const AgentPlan& a) {
            return a.character ? std::optional<CharacterParams>(*a.character) : std::nullopt;
          },
          "The agent's own character (a copy); None: the plan's.")
      .def("total_cost", &AgentPlan::total_cost)
      .def("end_time", &AgentPlan::end_time);
  m.def(
      "plan_agent",
      [](const AgentSpec& agent, const FootstepPlanner& planner) {
        return plan_agent(agent, planner);
      },
      py::arg("agent"), py::arg("planner"), py::call_guard<py::gil_scoped_release>());

  py::class_<FootPose>(m, "FootPose")
      .def_readonly("position", &FootPose::position)
      .def_readonly("orientation", &FootPose::orientation)
      .def_readonly("lift", &FootPose::lift)
      .def_readonly("planted", &FootPose::planted);
  m.def("com_at", py::overload_cast<const AgentPlan&, double>(&com_at), py::arg("plan"),
        py::arg("t"));
  m.def("feet_at", &feet_at, py::arg("plan"), py::arg("t"), "Both feet at time t, [left, right].");
  m.def(
      "sample_motion",
      [](const AgentPlan& plan, const py::array_t<double, py::array::c_style | py::array::forcecast>& times) {
        const py::ssize_t count = times.size();
        py::array_t<double> com({count, py::ssize_t{2}}), feet({count, py::ssize_t{2}, py::ssize_t{2}});
        py::array_t<double> yaw({count, py::ssize_t{2}}), lift({count, py::ssize_t{2}});
        py::array_t<bool> planted({count, py::ssize_t{2}});
        auto c = com.mutable_unchecked<2>();
        auto f = feet.mutable_unchecked<3>();
        auto y = yaw.mutable_unchecked<2>();
        auto l = lift.mutable_unchecked<2>();
        auto p = planted.mutable_unchecked<2>();
        const double* t = times.data();
        {
          py::gil_scoped_release release;
          for (py::ssize_t i = 0; i < count; ++i) {
            const Vec2 at = com_at(plan, t[i]).position;
            c(i, 0) = at.x;
            c(i, 1) = at.y;
            const std::array<FootPose, 2> both = feet_at(plan, t[i]);
            for (py::ssize_t side = 0; side < 2; ++side) {
              const FootPose& foot = both[static_cast<std::size_t>(side)];
              f(i, side, 0) = foot.position.x;
              f(i, side, 1) = foot.position.y;
              y(i, side) = foot.orientation;
              l(i, side) = foot.lift;
              p(i, side) = foot.planted;
            }
          }
        }
        return py::make_tuple(com, feet, yaw, lift, planted);
      },
      py::arg("plan"), py::arg("times"),
      "com_at and feet_at at every one of `times` [s], as arrays: (com (n, 2), feet (n, 2, 2), "
      "their orientations (n, 2), lifts (n, 2), planted (n, 2)), feet [left, right].");
  m.def("facing_at", &facing_at, py::arg("plan"), py::arg("t"));
  m.def("collision_circles",
        py::overload_cast<const AgentPlan&, const CharacterParams&, double>(&collision_circles),
        py::arg("plan"), py::arg("character"), py::arg("t"));
}

}  // namespace footfall::bindings
