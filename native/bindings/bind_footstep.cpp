#include "bindings.hpp"
#include "footfall/model/footstep.hpp"
#include "footfall/model/status.hpp"

namespace py = pybind11;

namespace footfall::bindings {

void bind_footstep(py::module_& m) {
  py::enum_<Foot>(m, "Foot").value("LEFT", Foot::kLeft).value("RIGHT", Foot::kRight);
  py::enum_<StepKind>(m, "StepKind")
      .value("WALK", StepKind::kWalk)
      .value("STOP", StepKind::kStop)
      .value("SIDE_STEP", StepKind::kSideStep)
      .value("START", StepKind::kStart);
  py::enum_<Behavior>(m, "Behavior")
      .value("WALK", Behavior::kWalk)
      .value("ARMS_IN", Behavior::kArmsIn)
      .value("SIDE_STEP", Behavior::kSideStep);
  py::enum_<Status>(m, "Status")
      .value("SUCCESS", Status::kSuccess)
      .value("PARTIAL", Status::kPartial)
      .value("NO_PATH", Status::kNoPath)
      .value("INVALID_START", Status::kInvalidStart)
      .value("INVALID_GOAL", Status::kInvalidGoal)
      .value("CANCELLED", Status::kCancelled);
  py::enum_<StepValidity>(m, "StepValidity")
      .value("VALID", StepValidity::kValid)
      .value("WRONG_FOOT", StepValidity::kWrongFoot)
      .value("NOT_STANDING", StepValidity::kNotStanding)
      .value("NOT_AN_ACTION", StepValidity::kNotAnAction)
      .value("NO_SWING", StepValidity::kNoSwing)
      .value("DURATION_OUT_OF_RANGE", StepValidity::kDurationOutOfRange)
      .value("SPEED_OUT_OF_RANGE", StepValidity::kSpeedOutOfRange)
      .value("LENGTH_OUT_OF_RANGE", StepValidity::kLengthOutOfRange)
      .value("NOT_POSITIVE", StepValidity::kNotPositive)
      .value("ORIENTATION_EMPTY", StepValidity::kOrientationEmpty)
      .value("NOT_FINITE", StepValidity::kNotFinite)
      .value("COLLIDES", StepValidity::kCollides);

  py::class_<Circle>(m, "Circle")
      .def(py::init<>())
      .def(py::init<Vec2, double>(), py::arg("center"), py::arg("radius"))
      .def_readwrite("center", &Circle::center)
      .def_readwrite("radius", &Circle::radius);

  py::class_<OrientationInterval>(m, "OrientationInterval",
                                  "Valid foot orientations [rad], inner to outer.")
      .def(py::init<>())
      .def(py::init<double, double>(), py::arg("inner"), py::arg("outer"))
      .def_readwrite("inner", &OrientationInterval::inner)
      .def_readwrite("outer", &OrientationInterval::outer);

  py::class_<FootstepState>(m, "FootstepState", "The character at the end of a step.")
      .def(py::init<>())
      .def_readwrite("com", &FootstepState::com)
      .def_readwrite("com_velocity", &FootstepState::com_velocity)
      .def_readwrite("last_foot", &FootstepState::last_foot)
      .def_readwrite("feet", &FootstepState::feet)
      .def_readwrite("foot_orientation", &FootstepState::foot_orientation)
      .def_readwrite("facing", &FootstepState::facing)
      .def_readwrite("time", &FootstepState::time)
      .def_readwrite("before_first_step", &FootstepState::before_first_step)
      .def("standing", &FootstepState::standing);
  m.def("standing_state", &standing_state, py::arg("position"), py::arg("facing"),
        py::arg("character"));

  py::class_<FootstepAction>(m, "FootstepAction",
                             "Parabola orientation phi [rad], speed [m/s], duration [s].")
      .def(py::init([](StepKind kind, Foot foot, double phi, double speed, double duration) {
             return FootstepAction{kind, foot, phi, speed, duration};
           }),
           py::arg("kind") = StepKind::kWalk, py::arg("foot") = Foot::kLeft, py::arg("phi") = 0.0,
           py::arg("speed") = 1.3, py::arg("duration") = 0.5)
      .def_readwrite("kind", &FootstepAction::kind)
      .def_readwrite("foot", &FootstepAction::foot)
      .def_readwrite("phi", &FootstepAction::phi)
      .def_readwrite("speed", &FootstepAction::speed)
      .def_readwrite("duration", &FootstepAction::duration);

  py::class_<StepCost>(m, "StepCost", "The energy terms of a step [J].")
      .def_readonly("fixed_rate", &StepCost::fixed_rate)
      .def_readonly("speed_change", &StepCost::speed_change)
      .def_readonly("curvature", &StepCost::curvature)
      .def("total", &StepCost::total);

  py::class_<Footstep>(m, "Footstep", "One timed footstep.")
      .def_readonly("foot", &Footstep::foot)
      .def_readonly("kind", &Footstep::kind)
      .def_readonly("behavior", &Footstep::behavior)
      .def_readonly("start_time", &Footstep::start_time)
      .def_readonly("end_time", &Footstep::end_time)
      .def_readonly("foot_position", &Footstep::foot_position)
      .def_readonly("foot_height", &Footstep::foot_height,
                    "Height of the ground under the planted foot; 0 on flat ground [m].")
      .def_readonly("orientation_interval", &Footstep::orientation_interval)
      .def_readonly("foot_orientation", &Footstep::foot_orientation)
      .def_readonly("com_start", &Footstep::com_start)
      .def_readonly("com_end", &Footstep::com_end)
      .def_readonly("com_velocity_start", &Footstep::com_velocity_start)
      .def_readonly("com_velocity_end", &Footstep::com_velocity_end)
      .def_readonly("phi", &Footstep::phi)
      .def_readonly("speed", &Footstep::speed)
      .def_readonly("alpha", &Footstep::alpha)
      .def_readonly("cost", &Footstep::cost)
      .def("duration", &Footstep::duration);

  py::class_<StepResult>(m, "StepResult")
      .def_readonly("validity", &StepResult::validity)
      .def_readonly("step", &StepResult::step)
      .def_readonly("state", &StepResult::state)
      .def("valid", &StepResult::valid);
  m.def("create_footstep", &create_footstep, py::arg("state"), py::arg("action"),
        py::arg("character"), "createFootstep(s, a) of the paper, or the stop action.");

  py::class_<ComSample>(m, "ComSample")
      .def_readonly("position", &ComSample::position)
      .def_readonly("velocity", &ComSample::velocity);
  m.def("com_at", py::overload_cast<const Footstep&, double>(&com_at), py::arg("step"),
        py::arg("t"), "COM position and velocity of a step at absolute time t.");
  m.def("torso_circles", &torso_circles, py::arg("com"), py::arg("facing"), py::arg("character"),
        py::arg("pad") = 0.0, py::arg("behavior") = Behavior::kWalk,
        "The torso circles (centre, left and right shoulder); with the arms in, the shoulders "
        "come in to shoulder_width.");
}

}  // namespace footfall::bindings
