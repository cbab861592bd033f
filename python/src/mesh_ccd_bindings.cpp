// exactgeo.MeshCcd: every colliding pair of a triangle mesh over a time step.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::python {

namespace {

/// The library object and a lock: step() keeps state for the next step, and the GIL is
/// released while it runs, so two Python threads stepping one MeshCcd take turns.
struct MeshCcdObject {
  ccd::MeshCcd ccd;
  std::mutex stepping;

  MeshCcdObject(std::size_t vertex_count, std::span<const ccd::Triangle> faces)
      : ccd(vertex_count, faces) {}
};

/// One step's answer, as Python sees it.
struct StepResult {
  py::array_t<std::uint32_t> vertex_face;  ///< (k, 2): vertex, face
  py::array_t<std::uint32_t> edge_edge;    ///< (k, 4): edge a's vertices, edge b's
  py::object time_of_impact;               ///< (start, end) or None
  std::size_t vertex_face_candidates = 0;
  std::size_t edge_edge_candidates = 0;
  double broad_phase_seconds = 0.0;
  double narrow_phase_seconds = 0.0;
};

std::unique_ptr<MeshCcdObject> make(const py::object& faces_in, const py::object& vertex_count_in) {
  std::optional<std::uint64_t> vertex_count;
  if (!vertex_count_in.is_none())
    vertex_count = count_of(vertex_count_in, "vertex_count", UINT32_MAX);
  const py::array_t<VertexIndex> faces =
      vertex_indices(faces_in, "faces", {3}, vertex_range(vertex_count));
  std::vector<ccd::Triangle> triangles(static_cast<std::size_t>(faces.shape(0)));
  std::uint64_t used = 0;  // the largest index + 1
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    for (std::size_t k = 0; k < 3; ++k) {
      triangles[f][k] = faces.data()[3 * f + k];
      used = std::max<std::uint64_t>(used, triangles[f][k] + std::uint64_t{1});
    }
  }
  return std::make_unique<MeshCcdObject>(static_cast<std::size_t>(vertex_count.value_or(used)),
                                         triangles);
}

StepResult step(MeshCcdObject& object, const py::object& x0_in, const py::object& x1_in,
                const std::string& method, const py::object& toi, int threads,
                const py::object& min_separation_in) {
  const std::size_t n = object.ccd.vertex_count();
  const Doubles x0 = coordinates(x0_in, "x0", {-1, 3});
  const Doubles x1 = coordinates(x1_in, "x1", {-1, 3});
  for (const auto& [array, name] : {std::pair{&x0, "x0"}, std::pair{&x1, "x1"}}) {
    if (static_cast<std::size_t>(array->shape(0)) != n) {
      throw py::value_error(std::string(name) + " has " + std::to_string(array->shape(0)) +
                            " rows, the mesh has " + std::to_string(n) + " vertices");
    }
  }
  ccd::MeshCcdOptions options;
  options.method = ccd_method_named(method);
  options.threads = thread_count(threads);
  // toi: False, True (brackets of width 1e-6, as the command line's --toi), or a width.
  if (py::isinstance<py::bool_>(toi)) {
    if (toi.cast<bool>()) options.time_of_impact_width = 1e-6;
  } else {
    const double width = option_number(toi, "toi");
    if (!(width > 0.0 && width <= 1.0)) {
      throw py::value_error("toi must be True, False or a width in (0, 1], got " +
                            std::string(py::repr(toi)));
    }
    options.time_of_impact_width = width;
  }
  if (options.time_of_impact_width && options.method != ccd::Method::exact) {
    throw py::value_error(
        "toi needs method='exact' (the other methods only say whether a pair "
        "collides)");
  }

  const double min_separation = option_number(min_separation_in, "min_separation");
  if (!ccd::is_valid_min_separation(min_separation)) {
    throw py::value_error("min_separation must be finite and >= 0");
  }
  if (min_separation > 0.0 && options.method != ccd::Method::exact) {
    throw py::value_error("min_separation needs method='exact'");
  }
  options.min_separation = min_separation;

  ccd::MeshCcdResult result;
  {
    const ccd::StepPositions frames{{x0.data(), 3 * n}, {x1.data(), 3 * n}};
    py::gil_scoped_release release;
    const std::lock_guard lock(object.stepping);
    result = object.ccd.step(frames, options);
  }
  StepResult out;
  out.vertex_face = py::array_t<std::uint32_t>(
      {static_cast<py::ssize_t>(result.vertex_face.size()), py::ssize_t{2}});
  std::uint32_t* vf = out.vertex_face.mutable_data();
  for (const ccd::VertexFacePair& p : result.vertex_face) {
    *vf++ = p.vertex;
    *vf++ = p.face;
  }
  out.edge_edge = py::array_t<std::uint32_t>(
      {static_cast<py::ssize_t>(result.edge_edge.size()), py::ssize_t{4}});
  std::uint32_t* ee = out.edge_edge.mutable_data();
  for (const ccd::EdgeEdgePair& p : result.edge_edge) {
    for (const VertexIndex v : {p.a[0], p.a[1], p.b[0], p.b[1]})
      *ee++ = v;
  }
  out.time_of_impact =
      result.time_of_impact
          ? py::object(py::make_tuple(result.time_of_impact->start, result.time_of_impact->end))
          : py::none();
  out.vertex_face_candidates = result.vertex_face_candidates;
  out.edge_edge_candidates = result.edge_edge_candidates;
  out.broad_phase_seconds = result.broad_phase_seconds;
  out.narrow_phase_seconds = result.narrow_phase_seconds;
  return out;
}

py::array_t<std::uint32_t> edges_of(const MeshCcdObject& object) {
  const std::span<const ccd::Edge> edges = object.ccd.edges();
  py::array_t<std::uint32_t> array({static_cast<py::ssize_t>(edges.size()), py::ssize_t{2}});
  std::copy_n(edges.data()->data(), 2 * edges.size(), array.mutable_data());
  return array;
}

}  // namespace

void bind_mesh_ccd(py::module_& module) {
  py::class_<StepResult>(module, "MeshCcdStep", "The colliding pairs of one MeshCcd.step.")
      .def_readonly("vertex_face", &StepResult::vertex_face,
                    "(k, 2) uint32: vertex, face index; sorted, each pair once")
      .def_readonly("edge_edge", &StepResult::edge_edge,
                    "(k, 4) uint32: edge a's two vertices, edge b's two vertices (each edge "
                    "smaller vertex first, the smaller edge first); sorted, each pair once")
      .def_readonly("time_of_impact", &StepResult::time_of_impact,
                    "with toi and a collision: (start, end), no contact before start, a "
                    "contact by end; else None")
      .def_readonly("vertex_face_candidates", &StepResult::vertex_face_candidates)
      .def_readonly("edge_edge_candidates", &StepResult::edge_edge_candidates)
      .def_readonly("broad_phase_seconds", &StepResult::broad_phase_seconds)
      .def_readonly("narrow_phase_seconds", &StepResult::narrow_phase_seconds)
      .def_property_readonly("collision", [](const StepResult& r) {
        return r.vertex_face.shape(0) > 0 || r.edge_edge.shape(0) > 0;
      });

  py::class_<MeshCcdObject>(module, "MeshCcd",
                            R"doc(Mesh-level continuous collision detection for a triangle mesh.

The connectivity is fixed here; each step gives the positions at its start and end (each
vertex moves on the straight line between them) and gets every colliding vertex-face
and edge-edge pair. Pairs sharing a vertex, and pairs whose four corners all move by the
same vector, are skipped. Exact by default: no collision is ever missed.)doc")
      .def(py::init(&make), py::arg("faces"), py::arg("vertex_count") = py::none(),
           R"doc(faces: (m, 3) integer array of vertex indices.
vertex_count: the number of vertices (default: the largest index + 1).

Indices are integers (ints, integer arrays), never floats. Raises ValueError for an index
that is negative, not an integer or >= vertex_count (naming the row and the index as
given), and for a repeated corner.)doc")
      .def("step", &step, py::arg("x0"), py::arg("x1"), py::kw_only(), py::arg("method") = "exact",
           py::arg("toi") = false, py::arg("threads") = 0, py::arg("min_separation") = 0.0,
           R"doc(Every colliding pair over one step, as a MeshCcdStep.

x0, x1: (vertex_count, 3) positions at the start and the end of the step, each exactly a
    double (other dtypes are converted exactly or refused: see docs/python.md).
method: "exact" (default) or "parity" (the others are accepted for measurements).
toi: also bracket the earliest contact (exact only): True for a width of 1e-6, or the
    width as a float.
min_separation: also report pairs whose Euclidean distance drops to at most this (exact
    only; the bracket is then of the earliest time within it).
threads: worker threads, 0 for all hardware threads. The GIL is released.)doc")
      .def_property_readonly("vertex_count",
                             [](const MeshCcdObject& o) { return o.ccd.vertex_count(); })
      .def_property_readonly("edges", &edges_of,
                             "(e, 2) uint32: the unique edges, sorted, smaller vertex first");
}

}  // namespace exactgeo::python
