// The _exactgeo extension module. Python code imports the package `exactgeo`, whose
// __init__.py re-exports what is bound here.

#include <pybind11/pybind11.h>

#include <exception>

#include "bindings.hpp"
#include "exactgeo/io/input_error.hpp"

PYBIND11_MODULE(_exactgeo, module) {
  namespace py = pybind11;
  module.doc() =
      "Exact geometric predicates: point-in-volume classification against closed meshes of "
      "quads (bilinear patches) and triangles, continuous collision detection, orient3d.";
  module.attr("__version__") = EXACTGEO_VERSION;

  // Malformed input from a file (a bad number, an index out of range, a truncated PLY) is
  // a ValueError with the file and line; a file that cannot be opened is an OSError,
  // raised before reading (arrays.hpp, require_openable).
  py::register_exception_translator([](std::exception_ptr failure) {
    try {
      if (failure) std::rethrow_exception(failure);
    } catch (const exactgeo::io::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  exactgeo::python::bind_predicates(module);
  exactgeo::python::bind_mesh(module);
  exactgeo::python::bind_inside(module);
  exactgeo::python::bind_ccd(module);
  exactgeo::python::bind_mesh_ccd(module);
  exactgeo::python::bind_remesh(module);
}
