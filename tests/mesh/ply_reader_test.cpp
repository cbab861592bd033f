// The PLY reader (ply_reader.hpp): the index list under either name, CRLF headers, every
// scalar type, both byte orders from literal bytes, ASCII values read as their declared
// types (a float "0.1" is the float nearest 0.1) and checked to fit them, and errors naming
// the file and the line (ASCII) or the element and its index (binary) for truncated data,
// bad values and indices, with counts checked against the bytes before any allocation.

#include "exactgeo/mesh/ply_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "mesh/mesh_io.hpp"

namespace exactgeo::mesh {
namespace {

using namespace test_io;  // the readers' shared helpers (mesh_io.hpp)

// ---------------------------------------------------------------------------------------
// PLY specifics

TEST_F(mesh_io, PlyVertexIndexNameCrlfHeaderAndOtherTypes) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty short x\r\nproperty uint8 y\r\n"
      "property float64 z\r\nproperty list uchar float normals\r\nelement face 1\r\n"
      "property list int uint vertex_index\r\nend_header\r\n"
      "-3 200 0.1 2 0.5 0.5\r\n1 0 0 0\r\n0 1 0 1 7\r\n\r\n3 0 1 2\r\n";
  const LoadedMesh m = load("crlf.ply", text);
  ASSERT_EQ(m.mesh.vertices.size(), 3u);
  EXPECT_EQ(m.mesh.vertices[0], (Point3{-3, 200, 0.1}));
  EXPECT_TRUE(m.mesh.faces == std::vector<Face>{make_triangle(0, 1, 2)});

  // Binary with a CRLF header, big-endian shorts and a uint16 count.
  std::string bin =
      "ply\r\nformat binary_big_endian 1.0\r\nelement vertex 3\r\n"
      "property int16 x\r\nproperty int16 y\r\nproperty int16 z\r\n"
      "element face 1\r\nproperty list ushort uint vertex_indices\r\nend_header\r\n";
  for (const int x : {-1, 2, 3, 4, -5, 6, 7, 8, 9})
    put(bin, static_cast<std::int16_t>(x), true);
  put(bin, std::uint16_t{3}, true);
  for (const std::uint32_t i : {2u, 1u, 0u})
    put(bin, i, true);
  const LoadedMesh b = load("crlf_bin.ply", bin);
  EXPECT_EQ(b.mesh.vertices[1], (Point3{4, -5, 6}));
  EXPECT_TRUE(b.mesh.faces == std::vector<Face>{make_triangle(2, 1, 0)});
}

TEST_F(mesh_io, PlyByteOrderFromLiteralBytes) {
  // One triangle, x = 1.0f, y = 0.1 (double), z = -2 (int16), written out byte by byte.
  const std::string header_end =
      " 1.0\nelement vertex 3\nproperty float x\nproperty double y\nproperty short z\n"
      "element face 1\nproperty list uchar ushort vertex_indices\nend_header\n";
  const std::string le_vertex("\x00\x00\x80\x3f\x9a\x99\x99\x99\x99\x99\xb9\x3f\xfe\xff", 14);
  const std::string be_vertex("\x3f\x80\x00\x00\x3f\xb9\x99\x99\x99\x99\x99\x9a\xff\xfe", 14);
  const std::string le = cat("ply\nformat binary_little_endian", header_end, le_vertex, le_vertex,
                             le_vertex, std::string("\x03\x00\x00\x01\x00\x02\x00", 7));
  const std::string be = cat("ply\nformat binary_big_endian", header_end, be_vertex, be_vertex,
                             be_vertex, std::string("\x03\x00\x00\x00\x01\x00\x02", 7));
  for (const LoadedMesh& m : {load("le.ply", le), load("be.ply", be)}) {
    SCOPED_TRACE(m.format);
    ASSERT_EQ(m.mesh.vertices.size(), 3u);
    EXPECT_EQ(bits(m.mesh.vertices[2][0]), bits(1.0));
    EXPECT_EQ(bits(m.mesh.vertices[2][1]), bits(0.1));
    EXPECT_EQ(bits(m.mesh.vertices[2][2]), bits(-2.0));
    EXPECT_TRUE(m.mesh.faces == std::vector<Face>{make_triangle(0, 1, 2)});
  }
}

TEST_F(mesh_io, PlyAsciiDataErrors) {
  const std::string header = ply_header("ascii", 3, 1);  // 9 header lines
  EXPECT_MESSAGE_HAS(load_error("nan.ply", cat(header, "0 0 0\n0 nan 0\n")),
                     "nan.ply:11:", "vertex 1", "'nan'");
  EXPECT_MESSAGE_HAS(load_error("inf.ply", cat(header, "0 0 0\n0 0 0\n1e999 0 0\n")),
                     "inf.ply:12:", "vertex 2", "'1e999'");
  EXPECT_MESSAGE_HAS(load_error("few.ply", cat(header, "0 0 0\n0 0\n")), "few.ply:11:", "vertex 1",
                     "too few values");
  EXPECT_MESSAGE_HAS(load_error("more.ply", cat(header, "0 0 0 0\n")), "more.ply:10:", "vertex 0",
                     "more values");
  EXPECT_MESSAGE_HAS(load_error("end.ply", cat(header, "0 0 0\n0 0 0\n")),
                     "end.ply:11:", "vertex 2", "ends");
  const std::string v = "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_MESSAGE_HAS(load_error("range.ply", cat(header, v, "3 0 1 3\n")),
                     "range.ply:13:", "face 0", "vertex index 3", "0..2");
  EXPECT_MESSAGE_HAS(load_error("wrap.ply", cat(header, v, "3 0 1 4294967296\n")),
                     "wrap.ply:13:", "'4294967296' is outside the range of int");
  EXPECT_MESSAGE_HAS(load_error("neg.ply", cat(header, v, "3 0 1 -1\n")), "neg.ply:13:", "-1");
  EXPECT_MESSAGE_HAS(load_error("len.ply", cat(header, v, "4 0 1 2\n")), "len.ply:13:", "face 0",
                     "has length 4");
  EXPECT_MESSAGE_HAS(load_error("absurd.ply", cat(ply_header("ascii", 4000000000u, 1), v)),
                     "absurd.ply:12:", "vertex 3", "4000000000");
  EXPECT_MESSAGE_HAS(load_error("nof.ply", cat(ply_header("ascii", 3, 0), v)), "nof.ply",
                     "no faces");
}

TEST_F(mesh_io, PlyAsciiValuesAreReadAsTheirDeclaredTypes) {
  // A float "0.1" is the float nearest 0.1, as a binary copy of the same mesh holds it,
  // not the double 0.1; a double "0.1" is the double.
  const std::string v = "0.1 0.2 0.3\n1 0 0\n0 1 0\n3 0 1 2\n";
  const LoadedMesh f = load("f.ply", cat(ply_header("ascii", 3, 1, "float"), v));
  EXPECT_EQ(f.mesh.vertices[0], (Point3{double(0.1f), double(0.2f), double(0.3f)}));
  const LoadedMesh d = load("d.ply", cat(ply_header("ascii", 3, 1, "double"), v));
  EXPECT_EQ(d.mesh.vertices[0], (Point3{0.1, 0.2, 0.3}));
  // Rounded once, to float: a decimal between two floats goes to the nearer (a double
  // rounding through the double nearest could land on the other one).
  const LoadedMesh once =
      load("once.ply", cat(ply_header("ascii", 3, 1, "float"),
                           "1.000000059604644775390625000000001 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  EXPECT_EQ(once.mesh.vertices[0][0], double(std::nextafter(1.0f, 2.0f)));
  // Integer types take integers in their range, and every value is checked, read or not.
  const std::string with_colour =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";  // 10 header lines
  const std::string faces = "3 0 1 2\n";
  EXPECT_EQ(
      load("c.ply", cat(with_colour, "0 0 0 255\n1 0 0 0\n0 1 0 7\n", faces)).mesh.vertices.size(),
      3u);
  EXPECT_MESSAGE_HAS(
      load_error("c300.ply", cat(with_colour, "0 0 0 300\n1 0 0 0\n0 1 0 7\n", faces)),
      "c300.ply:11:", "vertex 0", "property 'red'", "'300' is outside the range of uchar");
  EXPECT_MESSAGE_HAS(
      load_error("chalf.ply", cat(with_colour, "0 0 0 1\n1 0 0 0.5\n0 1 0 7\n", faces)),
      "chalf.ply:12:", "vertex 1", "'0.5' is not an integer");
  EXPECT_MESSAGE_HAS(
      load_error("cneg.ply", cat(with_colour, "0 0 0 1\n1 0 0 1\n0 1 0 -1\n", faces)),
      "cneg.ply:13:", "vertex 2", "'-1' is outside the range of uchar");
  const std::string v3 = "0 0 0 1\n1 0 0 1\n0 1 0 1\n";
  EXPECT_MESSAGE_HAS(load_error("len.ply", cat(with_colour, v3, "256 0 1 2\n")),
                     "len.ply:14:", "face 0", "'256' is outside the range of uchar");
  EXPECT_MESSAGE_HAS(load_error("idx.ply", cat(with_colour, v3, "3 0 1 2.0\n")),
                     "idx.ply:14:", "'2.0' is not an integer");
  EXPECT_MESSAGE_HAS(load_error("big.ply", cat(ply_header("ascii", 3, 1, "float"),
                                               "1e39 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")),
                     "big.ply:10:", "'1e39' is outside the range of float");
  EXPECT_MESSAGE_HAS(load_error("int.ply", cat(ply_header("ascii", 3, 1, "int"),
                                               "0.5 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")),
                     "int.ply:10:", "property 'x'", "'0.5' is not an integer");
}

TEST_F(mesh_io, PlyBinaryErrorsNameElementAndIndex) {
  const Mesh mesh = quad_and_triangle();
  for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    const std::string full = to_ply(mesh, {format, "float", "uchar", "int"});
    // Faces are 1 + 4*4 + 2 and 1 + 3*4 + 2 bytes: cut into the last one.
    EXPECT_MESSAGE_HAS(load_error("cut.ply", full.substr(0, full.size() - 3)),
                       "cut.ply: face 1:", "truncated");
    // Cut into the vertices: the declared counts no longer fit.
    const std::size_t header_size = full.find("end_header\n") + 11;
    EXPECT_MESSAGE_HAS(load_error("cutv.ply", full.substr(0, header_size + 20)),
                       "cutv.ply:", "truncated", "vertex 1", "declares 5");
    EXPECT_MESSAGE_HAS(load_error("none.ply", full.substr(0, header_size)),
                       "none.ply:", "truncated", "vertex 0");
  }
  // Huge vertex counts on a tiny file: refused before any allocation.
  std::string absurd = ply_header("binary_little_endian", 4000000000u, 1);
  for (int i = 0; i < 9; ++i)
    put(absurd, 1.0f, false);
  EXPECT_MESSAGE_HAS(load_error("absurd.ply", absurd), "absurd.ply:", "vertex 3",
                     "declares 4000000000");
  EXPECT_MESSAGE_HAS(load_error("many.ply", ply_header("binary_little_endian", 99999999999, 1)),
                     "many.ply:3:", "too many vertices");
  std::string faces = ply_header("binary_little_endian", 3, 4000000000u);
  for (int i = 0; i < 9; ++i)
    put(faces, 1.0f, false);
  EXPECT_MESSAGE_HAS(load_error("faces.ply", faces), "faces.ply:", "face 0", "declares 4000000000");
  // An element no one reads, with a huge count, must not be trusted either.
  const std::string other =
      "ply\nformat binary_little_endian 1.0\nelement junk 99999999999\n"
      "property list int int stuff\nelement vertex 0\nproperty float x\nproperty float y\n"
      "property float z\nelement face 0\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_MESSAGE_HAS(load_error("junk.ply", other), "junk.ply:", "junk 0", "truncated");

  const std::string header = ply_header("binary_little_endian", 3, 1, "float", "int uint");
  auto vertices = [](float bad) {
    std::string s;
    for (const float x : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, bad, 0.0f})
      put(s, x, false);
    return s;
  };
  auto face = [](std::int32_t n, std::initializer_list<std::uint32_t> corners) {
    std::string s;
    put(s, n, false);
    for (const std::uint32_t c : corners)
      put(s, c, false);
    return s;
  };
  EXPECT_MESSAGE_HAS(
      load_error("nan.ply", cat(header, vertices(std::numeric_limits<float>::quiet_NaN()),
                                face(3, {0, 1, 2}))),
      "nan.ply: vertex 2:", "y is NaN");
  EXPECT_MESSAGE_HAS(
      load_error("inf.ply", cat(header, vertices(-std::numeric_limits<float>::infinity()),
                                face(3, {0, 1, 2}))),
      "inf.ply: vertex 2:", "y is infinite");
  EXPECT_MESSAGE_HAS(load_error("range.ply", cat(header, vertices(1), face(3, {0, 1, 3}))),
                     "range.ply: face 0:", "vertex index 3", "0..2");
  EXPECT_MESSAGE_HAS(load_error("max.ply", cat(header, vertices(1), face(3, {0, 4294967295u, 1}))),
                     "max.ply: face 0:", "vertex index 4294967295", "0..2");
  EXPECT_MESSAGE_HAS(load_error("negn.ply", cat(header, vertices(1), face(-1, {}))),
                     "negn.ply: face 0:", "negative length -1");
  EXPECT_MESSAGE_HAS(load_error("bign.ply", cat(header, vertices(1), face(2000000000, {0, 1, 2}))),
                     "bign.ply: face 0:", "truncated");
  EXPECT_MESSAGE_HAS(load_error("two.ply", cat(header, vertices(1), face(2, {0, 1}))),
                     "two.ply: face 0:", "at least 3 corners");
  const std::string signed_header = ply_header("binary_little_endian", 3, 1, "float", "uchar int");
  std::string negative = signed_header + vertices(1);
  put(negative, std::uint8_t{3}, false);
  for (const std::int32_t c : {0, -2, 1})
    put(negative, c, false);
  EXPECT_MESSAGE_HAS(load_error("neg.ply", negative), "neg.ply: face 0:", "vertex index -2");
}

}  // namespace
}  // namespace exactgeo::mesh
