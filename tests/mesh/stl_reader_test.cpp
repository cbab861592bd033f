// The STL reader (stl_reader.hpp): ASCII and binary read exactly (decimals correctly
// rounded, float32 widened bit for bit) and always welded (exactly equal positions only,
// +0 and -0 alike); what exporters write besides the plain layout; binary headers that
// begin with "solid"; every spelling a writer puts in a normal slot taken, and anything
// else refused; and errors naming the file and the line (ASCII) or triangle (binary).

#include "exactgeo/mesh/stl_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/weld.hpp"
#include "mesh/mesh_io.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

using namespace test_io;  // the readers' shared helpers (mesh_io.hpp)

// ---------------------------------------------------------------------------------------
// ASCII and binary, read exactly, always welded

using Triangle = std::array<Point3, 3>;

// A box whose corners are decimals that no float (and, but for 0.5, no short binary
// fraction) holds, as 12 outward triangles: 36 corners at 8 positions.
std::vector<Triangle> box_soup() {
  const double x[2] = {0.1, 0.7}, y[2] = {-1.0 / 3, 2.2}, z[2] = {1e-7, 1e5 + 0.3};
  auto p = [&](int v) { return Point3{x[v & 1], y[(v >> 1) & 1], z[(v >> 2) & 1]}; };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Triangle> soup;
  for (const auto& q : quads) {
    soup.push_back({p(q[0]), p(q[1]), p(q[2])});
    soup.push_back({p(q[0]), p(q[2]), p(q[3])});
  }
  return soup;
}

// The triangles as ASCII STL (coordinates with 17 significant digits), each line ended by
// `eol`.
std::string to_ascii_stl(const std::vector<Triangle>& soup, const std::string& eol = "\n") {
  std::string s = cat("solid box", eol);
  for (const Triangle& t : soup) {
    s.append(cat("  facet normal 0 0 0", eol, "    outer loop", eol));
    for (const Point3& p : t) {
      s.append(cat("      vertex ", decimal(p[0]), " ", decimal(p[1]), " ", decimal(p[2]), eol));
    }
    s.append(cat("    endloop", eol, "  endfacet", eol));
  }
  s.append(cat("endsolid box", eol));
  return s;
}

// The triangles as binary STL: a header of 80 bytes beginning with `header`, then the count
// and a record per triangle (coordinates as float32: they must be floats).
std::string to_binary_stl(const std::vector<Triangle>& soup, std::string_view header) {
  std::string s(header);
  s.resize(80, ' ');
  put(s, static_cast<std::uint32_t>(soup.size()), false);
  for (const Triangle& t : soup) {
    for (const float n : {0.0f, 0.0f, 1.0f})
      put(s, n, false);
    for (const Point3& p : t) {
      for (const double c : p)
        put(s, static_cast<float>(c), false);
    }
    put(s, std::uint16_t{0}, false);
  }
  return s;
}

// Every facet of `loaded` has the corners at the positions `soup` gives, bit for bit, and
// the vertices are distinct positions (welded).
void expect_soup(const LoadedMesh& loaded, const std::vector<Triangle>& soup) {
  const Mesh& mesh = loaded.mesh;
  ASSERT_EQ(mesh.faces.size(), soup.size());
  for (std::size_t f = 0; f < soup.size(); ++f) {
    ASSERT_TRUE(mesh.faces[f].is_triangle()) << "face " << f;
    for (std::size_t c = 0; c < 3; ++c) {
      const Point3& actual = mesh.vertices.at(mesh.faces[f].corners[c]);
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(bits(actual[i]), bits(soup[f][c][i]))
            << "facet " << f << " corner " << c << ": " << actual[i] << " vs " << soup[f][c][i];
      }
    }
  }
  Mesh again = mesh;
  EXPECT_EQ(weld_vertices(again), 0u) << "the vertices are not welded";
  EXPECT_EQ(mesh.vertices.size() + loaded.welded_vertices, 3 * soup.size());
}

TEST_F(mesh_io, StlAsciiIsReadExactlyAndWelded) {
  const std::vector<Triangle> soup = box_soup();
  const LoadedMesh m = load("box.STL", to_ascii_stl(soup));
  EXPECT_EQ(m.format, "stl ascii");
  EXPECT_FALSE(m.coordinates_via_float);
  EXPECT_EQ(m.mesh.vertices.size(), 8u);
  EXPECT_EQ(m.welded_vertices, 36u - 8u);
  expect_soup(m, soup);
  // 0.1 is the double nearest 0.1, not the float.
  const auto tenth = std::count_if(m.mesh.vertices.begin(), m.mesh.vertices.end(),
                                   [](const Point3& p) { return p[0] == 0.1; });
  EXPECT_EQ(tenth, 4);
  EXPECT_TRUE(check_mesh(m.mesh).closed());
  // Asking for welding changes nothing, and the count is not lost.
  const LoadedMesh welded = load("box.stl", to_ascii_stl(soup), {.weld = true});
  EXPECT_EQ(welded.welded_vertices, 28u);
  EXPECT_EQ(welded.mesh.vertices, m.mesh.vertices);
  // The format option names STL for a file without an extension.
  EXPECT_EQ(load("box", to_ascii_stl(soup), {.format = "stl"}).mesh.faces, m.mesh.faces);
}

// `n` triangles of random finite values of type T (double or float; random bits, so
// subnormals and zeros of either sign among them), as doubles.
template <class T>
std::vector<Triangle> random_soup(std::string_view stream, std::size_t n) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  auto engine = exactgeo::testing::seeded_engine(stream);
  std::uniform_int_distribution<Bits> any_bits;
  std::vector<Triangle> soup(n);
  for (Triangle& t : soup) {
    for (Point3& p : t) {
      for (double& x : p) {
        T value{};
        do {
          value = std::bit_cast<T>(any_bits(engine));
        } while (!std::isfinite(value));
        x = value;
      }
    }
  }
  return soup;
}

TEST_F(mesh_io, StlAsciiRandomDoublesRoundTrip) {
  const std::vector<Triangle> soup = random_soup<double>("mesh_io.stl_random_doubles", 100);
  const LoadedMesh m = load("random.stl", to_ascii_stl(soup));
  EXPECT_EQ(m.mesh.vertices.size(), 300u);
  expect_soup(m, soup);
}

// What exporters write besides the plain layout: CRLF, upper case, a byte order mark, names
// with spaces or none, several solids, tokens spread over lines, NaN normals.
TEST_F(mesh_io, StlAsciiVariantsReadAlike) {
  const std::vector<Triangle> soup = box_soup();
  const LoadedMesh plain = load("plain.stl", to_ascii_stl(soup));

  std::string upper = to_ascii_stl(soup, "\r\n");
  std::transform(upper.begin(), upper.end(), upper.begin(), [](char c) {
    return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  });
  const LoadedMesh crlf = load("crlf.stl", cat("\xEF\xBB\xBF", upper));
  EXPECT_EQ(crlf.format, "stl ascii");
  expect_soup(crlf, soup);

  // The first two facets in a solid of their own, named with spaces; the rest unnamed, one
  // facet spread over lines and one on a single line, a normal of NaN and infinity.
  const std::string text = to_ascii_stl(soup);
  const std::size_t third = text.find("  facet", text.find("endfacet", text.find("endfacet") + 1));
  std::string several = cat("solid part one (mm)\n", text.substr(10, third - 10),
                            "endsolid part one (mm)\n\n solid\n", text.substr(third));
  several.replace(several.find("normal 0 0 0", third), 12, "normal\n nan -NaN\n +INF");
  const std::size_t last = several.rfind("  facet");
  std::string one_line = several.substr(last);
  std::replace(one_line.begin(), one_line.end(), '\n', ' ');
  several =
      cat(several.substr(0, last), one_line.substr(0, one_line.rfind("endsolid")), "\nendsolid\n");
  const LoadedMesh multi = load("several.stl", several);
  expect_soup(multi, soup);
  EXPECT_EQ(multi.mesh.vertices, plain.mesh.vertices);
  EXPECT_EQ(multi.welded_vertices, plain.welded_vertices);
}

TEST_F(mesh_io, StlBinaryIsBitExact) {
  std::vector<Triangle> soup = random_soup<float>("mesh_io.stl_binary", 200);
  soup[0][0] = {std::numeric_limits<float>::denorm_min(), -0.0, std::numeric_limits<float>::max()};
  // Many binary headers begin with "solid" although the file is not text.
  for (const std::string_view header : {"binary STL", "solid written by a CAD program"}) {
    SCOPED_TRACE(header);
    const LoadedMesh m = load("random.stl", to_binary_stl(soup, header));
    EXPECT_EQ(m.format, "stl binary");
    EXPECT_FALSE(m.coordinates_via_float);
    EXPECT_EQ(m.mesh.vertices.size(), 600u);
    expect_soup(m, soup);
  }
  // "solid", a name and a newline, as some writers put it, and no NUL byte anywhere: the
  // size decides, and the text does not read as ASCII STL.
  std::vector<Triangle> ones(3, Triangle{{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}});
  std::string no_nul = to_binary_stl(ones, "solid x\n");
  for (std::size_t i = 84; i < no_nul.size(); ++i)
    if (no_nul[i] == '\0') no_nul[i] = 1;  // normals, attributes: not read
  const LoadedMesh m = load("nonul.stl", no_nul);
  EXPECT_EQ(m.format, "stl binary");
  EXPECT_EQ(m.mesh.vertices.size(), 3u);
  EXPECT_EQ(m.welded_vertices, 6u);
}

TEST_F(mesh_io, StlWeldingJoinsExactlyEqualPositionsOnly) {
  // A tetrahedron whose corners appear with +0 and -0, a fifth facet with a corner repeated
  // (kept: the mesh checks report it), and a corner one float step away (not joined).
  const Point3 a{0, 0, 0}, a_negative{-0.0, 0, -0.0}, b{1, 0, 0}, c{0, 1, 0}, d{0, 0, 1};
  const Point3 near_b{static_cast<double>(std::nextafter(1.0f, 2.0f)), 0, 0};
  const std::vector<Triangle> soup = {{a, c, b}, {a_negative, b, d}, {a, d, c},
                                      {b, c, d}, {b, b, c},          {near_b, c, d}};
  for (const bool binary : {false, true}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    const LoadedMesh m = load("tet.stl", binary ? to_binary_stl(soup, "tet") : to_ascii_stl(soup));
    EXPECT_EQ(m.mesh.vertices.size(), 5u);
    EXPECT_EQ(m.welded_vertices, 18u - 5u);
    ASSERT_EQ(m.mesh.faces.size(), 6u);
    EXPECT_EQ(m.mesh.faces[4].corners[0], m.mesh.faces[4].corners[1]);
    EXPECT_EQ(m.mesh.faces[1].corners[0], m.mesh.faces[0].corners[0]);  // -0 joined +0
    EXPECT_NE(m.mesh.faces[5].corners[0], m.mesh.faces[3].corners[0]);
    const MeshCheck check = check_mesh(m.mesh);
    EXPECT_EQ(check.degenerate_faces.count, 1u);
  }
}

TEST_F(mesh_io, StlAsciiErrorsNameTheFileAndLine) {
  const std::string facet =  // lines 2 to 8
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n"
      " endloop\nendfacet\n";
  auto solid = [](const std::string& body) { return cat("solid s\n", body, "endsolid s\n"); };
  auto with = [&](std::string_view from, std::string_view to) {
    std::string s = solid(cat(facet, facet));
    s.replace(s.find(from, 8 + facet.size()), from.size(), to);  // the second facet: lines 9-15
    return s;
  };
  struct Case {
    const char* file;
    std::string_view from, to;  // in the second facet
    const char* message;
  };
  const Case cases[] = {
      {"bad.stl", "1 0 0", "1 0.5x 0",
       "bad.stl:12: facet 1: the second vertex: '0.5x' is not a number"},
      {"nan.stl", "0 1 0", "0 nan 0",
       "nan.stl:13: facet 1: the third vertex: 'nan' is not a number"},
      {"big.stl", "1 0 0", "1e999 0 0",
       "big.stl:12: facet 1: the second vertex: '1e999' is outside the range"},
      {"two.stl", "  vertex 0 1 0\n", "",
       "two.stl:13: facet 1: expected 'vertex' (a facet has three vertices), found 'endloop'"},
      {"four.stl", " endloop", "vertex 1 1 1\nendloop",
       "four.stl:14: facet 1: expected 'endloop' (a facet has three vertices), found 'vertex'"},
      {"short.stl", " 0 1 0\n", " 0 1\n",
       "short.stl:14: facet 1: the third vertex: 'endloop' is not a number"},
      {"normal.stl", "normal 0 0 1", "normal a b c",
       "normal.stl:9: facet 1: the normal: 'a' is not a number"},
      {"loop.stl", "outer loop", "outer", "loop.stl:11: facet 1: expected 'loop', found 'vertex'"},
      {"word.stl", "endfacet", "endfacet x",
       "word.stl:15: expected 'facet' or 'endsolid', found 'x'"},
  };
  for (const Case& c : cases)
    EXPECT_MESSAGE_HAS(load_error(c.file, with(c.from, c.to)), c.message);
  EXPECT_MESSAGE_HAS(load_error("cut.stl", cat("solid s\n", facet.substr(0, 40))),
                     "cut.stl:4: facet 0: the file ends where a coordinate should be");
  EXPECT_MESSAGE_HAS(load_error("open.stl", cat("solid s\r\n", facet)),
                     "open.stl:8: the file ends inside a solid: 'endsolid' is missing");
  EXPECT_MESSAGE_HAS(load_error("after.stl", cat(solid(facet), "facet\n")),
                     "after.stl:10: expected 'solid' or the end of the file, found 'facet'");
}

TEST_F(mesh_io, StlBinaryErrorsNameTheFileAndTriangle) {
  const std::vector<Triangle> three(3, Triangle{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  const std::string whole = to_binary_stl(three, "three");  // 84 + 150 bytes
  EXPECT_MESSAGE_HAS(load_error("cut.stl", whole.substr(0, 84 + 100 + 20)),
                     "cut.stl: triangle 2: the file ends 20 bytes into it: the header declares 3 "
                     "triangles, 84 + 50 * 3 = 234 bytes, the file has 204",
                     "it does not begin with 'solid'");
  // A header that begins with "solid" does not make a cut binary file text.
  EXPECT_MESSAGE_HAS(load_error("cut_solid.stl", to_binary_stl(three, "solid x").substr(0, 134)),
                     "cut_solid.stl: triangle 1: the file ends 0 bytes into it",
                     "it holds NUL bytes");
  EXPECT_MESSAGE_HAS(load_error("extra.stl", cat(whole, "garbage")),
                     "extra.stl: 7 bytes follow the last triangle (2): the header declares 3");
  EXPECT_MESSAGE_HAS(load_error("header.stl", cat(to_binary_stl({}, "none"), "x")),
                     "header.stl: 1 bytes follow the header: the header declares 0 triangles");
  EXPECT_MESSAGE_HAS(load_error("tiny.stl", "v 0 0 0\n"),
                     "tiny.stl: 8 bytes, too few for binary STL (it does not begin with 'solid'): "
                     "its header and triangle count take 84");
  for (const float bad :
       {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::infinity()}) {
    std::vector<Triangle> soup = three;
    soup[1][1][1] = bad;
    const std::string expected =
        cat("bad.stl: triangle 1: the second vertex: y is ", std::isnan(bad) ? "NaN" : "infinite");
    EXPECT_MESSAGE_HAS(load_error("bad.stl", to_binary_stl(soup, "solid")), expected);
  }
}

TEST_F(mesh_io, StlWithoutFacetsIsAnError) {
  EXPECT_MESSAGE_HAS(load_error("empty.stl", "solid empty\nendsolid empty\n"),
                     "empty.stl: the mesh has no faces");
  EXPECT_MESSAGE_HAS(load_error("solids.stl", "solid a\nendsolid a\nsolid b\nendsolid\n"),
                     "solids.stl: the mesh has no faces");
  EXPECT_MESSAGE_HAS(load_error("none.stl", to_binary_stl({}, "solid none")),
                     "none.stl: the mesh has no faces");
  EXPECT_MESSAGE_HAS(load_error("zero.stl", ""), "zero.stl: 0 bytes, too few for binary STL");
}

// ---------------------------------------------------------------------------------------
// Normals

/// An STL facet with the normal written `normal`.
std::string stl_with_normal(std::string_view normal) {
  std::string s = "solid s\nfacet normal ";
  s.append(normal);
  s.append("\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
  return s;
}

TEST(StlNormals, EveryFloatAWriterPrintsIsTaken) {
  // glibc and MSVC since 2015, older MSVC (%f, %e, %g), Java, in several cases; numbers
  // beyond the double range (the normal is not used).
  const std::vector<std::string> spellings = {"nan",
                                              "-nan",
                                              "NAN",
                                              "inf",
                                              "-INF",
                                              "Infinity",
                                              "-nan(ind)",
                                              "nan(snan)",
                                              "nan(0x7fc00000)",
                                              "-NaN(IND)",
                                              "1.#INF00",
                                              "-1.#IND00",
                                              "1.#QNAN0",
                                              "1.#SNAN0",
                                              "-1.#INF",
                                              "1.#IND",
                                              "1.#INF00e+000",
                                              "-1.#QNAN0E-000",
                                              "1.#qnan",
                                              "1e400",
                                              "-1e-400",
                                              "0x1p-1080",
                                              "+0",
                                              "-0.0"};
  for (const std::string& spelling : spellings) {
    const std::string normal = spelling + " " + spelling + " " + spelling;
    try {
      const LoadedMesh m = read_stl(stl_with_normal(normal), "n.stl", {});
      EXPECT_EQ(m.mesh.vertices.size(), 3u) << spelling;
    } catch (const io::InputError& e) {
      ADD_FAILURE() << spelling << ": " << e.what();
    }
  }
}

TEST(StlNormals, WhatNoWriterPrintsIsRefused) {
  for (const char* bad :
       {"a", "1,5", "0x", "1.#", "1.#INFX", "1.#IN", "2.#INF", "1.#INF00e", "1.#INF00e+", "nan(",
        "nan(a b)", "nan()x", "infinit", "+-1", "--nan", "1.#QNAN0-"}) {
    const std::string normal = std::string("0 ") + bad + " 0";
    try {
      (void)read_stl(stl_with_normal(normal), "n.stl", {});
      ADD_FAILURE() << bad << " was taken";
    } catch (const io::InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("n.stl:2:", 0), 0u) << message;
      EXPECT_NE(message.find("the normal"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace exactgeo::mesh
