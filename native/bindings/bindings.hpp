// Private to the bindings: one bind_* function per area, and the conversion of
// Vec2 to and from a Python (x, y) tuple. Type conversion only, no logic.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "footfall/model/geometry.hpp"

namespace footfall::bindings {

void bind_params(pybind11::module_& m);
void bind_footstep(pybind11::module_& m);
void bind_planner(pybind11::module_& m);
void bind_scenario(pybind11::module_& m);
void bind_navmesh(pybind11::module_& m);
void bind_fullbody(pybind11::module_& m);
void bind_animate(pybind11::module_& m);

}  // namespace footfall::bindings

namespace pybind11::detail {

/// footfall::Vec2 <-> any sequence of two numbers; returned as a tuple (x, y).
template <>
struct type_caster<footfall::Vec2> {
  PYBIND11_TYPE_CASTER(footfall::Vec2, const_name("tuple[float, float]"));

  bool load(handle source, bool convert) {
    if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
    const auto items = reinterpret_borrow<sequence>(source);
    if (items.size() != 2) return false;
    make_caster<double> x, y;
    if (!x.load(items[0], convert) || !y.load(items[1], convert)) return false;
    value = {cast_op<double>(x), cast_op<double>(y)};
    return true;
  }

  static handle cast(const footfall::Vec2& v, return_value_policy, handle) {
    return make_tuple(v.x, v.y).release();
  }
};

}  // namespace pybind11::detail
