// Every other format, through assimp (assimp_reader.hpp, internal): a tetrahedron written
// as RAW text (a triangle a line) from a file, from memory and by load_mesh's extension,
// read with coordinates rounded to float (0.1 becomes the float nearest 0.1) and always
// welded, the format named "assimp raw"; a quad (OFF, read by assimp) kept a quad; and
// errors naming the source for an extension assimp does not take, no extension, a missing
// file and a scene without faces.

#include "../../mesh/src/assimp_reader.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <fstream>
#include <string>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "mesh/mesh_io.hpp"
#include "support/scratch_dir.hpp"

namespace exactgeo::mesh::internal {
namespace {

using test_io::error_of;

/// A tetrahedron of four outward triangles, one corner at 0.1 (no float holds it).
const std::array<std::array<Point3, 3>, 4> kTetrahedron{{
    {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}},
    {{{0, 0, 0}, {1, 0, 0}, {0, 0, 0.1}}},
    {{{0, 0, 0}, {0, 0, 0.1}, {0, 1, 0}}},
    {{{1, 0, 0}, {0, 1, 0}, {0, 0, 0.1}}},
}};

std::string tetrahedron_raw() {
  std::string raw;
  for (const auto& t : kTetrahedron) {
    for (const Point3& p : t) {
      for (const double x : p)
        raw.append(test_io::decimal(x)).append(" ");
    }
    raw.back() = '\n';
  }
  return raw;
}

/// The mesh read is the tetrahedron, each coordinate rounded to float, welded.
void expect_tetrahedron(const LoadedMesh& m) {
  EXPECT_EQ(m.format, "assimp raw");
  EXPECT_TRUE(m.coordinates_via_float);
  ASSERT_EQ(m.mesh.vertices.size(), 4u);
  EXPECT_EQ(m.welded_vertices, 8u);
  ASSERT_EQ(m.mesh.faces.size(), 4u);
  for (std::size_t f = 0; f < 4; ++f) {
    ASSERT_TRUE(m.mesh.faces[f].is_triangle());
    for (std::size_t c = 0; c < 3; ++c) {
      const Point3& p = m.mesh.vertices[m.mesh.faces[f].corners[c]];
      for (int i = 0; i < 3; ++i) {
        const double x = kTetrahedron[f][c][static_cast<std::size_t>(i)];
        EXPECT_EQ(p[static_cast<std::size_t>(i)], static_cast<double>(static_cast<float>(x)))
            << "face " << f << " corner " << c;
      }
    }
  }
  const MeshCheck check = check_mesh(m.mesh);
  EXPECT_TRUE(check.closed());
  EXPECT_EQ(check.consistently_oriented, std::optional<bool>(true));
}

TEST(AssimpReader, RawTextFromAFileFromMemoryAndByExtension) {
  const exactgeo::testing::ScratchDir dir("exactgeo_assimp_reader");
  const std::string path = (dir.path / "tetrahedron.raw").string();
  std::ofstream(path) << tetrahedron_raw();
  expect_tetrahedron(read_with_assimp(path, "raw", {}));
  expect_tetrahedron(read_with_assimp_from_memory(tetrahedron_raw(), "<raw>", "raw", {}));
  expect_tetrahedron(load_mesh(path));
}

TEST(AssimpReader, AQuadStaysAQuad) {
  // No post-process triangulates: OFF read by assimp (not by exactgeo's reader) keeps its
  // quad, corner order and all.
  const LoadedMesh m = read_with_assimp_from_memory(
      "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", "<quad>", "off", {});
  EXPECT_EQ(m.format, "assimp off");
  ASSERT_EQ(m.mesh.faces.size(), 1u);
  ASSERT_FALSE(m.mesh.faces[0].is_triangle());
  ASSERT_EQ(m.mesh.vertices.size(), 4u);
  const std::array<Point3, 4> corners{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  for (std::size_t c = 0; c < 4; ++c)
    EXPECT_EQ(m.mesh.vertices[m.mesh.faces[0].corners[c]], corners[c]) << "corner " << c;
}

TEST(AssimpReader, ErrorsNameTheSource) {
  EXPECT_MESSAGE_HAS(error_of([] { (void)read_with_assimp_from_memory("x", "<in>", "xyzzy", {}); }),
                     "<in>: unsupported mesh format 'xyzzy'");
  EXPECT_MESSAGE_HAS(error_of([] { (void)read_with_assimp_from_memory("x", "<in>", "", {}); }),
                     "<in>: unsupported mesh format (no file extension");
  const exactgeo::testing::ScratchDir dir("exactgeo_assimp_reader_errors");
  const std::string missing = (dir.path / "missing.raw").string();
  EXPECT_MESSAGE_HAS(error_of([&] { (void)read_with_assimp(missing, "raw", {}); }), missing,
                     "cannot open");
  EXPECT_MESSAGE_HAS(
      error_of([] { (void)read_with_assimp_from_memory("\n\n", "<blank>", "raw", {}); }),
      "<blank>: assimp cannot read it");
  // A segment is no face: assimp's scene has a line only, and the mesh has no faces.
  EXPECT_MESSAGE_HAS(error_of([] {
                       (void)read_with_assimp_from_memory(
                           "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "<segment>", "off", {});
                     }),
                     "<segment>: the mesh has no faces");
}

}  // namespace
}  // namespace exactgeo::mesh::internal
