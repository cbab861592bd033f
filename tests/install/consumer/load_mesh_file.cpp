// Uses exactgeo::mesh_files from an installed exactgeo (built only when the consumer asks
// for it, with assimp available): loads the mesh file given on the command line, through
// the exact reader and through assimp, and checks that both agree and that it is closed.

#include <cstdio>
#include <exception>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::printf("usage: load_mesh_file MESH.off MESH.raw\n");
    return 2;
  }
  try {
    const exactgeo::mesh::LoadedMesh exact = exactgeo::mesh::load_mesh(argv[1]);
    const exactgeo::mesh::LoadedMesh via_assimp =
        exactgeo::mesh::load_mesh(argv[2], {.weld = true});
    const bool ok = exact.format == "off" && via_assimp.coordinates_via_float &&
                    exactgeo::mesh::check_mesh(exact.mesh).closed() &&
                    exactgeo::mesh::check_mesh(via_assimp.mesh).closed();
    std::printf("%s: load_mesh through the exact reader and through assimp\n",
                ok ? "ok  " : "FAIL");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::printf("FAIL: exception: %s\n", e.what());
    return 1;
  }
}
