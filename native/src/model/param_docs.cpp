// Footfall — docs/parameters.md, written from the parameter tables.
#include "footfall/model/param_docs.hpp"

#include <cmath>
#include <sstream>
#include <type_traits>

#include "footfall/model/params.hpp"

namespace footfall {
namespace {

// A number as the docs write it: pi and pi/2 by name, else 10 digits at most.
std::string number_text(double value) {
  if (value == 3.141592653589793) return "pi";
  if (value == 1.5707963267948966) return "pi/2";
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

std::string bound_text(const ParamBound& bound) {
  if (bound.field == nullptr) return number_text(bound.value);
  if (bound.value == 1.0) return bound.field;
  if (bound.value == 0.5) return std::string(bound.field) + " / 2";
  return number_text(bound.value) + " * " + bound.field;
}

// One row per field: name, unit, range, default, meaning.
template <class S>
struct RowWriter {
  std::ostringstream& out;
  S defaults{};

  template <class T>
  void operator()(const ScalarParam<S, T>& field) {
    row(field.name, field.unit, range_text(field.range), number_text(defaults.*field.member),
        field.doc);
  }
  template <class N>
  void operator()(const NestedParam<S, N>& field) {
    row(field.name, "", ParamTable<N>::name, "", field.doc);
  }
  void operator()(const NumberListParam<S>& field) {
    std::string values;
    for (const double value : defaults.*field.member)
      values += (values.empty() ? "" : ", ") + number_text(value);
    row(field.name, field.unit,
        std::to_string(field.min_count) + " to " + std::to_string(field.max_count) +
            ", each in " + range_text(field.range),
        values, field.doc);
  }
  template <class E>
  void operator()(const StructListParam<S, E>& field) {
    std::string values;
    for (const E& element : defaults.*field.member) {
      std::string item;
      for_each_param<E>([&](const auto& f) {
        if constexpr (std::is_arithmetic_v<std::decay_t<decltype(element.*f.member)>>)
          item += (item.empty() ? "" : ", ") + number_text(element.*f.member);
      });
      values += (values.empty() ? "(" : "; (") + item + ")";
    }
    row(field.name, "",
        std::to_string(field.min_count) + " to " + std::to_string(field.max_count) + " " +
            ParamTable<E>::name,
        values, field.doc);
  }

  void row(const std::string& name, const std::string& unit, const std::string& range,
           const std::string& value, const std::string& doc) {
    out << "| `" << name << "` | " << unit << " | " << range << " | " << value << " | " << doc
        << " |\n";
  }
};

template <class S>
void write_table(std::ostringstream& out, const char* intro) {
  out << "\n## " << ParamTable<S>::name << "\n\n" << intro << "\n\n"
      << "| field | unit | valid range | default | meaning |\n"
      << "|---|---|---|---|---|\n";
  for_each_param<S>(RowWriter<S>{out});
}

}  // namespace

std::string range_text(const ParamRange& range) {
  std::string text = (range.low.open ? "(" : "[") + bound_text(range.low) + ", " +
                     bound_text(range.high) + (range.high.open ? ")" : "]");
  if (range.below_field != nullptr) text += ", < " + std::string(range.below_field);
  return text;
}

std::string parameter_docs() {
  std::ostringstream out;
  out << "# Parameters\n\n"
         "Every parameter of the character and the planner, with its unit, valid range and\n"
         "default. Scenario files set them under `\"character\"` and `\"planner\"`\n"
         "(docs/file-formats.md); Python has them as attributes of the classes of the same\n"
         "names. A value outside its range is refused with the field's path and the limit.\n\n"
         "This page is written from the parameter tables in\n"
         "`native/include/footfall/model/params.hpp` (`footfall._native.parameter_docs()`);\n"
         "a test keeps the two the same.\n";
  write_table<CharacterParams>(out, "The walking character: pendulum, energy and collision "
                                    "model (`\"character\"`).");
  write_table<FootLimits>(out, "Limits on the steps of one foot: `character.left` and "
                               "`character.right` (flat keys in a file set both feet).");
  write_table<PlannerParams>(out, "The short-horizon footstep search and the crowd driver "
                                  "(`\"planner\"`).");
  write_table<Gait>(out, "One walking gait of the discretised action space "
                         "(`planner.gaits[i]`): a desired speed and a step duration, paired "
                         "because the two are inversely correlated.");
  return out.str();
}

}  // namespace footfall
