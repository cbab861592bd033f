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
#include <cstdint>
#include <exception>
#include <fstream>
#include <string>
#include <utility>

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

/// A tetrahedron in AMF, the XML format.
std::string tetrahedron_amf() {
  std::string amf =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<amf unit=\"millimeter\">\n"
      "<object id=\"0\"><mesh><vertices>\n";
  for (const char* xyz : {"<x>0</x><y>0</y><z>0</z>", "<x>1</x><y>0</y><z>0</z>",
                          "<x>0</x><y>1</y><z>0</z>", "<x>0</x><y>0</y><z>1</z>"}) {
    amf.append("<vertex><coordinates>").append(xyz).append("</coordinates></vertex>\n");
  }
  amf.append("</vertices><volume>\n");
  for (const char* t : {"<v1>0</v1><v2>2</v2><v3>1</v3>", "<v1>0</v1><v2>1</v2><v3>3</v3>",
                        "<v1>0</v1><v2>3</v2><v3>2</v3>", "<v1>1</v1><v2>2</v2><v3>3</v3>"}) {
    amf.append("<triangle>").append(t).append("</triangle>\n");
  }
  amf.append("</volume></mesh></object>\n</amf>\n");
  return amf;
}

/// The bytes of `value`, little-endian, in `size` bytes.
void put(std::string& out, std::uint32_t value, int size) {
  for (int i = 0; i < size; ++i)
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
}

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (const char c : bytes) {
    crc ^= static_cast<unsigned char>(c);
    for (int k = 0; k < 8; ++k)
      crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

/// A zip archive holding `content` as the file `name`, stored (the AMF format's compressed
/// form is a zip archive holding the XML; how it is compressed does not matter here).
std::string zip_of(const std::string& name, const std::string& content) {
  const std::uint32_t crc = crc32(content);
  const auto size = static_cast<std::uint32_t>(content.size());
  const auto name_size = static_cast<std::uint32_t>(name.size());
  std::string zip;
  put(zip, 0x04034b50u, 4);  // local file header: "PK\3\4"
  for (const auto& [value, bytes] : {std::pair{20u, 2}, {0u, 2}, {0u, 2}, {0u, 2}, {0u, 2}})
    put(zip, value, bytes);  // version, flags, stored, time, date
  put(zip, crc, 4);
  put(zip, size, 4);
  put(zip, size, 4);
  put(zip, name_size, 2);
  put(zip, 0, 2);
  zip.append(name).append(content);
  const auto directory = static_cast<std::uint32_t>(zip.size());
  put(zip, 0x02014b50u, 4);  // central directory header
  for (const auto& [value, bytes] :
       {std::pair{20u, 2}, {20u, 2}, {0u, 2}, {0u, 2}, {0u, 2}, {0u, 2}})
    put(zip, value, bytes);  // made by, needed, flags, stored, time, date
  put(zip, crc, 4);
  put(zip, size, 4);
  put(zip, size, 4);
  put(zip, name_size, 2);
  for (int i = 0; i < 4; ++i)
    put(zip, 0, 2);  // extra, comment, disk, internal attributes
  put(zip, 0, 4);    // external attributes
  put(zip, 0, 4);    // the local header's offset
  zip.append(name);
  const auto directory_size = static_cast<std::uint32_t>(zip.size()) - directory;
  put(zip, 0x06054b50u, 4);  // end of central directory
  for (int i = 0; i < 2; ++i)
    put(zip, 0, 2);
  put(zip, 1, 2);
  put(zip, 1, 2);
  put(zip, directory_size, 4);
  put(zip, directory, 4);
  put(zip, 0, 2);
  return zip;
}

TEST(AssimpReader, AZippedAmfIsNamedAsSuchWithTheWayOut) {
  const exactgeo::testing::ScratchDir dir("exactgeo_assimp_reader_amf");
  const std::string plain = (dir.path / "tetrahedron.amf").string();
  const std::string zipped = (dir.path / "zipped.amf").string();
  std::ofstream(plain, std::ios::binary) << tetrahedron_amf();
  const std::string zip = zip_of("tetrahedron.amf", tetrahedron_amf());
  ASSERT_EQ(zip.substr(0, 4), std::string("PK\x03\x04", 4));
  std::ofstream(zipped, std::ios::binary) << zip;
  // The XML itself is read.
  const LoadedMesh m = read_with_assimp(plain, "amf", {});
  EXPECT_EQ(m.format, "assimp amf");
  EXPECT_EQ(m.mesh.faces.size(), 4u);
  // The archive is named for what it is, by file, by extension through load_mesh, and from
  // memory, with the way out.
  for (const std::string& message :
       {error_of([&] { (void)read_with_assimp(zipped, "amf", {}); }),
        error_of([&] { (void)load_mesh(zipped); }),
        error_of([&] { (void)read_with_assimp_from_memory(zip, "<stdin>", "amf", {}); })}) {
    EXPECT_NE(message.find("zip-compressed AMF file"), std::string::npos) << message;
    EXPECT_NE(message.find("unzip -p FILE > plain.amf"), std::string::npos) << message;
  }
  EXPECT_EQ(error_of([&] { (void)load_mesh(zipped); }).rfind(zipped + ": a zip-compressed AMF", 0),
            0u);
  // The signature matters for AMF only: a RAW file that starts with it is assimp's to judge.
  std::string as_raw;
  try {
    (void)read_with_assimp_from_memory(zip, "<raw>", "raw", {});
  } catch (const std::exception& e) {
    as_raw = e.what();
  }
  EXPECT_EQ(as_raw.find("zip-compressed"), std::string::npos) << as_raw;
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
