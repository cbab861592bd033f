#include "arrays.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <vector>

namespace exactgeo::python {

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t k = 0; k < array.ndim(); ++k) {
    if (k > 0) text += ", ";
    text += std::to_string(array.shape(k));
  }
  if (array.ndim() == 1) text += ",";
  return text + ")";
}

namespace {

std::string shape_text(std::initializer_list<py::ssize_t> shape) {
  std::string text = "(";
  const char* names[] = {"n", "m", "k"};
  std::size_t unnamed = 0;
  for (const py::ssize_t length : shape) {
    if (text.size() > 1) text += ", ";
    text += length < 0 ? std::string(names[unnamed++ % 3]) : std::to_string(length);
  }
  if (shape.size() == 1) text += ",";
  return text + ")";
}

}  // namespace

void require_shape(const py::array& array, std::string_view name,
                   std::initializer_list<py::ssize_t> shape) {
  bool matches = array.ndim() == static_cast<py::ssize_t>(shape.size());
  py::ssize_t axis = 0;
  for (const py::ssize_t length : shape) {
    if (!matches) break;
    matches = length < 0 || array.shape(axis) == length;
    ++axis;
  }
  if (!matches) {
    throw py::value_error(std::string(name) + " must have shape " + shape_text(shape) + ", got " +
                          shape_text(array));
  }
}

void require_finite(const Doubles& array, std::string_view name, std::size_t first_row) {
  const double* values = array.data();
  const double* end = values + array.size();
  // The search alone in the loop (libstdc++ unrolls it); the message is made outside.
  const double* bad = std::find_if_not(values, end, [](double x) { return std::isfinite(x); });
  if (bad == end) return;
  const auto row_length = static_cast<std::size_t>(array.size() / array.shape(0));
  coordinate(*bad,
             {name, first_row + static_cast<std::size_t>(bad - values) / row_length});  // throws
}

namespace {

std::vector<py::ssize_t> shape_of(const py::array& array) {
  return {array.shape(), array.shape() + array.ndim()};
}

/// A list or a tuple: NumPy would give its numbers their common type and round them into
/// it (a Python int and a float together become float64, and so do a uint64 and a negative
/// int), so they are read one by one instead, each as what it is.
bool is_python_sequence(const py::object& object) {
  return py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object);
}

/// A list's or tuple's elements as the Python objects they are, in a C-contiguous object
/// array of the nested lists' shape; none when NumPy makes no array of them.
std::optional<py::array> objects_of(const py::object& sequence) {
  const py::module_ numpy = py::module_::import("numpy");
  try {
    return numpy.attr("asarray")(sequence, py::arg("dtype") = numpy.attr("object_"),
                                 py::arg("order") = "C");
  } catch (const py::error_already_set&) {
    return std::nullopt;
  }
}

/// Calls `visit(element, where)` for each element of a C-contiguous array of Elements, in
/// order, with the element's row (counted from `first_row`).
template <typename Element, typename Visit>
void for_each_element(const py::array& array, std::string_view name, std::size_t first_row,
                      Visit&& visit) {
  const auto* elements = static_cast<const Element*>(array.data());
  const std::size_t rows = array.ndim() == 0 ? 1 : static_cast<std::size_t>(array.shape(0));
  const std::size_t row_length = rows == 0 ? 0 : static_cast<std::size_t>(array.size()) / rows;
  for (std::size_t row = 0; row < rows; ++row) {
    const Where where{name, first_row + row};
    for (std::size_t k = 0; k < row_length; ++k, ++elements)
      visit(*elements, where);
  }
}

/// The elements of a C-contiguous array of Elements (numbers, or PyObject* for an object
/// array) in a new float64 array of the same shape, each through `coordinate`: checked and
/// converted in one pass.
template <typename Element>
Doubles doubles_from(const py::array& array, std::string_view name, std::size_t first_row) {
  Doubles doubles(shape_of(array));
  double* out = doubles.mutable_data();
  for_each_element<Element>(array, name, first_row, [&](Element element, const Where& where) {
    if constexpr (std::is_same_v<Element, PyObject*>) {
      *out++ = coordinate(py::handle(element), where);
    } else {
      *out++ = coordinate(element, where);
    }
  });
  return doubles;
}

/// The same from an array of any dtype, first converted to Number without loss.
template <typename Number>
Doubles doubles_via(const py::array& array, std::string_view name, std::size_t first_row) {
  using Numbers = py::array_t<Number, py::array::c_style | py::array::forcecast>;
  return doubles_from<Number>(Numbers::ensure(array), name, first_row);
}

}  // namespace

Doubles coordinates(const py::object& object, std::string_view name,
                    std::initializer_list<py::ssize_t> shape, std::size_t first_row) {
  if (is_python_sequence(object)) {
    const std::optional<py::array> objects = objects_of(object);
    if (!objects) throw py::type_error(std::string(name) + " must be an array of coordinates");
    require_shape(*objects, name, shape);
    return doubles_from<PyObject*>(*objects, name, first_row);
  }
  const py::array array = py::array::ensure(object);
  if (!array) throw py::type_error(std::string(name) + " must be an array of coordinates");
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'O') {
    throw py::type_error(std::string(name) + " must hold real numbers, got dtype " +
                         std::string(py::str(array.dtype())));
  }
  require_shape(array, name, shape);
  if (kind == 'O')
    return doubles_from<PyObject*>(py::array::ensure(array, py::array::c_style), name, first_row);
  const auto itemsize = static_cast<std::size_t>(array.dtype().itemsize());
  if (kind == 'f' && itemsize > sizeof(double))
    return doubles_via<long double>(array, name, first_row);
  if (kind == 'i' && itemsize == 8) return doubles_via<std::int64_t>(array, name, first_row);
  if (kind == 'u' && itemsize == 8) return doubles_via<std::uint64_t>(array, name, first_row);
  // float16, float32, float64 and integers of up to 32 bits: every value is a double. A
  // C-contiguous float64 array is not copied; the others are converted exactly.
  Doubles doubles = Doubles::ensure(array);
  require_finite(doubles, name, first_row);
  return doubles;
}

namespace {

[[noreturn]] void refuse_face_shape(const py::array& array, std::string_view name,
                                    std::initializer_list<py::ssize_t> widths) {
  std::string expected;
  for (const py::ssize_t width : widths)
    expected +=
        (expected.empty() ? "" : " or ") + std::string("(m, ") + std::to_string(width) + ")";
  throw py::value_error(std::string(name) + " must have shape " + expected + ", got " +
                        python::shape_text(array));
}

bool has_face_shape(const py::array& array, std::initializer_list<py::ssize_t> widths) {
  return array.ndim() == 2 &&
         std::find(widths.begin(), widths.end(), array.shape(1)) != widths.end();
}

/// The checked indices of a C-contiguous array of Elements (integers, or PyObject*).
template <typename Element>
py::array_t<VertexIndex> indices_from(const py::array& array, std::string_view name,
                                      const IndexRange& range) {
  py::array_t<VertexIndex> indices(shape_of(array));
  VertexIndex* out = indices.mutable_data();
  for_each_element<Element>(array, name, 0, [&](Element element, const Where& where) {
    if constexpr (std::is_same_v<Element, PyObject*>) {
      *out++ = corner_index(py::handle(element), where, range);
    } else {
      *out++ = corner_index(element, where, range);
    }
  });
  return indices;
}

/// The checked indices of an array of any dtype (vertex_indices).
py::array_t<VertexIndex> indices_of(const py::array& array, std::string_view name,
                                    std::initializer_list<py::ssize_t> widths,
                                    const IndexRange& range) {
  // An empty list (or an empty array of any dtype) is no faces.
  if (array.size() == 0 && array.ndim() == 1) {
    return py::array_t<VertexIndex>(std::vector<py::ssize_t>{0, *widths.begin()});
  }
  if (!has_face_shape(array, widths)) refuse_face_shape(array, name, widths);
  if (array.size() == 0) return py::array_t<VertexIndex>(shape_of(array));  // no index to lose
  const char kind = array.dtype().kind();
  if (kind == 'O') {
    return indices_from<PyObject*>(py::array::ensure(array, py::array::c_style), name, range);
  }
  // Signed and unsigned dtypes apart: a uint64 of 2^63 or more would wrap in an int64.
  using Signed = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
  using Unsigned = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>;
  if (kind == 'i') return indices_from<std::int64_t>(Signed::ensure(array), name, range);
  if (kind == 'u') return indices_from<std::uint64_t>(Unsigned::ensure(array), name, range);
  throw py::value_error(std::string(name) + " must hold integers, got dtype " +
                        std::string(py::str(array.dtype())));
}

}  // namespace

py::array_t<VertexIndex> vertex_indices(const py::object& object, std::string_view name,
                                        std::initializer_list<py::ssize_t> widths,
                                        const IndexRange& range) {
  const std::optional<py::array> array =
      is_python_sequence(object) ? objects_of(object) : py::array::ensure(object);
  if (!array || !*array) {
    throw py::value_error(std::string(name) + " must be an array of integers");
  }
  return indices_of(*array, name, widths, range);
}

std::span<const Point3> points_of(const Doubles& array) {
  static_assert(sizeof(Point3) == 3 * sizeof(double), "Point3 is three packed doubles");
  return {reinterpret_cast<const Point3*>(array.data()), static_cast<std::size_t>(array.shape(0))};
}

Arithmetic arithmetic_named(std::string_view name) {
  const std::optional<Arithmetic> arithmetic = parse_arithmetic(name);
  if (!arithmetic || *arithmetic == Arithmetic::rational) {
    throw py::value_error("method must be 'exact' or 'double', got '" + std::string(name) + "'");
  }
  return *arithmetic;
}

ccd::Method ccd_method_named(std::string_view name) {
  const std::optional<ccd::Method> method = ccd::parse_method(name);
  if (!method) {
    throw py::value_error(
        "method must be 'exact', 'parity', 'double', 'rational' or 'cubic', got '" +
        std::string(name) + "'");
  }
  return *method;
}

unsigned thread_count(int threads) {
  if (threads < 0) {
    throw py::value_error("threads must be 0 (all hardware threads) or positive, got " +
                          std::to_string(threads));
  }
  return static_cast<unsigned>(threads);
}

void require_openable(const std::filesystem::path& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file != nullptr) {
    std::fclose(file);
    return;
  }
  PyErr_SetFromErrnoWithFilename(PyExc_OSError, path.c_str());
  throw py::error_already_set();
}

}  // namespace exactgeo::python
