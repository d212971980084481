// Footfall — the parameter tables as text: a field's unit, range and meaning
// in one line (the Python attributes' docs), and docs/parameters.md whole.
#pragma once

#include <string>

#include "footfall/model/param_table.hpp"

namespace footfall {

/// A range as the docs write it: "[0.2, 3]", "(0, torso_width / 2]".
std::string range_text(const ParamRange& range);

/// "[m] [0.2, 3]. Height of the centre of mass, the pendulum length."
template <class S, class T>
std::string describe_param(const ScalarParam<S, T>& field) {
  return std::string("[") + field.unit + "] " + range_text(field.range) + ". " + field.doc;
}
/// The nested struct's meaning.
template <class S, class N>
std::string describe_param(const NestedParam<S, N>& field) {
  return field.doc;
}
/// "[rad] 1 to 32, each in (0, pi/2). Parabola orientations ..."
template <class S>
std::string describe_param(const NumberListParam<S>& field) {
  return std::string("[") + field.unit + "] " + std::to_string(field.min_count) + " to " +
         std::to_string(field.max_count) + ", each in " + range_text(field.range) + ". " +
         field.doc;
}
/// "1 to 16. Gaits tried at every expansion ..."
template <class S, class E>
std::string describe_param(const StructListParam<S, E>& field) {
  return std::to_string(field.min_count) + " to " + std::to_string(field.max_count) + ". " +
         field.doc;
}

/// docs/parameters.md: every field of every parameter struct with its unit,
/// valid range, default and meaning.
std::string parameter_docs();

}  // namespace footfall
