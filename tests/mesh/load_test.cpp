// Exact mesh loading: OBJ, OFF, PLY (ASCII, binary little/big endian) and STL (ASCII,
// binary) read bit for bit, welding, polygon splitting, and an error naming the file and
// the line or element index for every kind of bad input.

#include "exactgeo/mesh/load.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/read_bytes.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "exactgeo/mesh/weld.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------
// Helpers

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// "%.17g": the shortest form that always reads back as the same double.
std::string decimal(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// The pieces, appended (chained std::string + trips a false GCC 12 -Wrestrict warning).
template <class... Parts>
std::string cat(const Parts&... parts) {
  std::string s;
  (s.append(parts), ...);
  return s;
}

// The message of the InputError `f` throws; a test failure if it throws nothing else.
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return {};
  }
  ADD_FAILURE() << "no error";
  return {};
}

#define EXPECT_MESSAGE_HAS(message, ...)                                                        \
  do {                                                                                          \
    const std::string message_ = (message);                                                     \
    /* Strings, not views: a part may be a temporary (std::to_string) of this statement. */    \
    const std::initializer_list<std::string> parts_ = {__VA_ARGS__};                           \
    for (const std::string& part_ : parts_) {                                                   \
      EXPECT_NE(message_.find(part_), std::string::npos)                                        \
          << "message: " << message_ << "\nlacks: " << part_;                                   \
    }                                                                                           \
  } while (0)

void expect_same_mesh(const Mesh& actual, const Mesh& expected) {
  ASSERT_EQ(actual.vertices.size(), expected.vertices.size());
  for (std::size_t v = 0; v < expected.vertices.size(); ++v) {
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(bits(actual.vertices[v][i]), bits(expected.vertices[v][i]))
          << "vertex " << v << " coordinate " << i << ": " << actual.vertices[v][i] << " vs "
          << expected.vertices[v][i];
    }
  }
  EXPECT_TRUE(actual.faces == expected.faces);
}

// A test with its own temporary directory.
class mesh_io : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = "exactgeo_mesh_io_";
    name.append(std::to_string(::getpid()));
    name.push_back('_');
    name.append(::testing::UnitTest::GetInstance()->current_test_info()->name());
    dir_ = fs::temp_directory_path() / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string write(const std::string& name, std::string_view bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(out.good()) << path;
    return path.string();
  }

  LoadedMesh load(const std::string& name, std::string_view bytes, LoadOptions options = {}) {
    return load_mesh(write(name, bytes), options);
  }

  std::string load_error(const std::string& name, std::string_view bytes,
                         LoadOptions options = {}) {
    const std::string path = write(name, bytes);
    return error_of([&] { (void)load_mesh(path, options); });
  }

  fs::path dir_;
};

// ---------------------------------------------------------------------------------------
// One quad and one triangle, with coordinates that are floats (so a float PLY holds them).

Mesh quad_and_triangle() {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0},
                   {1, 0, 0},
                   {1, 1, static_cast<double>(0.1f)},
                   {0, 1, 0},
                   {static_cast<double>(-1.5e-3f), 2, -0.25}};
  mesh.faces = {make_quad(0, 1, 2, 3), make_triangle(3, 2, 4)};
  return mesh;
}

std::string to_obj(const Mesh& mesh) {
  std::string s = "# quad and triangle\r\nmtllib x.mtl\no thing\n";
  for (const auto& p : mesh.vertices) {
    s.append(cat("v ", decimal(p[0]), " ", decimal(p[1]), " ", decimal(p[2]), "\n"));
  }
  s.append("vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n\ng group\nusemtl m\ns off\n");
  for (const Face& f : mesh.faces) {
    s.append("f");
    for (std::size_t c = 0; c < f.size(); ++c) {
      // Every corner syntax: i, i/t, i//n, i/t/n.
      const std::string i = std::to_string(f.corners[c] + 1);
      const char* const forms[] = {"", "/1", "//1", "/2/1"};
      s.append(cat(" ", i, forms[c % 4]));
    }
    s.append("\n");
  }
  s.append("l 1 2\n");
  return s;
}

std::string to_off(const Mesh& mesh) {
  std::string s = cat("OFF\n# a comment\n", std::to_string(mesh.vertices.size()), " ",
                      std::to_string(mesh.faces.size()), " 0\n\n");
  for (const auto& p : mesh.vertices) {
    s.append(cat(decimal(p[0]), " ", decimal(p[1]), " ", decimal(p[2]), "\n"));
  }
  for (const Face& f : mesh.faces) {
    s.append(std::to_string(f.size()));
    for (std::size_t c = 0; c < f.size(); ++c)
      s.append(cat(" ", std::to_string(f.corners[c])));
    s.append(" 255 0 0\n");  // a colour
  }
  return s;
}

struct PlyLayout {
  std::string format;  // ascii, binary_little_endian, binary_big_endian
  std::string coordinate_type = "double";
  std::string count_type = "uchar";
  std::string index_type = "int";
};

template <class T>
void put(std::string& out, T value, bool big_endian) {
  auto raw = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
  out.append(raw.data(), raw.size());
}

// Writes `value` as PLY type `type` (binary), or as text.
void put_value(std::string& out, const std::string& type, double value, bool binary, bool big) {
  if (!binary) {
    out.append(decimal(value));
    out.push_back(' ');
  } else if (type == "double" || type == "float64") {
    put(out, value, big);
  } else if (type == "float" || type == "float32") {
    put(out, static_cast<float>(value), big);
  } else if (type == "uchar" || type == "uint8") {
    put(out, static_cast<std::uint8_t>(value), big);
  } else if (type == "int" || type == "int32") {
    put(out, static_cast<std::int32_t>(value), big);
  } else if (type == "uint" || type == "uint32") {
    put(out, static_cast<std::uint32_t>(value), big);
  } else if (type == "short" || type == "int16") {
    put(out, static_cast<std::int16_t>(value), big);
  } else {
    ADD_FAILURE() << "type " << type;
  }
}

// The mesh as PLY, with a skipped vertex property, a skipped element with a list property
// between vertices and faces, and a skipped face property.
std::string to_ply(const Mesh& mesh, const PlyLayout& layout) {
  const bool binary = layout.format != "ascii";
  const bool big = layout.format == "binary_big_endian";
  const std::string& c = layout.coordinate_type;
  std::string s = cat("ply\nformat ", layout.format, " 1.0\ncomment written by a test\n");
  s.append(cat("obj_info nothing\nelement vertex ", std::to_string(mesh.vertices.size()), "\n"));
  s.append(cat("property ", c, " x\nproperty uchar red\nproperty ", c, " y\nproperty ", c, " z\n"));
  s.append("element edge 2\nproperty list uchar int vertex_pair\nproperty float weight\n");
  s.append(cat("element face ", std::to_string(mesh.faces.size()), "\n"));
  s.append(cat("property list ", layout.count_type, " ", layout.index_type, " vertex_indices\n"));
  s.append("property short flags\nend_header\n");
  auto line_end = [&] {
    if (!binary) {
      s.pop_back();
      s.push_back('\n');
    }
  };
  for (const auto& p : mesh.vertices) {
    put_value(s, c, p[0], binary, big);
    put_value(s, "uchar", 200, binary, big);
    put_value(s, c, p[1], binary, big);
    put_value(s, c, p[2], binary, big);
    line_end();
  }
  for (int e = 0; e < 2; ++e) {
    put_value(s, "uchar", 2, binary, big);
    put_value(s, "int", e, binary, big);
    put_value(s, "int", e + 1, binary, big);
    put_value(s, "float", 0.5, binary, big);
    line_end();
  }
  for (const Face& f : mesh.faces) {
    put_value(s, layout.count_type, static_cast<double>(f.size()), binary, big);
    for (std::size_t k = 0; k < f.size(); ++k) {
      put_value(s, layout.index_type, f.corners[k], binary, big);
    }
    put_value(s, "short", -7, binary, big);
    line_end();
  }
  return s;
}

// ---------------------------------------------------------------------------------------
// The same mesh in every format

TEST_F(mesh_io, SameMeshFromObjOffAndEveryPlyLayout) {
  const Mesh expected = quad_and_triangle();

  const LoadedMesh obj = load("m.obj", to_obj(expected));
  EXPECT_EQ(obj.format, "obj");
  expect_same_mesh(obj.mesh, expected);
  EXPECT_FALSE(obj.coordinates_via_float);
  EXPECT_EQ(obj.welded_vertices, 0u);
  EXPECT_EQ(obj.split_polygons, 0u);

  const LoadedMesh off = load("m.off", to_off(expected));
  EXPECT_EQ(off.format, "off");
  expect_same_mesh(off.mesh, expected);

  const LoadedMesh ascii = load("m.ply", to_ply(expected, {"ascii"}));
  EXPECT_EQ(ascii.format, "ply ascii");
  expect_same_mesh(ascii.mesh, expected);

  const std::pair<const char*, const char*> formats[] = {
      {"binary_little_endian", "ply binary little endian"},
      {"binary_big_endian", "ply binary big endian"}};
  for (const auto& [format, name] : formats) {
    for (const char* coordinates : {"float", "double", "float32", "float64"}) {
      for (const auto& [count, index] :
           {std::pair{"uchar", "int"}, std::pair{"int", "uint"}, std::pair{"uint8", "int32"}}) {
        SCOPED_TRACE(cat(format, " ", coordinates, " ", count, " ", index));
        const PlyLayout layout{format, coordinates, count, index};
        const LoadedMesh ply = load("m.ply", to_ply(expected, layout));
        EXPECT_EQ(ply.format, name);
        expect_same_mesh(ply.mesh, expected);
        for (const auto& p : ply.mesh.vertices) {
          for (const double x : p)
            EXPECT_EQ(static_cast<double>(static_cast<float>(x)), x);
        }
      }
    }
  }
}

TEST_F(mesh_io, ExtensionIsCaseInsensitive) {
  const Mesh expected = quad_and_triangle();
  expect_same_mesh(load("UPPER.OBJ", to_obj(expected)).mesh, expected);
  expect_same_mesh(load("Mixed.Off", to_off(expected)).mesh, expected);
  expect_same_mesh(load("x.PLY", to_ply(expected, {"binary_big_endian"})).mesh, expected);
}

TEST(mesh_io_streams, ReadersTakeStreamsAndMemory) {
  const Mesh expected = quad_and_triangle();
  std::istringstream obj(to_obj(expected));
  expect_same_mesh(read_obj(io::read_stream(obj, "<obj>"), "<obj>", {}).mesh, expected);
  std::istringstream off(to_off(expected));
  expect_same_mesh(read_off(io::read_stream(off, "<off>"), "<off>", {}).mesh, expected);
  const std::string ply = to_ply(expected, {"binary_little_endian"});
  expect_same_mesh(read_ply(std::string_view(ply), "<ply>", {}).mesh, expected);
  EXPECT_MESSAGE_HAS(error_of([] { (void)read_obj(std::string_view("v 1 2 x\n"), "<mem>", {}); }),
                     "<mem>:1:", "'x'");
}

// ---------------------------------------------------------------------------------------
// Exactness

// Text forms of awkward doubles and their exact values.
struct ExactCase {
  const char* text;
  double value;
};
const ExactCase kExactCases[] = {
    {"0.1", 0.1},
    {"0.30000000000000004", 0.30000000000000004},
    {"0.12345678901234568", 0.12345678901234568},
    {"-2.7182818284590451", -2.7182818284590451},
    {"0x1.999999999999ap-4", 0.1},
    {"-0x1.8p+3", -12.0},
    {"4.9e-324", std::numeric_limits<double>::denorm_min()},
    {"-4.9406564584124654e-324", -std::numeric_limits<double>::denorm_min()},
    {"2.2250738585072009e-308", std::nextafter(DBL_MIN, 0.0)},
    {"0x1p-1074", std::numeric_limits<double>::denorm_min()},
    {"1.0715086071862673e301", 0x1p1000},
    {"9.332636185032189e-302", 0x1p-1000},
    {"0x1.fffffffffffffp+1023", DBL_MAX},
    {"-1.7976931348623157e308", -DBL_MAX},
    {"3", 3.0},
    {"-0", -0.0},
};

TEST_F(mesh_io, DecimalAndHexfloatTextIsCorrectlyRounded) {
  constexpr std::size_t n = std::size(kExactCases);
  std::string obj, off_vertices, ply_vertices;
  for (std::size_t v = 0; v < n; ++v) {
    // Vertex v holds case v in x, case v+1 in y, case v+2 in z.
    std::string xyz;
    for (std::size_t i = 0; i < 3; ++i) {
      xyz.append(kExactCases[(v + i) % n].text);
      xyz.push_back(i < 2 ? ' ' : '\n');
    }
    obj.append(cat("v ", xyz));
    off_vertices.append(xyz);
    ply_vertices.append(xyz);
  }
  obj.append("f 1 2 3\n");
  const std::string off = cat("OFF ", std::to_string(n), " 1 0\n", off_vertices, "3 0 1 2\n");
  const std::string ply = cat("ply\nformat ascii 1.0\nelement vertex ", std::to_string(n),
                              "\nproperty double x\nproperty double y\nproperty double z\n"
                              "element face 1\nproperty list uchar int vertex_indices\n"
                              "end_header\n",
                              ply_vertices, "3 0 1 2\n");
  for (const LoadedMesh& m : {load("e.obj", obj), load("e.off", off), load("e.ply", ply)}) {
    SCOPED_TRACE(m.format);
    ASSERT_EQ(m.mesh.vertices.size(), n);
    for (std::size_t v = 0; v < n; ++v) {
      for (std::size_t i = 0; i < 3; ++i) {
        const ExactCase& c = kExactCases[(v + i) % n];
        EXPECT_EQ(bits(m.mesh.vertices[v][i]), bits(c.value)) << c.text;
      }
    }
  }
}

TEST_F(mesh_io, BinaryDoublesAreReadBitForBit) {
  Mesh mesh;
  for (std::size_t v = 0; v + 2 < std::size(kExactCases); ++v) {
    mesh.vertices.push_back(
        {kExactCases[v].value, kExactCases[v + 1].value, kExactCases[v + 2].value});
  }
  mesh.faces = {make_triangle(0, 1, 2), make_quad(3, 4, 5, 6)};
  for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
    expect_same_mesh(load("b.ply", to_ply(mesh, {format})).mesh, mesh);
  }
}

TEST_F(mesh_io, RandomDoublesRoundTripThroughTextAndBinary) {
  auto engine = exactgeo::testing::seeded_engine("mesh_io.random_doubles");
  std::uniform_int_distribution<std::uint64_t> any_bits;
  Mesh mesh;
  while (mesh.vertices.size() < 300) {
    Point3 p{};
    for (double& x : p) {
      do {
        x = std::bit_cast<double>(any_bits(engine));
      } while (!std::isfinite(x));
    }
    mesh.vertices.push_back(p);
  }
  for (mesh::VertexIndex v = 0; v + 3 < 300; v += 4)
    mesh.faces.push_back(make_quad(v, v + 1, v + 2, v + 3));
  expect_same_mesh(load("r.obj", to_obj(mesh)).mesh, mesh);
  expect_same_mesh(load("r.off", to_off(mesh)).mesh, mesh);
  expect_same_mesh(load("r.ply", to_ply(mesh, {"ascii"})).mesh, mesh);
  expect_same_mesh(load("r.ply", to_ply(mesh, {"binary_big_endian"})).mesh, mesh);
}

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

TEST_F(mesh_io, Utf16TextIsReadAsItsCharacters) {
  // Some Windows tools save OBJ and OFF as UTF-16, with a byte order mark.
  const std::string obj =
      "# caf\u00e9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  const std::string off =
      "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0.1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  for (const auto& [name, text] : {std::pair{"t.obj", obj}, std::pair{"t.off", off}}) {
    const LoadedMesh utf8 = load(name, text);
    for (const bool big : {true, false}) {
      std::string utf16 = big ? "\xFE\xFF" : "\xFF\xFE";
      // The text's characters are ASCII but for the comment's e-acute (U+00E9, two UTF-8
      // bytes): each as one 16-bit unit.
      for (std::size_t i = 0; i < text.size(); ++i) {
        unsigned unit = static_cast<unsigned char>(text[i]);
        if (unit == 0xC3) unit = 0xC0 | (static_cast<unsigned char>(text[++i]) & 0x3F);
        const char high = static_cast<char>(unit >> 8), low = static_cast<char>(unit & 0xFF);
        utf16.push_back(big ? high : low);
        utf16.push_back(big ? low : high);
      }
      const LoadedMesh read = load(name, utf16);
      EXPECT_EQ(read.mesh.vertices, utf8.mesh.vertices) << name << (big ? " big" : " little");
      EXPECT_EQ(read.mesh.faces, utf8.mesh.faces) << name;
      // Cut by one byte, inside its last character: refused, never read short (a cut quad
      // once loaded as a triangle).
      utf16.pop_back();
      EXPECT_MESSAGE_HAS(load_error(name, utf16), name, "UTF-16",
                         big ? "big-endian" : "little-endian", "odd number of bytes",
                         std::to_string(utf16.size()));
    }
  }
}

// ---------------------------------------------------------------------------------------
// Polygons with more than four corners

TEST_F(mesh_io, PolygonsAreSplitInEveryReader) {
  // A convex pentagon and a concave hexagon, flat: triangles, no option needed. (Their
  // tiling is checked against exact oracles in polygon_test.cpp.)
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n";
  const LoadedMesh pentagon = load("p.obj", obj);
  EXPECT_EQ(pentagon.split_polygons, 1u);
  EXPECT_EQ(pentagon.mesh.faces.size(), 3u);

  const std::string off = "OFF\n5 2 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n3 0 1 2\n5 0 1 2 3 4\n";
  const LoadedMesh two = load("p.off", off);
  EXPECT_EQ(two.mesh.faces.size(), 4u);
  EXPECT_EQ(two.numbering.file_faces, (std::vector<std::size_t>{0, 1, 1, 1}));
  // The pentagram's edges cross: refused at its line, with the way out.
  const std::string star = "OFF\n5 1 0\n0 10 0\n6 -8 0\n-10 3 0\n10 3 0\n-6 -8 0\n5 0 1 2 3 4\n";
  EXPECT_MESSAGE_HAS(load_error("s.off", star), "s.off:8: face 0:", "cross", "--split-polygons");

  Mesh mesh;
  // An L: corner 1 is its inner corner; seen from corner 0, the end of an arm, the
  // other arm is hidden behind it.
  mesh.vertices = {{4, 1, 0}, {1, 1, 0}, {1, 4, 0}, {0, 4, 0}, {0, 0, 0}, {4, 0, 0}};
  mesh.faces = {make_triangle(0, 1, 5)};
  std::string ply = to_ply(mesh, {"binary_little_endian"});
  // Turn the triangle into the hexagon 0 1 2 3 4 5: count byte 6, then three more indices.
  const std::size_t face_at = ply.size() - (1 + 3 * 4 + 2);
  ply[face_at] = 6;
  std::string extra;
  for (const std::int32_t i : {2, 3, 4})
    put(extra, i, false);
  ply.insert(face_at + 1 + 2 * 4, extra);  // after corners 0 1: 0 1 2 3 4 5
  const LoadedMesh hex = load("h.ply", ply);
  EXPECT_EQ(hex.split_polygons, 1u);
  EXPECT_EQ(hex.mesh.faces.size(), 4u);
  // Not the fan from corner 0, whose first two triangles lie outside the L.
  for (const Face& f : hex.mesh.faces) {
    EXPECT_FALSE(f == make_triangle(0, 1, 2) || f == make_triangle(0, 2, 3));
  }
  // A binary file has no lines: the face is named alone.
  std::string crossed = ply;
  std::swap(crossed[face_at + 1 + 2 * 4], crossed[face_at + 1 + 4 * 4]);  // 0 1 4 3 2 5
  EXPECT_MESSAGE_HAS(load_error("x.ply", crossed), "x.ply: face 0:", "cross", "--split-polygons");
}

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

// ---------------------------------------------------------------------------------------
// PLY specifics

std::string ply_header(const std::string& format, std::uint64_t vertices, std::uint64_t faces,
                       const std::string& coordinate = "float",
                       const std::string& list = "uchar int") {
  return cat("ply\nformat ", format, " 1.0\nelement vertex ", std::to_string(vertices),
             "\nproperty ", coordinate, " x\nproperty ", coordinate, " y\nproperty ", coordinate,
             " z\nelement face ", std::to_string(faces), "\nproperty list ", list,
             " vertex_indices\nend_header\n");
}

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

TEST_F(mesh_io, PlyHeaderLinesOfNoKeywordAreSkippedAndSaid) {
  // Exporters write lines such as "Created by ..." into the header (assimp-testmodels'
  // Wuson.ply): nothing the data's layout depends on, so they are skipped, and listed.
  std::string text = ply_header("ascii", 3, 1);
  text.insert(text.find("element vertex"), "Created by an exporter 2.1\n");
  text.insert(text.find("end_header"), "  \nunits millimetre\n");
  text += "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const LoadedMesh m = load("wuson.ply", text);
  EXPECT_TRUE(m.mesh.faces == std::vector<Face>{make_triangle(0, 1, 2)});
  ASSERT_EQ(m.notes.size(), 2u);
  EXPECT_MESSAGE_HAS(m.notes[0],
                     "wuson.ply:3: skipped header line 'Created by an exporter 2.1': not a PLY "
                     "keyword, and nothing the data's layout depends on");
  EXPECT_MESSAGE_HAS(m.notes[1], "wuson.ply:11: skipped header line 'units millimetre'");
  // The same in binary: the data still starts right after end_header.
  std::string bin = ply_header("binary_little_endian", 3, 1);
  bin.insert(bin.find("element vertex"), "Created by an exporter\n");
  for (const float x : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
    put(bin, x, false);
  put(bin, std::uint8_t{3}, false);
  for (const std::int32_t i : {0, 1, 2})
    put(bin, i, false);
  const LoadedMesh b = load("wuson_bin.ply", bin);
  EXPECT_EQ(b.mesh.vertices[1], (Point3{1, 0, 0}));
  EXPECT_EQ(b.notes.size(), 1u);
  EXPECT_TRUE(load("plain.ply", ply_header("ascii", 3, 1) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
                  .notes.empty());
}

TEST_F(mesh_io, PlyHeaderErrors) {
  EXPECT_MESSAGE_HAS(load_error("magic.ply", "PLY\n"), "magic.ply:1:", "'ply'");
  EXPECT_MESSAGE_HAS(load_error("ver.ply", "ply\nformat ascii 2.0\n"), "ver.ply:2:", "'2.0'");
  EXPECT_MESSAGE_HAS(load_error("fmt.ply", "ply\nformat binary 1.0\n"), "fmt.ply:2:", "'binary'");
  EXPECT_MESSAGE_HAS(load_error("end.ply", "ply\nformat ascii 1.0\nelement vertex 0\n"),
                     "end.ply:3:", "end_header");
  EXPECT_MESSAGE_HAS(load_error("nofmt.ply", "ply\nelement vertex 0\nend_header\n"),
                     "nofmt.ply:3:", "format");
  EXPECT_MESSAGE_HAS(load_error("type.ply",
                                "ply\nformat ascii 1.0\nelement vertex 1\n"
                                "property real x\n"),
                     "type.ply:4:", "'real'");
  EXPECT_MESSAGE_HAS(load_error("prop.ply", "ply\nformat ascii 1.0\nproperty float x\n"),
                     "prop.ply:3:", "before any element");
  EXPECT_MESSAGE_HAS(load_error("cnt.ply", "ply\nformat ascii 1.0\nelement vertex -1\n"),
                     "cnt.ply:3:", "negative");
  // An unknown line is skipped (below); the header must still end.
  EXPECT_MESSAGE_HAS(load_error("key.ply", "ply\nformat ascii 1.0\nfoo bar\n"),
                     "key.ply:3:", "end_header");
  EXPECT_MESSAGE_HAS(load_error("noz.ply",
                                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                "property float y\nelement face 0\n"
                                "property list uchar int vertex_indices\nend_header\n"),
                     "noz.ply:3:", "property z is missing");
  EXPECT_MESSAGE_HAS(load_error("flist.ply", ply_header("ascii", 3, 1, "float", "uchar float")),
                     "flist.ply:8:", "integer type");
  EXPECT_MESSAGE_HAS(load_error("fcount.ply", ply_header("ascii", 3, 1, "float", "float int")),
                     "fcount.ply:8:", "count type");
  EXPECT_MESSAGE_HAS(load_error("noface.ply",
                                "ply\nformat ascii 1.0\nelement vertex 0\n"
                                "property float x\nproperty float y\n"
                                "property float z\nend_header\n"),
                     "noface.ply", "no 'face' element");
  EXPECT_MESSAGE_HAS(load_error("dup.ply",
                                "ply\nformat ascii 1.0\nelement vertex 0\n"
                                "property float x\nproperty float x\n"),
                     "dup.ply:5:", "second property");
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

// ---------------------------------------------------------------------------------------
// Files and extensions

TEST_F(mesh_io, FileAndExtensionErrors) {
  const std::string missing = (dir_ / "missing.obj").string();
  EXPECT_MESSAGE_HAS(error_of([&] { (void)load_mesh(missing); }), missing, "cannot open");
  const std::string missing_stl = (dir_ / "missing.stl").string();
  EXPECT_MESSAGE_HAS(error_of([&] { (void)load_mesh(missing_stl); }), missing_stl, "cannot open");
  EXPECT_MESSAGE_HAS(error_of([&] { (void)load_mesh(cat(dir_.string(), "/")); }), "unsupported");
  fs::create_directories(dir_ / "folder.obj");
  EXPECT_MESSAGE_HAS(error_of([&] { (void)load_mesh((dir_ / "folder.obj").string()); }),
                     "folder.obj", "directory");
  EXPECT_MESSAGE_HAS(load_error("mesh.xyzzy", "v 0 0 0\n"), "mesh.xyzzy", "unsupported", ".xyzzy");
  EXPECT_MESSAGE_HAS(load_error("noextension", "v 0 0 0\n"), "noextension", "no file extension");
}

// LoadOptions::format names the format when the name does not tell it, and overrides an
// extension that lies; the same bytes give the same mesh either way.
TEST_F(mesh_io, FormatOptionOverridesTheExtension) {
  const Mesh expected = quad_and_triangle();
  const LoadedMesh by_extension = load("m.obj", to_obj(expected));
  const LoadedMesh named = load("no_extension", to_obj(expected), {.format = "obj"});
  EXPECT_EQ(named.format, "obj");
  EXPECT_EQ(named.mesh.vertices, by_extension.mesh.vertices);
  EXPECT_EQ(named.mesh.faces, by_extension.mesh.faces);
  // Upper case is fine; an OFF file called .obj is read as OFF when told so.
  const LoadedMesh off = load("really_off.obj", to_off(expected), {.format = "OFF"});
  EXPECT_EQ(off.format, "off");
  EXPECT_EQ(off.mesh.faces, by_extension.mesh.faces);
  // Without the option the extension decides, and the OFF text is not OBJ.
  EXPECT_MESSAGE_HAS(load_error("really_off2.obj", to_off(expected)), "really_off2.obj");
  EXPECT_MESSAGE_HAS(load_error("m2.obj", to_obj(expected), {.format = "xyzzy"}), "m2.obj",
                     "unsupported mesh format 'xyzzy'");
}

// ---------------------------------------------------------------------------------------
// STL: ASCII and binary, read exactly, always welded

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
// Welding

TEST_F(mesh_io, WeldingTurnsAQuadSoupIntoSharedVertices) {
  // A cube stored as six quads with four vertices each.
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  auto corner = [](int v) {
    return Point3{static_cast<double>(v & 1 ? 1 : 0) * 0.1, v & 2 ? 1e-300 : 0.0,
                  v & 4 ? -3.0 : 0.0};
  };
  std::string off = "OFF\n24 6 0\n";
  for (const auto& q : quads) {
    for (const int v : q) {
      const Point3 p = corner(v);
      off.append(cat(decimal(p[0]), " ", decimal(p[1]), " ", decimal(p[2]), "\n"));
    }
  }
  for (int f = 0; f < 6; ++f) {
    off.append("4");
    for (int c = 0; c < 4; ++c)
      off.append(cat(" ", std::to_string(4 * f + c)));
    off.append("\n");
  }
  const LoadedMesh soup = load("soup.off", off);
  EXPECT_EQ(soup.mesh.vertices.size(), 24u);
  EXPECT_EQ(soup.welded_vertices, 0u);

  const LoadedMesh welded = load("soup.off", off, {.weld = true});
  EXPECT_EQ(welded.mesh.vertices.size(), 8u);
  EXPECT_EQ(welded.welded_vertices, 16u);
  ASSERT_EQ(welded.mesh.faces.size(), 6u);
  for (std::size_t f = 0; f < 6; ++f) {
    EXPECT_FALSE(welded.mesh.faces[f].is_triangle());
    for (std::size_t c = 0; c < 4; ++c) {
      // Same corner positions as before, now shared.
      EXPECT_EQ(welded.mesh.vertices[welded.mesh.faces[f].corners[c]],
                soup.mesh.vertices[soup.mesh.faces[f].corners[c]]);
    }
  }
  // First-occurrence order: the first face's corners are vertices 0..3.
  EXPECT_TRUE(welded.mesh.faces[0] == make_quad(0, 1, 2, 3));
}

TEST_F(mesh_io, WeldingComesBeforePolygonsAreSplit) {
  // A pentagon whose first corner is written again as vertex 6 at the same place: without
  // welding the polygon touches itself there (refused in every reader, for want of
  // --split-polygons); welded, it is the pentagon, split exactly.
  const std::string vertices = "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nv 0 0 0\n";
  const std::string faces = "f 1 2 3 4 5 6\n";
  EXPECT_MESSAGE_HAS(load_error("touch.obj", vertices + faces), "touch.obj:7:", "face 1",
                     "--split-polygons");
  const LoadedMesh welded = load("touch.obj", vertices + faces, {.weld = true});
  EXPECT_EQ(welded.welded_vertices, 1u);
  EXPECT_EQ(welded.mesh.vertices.size(), 5u);
  EXPECT_EQ(welded.mesh.faces.size(), 3u);
  EXPECT_EQ(welded.split_polygons, 1u);
  for (const Face& f : welded.mesh.faces) {
    EXPECT_TRUE(f.is_triangle());
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_LT(f.corners[c], 5u);
  }
  // The same in OFF and PLY.
  const std::string off = "OFF\n6 1 0\n0 0 0\n2 0 0\n3 1 0\n1 2 0\n-1 1 0\n0 0 0\n6 0 1 2 3 4 5\n";
  EXPECT_MESSAGE_HAS(load_error("touch.off", off), "touch.off:9:", "--split-polygons");
  EXPECT_EQ(load("touch.off", off, {.weld = true}).mesh.faces.size(), 3u);
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n2 0 0\n3 1 0\n1 2 0\n-1 1 0\n0 0 0\n6 0 1 2 3 4 5\n";
  EXPECT_MESSAGE_HAS(load_error("touch.ply", ply), "touch.ply", "--split-polygons");
  EXPECT_EQ(load("touch.ply", ply, {.weld = true}).mesh.faces.size(), 3u);
}

TEST(mesh_io_weld, SignedZerosMergeAndFirstOccurrenceWins) {
  Mesh mesh;
  mesh.vertices = {{-0.0, 0.0, 1.0},    // 0
                   {5.0, 5.0, 5.0},     // 1: unreferenced, kept
                   {0.0, -0.0, 1.0},    // 2 == 0
                   {2.0, 0.0, 0.0},     // 3
                   {0.0, 0.0, 1.0},     // 4 == 0
                   {2.0, -0.0, -0.0}};  // 5 == 3
  mesh.faces = {make_triangle(2, 3, 4), make_quad(5, 0, 2, 3)};
  EXPECT_EQ(weld_vertices(mesh), 3u);
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_TRUE(std::signbit(mesh.vertices[0][0]));  // the first occurrence's coordinates
  EXPECT_EQ(mesh.vertices[1], (Point3{5, 5, 5}));
  EXPECT_EQ(mesh.vertices[2], (Point3{2, 0, 0}));
  EXPECT_TRUE(mesh.faces == (std::vector<Face>{make_triangle(0, 2, 0), make_quad(2, 0, 0, 2)}));

  Mesh distinct;
  distinct.vertices = {{0, 0, 0}, {0, 0, std::numeric_limits<double>::denorm_min()}};
  distinct.faces = {make_triangle(0, 1, 1)};
  EXPECT_EQ(weld_vertices(distinct), 0u);
  EXPECT_EQ(distinct.vertices.size(), 2u);
}

// ---------------------------------------------------------------------------------------
// Bundled and shared data

struct DataFile {
  const char* path;  // under meshes/
  std::size_t vertices;
  std::size_t triangles;
  std::size_t quads;
  std::size_t larger;             // faces with more than four corners
  std::size_t polygon_triangles;  // the triangles they split into (n - 2 each)
};

// Counts as listed in the shared data's README (and counted in the files).
const DataFile kBundled[] = {
    {"cgal/3torus.off", 19, 0, 23, 0, 0},
    {"cgal/P.off", 26, 2, 21, 2, 8},
    {"cgal/corner.off", 16, 0, 14, 0, 0},
    {"cgal/cross_quad.off", 40, 0, 38, 0, 0},
    {"cgal/cube_quad.off", 8, 0, 6, 0, 0},
    {"cgal/double-torus-example.off", 231, 0, 202, 18, 62},
    {"cgal/hole.off", 20, 16, 12, 0, 0},
    {"cgal/mpi.off", 90, 13, 12, 27, 143},
    {"cgal/torus_quad.off", 25, 0, 25, 0, 0},
    {"negative/corner_with_hole.off", 16, 0, 13, 0, 0},
    {"negative/cube4-shuffled.off", 8, 0, 6, 0, 0},
    {"negative/double-torus-3-holes.off", 228, 0, 183, 18, 62},
    {"spot/spot_control_mesh.obj", 188, 4, 160, 16, 48},
    {"spot/spot_quadrangulated.obj", 2930, 0, 2928, 0, 0},
    {"spot/spot_quad_cc1.ply", 11714, 0, 11712, 0, 0},  // binary float64 PLY
};

void expect_counts(const LoadedMesh& m, const DataFile& d) {
  EXPECT_EQ(m.mesh.vertices.size(), d.vertices);
  std::size_t triangles = 0;
  std::size_t quads = 0;
  for (const Face& f : m.mesh.faces) {
    (f.is_triangle() ? triangles : quads) += 1;
    for (std::size_t c = 0; c < f.size(); ++c)
      ASSERT_LT(f.corners[c], m.mesh.vertices.size());
  }
  EXPECT_EQ(quads, d.quads);
  EXPECT_EQ(triangles, d.triangles + d.polygon_triangles);
  EXPECT_EQ(m.split_polygons, d.larger);
  // Split polygons keep the file's face numbers: each file face gives one face or more.
  if (d.larger == 0) {
    EXPECT_TRUE(m.numbering.file_faces.empty());
  } else {
    ASSERT_EQ(m.numbering.file_faces.size(), m.mesh.faces.size());
    EXPECT_EQ(m.numbering.file_faces.back() + 1, d.triangles + d.quads + d.larger);
  }
}

TEST(mesh_io_data, BundledMeshesLoadWithTheirFaceCounts) {
  for (const DataFile& d : kBundled) {
    SCOPED_TRACE(d.path);
    const std::string path = cat(EXACTGEO_TEST_DATA_DIR, "/meshes/", d.path);
    // Polygons need no option: these are flat, or split over a projection (with a note).
    expect_counts(load_mesh(path), d);
  }
}

/// The finer Spot levels (cc1 is bundled, see kBundled).
TEST(mesh_io_data, SharedSpotPlyFilesLoadAsQuads) {
  const fs::path dir = fs::path(EXACTGEO_SHARED_DATA_DIR) / "meshes" / "spot";
  const DataFile levels[] = {{"spot_quad_cc2.ply", 46850, 0, 46848, 0, 0},
                             {"spot_quad_cc3.ply", 187394, 0, 187392, 0, 0},
                             {"spot_quad_cc4.ply", 749570, 0, 749568, 0, 0}};
  for (const DataFile& d : levels) {
    if (!fs::exists(dir / d.path)) GTEST_SKIP() << "no " << (dir / d.path);
  }
  for (const DataFile& d : levels) {
    SCOPED_TRACE(d.path);
    const LoadedMesh m = load_mesh((dir / d.path).string());
    EXPECT_EQ(m.format, "ply binary little endian");
    expect_counts(m, d);
  }
}

}  // namespace
}  // namespace exactgeo::mesh
