// The parameter structs in Python: one attribute per field of their tables
// (model/params.hpp), with the table's unit, range and meaning as its doc.
#include <sstream>
#include <type_traits>

#include "bindings.hpp"
#include "footfall/model/params.hpp"
#include "footfall/model/param_docs.hpp"

namespace py = pybind11;

namespace footfall::bindings {
namespace {

template <class S>
void bind_fields(py::class_<S>& cls) {
  for_each_param<S>([&](const auto& field) {
    const std::string doc = describe_param(field);
    cls.def_readwrite(field.name, field.member, doc.c_str());
  });
}

}  // namespace

void bind_params(py::module_& m) {
  py::class_<FootLimits> foot_limits(m, "FootLimits",
                                     "Limits on the steps of one foot (docs/parameters.md).");
  foot_limits.def(py::init<>());
  bind_fields(foot_limits);

  py::class_<CharacterParams> character(
      m, "CharacterParams", "The walking character (docs/parameters.md for units and ranges).");
  character.def(py::init<>());
  bind_fields(character);

  py::class_<Gait> gait(m, "Gait", "A desired speed [m/s] paired with a step duration [s].");
  gait.def(py::init<>()).def(py::init<double, double>(), py::arg("speed"), py::arg("duration"));
  bind_fields(gait);

  py::class_<PlannerParams> planner(
      m, "PlannerParams", "The footstep planner (docs/parameters.md for units and ranges).");
  planner.def(py::init<>());
  bind_fields(planner);

  m.def(
      "validate", [](const CharacterParams& p) { validate(p); },
      "Raises ValueError naming the field and the limit it breaks.", py::arg("params"));
  m.def(
      "validate", [](const PlannerParams& p) { validate(p); },
      "Raises ValueError naming the field and the limit it breaks.", py::arg("params"));
  m.attr("MOST_SPEED") = kMostSpeed;
  m.attr("SCALE_RANGE") = py::make_tuple(kLeastScale, kMostScale);
  m.def("parameter_docs", &parameter_docs,
        "docs/parameters.md as the parameter tables give it: every field of every parameter "
        "struct with its unit, valid range, default and meaning.");
}

}  // namespace footfall::bindings
