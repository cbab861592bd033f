// exactgeo.Surface: collision-safe remeshing operations on a triangle surface.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exactgeo/remesh/operations.hpp"

namespace exactgeo::python {

namespace {

using remesh::Outcome;
using remesh::Surface;

Point3 point_of(const py::object& object, std::string_view name) {
  const Doubles p = coordinates(object, name, {3});
  return {p.data()[0], p.data()[1], p.data()[2]};
}

VertexIndex vertex_of(const Surface& s, std::int64_t v) {
  if (v < 0 || static_cast<std::uint64_t>(v) >= s.vertices.size()) {
    throw py::value_error("vertex " + std::to_string(v) + " is out of range (the surface has " +
                          std::to_string(s.vertices.size()) + " vertices)");
  }
  return static_cast<VertexIndex>(v);
}

Surface make(const py::object& vertices_in, const py::object& triangles_in,
             const py::object& fixed_in) {
  Surface s;
  const Doubles vertices = coordinates(vertices_in, "vertices", {-1, 3});
  const std::span<const Point3> points = points_of(vertices);
  s.vertices.assign(points.begin(), points.end());
  const py::array_t<VertexIndex> triangles =
      vertex_indices(triangles_in, "triangles", {3}, vertex_range(s.vertices.size()));
  for (py::ssize_t t = 0; t < triangles.shape(0); ++t) {
    const VertexIndex* c = triangles.data() + 3 * t;
    s.triangles.push_back({c[0], c[1], c[2]});
  }
  if (!fixed_in.is_none()) {
    const auto fixed =
        py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(fixed_in);
    if (!fixed || fixed.ndim() != 1 ||
        static_cast<std::size_t>(fixed.shape(0)) != s.vertices.size()) {
      throw py::value_error("fixed must be a bool array of one flag per vertex");
    }
    s.fixed.assign(fixed.data(), fixed.data() + fixed.shape(0));
  }
  return s;
}

/// An outcome as a dict: applied, verdict, reason, blocker ((kind, corners) or None),
/// new_vertex (or None).
py::dict outcome_dict(const Outcome& o) {
  py::dict d;
  d["applied"] = o.applied();
  switch (o.verdict) {
    case remesh::Verdict::applied:
      d["verdict"] = "applied";
      break;
    case remesh::Verdict::refused_topology:
      d["verdict"] = "refused_topology";
      break;
    case remesh::Verdict::refused_collision:
      d["verdict"] = "refused_collision";
      break;
    case remesh::Verdict::deferred:
      d["verdict"] = "deferred";
      break;
  }
  d["reason"] = o.reason;
  if (o.blocker) {
    py::list corners;
    for (const VertexIndex v : o.blocker->corners)
      if (v != kNoVertex) corners.append(v);
    const char* kind = o.blocker->kind == remesh::Blocker::Kind::vertex ? "vertex"
                       : o.blocker->kind == remesh::Blocker::Kind::edge ? "edge"
                                                                        : "triangle";
    d["blocker"] = py::make_tuple(kind, py::tuple(corners));
  } else {
    d["blocker"] = py::none();
  }
  d["new_vertex"] = o.new_vertex ? py::object(py::int_(*o.new_vertex)) : py::none();
  return d;
}

py::array_t<double> vertices_of(const Surface& s) {
  py::array_t<double> out({static_cast<py::ssize_t>(s.vertices.size()), py::ssize_t{3}});
  std::copy_n(s.vertices.data()->data(), 3 * s.vertices.size(), out.mutable_data());
  return out;
}

py::array_t<std::uint32_t> triangles_of(const Surface& s) {
  py::array_t<std::uint32_t> out({static_cast<py::ssize_t>(s.triangles.size()), py::ssize_t{3}});
  std::copy_n(s.triangles.data()->data(), 3 * s.triangles.size(), out.mutable_data());
  return out;
}

py::array_t<bool> relocate_many(Surface& s, const py::object& indices_in,
                                const py::object& targets_in) {
  const Doubles targets = coordinates(targets_in, "targets", {-1, 3});
  // A one-dimensional index array, checked as the one-column array of the faces' checks.
  const py::object column = py::module_::import("numpy").attr("reshape")(
      py::module_::import("numpy").attr("asarray")(indices_in), py::make_tuple(-1, 1));
  const py::array_t<VertexIndex> indices =
      vertex_indices(column, "indices", {1}, vertex_range(s.vertices.size()));
  if (indices.shape(0) != targets.shape(0)) {
    throw py::value_error("indices and targets must have the same length");
  }
  std::vector<remesh::Move> moves;
  const std::span<const Point3> to = points_of(targets);
  for (std::size_t i = 0; i < to.size(); ++i)
    moves.push_back({indices.data()[i], to[i]});
  std::vector<Outcome> done;
  {
    py::gil_scoped_release release;
    done = remesh::relocate_vertices(s, moves);
  }
  py::array_t<bool> applied(static_cast<py::ssize_t>(done.size()));
  std::transform(done.begin(), done.end(), applied.mutable_data(),
                 [](const Outcome& o) { return o.applied(); });
  return applied;
}

std::vector<remesh::Edge> edges_of(const Surface& s, const py::object& edges_in) {
  const py::array_t<VertexIndex> edges =
      vertex_indices(edges_in, "edges", {2}, vertex_range(s.vertices.size()));
  std::vector<remesh::Edge> out;
  for (py::ssize_t e = 0; e < edges.shape(0); ++e)
    out.push_back({edges.data()[2 * e], edges.data()[2 * e + 1]});
  return out;
}

py::list outcome_list(const std::vector<Outcome>& done) {
  py::list out;
  for (const Outcome& o : done)
    out.append(outcome_dict(o));
  return out;
}

/// Runs a pass (a callable returning its outcomes) without the GIL; one dict per outcome.
template <class Pass>
py::list run_pass(const Pass& pass) {
  std::vector<Outcome> done;
  {
    py::gil_scoped_release release;
    done = pass();
  }
  return outcome_list(done);
}

py::list flip_many(Surface& s, const py::object& edges_in) {
  const std::vector<remesh::Edge> edges = edges_of(s, edges_in);
  return run_pass([&] { return remesh::flip_edges(s, edges); });
}

/// A pass's (k, 2) edges and (k, 3) points, checked.
std::vector<std::pair<remesh::Edge, Point3>> edges_and_points(const Surface& s,
                                                              const py::object& edges_in,
                                                              const py::object& points_in) {
  const std::vector<remesh::Edge> edges = edges_of(s, edges_in);
  const Doubles points = coordinates(points_in, "points", {-1, 3});
  if (static_cast<std::size_t>(points.shape(0)) != edges.size()) {
    throw py::value_error("edges and points must have the same length");
  }
  const std::span<const Point3> at = points_of(points);
  std::vector<std::pair<remesh::Edge, Point3>> out;
  for (std::size_t i = 0; i < edges.size(); ++i)
    out.emplace_back(edges[i], at[i]);
  return out;
}

py::list split_many(Surface& s, const py::object& edges_in, const py::object& points_in) {
  std::vector<remesh::Split> splits;
  for (const auto& [e, at] : edges_and_points(s, edges_in, points_in))
    splits.push_back({e[0], e[1], at});
  return run_pass([&] { return remesh::split_edges(s, splits); });
}

py::list collapse_many(Surface& s, const py::object& edges_in, const py::object& points_in) {
  std::vector<remesh::Collapse> collapses;
  for (const auto& [e, to] : edges_and_points(s, edges_in, points_in))
    collapses.push_back({e[0], e[1], to});
  return run_pass([&] { return remesh::collapse_edges(s, collapses); });
}

}  // namespace

void bind_remesh(py::module_& module) {
  py::class_<Surface>(module, "Surface",
                      R"doc(A triangle surface that collision-safe operations change in place.

Each operation is applied only when exact tests show that the motion it stands for meets
nothing else of the surface (relocation and collapse: exact CCD of the moving vertices;
flip and split: the closed region the surface sweeps), so an intersection-free surface
stays so. Each returns a dict: "applied" (bool), "verdict" ("applied",
"refused_topology" or "refused_collision"), "reason" (why, when refused), "blocker"
(("vertex" | "edge" | "triangle", corners) that would be met, or None) and "new_vertex"
(split_edge).)doc")
      .def(py::init(&make), py::arg("vertices"), py::arg("triangles"), py::kw_only(),
           py::arg("fixed") = py::none(),
           R"doc(vertices: (n, 3) coordinates; triangles: (m, 3) vertex indices; fixed: an
optional bool array, one flag per vertex (obstacles: never moved or re-connected).)doc")
      .def_property_readonly("vertices", &vertices_of, "The vertices, an (n, 3) float64 copy.")
      .def_property_readonly("triangles", &triangles_of,
                             "The triangles, an (m, 3) uint32 copy (a collapsed vertex stays, "
                             "used by none).")
      .def(
          "relocate_vertex",
          [](Surface& s, std::int64_t v, const py::object& to) {
            const Point3 target = point_of(to, "to");
            return outcome_dict(remesh::relocate_vertex(s, vertex_of(s, v), target));
          },
          py::arg("vertex"), py::arg("to"), "Moves a vertex on a straight line.")
      .def("relocate_vertices", &relocate_many, py::arg("indices"), py::arg("targets"),
           R"doc(Moves many vertices at once (a smoothing pass), checked as one motion by the
mesh broad phase; the moves that would collide are refused and the others made. Returns a
bool array, True where the move was made. The GIL is released.)doc")
      .def(
          "collapse_edge",
          [](Surface& s, std::int64_t a, std::int64_t b, const py::object& to) {
            const Point3 target = point_of(to, "to");
            return outcome_dict(remesh::collapse_edge(s, vertex_of(s, a), vertex_of(s, b), target));
          },
          py::arg("a"), py::arg("b"), py::arg("to"),
          "Merges a and b into a, at `to` (both move there on straight lines).")
      .def(
          "flip_edge",
          [](Surface& s, std::int64_t a, std::int64_t b) {
            return outcome_dict(remesh::flip_edge(s, vertex_of(s, a), vertex_of(s, b)));
          },
          py::arg("a"), py::arg("b"), "Replaces triangles abc and bad by cad and dbc.")
      .def(
          "split_edge",
          [](Surface& s, std::int64_t a, std::int64_t b, const py::object& at) {
            const Point3 point = point_of(at, "at");
            return outcome_dict(remesh::split_edge(s, vertex_of(s, a), vertex_of(s, b), point));
          },
          py::arg("a"), py::arg("b"), py::arg("at"), "Splits edge ab at a new vertex `at`.")
      .def("flip_edges", &flip_many, py::arg("edges"),
           R"doc(A pass of flips over the (k, 2) edges: a flip near an earlier one of the pass is
deferred (verdict "deferred"), the others checked in one pass over the surface. One dict
per edge. The GIL is released.)doc")
      .def("split_edges", &split_many, py::arg("edges"), py::arg("points"),
           R"doc(A pass of splits of the (k, 2) edges at the (k, 3) points, as flip_edges. One
dict per split. The GIL is released.)doc")
      .def("collapse_edges", &collapse_many, py::arg("edges"), py::arg("points"),
           R"doc(A pass of collapses: edge (a, b) of the (k, 2) edges merged into a at the
matching one of the (k, 3) points. A collapse near an earlier one of the pass is deferred;
the others' motions are checked together by the mesh broad phase and their results by the
exact self-intersection finder. One dict per collapse. The GIL is released.)doc");
}

}  // namespace exactgeo::python
