#include "bindings.hpp"
#include "footfall/model/params.hpp"

namespace py = pybind11;

namespace footfall::bindings {

void bind_params(py::module_& m) {
  py::class_<FootLimits>(m, "FootLimits",
                         "Limits on the steps of one foot (see params.hpp for units).")
      .def(py::init<>())
      .def_readwrite("min_step_duration", &FootLimits::min_step_duration)
      .def_readwrite("max_step_duration", &FootLimits::max_step_duration)
      .def_readwrite("min_step_length", &FootLimits::min_step_length)
      .def_readwrite("max_step_length", &FootLimits::max_step_length)
      .def_readwrite("min_speed", &FootLimits::min_speed)
      .def_readwrite("max_speed", &FootLimits::max_speed);

  py::class_<CharacterParams>(m, "CharacterParams",
                              "The walking character (see params.hpp for units and ranges).")
      .def(py::init<>())
      .def_readwrite("com_height", &CharacterParams::com_height)
      .def_readwrite("mass", &CharacterParams::mass)
      .def_readwrite("energy_rate", &CharacterParams::energy_rate)
      .def_readwrite("curvature_weight", &CharacterParams::curvature_weight)
      .def_readwrite("foot_offset", &CharacterParams::foot_offset)
      .def_readwrite("torso_width", &CharacterParams::torso_width)
      .def_readwrite("torso_radius", &CharacterParams::torso_radius)
      .def_readwrite("shoulder_radius", &CharacterParams::shoulder_radius)
      .def_readwrite("foot_radius", &CharacterParams::foot_radius)
      .def_readwrite("preferred_speed", &CharacterParams::preferred_speed)
      .def_readwrite("preferred_step_duration", &CharacterParams::preferred_step_duration)
      .def_readwrite("max_foot_turn", &CharacterParams::max_foot_turn)
      .def_readwrite("left", &CharacterParams::left)
      .def_readwrite("right", &CharacterParams::right);

  py::class_<Gait>(m, "Gait", "A desired speed [m/s] paired with a step duration [s].")
      .def(py::init<>())
      .def(py::init<double, double>(), py::arg("speed"), py::arg("duration"))
      .def_readwrite("speed", &Gait::speed)
      .def_readwrite("duration", &Gait::duration);

  py::class_<PlannerParams>(m, "PlannerParams",
                            "The footstep planner (see params.hpp for units and ranges).")
      .def(py::init<>())
      .def_readwrite("max_expansions", &PlannerParams::max_expansions)
      .def_readwrite("stall_expansions", &PlannerParams::stall_expansions)
      .def_readwrite("heuristic_weight", &PlannerParams::heuristic_weight)
      .def_readwrite("goal_tolerance", &PlannerParams::goal_tolerance)
      .def_readwrite("local_goal_distance", &PlannerParams::local_goal_distance)
      .def_readwrite("max_time", &PlannerParams::max_time)
      .def_readwrite("stop_duration", &PlannerParams::stop_duration)
      .def_readwrite("collision_sample_spacing", &PlannerParams::collision_sample_spacing)
      .def_readwrite("min_progress", &PlannerParams::min_progress)
      .def_readwrite("gaits", &PlannerParams::gaits)
      .def_readwrite("turn_angles", &PlannerParams::turn_angles);

  m.def(
      "validate", [](const CharacterParams& p) { validate(p); },
      "Raises ValueError naming the field and the limit it breaks.", py::arg("params"));
  m.def(
      "validate", [](const PlannerParams& p) { validate(p); },
      "Raises ValueError naming the field and the limit it breaks.", py::arg("params"));
}

}  // namespace footfall::bindings
