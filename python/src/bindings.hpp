#pragma once

// The parts of the _exactgeo extension module, one per library it binds. The module
// binds the libraries (predicates, mesh, inside, ccd), never the command-line tool.

#include <pybind11/pybind11.h>

#include <string>

namespace exactgeo::python {

/// A UserWarning with `message`: what the command line says on stderr, Python says so.
inline void warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) {
    throw pybind11::error_already_set();
  }
}

void bind_predicates(pybind11::module_& module);  // orient3d
void bind_mesh(pybind11::module_& module);        // Mesh, load_mesh
void bind_inside(pybind11::module_& module);      // Classifier (needs Mesh)
void bind_ccd(pybind11::module_& module);         // vertex_face_ccd, edge_edge_ccd, query files
void bind_mesh_ccd(pybind11::module_& module);    // MeshCcd
void bind_remesh(pybind11::module_& module);      // Surface (collision-safe operations)

}  // namespace exactgeo::python
