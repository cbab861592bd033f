// exactgeo.vertex_face_ccd, exactgeo.edge_edge_ccd and the benchmark's query files.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"
#include "exactgeo/parallel/blocks.hpp"

namespace exactgeo::python {

namespace {

using ccd::QueryRecord;
using ccd::QueryType;

constexpr std::size_t kBlock = 256;  // queries per parallel block

ccd::Options options_from(const std::string& method, const py::object& toi_width_in,
                          const py::object& cubic_tolerance_in,
                          const py::object& min_separation_in) {
  ccd::Options options;
  options.method = ccd_method_named(method);
  const double min_separation = option_number(min_separation_in, "min_separation");
  const double cubic_tolerance = option_number(cubic_tolerance_in, "cubic_tolerance");
  const std::optional<double> toi_width =
      toi_width_in.is_none() ? std::nullopt
                             : std::optional(option_number(toi_width_in, "toi_width"));
  if (!ccd::is_valid_min_separation(min_separation)) {
    throw py::value_error("min_separation must be finite and >= 0");
  }
  if (min_separation > 0.0 && options.method != ccd::Method::exact &&
      options.method != ccd::Method::plain_double) {
    throw py::value_error(
        "min_separation needs method='exact' (or 'double': the per-axis box test in plain "
        "doubles)");
  }
  options.min_separation = min_separation;
  if (toi_width) {
    if (options.method != ccd::Method::exact) {
      throw py::value_error(
          "toi_width needs method='exact' (the other methods only say whether "
          "a pair collides)");
    }
    if (!(*toi_width > 0.0 && *toi_width <= 1.0)) {
      throw py::value_error("toi_width must be in (0, 1], got " +
                            std::string(py::repr(toi_width_in)));
    }
    options.time_of_impact_width = toi_width;
  }
  if (!(cubic_tolerance >= 0.0 && std::isfinite(cubic_tolerance))) {
    throw py::value_error("cubic_tolerance must be finite and >= 0");
  }
  options.cubic_tolerance = cubic_tolerance;
  return options;
}

/// Runs one query type over (n, 4, 3) start and end positions: a bool array, and with
/// toi_width an (n, 2) array of brackets (NaN rows where there is no collision).
template <ccd::QueryType type>
py::object run_queries(const py::object& x0_in, const py::object& x1_in, const std::string& method,
                       const py::object& toi_width, const py::object& cubic_tolerance, int threads,
                       const py::object& min_separation) {
  const ccd::Options options = options_from(method, toi_width, cubic_tolerance, min_separation);
  const Doubles x0 = coordinates(x0_in, "x0", {-1, 4, 3});
  const Doubles x1 = coordinates(x1_in, "x1", {-1, 4, 3});
  if (x0.shape(0) != x1.shape(0)) {
    throw py::value_error("x0 has " + std::to_string(x0.shape(0)) + " queries, x1 has " +
                          std::to_string(x1.shape(0)));
  }
  const unsigned workers = thread_count(threads);
  const auto n = static_cast<std::size_t>(x0.shape(0));
  const bool with_toi = options.time_of_impact_width.has_value();

  py::array_t<bool> collisions(static_cast<py::ssize_t>(n));
  py::array_t<double> brackets({static_cast<py::ssize_t>(with_toi ? n : 0), py::ssize_t{2}});
  bool* hit = collisions.mutable_data();
  double* toi = brackets.mutable_data();
  const Point3* start = points_of(x0).data();
  const Point3* end = points_of(x1).data();
  {
    py::gil_scoped_release release;
    parallel::for_each_block((n + kBlock - 1) / kBlock, workers, [&](std::size_t block) {
      QueryRecord record;
      for (std::size_t i = block * kBlock; i < std::min(n, (block + 1) * kBlock); ++i) {
        std::copy_n(start + 4 * i, 4, record.points.begin());
        std::copy_n(end + 4 * i, 4, record.points.begin() + 4);
        ccd::Result result;
        if constexpr (type == QueryType::vertex_face) {
          result = ccd::vertex_face_ccd(ccd::vertex_face_query(record), options);
        } else {
          result = ccd::edge_edge_ccd(ccd::edge_edge_query(record), options);
        }
        hit[i] = result.collision;
        if (with_toi) {
          constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
          toi[2 * i] = result.time_of_impact ? result.time_of_impact->start : kNone;
          toi[2 * i + 1] = result.time_of_impact ? result.time_of_impact->end : kNone;
        }
      }
    });
  }
  if (!with_toi) return collisions;
  return py::make_tuple(collisions, brackets);
}

const char* type_name(QueryType type) {
  return type == QueryType::vertex_face ? "vertex-face" : "edge-edge";
}

/// (type, x0, x1, truth or None) for every query of a file or folder of one type.
py::tuple read_queries(const std::filesystem::path& path, std::optional<std::string> type_name_in) {
  std::optional<QueryType> type;
  if (type_name_in) {
    if (*type_name_in == "vertex-face") {
      type = QueryType::vertex_face;
    } else if (*type_name_in == "edge-edge") {
      type = QueryType::edge_edge;
    } else {
      throw py::value_error("type must be 'vertex-face' or 'edge-edge', got '" + *type_name_in +
                            "'");
    }
  }
  if (!std::filesystem::is_directory(path)) require_openable(path);
  std::vector<ccd::QueryFile> files;
  {
    py::gil_scoped_release release;
    files = ccd::read_query_files({path.string()}, type);
  }
  std::size_t n = 0;
  bool all_truth = true;
  for (const ccd::QueryFile& file : files) {
    if (file.type != files.front().type) {
      throw py::value_error(path.string() + " holds both vertex-face and edge-edge files (" +
                            file.path + "); read each type's folder on its own");
    }
    n += file.records.size();
    for (const QueryRecord& r : file.records)
      all_truth = all_truth && r.truth.has_value();
  }
  if (files.empty()) throw py::value_error(path.string() + ": no query file (*.csv) found");

  const auto rows = static_cast<py::ssize_t>(n);
  py::array_t<double> x0({rows, py::ssize_t{4}, py::ssize_t{3}});
  py::array_t<double> x1({rows, py::ssize_t{4}, py::ssize_t{3}});
  py::array_t<bool> truth(all_truth ? rows : 0);
  double* start = x0.mutable_data();
  double* end = x1.mutable_data();
  bool* known = truth.mutable_data();
  for (const ccd::QueryFile& file : files) {
    for (const QueryRecord& r : file.records) {
      for (std::size_t k = 0; k < 4; ++k) {
        start = std::copy(r.points[k].begin(), r.points[k].end(), start);
        end = std::copy(r.points[k + 4].begin(), r.points[k + 4].end(), end);
      }
      if (all_truth) *known++ = *r.truth;
    }
  }
  return py::make_tuple(type_name(files.front().type), x0, x1,
                        all_truth ? py::object(truth) : py::none());
}

constexpr const char* kCcdDoc = R"doc(

x0, x1: (n, 4, 3) positions at the start and the end of the step; each point moves on
    the straight line between them. Vertex-face rows are (vertex, face corner 0, 1, 2);
    edge-edge rows are (edge a's two ends, edge b's two ends).
method: "exact" (default: any contact in the closed step, never missed), "parity"
    (the 2012 root parity algorithm, blind to two roots), "double" (parity in plain
    doubles), "rational" (parity in GMP rationals), "cubic" (coplanarity times and a
    distance tolerance, cubic_tolerance).
toi_width: exact only: also return an (n, 2) array of time-of-impact brackets no wider
    than this: no contact before the first column, a contact by the second (NaN rows
    where there is no collision).
min_separation: a collision is then a time at which the primitives' Euclidean distance
    is at most this (default 0: contact), decided exactly (the brackets hold the earliest
    such time); with method="double", the per-axis box test in plain doubles instead.
threads: worker threads, 0 for all hardware threads. The GIL is released.

Returns an (n,) bool array, or (collisions, brackets) with toi_width.
Raises ValueError for a wrong shape or a coordinate that is not finite or not exactly a
double (naming its row), and for a negative, NaN or infinite min_separation.)doc";

}  // namespace

void bind_ccd(py::module_& module) {
  const std::string vf_doc =
      std::string("Continuous collision detection of moving vertices against moving triangles.") +
      kCcdDoc;
  const std::string ee_doc =
      std::string("Continuous collision detection of moving edges against moving edges.") + kCcdDoc;
  module.def("vertex_face_ccd", &run_queries<QueryType::vertex_face>, py::arg("x0"), py::arg("x1"),
             py::kw_only(), py::arg("method") = "exact", py::arg("toi_width") = py::none(),
             py::arg("cubic_tolerance") = 1e-6, py::arg("threads") = 0,
             py::arg("min_separation") = 0.0, vf_doc.c_str());
  module.def("edge_edge_ccd", &run_queries<QueryType::edge_edge>, py::arg("x0"), py::arg("x1"),
             py::kw_only(), py::arg("method") = "exact", py::arg("toi_width") = py::none(),
             py::arg("cubic_tolerance") = 1e-6, py::arg("threads") = 0,
             py::arg("min_separation") = 0.0, ee_doc.c_str());
  module.def("_read_ccd_queries", &read_queries, py::arg("path"), py::arg("type") = py::none());
}

}  // namespace exactgeo::python
