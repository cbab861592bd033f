#pragma once

// NumPy arrays and options into the extension: every batch function takes its arrays and
// its options through these checks, so a wrong shape, a non-finite coordinate, a number
// that would be rounded or truncated on the way in, or a bad option is a ValueError that
// names the argument and the row, never a crash, a silent NaN label or a different input.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "exact_numbers.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::python {

namespace py = pybind11;

/// A C-contiguous float64 array. Not an argument type: pybind11 would convert any input
/// into one on the way in, rounding int64 and long double values silently; arguments come
/// as objects and through coordinates().
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// `object` (an array or anything NumPy makes one of) as a C-contiguous float64 array of
/// `shape` (-1: any length), every value exactly as given. Real numbers only: float16,
/// float32 and float64 arrays and integers of up to 32 bits widen exactly; int64, uint64
/// and long double values, and the numbers of a list, tuple or object array (Python ints of
/// any size, floats, NumPy numbers), are taken when they are exactly doubles. Every other
/// dtype or element (complex, strings, booleans, other objects) is a TypeError; a wrong
/// shape, a NaN or infinity, or a value that is not exactly a double is a ValueError naming
/// the argument and the row, counted from `first_row` (a block of a larger array names the
/// rows of the whole). A C-contiguous float64 array is used as it is.
Doubles coordinates(const py::object& object, std::string_view name,
                    std::initializer_list<py::ssize_t> shape, std::size_t first_row = 0);

/// "(5, 2)": an array's shape as Python prints it.
std::string shape_text(const py::array& array);

/// Throws ValueError "<name> must have shape (n, 3), got (5, 2)" unless the array has
/// `shape`, where -1 stands for any length.
void require_shape(const py::array& array, std::string_view name,
                   std::initializer_list<py::ssize_t> shape);

/// Throws ValueError naming the first row (index along the first axis) that holds a NaN or
/// an infinity, counted from `first_row`. Precondition: the shape was checked (at least one
/// axis).
void require_finite(const Doubles& array, std::string_view name, std::size_t first_row = 0);

/// The vertex indices of a faces argument: `object` (an (m, k) integer array, a list of
/// rows, an object array) as a C-contiguous (m, k) array, k one of `widths`; an empty list
/// is (0, first width). Integer dtypes only (a float array is a ValueError naming its
/// dtype); the elements of a list or an object array by corner_index (exact_numbers.hpp); every
/// index is checked against `range` as given (a uint64 index never wraps).
py::array_t<VertexIndex> vertex_indices(const py::object& object, std::string_view name,
                                        std::initializer_list<py::ssize_t> widths,
                                        const IndexRange& range);

/// The rows of an (n, 3) array as points. Precondition: require_shape(array, ..., {-1, 3}).
std::span<const Point3> points_of(const Doubles& array);

/// "exact" or "double"; throws ValueError listing the choices.
Arithmetic arithmetic_named(std::string_view name);

/// "exact", "parity", "double", "rational" or "cubic"; throws ValueError listing them.
ccd::Method ccd_method_named(std::string_view name);

/// A thread count: 0 for one per hardware thread; throws ValueError when negative.
unsigned thread_count(int threads);

/// Throws OSError (FileNotFoundError, PermissionError, ...) with the path when the file
/// cannot be opened for reading: Python code tells a missing file from a malformed one.
void require_openable(const std::filesystem::path& path);

}  // namespace exactgeo::python
