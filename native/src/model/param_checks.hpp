// Footfall — the checks a parameter table implies: a value within its range
// (whose ends may be other fields of the same struct), a list's length.
#pragma once

#include <cmath>
#include <cstring>
#include <type_traits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "footfall/model/param_table.hpp"

namespace footfall::detail {

/// The value of the number field `name` of `params`.
template <class S>
double param_value(const S& params, const char* name) {
  double value = NAN;
  for_each_param<S>([&](const auto& field) {
    if constexpr (std::is_arithmetic_v<std::decay_t<decltype(params.*field.member)>>) {
      if (std::strcmp(field.name, name) == 0) value = static_cast<double>(params.*field.member);
    }
  });
  return value;
}

/// The number an end of a range stands for, in `params`.
template <class S>
double bound_value(const S& params, const ParamBound& bound) {
  return bound.field == nullptr ? bound.value : bound.value * param_value(params, bound.field);
}

/// Throws std::invalid_argument "NAME: must be in [lo, hi], got VALUE" (or
/// "must be less than FIELD (...)") unless `value` lies in `range`.
template <class S>
void check_range(const S& params, double value, const ParamRange& range, const std::string& name) {
  const double lo = bound_value(params, range.low), hi = bound_value(params, range.high);
  const bool ok = std::isfinite(value) && (range.low.open ? value > lo : value >= lo) &&
                  (range.high.open ? value < hi : value <= hi);
  if (!ok) {
    std::ostringstream message;
    message.precision(10);
    message << name << ": must be in " << (range.low.open ? "(" : "[") << lo << ", " << hi
            << (range.high.open ? ")" : "]") << ", got " << value;
    throw std::invalid_argument(message.str());
  }
  if (range.below_field != nullptr) {
    const double limit = param_value(params, range.below_field);
    if (!(value < limit))
      throw std::invalid_argument(name + ": must be less than " + range.below_field + " (" +
                                  std::to_string(limit) + ")");
  }
}

/// Throws std::invalid_argument "NAME: must hold 1 to 16 gaits, got N"
/// unless min <= count <= max.
inline void check_count(std::size_t count, std::size_t min, std::size_t max, const char* noun,
                        const std::string& name) {
  if (count < min || count > max)
    throw std::invalid_argument(name + ": must hold " + std::to_string(min) + " to " +
                                std::to_string(max) + " " + noun + ", got " +
                                std::to_string(count));
}

}  // namespace footfall::detail
