#include "arrays.hpp"

#include <cmath>
#include <cstdio>

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

void require_finite(const Doubles& array, std::string_view name) {
  const double* values = array.data();
  const auto size = static_cast<std::size_t>(array.size());
  for (std::size_t i = 0; i < size; ++i) {
    if (std::isfinite(values[i])) continue;
    const std::size_t row_length = size / static_cast<std::size_t>(array.shape(0));
    throw py::value_error(std::string(name) + "[" + std::to_string(i / row_length) +
                          "] has a non-finite coordinate (" + std::to_string(values[i]) + ")");
  }
}

Doubles coordinates(const py::object& object, std::string_view name,
                    std::initializer_list<py::ssize_t> shape) {
  const py::array array = py::array::ensure(object);
  if (!array) throw py::type_error(std::string(name) + " must be an array of coordinates");
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::type_error(std::string(name) + " must hold real numbers, got dtype " +
                         std::string(py::str(array.dtype())));
  }
  require_shape(array, name, shape);
  Doubles doubles = Doubles::ensure(array);
  require_finite(doubles, name);
  return doubles;
}

Indices integer_array(const py::object& object, std::string_view name) {
  const py::array array = py::array::ensure(object);
  if (!array) throw py::value_error(std::string(name) + " must be an array of integers");
  const char kind = array.dtype().kind();
  // An empty list becomes a float64 array: no index is lost in converting it.
  if (kind != 'i' && kind != 'u' && array.size() > 0) {
    throw py::value_error(std::string(name) + " must hold integers, got dtype " +
                          std::string(py::str(array.dtype())));
  }
  return Indices::ensure(array);
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
