// Exact mesh loading (load.hpp): the same mesh from OBJ, OFF and every PLY layout, chosen by
// the extension (in any case) or by the format option, from files, streams and memory;
// decimal, hexfloat and binary numbers read bit for bit by every reader; UTF-16 text;
// every numeric field's sign spellings in every text reader; an error naming the file for
// a missing file or an unknown extension; and the bundled and shared data sets with their
// face counts. What is particular to one reader is tested in the file named after it
// (obj_reader_test.cpp, off_reader_test.cpp, ply_reader_test.cpp, ply_header_test.cpp,
// stl_reader_test.cpp), welding in weld_test.cpp, polygon splitting in polygon_test.cpp.

#include "exactgeo/mesh/load.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/read_bytes.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "exactgeo/mesh/stl_reader.hpp"
#include "mesh/mesh_io.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

using namespace test_io;  // the readers' shared helpers (mesh_io.hpp)

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
// UTF-16 text (the text readers that take it: OBJ and OFF)

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

/// Standard input as `text` while it lives.
class StandardInput {
 public:
  explicit StandardInput(const std::string& text)
      : text_(text), saved_(std::cin.rdbuf(text_.rdbuf())) {}
  ~StandardInput() {
    std::cin.rdbuf(saved_);
    std::cin.clear();
  }
  StandardInput(const StandardInput&) = delete;
  StandardInput& operator=(const StandardInput&) = delete;

 private:
  std::istringstream text_;
  std::streambuf* saved_;
};

// "-" is standard input, named so in messages; it has no extension, so the format option
// must name one (before anything is read).
TEST(mesh_io_streams, StandardInputIsReadInTheFormatNamed) {
  EXPECT_EQ(mesh_source_name("-"), "standard input");
  EXPECT_EQ(mesh_source_name("dir/m.obj"), "dir/m.obj");
  const Mesh expected = quad_and_triangle();
  {
    const StandardInput in(to_off(expected));
    const LoadedMesh m = load_mesh("-", {.format = "OFF"});
    EXPECT_EQ(m.format, "off");
    expect_same_mesh(m.mesh, expected);
  }
  {
    const StandardInput in(to_obj(expected));
    EXPECT_MESSAGE_HAS(error_of([] { (void)load_mesh("-"); }),
                       "standard input: the mesh's format cannot be told from a name", "--format");
  }
  {
    const StandardInput in("v 0 0 0\nv 1 x 0\n");
    EXPECT_MESSAGE_HAS(error_of([] { (void)load_mesh("-", {.format = "obj"}); }),
                       "standard input:2:", "'x'");
  }
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

// ---------------------------------------------------------------------------------------
// Every numeric field of every text reader, with every sign spelling: one sign is read as
// written ("+2" is 2), two signs are refused naming the field's line ("+-2" was once read
// as -2), in coordinates, counts, indices and the fields that are checked but not used
// (OBJ's texture and normal indices, OFF's face colours, STL's normals).

using Reader = LoadedMesh (*)(std::string_view, const std::string&, const LoadOptions&);

/// A file whose numeric fields are written '@', with each field's unsigned value.
struct Template {
  const char* name;
  Reader reader;
  std::string text;
  std::vector<std::string> values;

  /// The text with field `k` written `field` and every other as its value.
  std::string with(std::size_t k, const std::string& field) const {
    std::string out;
    std::size_t next = 0;
    for (const char c : text) {
      if (c != '@') {
        out.push_back(c);
        continue;
      }
      out.append(next == k ? field : values.at(next));
      ++next;
    }
    return out;
  }

  /// The line (from 1) of field `k`.
  std::size_t line_of(std::size_t k) const {
    std::size_t line = 1, field = 0;
    for (const char c : text) {
      if (c == '\n') ++line;
      if (c == '@' && field++ == k) return line;
    }
    ADD_FAILURE() << "no field " << k;
    return 0;
  }

  std::size_t fields() const { return values.size(); }
};

std::vector<Template> templates() {
  const std::vector<std::string> triangle = {"0", "0", "0", "1", "0", "0", "0", "1", "0"};
  const auto plus = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  return {
      {"t.obj", read_obj, "v @ @ @\nv @ @ @\nv @ @ @ @\nvt 0 0\nvn 0 0 1\nf @/@/@ @//@ @/@\n",
       plus(triangle, {"1", "1", "1", "1", "2", "1", "3", "1"})},  // w, then the face
      {"t.off", read_off, "OFF\n@ @ @\n@ @ @\n@ @ @\n@ @ @\n@ @ @ @ @ @ @\n",
       plus(plus({"3", "1", "0"}, triangle), {"3", "0", "1", "2", "255", "0", "0"})},
      {"t.ply",
       read_ply,
       "ply\nformat ascii 1.0\nelement vertex @\nproperty double x\nproperty float y\n"
       "property int z\nproperty uchar red\nelement face @\n"
       "property list uchar int vertex_indices\nproperty short flags\nend_header\n"
       "@ @ @ @\n@ @ @ @\n@ @ @ @\n@ @ @ @ @\n",
       {"3", "1", "0", "0", "0", "9", "1", "0", "0", "9", "0", "1", "0", "9", "3", "0", "1", "2",
        "7"}},
      {"t.stl", read_stl,
       "solid s\nfacet normal @ @ @\nouter loop\nvertex @ @ @\nvertex @ @ @\nvertex @ @ @\n"
       "endloop\nendfacet\nendsolid s\n",
       plus({"0", "0", "1"}, triangle)},
  };
}

Mesh read(const Template& t, const std::string& text) {
  return t.reader(text, t.name, {}).mesh;
}

TEST(NumericFields, OneSignIsReadAsWritten) {
  for (const Template& t : templates()) {
    const Mesh plain = read(t, t.with(t.fields(), ""));  // every field its value
    for (std::size_t k = 0; k < t.fields(); ++k) {
      const Mesh signed_plus = read(t, t.with(k, "+" + t.values[k]));
      EXPECT_EQ(signed_plus.vertices, plain.vertices) << t.name << " field " << k;
      EXPECT_TRUE(signed_plus.faces == plain.faces) << t.name << " field " << k;
    }
  }
}

TEST(NumericFields, TwoSignsAreRefusedNamingTheLine) {
  for (const Template& t : templates()) {
    for (std::size_t k = 0; k < t.fields(); ++k) {
      for (const char* two : {"+-", "-+", "++", "--"}) {
        const std::string text = t.with(k, two + t.values[k]);
        const std::string where = std::string(t.name) + ":" + std::to_string(t.line_of(k)) + ":";
        try {
          (void)read(t, text);
          ADD_FAILURE() << t.name << " field " << k << " as " << two << t.values[k] << " was read";
        } catch (const io::InputError& e) {
          EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u)
              << t.name << " field " << k << ": " << e.what();
        }
      }
    }
  }
}

TEST(NumericFields, AnySignAloneOrInsideIsRefused) {
  for (const Template& t : templates()) {
    for (std::size_t k = 0; k < t.fields(); ++k) {
      for (const std::string& bad : {std::string("+"), std::string("-"), t.values[k] + "-",
                                     "+ " + t.values[k], std::string("1+1")}) {
        bool refused = false;
        try {
          (void)read(t, t.with(k, bad));
        } catch (const io::InputError&) {
          refused = true;
        }
        // "+ 1" splits into two fields: refused for the count of fields, if not the sign.
        EXPECT_TRUE(refused) << t.name << " field " << k << " as '" << bad << "'";
      }
    }
  }
}

}  // namespace
}  // namespace exactgeo::mesh
