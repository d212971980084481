// footfall._native: the planning core for Python and Blender.
#include "bindings.hpp"
#include "footfall/model/status.hpp"

PYBIND11_MODULE(_native, m) {
  m.doc() =
      "Footfall's planning core: the footstep model, the footstep planner, the navigation "
      "mesh, scenario and plan files.";
  m.attr("__version__") = FOOTFALL_VERSION;
  // std::invalid_argument -> ValueError and std::out_of_range -> IndexError
  // are pybind11's own translations; footfall::Error gets its own class.
  pybind11::register_exception<footfall::Error>(m, "FootfallError", PyExc_RuntimeError);
  footfall::bindings::bind_params(m);
  footfall::bindings::bind_footstep(m);
  footfall::bindings::bind_planner(m);
  footfall::bindings::bind_scenario(m);
  footfall::bindings::bind_navmesh(m);
  footfall::bindings::bind_fullbody(m);
  footfall::bindings::bind_animate(m);
}
