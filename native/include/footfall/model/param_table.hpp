// Footfall — the vocabulary of the parameter tables (params.hpp): each
// parameter is declared once, in its struct's table, with its JSON and Python
// name, unit, valid range and meaning. Validation, the file readers and
// writers, the Python binding and docs/parameters.md are all derived from the
// tables, so they cannot disagree.
#pragma once

#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

namespace footfall {

/// One end of a valid range: a number, or another field of the same struct
/// times a factor (torso_radius <= torso_width / 2).
struct ParamBound {
  double value = 0.0;           ///< The number, or the factor on `field`.
  const char* field = nullptr;  ///< The field it refers to, or null.
  bool open = false;            ///< The end itself is excluded.
};

/// A valid range [low, high], (low, high], ... and, for a few fields, an upper
/// bound by another field besides (goal_tolerance < local_goal_distance).
struct ParamRange {
  ParamBound low;
  ParamBound high;
  const char* below_field = nullptr;  ///< Must also be strictly less than this field.
};

/// [lo, hi]
constexpr ParamRange closed(double lo, double hi) { return {{lo}, {hi}}; }
/// (lo, hi]
constexpr ParamRange above_up_to(double lo, double hi) { return {{lo, nullptr, true}, {hi}}; }
/// (lo, hi)
constexpr ParamRange open_range(double lo, double hi) {
  return {{lo, nullptr, true}, {hi, nullptr, true}};
}
/// [field, hi]
constexpr ParamRange from_field(const char* field, double hi) { return {{1.0, field}, {hi}}; }
/// (lo, field * factor]
constexpr ParamRange above_up_to_field(double lo, const char* field, double factor) {
  return {{lo, nullptr, true}, {factor, field}};
}
/// The same range, and strictly less than `field`.
constexpr ParamRange and_below(ParamRange range, const char* field) {
  range.below_field = field;
  return range;
}

/// A number (double or int) of struct S.
template <class S, class T>
struct ScalarParam {
  const char* name;  ///< The member's name, in files and in Python.
  T S::*member;
  const char* unit;  ///< "m", "s", "m/s", "kg", "J/s", "rad", "1".
  ParamRange range;
  const char* doc;  ///< What it means, one sentence or two.
};

/// A parameter struct N inside struct S (CharacterParams::left).
template <class S, class N>
struct NestedParam {
  const char* name;
  N S::*member;
  const char* doc;
};

/// A list of numbers of struct S, each in `range`, with min_count to
/// max_count items.
template <class S>
struct NumberListParam {
  const char* name;
  std::vector<double> S::*member;
  std::size_t min_count, max_count;
  const char* item_noun;  ///< Plural noun for messages: "must hold 1 to 32 angles".
  const char* unit;
  ParamRange range;
  const char* doc;
};

/// A list of parameter structs E (PlannerParams::gaits).
template <class S, class E>
struct StructListParam {
  const char* name;
  std::vector<E> S::*member;
  std::size_t min_count, max_count;
  const char* item_noun;
  const char* doc;
};

template <class S, class T>
constexpr ScalarParam<S, T> param(const char* name, T S::*member, const char* unit,
                                  ParamRange range, const char* doc) {
  return {name, member, unit, range, doc};
}
template <class S, class N>
constexpr NestedParam<S, N> nested_param(const char* name, N S::*member, const char* doc) {
  return {name, member, doc};
}

/// The table of struct S: `ParamTable<S>::fields` is a tuple of the
/// descriptors above, in the order fields are validated and documented;
/// `ParamTable<S>::name` names the struct in the docs. Specialised in
/// params.hpp for every parameter struct.
template <class S>
struct ParamTable;

/// Calls visit(descriptor) for every field of S's table, in order.
template <class S, class Visit>
void for_each_param(Visit&& visit) {
  std::apply([&](const auto&... field) { (visit(field), ...); }, ParamTable<S>::fields);
}

}  // namespace footfall
