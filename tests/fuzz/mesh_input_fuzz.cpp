// libFuzzer target for the exact mesh readers behind `exactgeo inside` and `exactgeo info`:
// OBJ, OFF, PLY and STL (ASCII and binary), from memory. The first byte picks the reader
// (byte % 4: OBJ, OFF, PLY, STL) and the options (bit 2: split polygons, bit 3: weld); the
// rest is the file. Invariants on every input:
//   - no crash, no sanitizer report, no huge allocation from a declared count;
//   - either an InputError whose message names "<fuzz>", or a mesh with at least one face,
//     every face a triangle or a quad whose corners index existing vertices, and every
//     coordinate finite (and the same after welding);
//   - STL: every face a triangle, and the vertices welded: three per face before welding,
//     none left to weld after; with the weld option, every reader leaves none to weld.
//
// Build with clang (EXACTGEO_BUILD_FUZZERS) and run e.g.
//   build-fuzz/bin/mesh_input_fuzz -max_total_time=300 <copy of tests/fuzz/corpus/mesh>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/loaded_mesh.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "exactgeo/mesh/stl_reader.hpp"
#include "exactgeo/mesh/weld.hpp"

namespace {

using exactgeo::mesh::kNoVertex;
using exactgeo::mesh::Mesh;

void check(bool condition) {
  if (!condition) std::abort();
}

void check_mesh(const Mesh& mesh) {
  check(!mesh.faces.empty());
  for (const auto& p : mesh.vertices) {
    for (const double x : p)
      check(std::isfinite(x));
  }
  for (const auto& face : mesh.faces) {
    for (std::size_t c = 0; c < 3; ++c)
      check(face.corners[c] < mesh.vertices.size());
    check(face.corners[3] == kNoVertex || face.corners[3] < mesh.vertices.size());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  exactgeo::mesh::LoadOptions options;
  options.split_polygons = (data[0] & 4) != 0;
  options.weld = (data[0] & 8) != 0;
  const std::string source = "<fuzz>";
  exactgeo::mesh::LoadedMesh loaded;
  try {
    switch (data[0] % 4) {
      case 0:
        loaded = exactgeo::mesh::read_obj(bytes, source, options);
        break;
      case 1:
        loaded = exactgeo::mesh::read_off(bytes, source, options);
        break;
      case 2:
        loaded = exactgeo::mesh::read_ply(bytes, source, options);
        break;
      default:
        loaded = exactgeo::mesh::read_stl(bytes, source, options);
        break;
    }
  } catch (const exactgeo::io::InputError& e) {
    check(std::string_view(e.what()).find(source) != std::string_view::npos);
    return 0;
  }
  check_mesh(loaded.mesh);
  // A split polygon's triangles keep its number: file faces in order, one or more each.
  const auto& file_faces = loaded.numbering.file_faces;
  check(file_faces.empty() || file_faces.size() == loaded.mesh.faces.size());
  for (std::size_t f = 1; f < file_faces.size(); ++f)
    check(file_faces[f] == file_faces[f - 1] || file_faces[f] == file_faces[f - 1] + 1);
  if (loaded.format.starts_with("stl")) {
    check(loaded.mesh.vertices.size() + loaded.welded_vertices == 3 * loaded.mesh.faces.size());
    for (const auto& face : loaded.mesh.faces)
      check(face.is_triangle());
    Mesh again = loaded.mesh;
    check(exactgeo::mesh::weld_vertices(again) == 0);
  }
  if (options.weld) {
    // Welded by the reader, before its polygons were split: nothing is left to weld.
    check(exactgeo::mesh::weld_vertices(loaded.mesh) == 0);
  }
  return 0;
}
