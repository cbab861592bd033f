// The OFF reader (off_reader.hpp): every header keyword with the vertex columns it
// announces (normals, colours, texture coordinates), face colours, faces wrapped over
// lines, vertex lines with exactly the columns the keyword allows, and an error naming the
// file and line for every kind of bad input.

#include "exactgeo/mesh/off_reader.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mesh/mesh_io.hpp"

namespace exactgeo::mesh {
namespace {

using namespace test_io;  // the readers' shared helpers (mesh_io.hpp)

// ---------------------------------------------------------------------------------------
// OFF specifics

TEST_F(mesh_io, OffHeaderVariantsExtraColumnsAndColours) {
  // Each keyword with the vertex columns it announces: N a normal, C a colour (RGB or
  // RGBA), ST texture coordinates; a face may carry a colour after its indices.
  struct Variant {
    const char* header;
    const char* extra;  ///< the values after x y z on every vertex line
  };
  for (const Variant& v :
       {Variant{"OFF\n3 1 0\n", ""}, Variant{"OFF 3 1 0\n", ""},
        Variant{"COFF\n3 1 0\n", " 0.5 0.5 0.5 1"}, Variant{"COFF\n3 1 0\n", " 255 128 0"},
        Variant{"NOFF\n3 1\n", " 0 0 1"}, Variant{"CNOFF\n3 1 3\n", " 0 0 1 1 1 1 1"},
        Variant{"STCNOFF 3 1 0\n", " 0 0 1 1 1 1 1 0.25 0.75"},
        Variant{"STOFF 3 1 0\n", " 0.25 0.75"}, Variant{"3 1 0\n", ""},
        Variant{"# first\n\nOFF # header\n\n# counts next\n3 1 0\n", ""}}) {
    SCOPED_TRACE(v.header);
    const std::string body =
        cat("0 0 0", v.extra, "\n1 0 0", v.extra, "\n0 1 0", v.extra, "\n3 0 1 2 0.1 0.2 0.3 1\n");
    const LoadedMesh m = load("h.off", cat(v.header, body));
    ASSERT_EQ(m.mesh.vertices.size(), 3u);
    EXPECT_EQ(m.mesh.vertices[1], (Point3{1, 0, 0}));
    EXPECT_TRUE(m.mesh.faces == std::vector<Face>{make_triangle(0, 1, 2)});
  }
}

TEST_F(mesh_io, OffVertexLinesHoldExactlyTheColumnsTheKeywordAllows) {
  // Under a plain OFF a fourth value is not a colour: "2 4 6 2" is refused, not read as
  // (2, 4, 6), and two vertices on one line are not silently split differently.
  const std::string face = "3 0 1 2\n";
  EXPECT_MESSAGE_HAS(load_error("g.off", cat("OFF\n3 1 0\n0 0 0\n1 2 3 garbage\n0 1 0\n", face)),
                     "g.off:4:", "vertex 1", "expected x y z under 'OFF'", "found 4 values");
  EXPECT_MESSAGE_HAS(load_error("w.off", cat("OFF\n3 1 0\n2 4 6 2\n1 0 0\n0 1 0\n", face)),
                     "w.off:3:", "vertex 0", "found 4 values");
  EXPECT_MESSAGE_HAS(
      load_error("two.off", cat("OFF\n3 1 0\n0 0 0 1 0 0\n0 1 0\n", face, "3 0 1 2\n")),
      "two.off:3:", "vertex 0", "found 6 values");
  EXPECT_MESSAGE_HAS(load_error("none.off", cat("3 1 0\n0 0 0 1\n1 0 0\n0 1 0\n", face)),
                     "none.off:2:", "(no keyword)");
  // With a keyword, the columns must match it, and they must be numbers.
  EXPECT_MESSAGE_HAS(load_error("n.off", cat("NOFF\n3 1 0\n0 0 0 0 0\n1 0 0 0 0 1\n", face)),
                     "n.off:3:", "expected x y z nx ny nz under 'NOFF'", "found 5 values");
  EXPECT_MESSAGE_HAS(load_error("c.off", cat("COFF\n3 1 0\n0 0 0 1 1\n", face)),
                     "c.off:3:", "x y z r g b [a]");
  EXPECT_MESSAGE_HAS(
      load_error("cg.off", cat("COFF\n3 1 0\n0 0 0 1 1 red\n1 0 0 1 1 1\n0 1 0 1 1 1\n", face)),
      "cg.off:3:", "'red'");
}

TEST_F(mesh_io, OffFacesWrappedOverLines) {
  // Some writers wrap a face's indices over several lines (the shared data set's
  // inspired_mesh_quads_Conjugate.off does): accepted when the indices end a line.
  const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  const LoadedMesh m = load("wrap.off", cat("OFF\n4 2 0\n", vertices, "4 0\n1\n2\n3\n3 0 1 2\n"));
  EXPECT_TRUE(m.mesh.faces == (std::vector<Face>{make_quad(0, 1, 2, 3), make_triangle(0, 1, 2)}));
  // A face line that is merely short must not swallow the next face as its colour.
  EXPECT_MESSAGE_HAS(load_error("short.off", cat("OFF\n4 2 0\n", vertices, "3 0 1\n3 0 2 3\n")),
                     "short.off:", "face 0: the corner count is 3");
}

TEST_F(mesh_io, OffErrorsNameFileAndLine) {
  const std::string cube_vertices =
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";  // lines 3-10
  EXPECT_MESSAGE_HAS(load_error("hdr.off", "FOO\n3 1 0\n"), "hdr.off:1:", "not an OFF file");
  EXPECT_MESSAGE_HAS(load_error("4d.off", "4OFF\n3 1 0\n"), "4d.off:1:", "not supported");
  EXPECT_MESSAGE_HAS(load_error("bin.off", "OFF BINARY\n"), "bin.off:1:", "binary OFF");
  EXPECT_MESSAGE_HAS(load_error("none.off", ""), "none.off:0:", "the OFF header");
  EXPECT_MESSAGE_HAS(load_error("cnt.off", "OFF\n8 six 0\n"), "cnt.off:2:", "'six'");
  EXPECT_MESSAGE_HAS(load_error("neg.off", "OFF\n-8 6 0\n"), "neg.off:2:", "negative");
  EXPECT_MESSAGE_HAS(load_error("many.off", "OFF\n99999999999 1 0\n0 0 0\n"),
                     "many.off:2:", "too many vertices");
  // A count that would be a 100 GB allocation: the file ends first.
  EXPECT_MESSAGE_HAS(load_error("absurd.off", "OFF\n4000000000 4000000000 0\n0 0 0\n"),
                     "absurd.off:3:", "1 of 4000000000 vertices");
  EXPECT_MESSAGE_HAS(
      load_error("fewf.off", cat("OFF\n8 99999999999 0\n", cube_vertices, "4 0 1 2 3\n")),
      "fewf.off:11:", "1 of 99999999999 faces");
  EXPECT_MESSAGE_HAS(load_error("nan.off", "OFF\n3 1 0\n0 0 0\n0 NaN 0\n"), "nan.off:4:", "'NaN'");
  EXPECT_MESSAGE_HAS(load_error("inf.off", "OFF\n3 1 0\n0 0 0\n0 0 Infinity\n"),
                     "inf.off:4:", "'Infinity'");
  EXPECT_MESSAGE_HAS(load_error("xy.off", "OFF\n3 1 0\n0 0\n"), "xy.off:3:", "vertex 0",
                     "expected x y z");
  EXPECT_MESSAGE_HAS(load_error("range.off", cat("OFF\n8 1 0\n", cube_vertices, "4 0 1 8 3\n")),
                     "range.off:11:", "face 0", "vertex index 8", "0..7");
  EXPECT_MESSAGE_HAS(
      load_error("wrap.off", cat("OFF\n8 1 0\n", cube_vertices, "4 0 1 4294967296 3\n")),
      "wrap.off:11:", "4294967296", "out of range");
  EXPECT_MESSAGE_HAS(load_error("neg.off", cat("OFF\n8 1 0\n", cube_vertices, "3 0 -1 2\n")),
                     "neg.off:11:", "-1", "out of range");
  EXPECT_MESSAGE_HAS(load_error("corners.off", cat("OFF\n8 1 0\n", cube_vertices, "4 0 1 2\n")),
                     "corners.off:11:", "face 0", "corner count");
  EXPECT_MESSAGE_HAS(
      load_error("hugen.off", cat("OFF\n8 1 0\n", cube_vertices, "999999999999 0\n")),
      "hugen.off:11:", "corner count");
  EXPECT_MESSAGE_HAS(load_error("two.off", cat("OFF\n8 1 0\n", cube_vertices, "2 0 1\n")),
                     "two.off:11:", "at least 3 corners");
  EXPECT_MESSAGE_HAS(load_error("nof.off", cat("OFF\n8 0 0\n", cube_vertices)), "nof.off",
                     "no faces");
}

}  // namespace
}  // namespace exactgeo::mesh
