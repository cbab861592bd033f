// exactgeo.Classifier: exact point-in-volume classification of point arrays.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/inside/self_intersection_warning.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "mesh_object.hpp"

namespace exactgeo::python {

namespace {

using inside::Location;

/// exactgeo.Classifier: the classifier, and the threads its calls use by default.
struct ClassifierObject {
  inside::Classifier classifier;
  unsigned threads = 0;  ///< Classifier(threads=): 0 for every hardware thread
};

/// A call's `threads`, or when None the classifier's.
unsigned threads_for(const ClassifierObject& object, const std::optional<int>& threads) {
  return threads ? thread_count(*threads) : object.threads;
}

/// The labels of `points` (validated), computed without the GIL.
std::vector<Location> locations_of(const ClassifierObject& object, const py::object& points_in,
                                   const std::string& method, const std::optional<int>& threads,
                                   std::size_t first_row) {
  const Doubles points = coordinates(points_in, "points", {-1, 3}, first_row);
  const Arithmetic arithmetic = arithmetic_named(method);
  const unsigned workers = threads_for(object, threads);
  const std::span<const Point3> rows = points_of(points);
  std::vector<Location> locations(rows.size());
  py::gil_scoped_release release;
  inside::classify_batch(object.classifier, rows, locations, arithmetic, workers);
  return locations;
}

py::array_t<std::int8_t> classify(const ClassifierObject& classifier, const py::object& points,
                                  const std::string& method, const std::optional<int>& threads,
                                  std::size_t first_row) {
  const std::vector<Location> locations =
      locations_of(classifier, points, method, threads, first_row);
  py::array_t<std::int8_t> labels(static_cast<py::ssize_t>(locations.size()));
  std::transform(locations.begin(), locations.end(), labels.mutable_data(),
                 [](Location l) { return static_cast<std::int8_t>(l); });
  return labels;
}

py::array_t<bool> contains(const ClassifierObject& classifier, const py::object& points,
                           bool boundary, const std::string& method,
                           const std::optional<int>& threads, std::size_t first_row) {
  const std::vector<Location> locations =
      locations_of(classifier, points, method, threads, first_row);
  py::array_t<bool> inside(static_cast<py::ssize_t>(locations.size()));
  std::transform(locations.begin(), locations.end(), inside.mutable_data(), [&](Location l) {
    return l == Location::inside || (boundary && l == Location::boundary);
  });
  return inside;
}

/// The winding numbers of `points` as int32, kOnSurface for points on a face.
constexpr std::int32_t kOnSurface = std::numeric_limits<std::int32_t>::min();

/// The winding numbers of `rows` of a closed oriented surface, as int32 (kOnSurface on a face).
py::array_t<std::int32_t> integer_windings(const inside::Classifier& classifier,
                                           std::span<const Point3> rows, Arithmetic arithmetic,
                                           unsigned workers) {
  std::vector<std::optional<std::int64_t>> windings(rows.size());
  {
    py::gil_scoped_release release;
    inside::winding_number_batch(classifier, rows, windings, arithmetic, workers);
  }
  py::array_t<std::int32_t> out(static_cast<py::ssize_t>(windings.size()));
  std::int32_t* data = out.mutable_data();
  for (std::size_t i = 0; i < windings.size(); ++i) {
    const auto& w = windings[i];
    // |w| is at most the number of faces a ray crosses, far below 2^31 for any mesh
    // that fits in memory; checked all the same.
    if (w && (*w <= kOnSurface || *w > std::numeric_limits<std::int32_t>::max())) {
      throw py::value_error("winding number " + std::to_string(*w) + " does not fit in int32");
    }
    data[i] = w ? static_cast<std::int32_t>(*w) : kOnSurface;
  }
  return out;
}

/// Bounds certain to hold the generalized winding numbers of `rows` (NaN on the surface).
std::pair<py::array_t<double>, py::array_t<double>> winding_bounds(
    const inside::Classifier& classifier, std::span<const Point3> rows, Arithmetic arithmetic,
    unsigned workers) {
  std::vector<std::optional<Enclosure>> windings(rows.size());
  {
    py::gil_scoped_release release;
    inside::generalized_winding_number_batch(classifier, rows, windings, arithmetic, workers);
  }
  const auto n = static_cast<py::ssize_t>(windings.size());
  py::array_t<double> lower(n), upper(n);
  double* low = lower.mutable_data();
  double* high = upper.mutable_data();
  for (std::size_t i = 0; i < windings.size(); ++i) {
    low[i] = windings[i] ? windings[i]->lower : std::numeric_limits<double>::quiet_NaN();
    high[i] = windings[i] ? windings[i]->upper : std::numeric_limits<double>::quiet_NaN();
  }
  return {std::move(lower), std::move(upper)};
}

/// Classifier.winding_numbers: int32 against a closed surface, float64 against an open
/// one, or (lower, upper) float64 bounds for either with bounds=True.
py::object winding_numbers(const ClassifierObject& object, const py::object& points_in,
                           const std::string& method, const std::optional<int>& threads,
                           bool bounds) {
  const inside::Classifier& classifier = object.classifier;
  if (!classifier.open() && !classifier.oriented()) {
    throw py::value_error(
        "no winding numbers: the mesh's faces are not oriented alike (some edge is used more "
        "often in one direction than in the other); only rule='parity' labels are defined");
  }
  const Doubles points = coordinates(points_in, "points", {-1, 3});
  const Arithmetic arithmetic = arithmetic_named(method);
  const unsigned workers = threads_for(object, threads);
  const std::span<const Point3> rows = points_of(points);
  if (!bounds && !classifier.open()) return integer_windings(classifier, rows, arithmetic, workers);
  auto [lower, upper] = winding_bounds(classifier, rows, arithmetic, workers);
  if (bounds) return py::make_tuple(std::move(lower), std::move(upper));
  // One double between the bounds: their midpoint (NaN stays NaN).
  py::array_t<double> value(lower.size());
  double* data = value.mutable_data();
  for (py::ssize_t i = 0; i < lower.size(); ++i) {
    data[i] = Enclosure{lower.at(i), upper.at(i)}.midpoint();
  }
  return value;
}

std::optional<inside::FillRule> rule_named(const py::object& name) {
  if (name.is_none()) return std::nullopt;
  const std::string text = py::cast<std::string>(py::str(name));
  if (const auto rule = inside::parse_fill_rule(text)) return *rule;
  throw py::value_error("rule must be 'nonzero', 'parity', 'positive' or None, not '" + text + "'");
}

ClassifierObject build(const MeshObject& mesh, const py::object& rule, bool allow_non_manifold,
                       bool space_cells, std::optional<std::size_t> expected_points, int threads) {
  const unsigned workers = thread_count(threads);
  inside::ClassifierOptions options;
  options.rule = rule_named(rule);
  options.allow_non_manifold = allow_non_manifold;
  options.space_cells = space_cells;
  options.expected_points = expected_points;
  if (auto problem = inside::face_soup_problem(mesh.loaded, options.rule, inside::kPythonNames)) {
    throw py::value_error(*problem);
  }
  mesh::Mesh copy = mesh.loaded.mesh;
  std::optional<inside::Classifier> built;
  std::optional<mesh::SelfIntersections> self;
  try {
    py::gil_scoped_release release;
    built.emplace(std::move(copy), options);
    if (built->rule() == inside::FillRule::parity) {
      // On the mesh as given: the classifier's lacks the faces of zero area, and the pairs
      // are named by the file's face numbers.
      self = mesh::find_self_intersections(mesh.loaded.mesh, workers);
    }
  } catch (const std::invalid_argument& e) {
    // The command line's message, in the file's own numbering, saying which.
    const inside::FillRule taken =
        inside::rule_for(mesh::check_mesh(mesh.loaded.mesh), options.rule);
    throw py::value_error(
        inside::refusal(mesh.loaded, taken, allow_non_manifold, inside::kPythonNames)
            .value_or(e.what()));
  }
  // What the command line says on stderr, Python says as warnings.
  if (const auto note = mesh::zero_area_note(built->zero_area_faces(), mesh.loaded.numbering)) {
    warn(*note);
  }
  if (const auto note = built->open_note()) {
    warn(*note);
  } else if (!options.rule && !built->oriented()) {
    warn(
        "the faces are not oriented alike (some edge is used more often in one direction "
        "than in the other), so they have no winding numbers: labelled by crossing parity "
        "(rule='parity')");
  }
  if (self) {
    for (const std::string& warning : inside::self_intersection_warnings(
             *self, mesh.loaded.numbering, built->oriented(), inside::kPythonNames)) {
      warn(warning);
    }
  }
  return {std::move(*built), workers};
}

}  // namespace

void bind_inside(py::module_& module) {
  module.attr("OUTSIDE") = static_cast<int>(Location::outside);
  module.attr("INSIDE") = static_cast<int>(Location::inside);
  module.attr("BOUNDARY") = static_cast<int>(Location::boundary);
  module.attr("UNDECIDED") = static_cast<int>(Location::undecided);
  module.attr("ON_SURFACE") = kOnSurface;

  py::class_<ClassifierObject>(module, "Classifier",
                               R"doc(Exact point-in-volume classification against a mesh.

A point is BOUNDARY when it lies exactly on a face, else INSIDE or OUTSIDE by its winding
number (the signed count of a ray's crossings with the faces) and the rule; every
crossing is decided by exact predicates, so the labels are exact for every finite point.
Against an open surface (holes, boundary edges) the label comes from the generalized
winding number w, the crossings plus a certified term over the boundary: INSIDE where
|w| >= 1/2 (rule "positive": w >= 1/2), UNDECIDED where no precision allowed settles it.)doc")
      .def(py::init(&build), py::arg("mesh"), py::kw_only(), py::arg("rule") = py::none(),
           py::arg("allow_non_manifold") = false, py::arg("space_cells") = true,
           py::arg("expected_points") = py::none(), py::arg("threads") = 0,
           R"doc(Checks the mesh and builds the search structure once (the GIL is released).

rule: which points the surface holds, by their winding number w (faces oriented by their
    corner order, counter-clockwise seen from outside): "nonzero" (w != 0, so parts that
    overlap read as their union), "parity" (w odd: overlaps read outside; the only rule
    for faces not oriented alike) or "positive" (w > 0). All three agree on a closed mesh
    that does not intersect itself; on an open one, nonzero and positive compare the
    generalized winding number with 1/2. None (default): "nonzero", or "parity" with a
    UserWarning for a closed mesh whose faces are not oriented alike (the `rule`
    attribute says which).
allow_non_manifold: with rule="parity", accept edges shared by 4, 6, ... faces (the
    winding rules accept any edge whose faces are oriented alike).
space_cells: label the cells of a grid that no face reaches once, exactly, so that
    points in them need no ray (method "exact" only; False: a ray for every point).
expected_points: about how many points will be classified, where known: the grid is then
    sized to them too (at most two cells a point), so that a few thousand points do not
    pay for a grid built for millions. Any value gives the same labels; None (default):
    sized by the mesh alone.
threads: worker threads for the checks here and, by default, for every call (a call's
    own threads= overrides it); 0 for all hardware threads.

Raises ValueError when the rule cannot classify against the mesh: faces not oriented
alike (winding rules), open or non-manifold (parity), a face that repeats a corner, with
the counts and the first few offending edges or faces. Warns (UserWarning) when the
surface is open (what its labels mean), when faces of zero area were dropped, and, by
parity, when faces intersect (the labels are then those of the parity solid).)doc")
      .def_property_readonly(
          "rule",
          [](const ClassifierObject& c) { return std::string(to_string(c.classifier.rule())); })
      .def_property_readonly(
          "threads", [](const ClassifierObject& c) { return c.threads; },
          "The threads calls use when they name none (0: all hardware threads).")
      .def("winding_numbers", &winding_numbers, py::arg("points"), py::kw_only(),
           py::arg("method") = "exact", py::arg("threads") = py::none(), py::arg("bounds") = false,
           R"doc(The winding number of every point.

Against a closed surface: an int32 array, exact; ON_SURFACE (the smallest int32) for
points on a face, where none is defined.

Against an open surface (holes, boundary edges): the generalized winding number w, a
float64 array (the sum of the faces' signed solid angles over 4 pi: the crossings of a ray
plus a term over the boundary, docs/inside.md "Open surfaces"): the midpoint of the
certified bounds below, which are at most about 2**-40 apart (wider only for a point
within rounding of a boundary edge's line); NaN for points on the surface (a face or a
boundary edge). classify() labels by it: INSIDE where |w| >= 1/2.

bounds=True returns (lower, upper), two float64 arrays with lower <= w <= upper for
every point, certified (method "exact"), for a closed surface or an open one (closed:
lower == upper == the winding number); NaN on the surface. With method "double" the two
are equal and not certified.

Other arguments as for classify. Raises ValueError when the faces of a closed surface are
not oriented alike (a mesh accepted by rule="parity" only).)doc")
      .def("classify", &classify, py::arg("points"), py::kw_only(), py::arg("method") = "exact",
           py::arg("threads") = py::none(), py::arg("first_row") = 0,
           R"doc(The location of every point: an int8 array of OUTSIDE, INSIDE, BOUNDARY (and
UNDECIDED against an open surface, where no precision allowed settles the label).

points: (n, 3) coordinates (float64, or converted exactly), finite.
method: "exact" (default) or "double" (the same traversal in plain doubles: faster,
    wrong near the surface, for comparison).
threads: worker threads, 0 for all hardware threads; None (default): the classifier's
    (Classifier(threads=)). The GIL is released.
first_row: the number messages give points[0]: a block of a larger array (as
    exactgeo.dask passes them) names its rows as the whole array numbers them.

Raises ValueError for a wrong shape, or for a coordinate that is not finite or not exactly
a double, such as the int64 2**53 + 1 (naming its row).)doc")
      .def("contains", &contains, py::arg("points"), py::kw_only(), py::arg("boundary") = true,
           py::arg("method") = "exact", py::arg("threads") = py::none(), py::arg("first_row") = 0,
           R"doc(A bool array: inside the solid, or on its boundary when `boundary` is true.

An UNDECIDED point (an open surface's w exactly 1/2, or too close to it) is not
contained; classify() tells those apart.)doc");
}

}  // namespace exactgeo::python
