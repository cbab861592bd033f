// exactgeo.Classifier: exact point-in-volume classification of point arrays.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/location.hpp"
#include "mesh_object.hpp"

namespace exactgeo::python {

namespace {

using inside::Location;

/// The labels of `points` (validated), computed without the GIL.
std::vector<Location> locations_of(const inside::Classifier& classifier,
                                   const py::object& points_in, const std::string& method,
                                   int threads) {
  const Doubles points = coordinates(points_in, "points", {-1, 3});
  const Arithmetic arithmetic = arithmetic_named(method);
  const unsigned workers = thread_count(threads);
  const std::span<const Point3> rows = points_of(points);
  std::vector<Location> locations(rows.size());
  py::gil_scoped_release release;
  inside::classify_batch(classifier, rows, locations, arithmetic, workers);
  return locations;
}

py::array_t<std::int8_t> classify(const inside::Classifier& classifier, const py::object& points,
                                  const std::string& method, int threads) {
  const std::vector<Location> locations = locations_of(classifier, points, method, threads);
  py::array_t<std::int8_t> labels(static_cast<py::ssize_t>(locations.size()));
  std::transform(locations.begin(), locations.end(), labels.mutable_data(),
                 [](Location l) { return static_cast<std::int8_t>(l); });
  return labels;
}

py::array_t<bool> contains(const inside::Classifier& classifier, const py::object& points,
                           bool boundary, const std::string& method, int threads) {
  const std::vector<Location> locations = locations_of(classifier, points, method, threads);
  py::array_t<bool> inside(static_cast<py::ssize_t>(locations.size()));
  std::transform(locations.begin(), locations.end(), inside.mutable_data(), [&](Location l) {
    return l == Location::inside || (boundary && l == Location::boundary);
  });
  return inside;
}

inside::Classifier build(const MeshObject& mesh, bool allow_non_manifold, bool space_cells) {
  inside::ClassifierOptions options;
  options.allow_non_manifold = allow_non_manifold;
  options.space_cells = space_cells;
  mesh::Mesh copy = mesh.loaded.mesh;
  py::gil_scoped_release release;
  return inside::Classifier(std::move(copy), options);
}

}  // namespace

void bind_inside(py::module_& module) {
  module.attr("OUTSIDE") = static_cast<int>(Location::outside);
  module.attr("INSIDE") = static_cast<int>(Location::inside);
  module.attr("BOUNDARY") = static_cast<int>(Location::boundary);

  py::class_<inside::Classifier>(module, "Classifier",
                                 R"doc(Exact point-in-volume classification against a closed mesh.

A point is BOUNDARY when it lies exactly on a face, else INSIDE or OUTSIDE by the parity
of a ray's crossings with the faces; every crossing is decided by exact predicates, so
the labels are exact for every finite point.)doc")
      .def(py::init(&build), py::arg("mesh"), py::kw_only(), py::arg("allow_non_manifold") = false,
           py::arg("space_cells") = true,
           R"doc(Checks the mesh and builds the search structure once (the GIL is released).

allow_non_manifold: accept edges shared by 4, 6, ... faces (parity stays defined).
space_cells: label the cells of a grid that no face reaches once, exactly, so that
    points in them need no ray (method "exact" only; False: a ray for every point).

Raises ValueError when the mesh does not bound a solid: open, non-manifold, degenerate
faces, with the counts and the first few offending edges or faces.)doc")
      .def("classify", &classify, py::arg("points"), py::kw_only(), py::arg("method") = "exact",
           py::arg("threads") = 0,
           R"doc(The location of every point: an int8 array of OUTSIDE, INSIDE, BOUNDARY.

points: (n, 3) coordinates (float64, or converted exactly), finite.
method: "exact" (default) or "double" (the same traversal in plain doubles: faster,
    wrong near the surface, for comparison).
threads: worker threads, 0 for all hardware threads. The GIL is released.

Raises ValueError for a wrong shape, or for a coordinate that is not finite or not exactly
a double, such as the int64 2**53 + 1 (naming its row).)doc")
      .def("contains", &contains, py::arg("points"), py::kw_only(), py::arg("boundary") = true,
           py::arg("method") = "exact", py::arg("threads") = 0,
           R"doc(A bool array: inside the solid, or on its boundary when `boundary` is true.)doc");
}

}  // namespace exactgeo::python
