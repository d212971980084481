// footfall._native: the navigation mesh.
#include "bindings.hpp"
#include "footfall/crowd/scenario.hpp"
#include "footfall/io/path_json.hpp"
#include "footfall/navmesh/navmesh.hpp"

namespace py = pybind11;

namespace footfall::bindings {
namespace {

py::dict path_dict(const PathResult& r) {
  py::list points;
  for (Vec2 p : r.points) points.append(py::make_tuple(p.x, p.y));
  py::dict out;
  out["status"] = to_string(r.status);
  out["points"] = points;
  out["length"] = r.length;
  out["min_clearance"] = r.min_clearance;
  return out;
}

py::dict triangle_dict(const NavTriangle& t) {
  py::dict out;
  out["corners"] = py::make_tuple(py::cast(t.corners[0]), py::cast(t.corners[1]),
                                  py::cast(t.corners[2]));
  out["walkable"] = t.walkable;
  out["corner_clearance"] = py::make_tuple(t.corner_clearance[0], t.corner_clearance[1],
                                           t.corner_clearance[2]);
  out["constrained"] = py::make_tuple(t.constrained[0], t.constrained[1], t.constrained[2]);
  return out;
}

}  // namespace

void bind_navmesh(py::module_& m) {
  py::class_<NavMesh>(m, "NavMesh",
                      "Triangulated walkable rectangle with obstacles by id; shortest paths for "
                      "a disc of any radius.")
      .def(py::init<Vec2, Vec2>(), py::arg("min_corner"), py::arg("max_corner"))
      .def("add_polygon", &NavMesh::add_polygon, py::arg("polygon"), py::arg("name") = "",
           "Adds a polygon obstacle [m]; returns its id.")
      .def("add_region", &NavMesh::add_region, py::arg("outlines"), py::arg("holes"), py::arg("name") = "",
           "Adds one obstacle covering the area inside its outlines and outside its holes (lists of "
           "polygons [m]); returns its id.")
      .def("add_point", &NavMesh::add_point, py::arg("point"), py::arg("name") = "",
           "Adds a point obstacle [m]; returns its id.")
      .def("remove", &NavMesh::remove, py::arg("id"), "Removes an obstacle (IndexError if unknown).")
      .def("__contains__", &NavMesh::contains, py::arg("id"))
      .def(
          "find_path",
          [](const NavMesh& mesh, Vec2 start, Vec2 goal, double radius, double arc_tolerance) {
            PathResult result;
            {
              py::gil_scoped_release release;
              result = mesh.find_path({start, goal, radius, arc_tolerance});
            }
            return path_dict(result);
          },
          py::arg("start"), py::arg("goal"), py::arg("radius"), py::arg("arc_tolerance") = 0.01,
          "Shortest path for a disc of `radius` [m]: {'status', 'points', 'length', "
          "'min_clearance'}, status one of found, no_path, start_blocked, goal_blocked, outside.")
      .def("clearance", &NavMesh::clearance, py::arg("point"),
           "Distance to the nearest obstacle [m]; 0 if blocked or outside.")
      .def("clearance_between", &NavMesh::clearance_between, py::arg("a"), py::arg("b"),
           py::arg("limit") = std::numeric_limits<double>::infinity(),
           "Distance from the segment a-b to the nearest obstacle, up to limit [m]; 0 if it "
           "crosses an obstacle or leaves the domain.")
      .def("line_of_sight", &NavMesh::line_of_sight, py::arg("a"), py::arg("b"),
           "True if the segment a-b stays in the walkable domain and crosses no obstacle.")
      .def(
          "triangles",
          [](const NavMesh& mesh) {
            py::list out;
            for (const NavTriangle& t : mesh.triangles()) out.append(triangle_dict(t));
            return out;
          },
          "Every triangle for drawing: {'corners', 'walkable', 'corner_clearance', "
          "'constrained'}.")
      .def_property_readonly("triangle_count", &NavMesh::triangle_count)
      .def_property_readonly("min_corner", &NavMesh::min_corner)
      .def_property_readonly("max_corner", &NavMesh::max_corner);
  m.def("navmesh_of", &navmesh_of, py::arg("scenario"), py::arg("margin") = 5.0,
        "The navigation mesh of a scenario: its bounding box grown by `margin` [m].");
}

}  // namespace footfall::bindings
