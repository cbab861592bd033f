// orient3d over arrays of points.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exactgeo/parallel/blocks.hpp"
#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::python {

namespace {

constexpr std::size_t kBlock = 4096;  // determinants per parallel block

py::object orient3d_arrays(const py::object& a_in, const py::object& b_in, const py::object& c_in,
                           const py::object& d_in, const std::string& method, int threads) {
  const Arithmetic arithmetic = arithmetic_named(method);
  const unsigned workers = thread_count(threads);
  // One point each, or one row per determinant.
  const py::array first = py::array::ensure(a_in);
  const bool single = first && first.ndim() == 1;
  const auto points = [single](const py::object& x, const char* name) {
    return single ? coordinates(x, name, {3}) : coordinates(x, name, {-1, 3});
  };
  const Doubles a = points(a_in, "a");
  const Doubles b = points(b_in, "b");
  const Doubles c = points(c_in, "c");
  const Doubles d = points(d_in, "d");
  for (const auto& [array, name] : {std::pair{&b, "b"}, std::pair{&c, "c"}, std::pair{&d, "d"}}) {
    if (array->shape(0) != a.shape(0)) {
      throw py::value_error(std::string(name) + " has " + std::to_string(array->shape(0)) +
                            " rows, a has " + std::to_string(a.shape(0)));
    }
  }
  const auto point = [](const Doubles& x, std::size_t i) {
    return reinterpret_cast<const Point3*>(x.data())[i];
  };
  if (single)
    return py::int_(
        to_int(orient3d(point(a, 0), point(b, 0), point(c, 0), point(d, 0), arithmetic)));

  const auto n = static_cast<std::size_t>(a.shape(0));
  py::array_t<std::int8_t> signs(static_cast<py::ssize_t>(n));
  std::int8_t* out = signs.mutable_data();
  {
    py::gil_scoped_release release;
    parallel::for_each_block((n + kBlock - 1) / kBlock, workers, [&](std::size_t block) {
      for (std::size_t i = block * kBlock; i < std::min(n, (block + 1) * kBlock); ++i) {
        out[i] = static_cast<std::int8_t>(
            to_int(orient3d(point(a, i), point(b, i), point(c, i), point(d, i), arithmetic)));
      }
    });
  }
  return signs;
}

}  // namespace

void bind_predicates(py::module_& module) {
  module.def("orient3d", &orient3d_arrays, py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
             py::kw_only(), py::arg("method") = "exact", py::arg("threads") = 0,
             R"doc(The sign of det[b - a, c - a, d - a], exactly.

Positive when d lies on the side of the plane (a, b, c) from which a, b, c appear
counter-clockwise (the side (b - a) x (c - a) points to): orient3d((0,0,0), (1,0,0),
(0,1,0), (0,0,1)) is positive.

a, b, c, d: points of shape (3,), or arrays of shape (n, 3) (one determinant per row),
    each coordinate exactly a double (ints and other dtypes are converted exactly or
    refused: see docs/python.md).
method: "exact" (default; correct for every finite input, subnormal and huge values
    included) or "double" (the determinant rounded in plain doubles, for comparison).
threads: worker threads, 0 for all hardware threads.

Returns an int (-1, 0, 1) for single points, an int8 array of shape (n,) for arrays.
Raises ValueError for a wrong shape, or for a coordinate that is not finite or not exactly
a double (naming its row).)doc");
}

}  // namespace exactgeo::python
