#include "exact_numbers.hpp"

#include <pybind11/numpy.h>

#include <cmath>

namespace exactgeo::python {

// The integer rule at its edges: 2^53 + 1 needs 54 significant bits, 2^63 and 2^60 + 2^8
// need one and 53, and 2^64 - 1 needs 64.
static_assert(exactly_double(std::uint64_t{1} << 53));
static_assert(!exactly_double((std::uint64_t{1} << 53) + 1));
static_assert(exactly_double((std::uint64_t{1} << 60) + (std::uint64_t{1} << 8)));
static_assert(!exactly_double((std::uint64_t{1} << 60) + (std::uint64_t{1} << 7)));
static_assert(exactly_double(std::uint64_t{1} << 63));
static_assert(!exactly_double(~std::uint64_t{0}));
static_assert(exactly_double(std::numeric_limits<std::int64_t>::min()));
static_assert(!exactly_double(std::numeric_limits<std::int64_t>::max()));
static_assert(!exactly_double(-(std::int64_t{1} << 53) - 1));

bool exactly_double(long double value) {
  return std::fabs(value) <= std::numeric_limits<double>::max() &&
         static_cast<long double>(static_cast<double>(value)) == value;
}

std::string Where::text() const {
  if (!row) return std::string(name);
  return std::string(name) + "[" + std::to_string(*row) + "]";
}

namespace {

constexpr std::string_view kIntegerBits =
    "an integer beyond 2^53 is a double only when it has at most 53 significant bits";
constexpr std::string_view kBetweenDoubles = "it lies between two doubles";
constexpr std::string_view kBeyondDoubles = "beyond the largest double";
constexpr std::string_view kRoundFirst =
    "; round it first (float(x), or .astype(numpy.float64) for an array) to use the nearest "
    "double";

/// repr(value); for an int of more than 128 bits, its size instead of its digits.
std::string repr_of(py::handle value) {
  if (PyLong_Check(value.ptr())) {
    const auto bits = value.attr("bit_length")().cast<std::size_t>();
    if (bits > 128) return "an int of " + std::to_string(bits) + " bits";
  }
  return py::repr(value);
}

/// "2.9 (numpy.float32)": the value and its type.
std::string described(py::handle value) {
  return repr_of(value) + " (" + Py_TYPE(value.ptr())->tp_name + ")";
}

/// A long double as NumPy prints it: the fewest digits that tell it from its neighbours.
std::string text_of(long double value) {
  py::array_t<long double> scalar(py::ssize_t{1});
  scalar.mutable_data()[0] = value;
  return py::str(scalar.attr("__getitem__")(0));
}

/// `roundable`: the nearest double is finite, so rounding first is a way out.
[[noreturn]] void refuse_inexact(const Where& where, const std::string& value, std::string_view why,
                                 bool roundable) {
  const char* is = where.row ? " has a coordinate that is" : " is";
  throw py::value_error(where.text() + is + " not exactly a double: " + value + " (" +
                        std::string(why) + ")" +
                        (roundable ? std::string(kRoundFirst) : std::string()));
}

[[noreturn]] void refuse_not_real(py::handle value, const Where& where) {
  if (!where.row) {
    throw py::type_error(std::string(where.name) +
                         " must be a real number (an int, a float or a NumPy number), got " +
                         described(value));
  }
  throw py::type_error(std::string(where.name) + " must hold real numbers, got " +
                       described(value) + " in " + where.text());
}

/// A Python int (of any size) as a double, when it is exactly one.
double python_int_coordinate(py::handle integer, const Where& where) {
  const double value = PyLong_AsDouble(integer.ptr());
  if (value == -1.0 && PyErr_Occurred()) {  // OverflowError: beyond the largest double
    PyErr_Clear();
    refuse_inexact(where, repr_of(integer), kBeyondDoubles, false);
  }
  // Python compares an int with a float exactly, neither rounded to the other's type.
  const int equal = PyObject_RichCompareBool(py::float_(value).ptr(), integer.ptr(), Py_EQ);
  if (equal < 0) throw py::error_already_set();
  if (equal == 0) refuse_inexact_integer(where, repr_of(integer));
  return value;
}

/// `value` as a 0-d array of its own dtype when it is a NumPy number (a scalar or a 0-d
/// array) of an integer or floating dtype.
std::optional<py::array> numpy_number(py::handle value) {
  const py::module_ numpy = py::module_::import("numpy");
  const bool zero_dimensional =
      py::isinstance<py::array>(value) && py::reinterpret_borrow<py::array>(value).ndim() == 0;
  if (!zero_dimensional && !py::isinstance(value, numpy.attr("generic"))) return std::nullopt;
  py::array scalar = py::array::ensure(value);
  const char kind = scalar ? scalar.dtype().kind() : '\0';
  if (kind != 'i' && kind != 'u' && kind != 'f') return std::nullopt;
  return scalar;
}

/// The one element of a 0-d array, converted to Number (exactly: the callers pick a Number
/// that holds every value of the array's dtype).
template <typename Number>
Number only_element(const py::array& scalar) {
  return py::array_t<Number, py::array::forcecast>::ensure(scalar).data()[0];
}

/// A NumPy number (numpy_number) as a coordinate, read in its own dtype.
double numpy_coordinate(const py::array& scalar, const Where& where) {
  switch (scalar.dtype().kind()) {
    case 'i':
      return coordinate(only_element<std::int64_t>(scalar), where);
    case 'u':
      return coordinate(only_element<std::uint64_t>(scalar), where);
    default:  // 'f': float16, float32 and float64 widen to double exactly
      if (scalar.dtype().itemsize() > static_cast<py::ssize_t>(sizeof(double))) {
        return coordinate(only_element<long double>(scalar), where);
      }
      return coordinate(only_element<double>(scalar), where);
  }
}

bool is_bool(py::handle value) {
  if (PyBool_Check(value.ptr())) return true;
  if (py::isinstance<py::array>(value)) {
    return py::reinterpret_borrow<py::array>(value).dtype().kind() == 'b';
  }
  return py::isinstance(value, py::module_::import("numpy").attr("bool_"));
}

/// `value` as a Python int when it is an integer: an int, or anything else with __index__
/// (NumPy integers, 0-d integer arrays) but a bool (True has __index__, but a bool array is
/// not indices either). Floats, Fractions and Decimals have no __index__.
std::optional<py::object> integer_of(py::handle value) {
  PyObject* object = value.ptr();
  if (PyLong_Check(object) && !PyBool_Check(object))
    return py::reinterpret_borrow<py::object>(value);
  if (!PyIndex_Check(object) || is_bool(value)) return std::nullopt;
  PyObject* integer = PyNumber_Index(object);
  if (integer == nullptr) {
    PyErr_Clear();
    return std::nullopt;
  }
  return py::reinterpret_steal<py::object>(integer);
}

}  // namespace

void refuse_non_finite(const Where& where, const std::string& value) {
  const char* is = where.row ? " has a non-finite coordinate (" : " is not finite (";
  throw py::value_error(where.text() + is + value + ")");
}

void refuse_inexact_integer(const Where& where, const std::string& value) {
  refuse_inexact(where, value, kIntegerBits, true);
}

double coordinate(long double value, const Where& where) {
  if (!std::isfinite(value)) refuse_non_finite(where, std::to_string(value));
  if (!exactly_double(value)) {
    const bool in_range = std::fabs(value) <= std::numeric_limits<double>::max();
    refuse_inexact(where, "the long double " + text_of(value),
                   in_range ? kBetweenDoubles : kBeyondDoubles, in_range);
  }
  return static_cast<double>(value);
}

double coordinate(py::handle value, const Where& where) {
  PyObject* object = value.ptr();
  if (PyFloat_Check(object))
    return coordinate(PyFloat_AS_DOUBLE(object), where);  // numpy.float64 too
  if (PyLong_Check(object) && !PyBool_Check(object)) return python_int_coordinate(value, where);
  if (const std::optional<py::array> scalar = numpy_number(value)) {
    return numpy_coordinate(*scalar, where);
  }
  refuse_not_real(value, where);
}

double option_number(py::handle value, std::string_view name) {
  return coordinate(value, Where{name, std::nullopt});  // a bool is refused there
}

IndexRange vertex_range(std::optional<std::uint64_t> vertex_count) {
  // The largest VertexIndex marks a missing corner (mesh::kNoVertex): it is no vertex's.
  constexpr std::uint64_t kIndices = std::numeric_limits<VertexIndex>::max();
  if (!vertex_count || *vertex_count > kIndices) {
    return {kIndices, "but a vertex index is at most " + std::to_string(kIndices - 1)};
  }
  if (*vertex_count == 0) return {0, "but there are no vertices"};
  return {*vertex_count, "but the vertices are 0.." + std::to_string(*vertex_count - 1)};
}

void refuse_corner(const Where& where, std::string_view given, const IndexRange& range) {
  throw py::value_error(where.text() + " has corner index " + std::string(given) + ", " +
                        range.text);
}

VertexIndex corner_index(py::handle corner, const Where& where, const IndexRange& range) {
  const std::optional<py::object> integer = integer_of(corner);
  if (!integer) {
    throw py::value_error(where.text() +
                          " holds a corner that is not an integer: " + described(corner));
  }
  int overflow = 0;
  const long long value = PyLong_AsLongLongAndOverflow(integer->ptr(), &overflow);
  if (overflow != 0) refuse_corner(where, repr_of(*integer), range);
  return corner_index(value, where, range);
}

std::uint64_t count_of(py::handle value, std::string_view name, std::uint64_t largest) {
  const std::optional<py::object> integer = integer_of(value);
  if (!integer) {
    throw py::type_error(std::string(name) + " must be an integer, got " + described(value));
  }
  int overflow = 0;
  const long long count = PyLong_AsLongLongAndOverflow(integer->ptr(), &overflow);
  if (overflow != 0 || std::cmp_less(count, 0) || std::cmp_greater(count, largest)) {
    throw py::value_error(std::string(name) + " must be in 0.." + std::to_string(largest) +
                          ", got " + repr_of(*integer));
  }
  return static_cast<std::uint64_t>(count);
}

}  // namespace exactgeo::python
