#pragma once

// What a Python `exactgeo.Mesh` holds: the mesh as the library sees it, and where it came
// from (the file and what loading it did), for Mesh.info().

#include <optional>
#include <string>

#include "exactgeo/mesh/loaded_mesh.hpp"

namespace exactgeo::python {

struct MeshObject {
  mesh::LoadedMesh loaded;
  std::optional<std::string> file;  ///< none for a mesh made from arrays
};

}  // namespace exactgeo::python
