#pragma once

// The parts of the _exactgeo extension module, one per library it binds. The module
// binds the libraries (predicates, mesh, inside, ccd), never the command-line tool.

#include <pybind11/pybind11.h>

namespace exactgeo::python {

void bind_predicates(pybind11::module_& module);  // orient3d
void bind_mesh(pybind11::module_& module);        // Mesh, load_mesh
void bind_inside(pybind11::module_& module);      // Classifier (needs Mesh)
void bind_ccd(pybind11::module_& module);         // vertex_face_ccd, edge_edge_ccd, query files
void bind_mesh_ccd(pybind11::module_& module);    // MeshCcd

}  // namespace exactgeo::python
