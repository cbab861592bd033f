// The OBJ reader (obj_reader.hpp): relative indices and forward references, statements
// other than v and f skipped (comments, CRLF, a byte order mark, texture and normal data,
// whose seams do not split vertices), w read exactly as 1 or refused, keywords in another
// case refused, and an error naming the file and line for every kind of bad input.

#include "exactgeo/mesh/obj_reader.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mesh/mesh_io.hpp"

namespace exactgeo::mesh {
namespace {

using namespace test_io;  // the readers' shared helpers (mesh_io.hpp)

// ---------------------------------------------------------------------------------------
// OBJ specifics

const char kObjSquare[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";  // lines 1-4

TEST_F(mesh_io, ObjRelativeIndicesAndForwardReferences) {
  // -1 is the last vertex defined before the line.
  LoadedMesh m = load("rel.obj", cat(kObjSquare, "f -4 -3 -2 -1\nv 0 0 1\nf -5 -4 -1\n"));
  EXPECT_TRUE(m.mesh.faces == (std::vector<Face>{make_quad(0, 1, 2, 3), make_triangle(0, 1, 4)}));
  // A face may name vertices defined further down.
  m = load("fwd.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_TRUE(m.mesh.faces == std::vector<Face>{make_triangle(0, 1, 2)});
}

TEST_F(mesh_io, ObjIgnoresOtherStatementsCommentsAndCrlf) {
  const std::string text =
      "\xEF\xBB\xBF# exported\r\nmtllib a.mtl\r\no cube\r\nv 0 0 0\r\nv 1 0 0 1\r\n"
      "v 1 1 0 0.5 0.5 0.5\r\nvt 0.5 0.5\r\nvn 0 0 1\r\nvp 0.1\r\ng g1 g2\r\ns 1\r\n"
      "usemtl red\r\n\r\n   \r\nl 1 2 3\r\np 1\r\nf 1/1/1 2/1/1 3/1/1 # trailing\r\n";
  const LoadedMesh m = load("crlf.obj", text);
  ASSERT_EQ(m.mesh.vertices.size(), 3u);
  EXPECT_EQ(m.mesh.vertices[2], (Point3{1, 1, 0}));
  EXPECT_TRUE(m.mesh.faces == std::vector<Face>{make_triangle(0, 1, 2)});
}

TEST_F(mesh_io, ObjTextureSeamsDoNotSplitVertices) {
  // Two faces sharing positions 2 and 3 with different texture coordinates.
  const LoadedMesh m =
      load("seam.obj", cat(kObjSquare, "vt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 3/2 4/2 1/2\n"));
  EXPECT_EQ(m.mesh.vertices.size(), 4u);
  EXPECT_TRUE(m.mesh.faces == (std::vector<Face>{make_triangle(0, 1, 2), make_triangle(2, 3, 0)}));
}

TEST_F(mesh_io, ObjErrorsNameFileAndLine) {
  const std::string square(kObjSquare);
  std::string e = load_error("w.obj", "v 1 2 3 0.5\nf 1 1 1\n");
  EXPECT_MESSAGE_HAS(e, "w.obj:1:", "w = 0.5");
  EXPECT_NO_THROW((void)load("w1.obj", "v 1 2 3 1\nv 0 0 0 1.0\nv 0 1 0\nf 1 2 3\n"));
  // w is compared with 1 exactly, on its digits: every spelling of 1 is 1, and a value
  // that only rounds to 1 is not.
  for (const char* one : {"1", "+1", "1.000", "001.0", "10e-1", "0.1E+1", "1e0", "100e-2", "0x1p0",
                          "0x.8p1", "0X10P-4", "0x2p-1", "0x0.08p5", "0x1.000p+0"}) {
    EXPECT_NO_THROW((void)load("w1.obj", cat("v 0 0 0 ", one, "\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")))
        << one;
  }
  for (const char* not_one :
       {"1.00000000000000000001", "0.99999999999999999999", "-1", "0", "1e-1", "10",
        "0x1.0000000000000000001p0", "0x3p-1", "0x1p1", "0.1", "2e-1"}) {
    const std::string expected = cat("w = ", not_one);
    EXPECT_MESSAGE_HAS(load_error("w2.obj", cat("v 0 0 0 ", not_one, "\nf 1 1 1\n")),
                       "w2.obj:1:", expected);
  }

  EXPECT_MESSAGE_HAS(load_error("token.obj", "v 0 0 0\nv 1 abc 3\n"), "token.obj:2:", "'abc'");
  EXPECT_MESSAGE_HAS(load_error("nan.obj", "v nan 0 0\n"), "nan.obj:1:", "'nan'");
  EXPECT_MESSAGE_HAS(load_error("inf.obj", "v 0 -inf 0\n"), "inf.obj:1:", "'-inf'");
  EXPECT_MESSAGE_HAS(load_error("big.obj", "v 0 0 1e999\n"), "big.obj:1:", "'1e999'",
                     "outside the range");
  EXPECT_MESSAGE_HAS(load_error("tiny.obj", "v 0 0 1e-400\n"), "tiny.obj:1:", "'1e-400'");
  EXPECT_MESSAGE_HAS(load_error("two.obj", "v 1 2\n"), "two.obj:1:", "found 2 values");

  e = load_error("range.obj", cat(square, "f 1 2 9\n"));
  EXPECT_MESSAGE_HAS(e, "range.obj:5:", "vertex index 9", "1..4");
  e = load_error("fwd.obj", cat(square, "f 1 2 7\nf 1 2 3\nv 0 0 2\n"));
  EXPECT_MESSAGE_HAS(e, "fwd.obj:5:", "vertex index 7", "1..5");
  // 2^32 + 1 and 2^32 would wrap to 1 and 0 in 32 bits: they must be refused.
  e = load_error("wrap.obj", cat(square, "f 1 2 4294967297\n"));
  EXPECT_MESSAGE_HAS(e, "wrap.obj:5:", "4294967297", "out of range");
  e = load_error("wrap0.obj", cat(square, "f 4294967296 2 3\n"));
  EXPECT_MESSAGE_HAS(e, "wrap0.obj:5:", "4294967296", "out of range");
  e = load_error("huge.obj", cat(square, "f 1 2 99999999999999999999999\n"));
  EXPECT_MESSAGE_HAS(e, "huge.obj:5:", "too large");
  e = load_error("neg.obj", cat(square, "f -1 -2 -5\n"));
  EXPECT_MESSAGE_HAS(e, "neg.obj:5:", "-5", "4 vertices are defined before");
  e = load_error("negbig.obj", cat(square, "f -1 -2 -9223372036854775808\n"));
  EXPECT_MESSAGE_HAS(e, "negbig.obj:5:", "-9223372036854775808");
  EXPECT_MESSAGE_HAS(load_error("zero.obj", cat(square, "f 0 1 2\n")), "zero.obj:5:", "index 0");
  EXPECT_MESSAGE_HAS(load_error("slash.obj", cat(square, "f 1 2 /3\n")), "slash.obj:5:", "'/3'");
  EXPECT_MESSAGE_HAS(load_error("x.obj", cat(square, "f 1 2 3x\n")), "x.obj:5:", "'3x'");
  EXPECT_MESSAGE_HAS(load_error("short.obj", cat(square, "f 1 2\n")),
                     "short.obj:5:", "at least 3 corners", "has 2");
  EXPECT_MESSAGE_HAS(load_error("empty.obj", cat(square, "# no faces\n")), "empty.obj", "no faces",
                     "4 vertices only, a point cloud (or lines), not a surface");
  // Texture and normal indices are not used, but they are integers.
  for (const char* corner : {"3/x", "3//+-1", "3/1/2/4", "3/1.5", "3/-+2/1"}) {
    EXPECT_MESSAGE_HAS(load_error("vt.obj", cat(square, "f 1 2 ", corner, "\n")),
                       "vt.obj:5:", corner);
  }
  EXPECT_NO_THROW((void)load("vt.obj", cat(square, "f 1/1 2//-1 3/+1/1 4/-2/\n")));
}

TEST_F(mesh_io, ObjKeywordsInAnotherCaseAreRefused) {
  // Skipping a "V" line would make the faces after it point at other vertices; an "F" line
  // would lose a face.
  const std::string square(kObjSquare);
  for (const char* keyword : {"V", "F", "Fo", "FO", "fO"}) {
    const std::string line = std::string(keyword) + (keyword[0] == 'V' ? " 0 0 2" : " 1 2 3");
    const std::string meant = keyword[0] == 'V' ? "'v'" : (keyword[1] ? "'fo'" : "'f'");
    const std::string said = cat("'", keyword, "' is not an OBJ keyword");
    EXPECT_MESSAGE_HAS(load_error("case.obj", cat(square, line, "\n")), "case.obj:5:", said, meant);
  }
  // Other statements in any case are not geometry, and are skipped as before.
  EXPECT_NO_THROW((void)load("case.obj", cat(square, "VT 0 0\nG group\nUsemtl x\nf 1 2 3\n")));
}

}  // namespace
}  // namespace exactgeo::mesh
