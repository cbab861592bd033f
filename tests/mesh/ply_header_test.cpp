// The PLY header (ply_header.hpp), read by the PLY reader: a line that is no PLY keyword is
// skipped only when it cannot be a layout line written wrong, and said in a note. Every
// header line's keyword miscased or misspelt, in ASCII and both binary byte orders, gives
// the file's mesh bit for bit or an error naming that line, never a different mesh; unknown
// lines before properties are refused, with the line; every malformed header is refused
// naming its line. And parse_ply_header itself: the elements, properties, types (under
// both of PLY 1.0's names, with the sizes the format gives them), where the data begins.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../../mesh/src/ply_header.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "mesh/mesh_io.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

using test_io::cat;  // the readers' fixture and PLY writers (mesh_io.hpp)
using test_io::mesh_io;
using test_io::ply_header;
using test_io::put;

constexpr std::array<const char*, 3> kFormats = {"ascii", "binary_little_endian",
                                                 "binary_big_endian"};

/// A PLY file as header lines and data: three vertices (x y z, an extra float) and one
/// triangle, so that a property that moves from one element to another changes no stride
/// count the reader could check.
struct PlyFile {
  std::vector<std::string> header;
  std::string data;

  std::string text() const {
    std::string s;
    for (const std::string& line : header)
      s.append(line).push_back('\n');
    return s + data;
  }
};

/// The file in `format`, with `extra_rows` rows of one float in an element "extra" between
/// the vertices and the face (0: no such element).
PlyFile triangle_file(std::string_view format, int extra_rows = 0) {
  PlyFile file;
  file.header = {"ply",
                 "format " + std::string(format) + " 1.0",
                 "comment a test",
                 "element vertex 3",
                 "property float x",
                 "property float y",
                 "property float z",
                 "property float w"};
  if (extra_rows > 0) {
    file.header.push_back("element extra " + std::to_string(extra_rows));
    file.header.push_back("property float q");
  }
  file.header.insert(file.header.end(),
                     {"element face 1", "property list uchar int vertex_indices", "end_header"});
  const float vertices[3][4] = {{0.f, 0.f, 0.f, 9.f}, {1.f, 0.f, 0.f, 8.f}, {0.f, 1.f, 0.f, 7.f}};
  const bool binary = format != "ascii";
  const bool big = format == "binary_big_endian";
  for (const auto& v : vertices) {
    for (const float x : v) {
      if (binary) {
        put(file.data, x, big);
      } else {
        file.data.append(std::to_string(x)).push_back(' ');
      }
    }
    if (!binary) file.data.back() = '\n';
  }
  for (int row = 0; row < extra_rows; ++row) {
    if (binary) {
      put(file.data, 5.f, big);
    } else {
      file.data.append("5\n");
    }
  }
  if (binary) {
    put(file.data, std::uint8_t{3}, big);
    for (const std::int32_t i : {0, 1, 2})
      put(file.data, i, big);
  } else {
    file.data.append("3 0 1 2\n");
  }
  return file;
}

/// The mesh read, or the error's message.
struct Outcome {
  std::optional<Mesh> mesh;
  std::string error;
};

Outcome read(const std::string& bytes) {
  try {
    return {read_ply(bytes, "t.ply", {}).mesh, {}};
  } catch (const io::InputError& e) {
    return {std::nullopt, e.what()};
  }
}

bool same(const Mesh& a, const Mesh& b) {
  if (a.vertices.size() != b.vertices.size() || !(a.faces == b.faces)) return false;
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    for (int i = 0; i < 3; ++i) {
      if (std::bit_cast<std::uint64_t>(a.vertices[v][i]) !=
          std::bit_cast<std::uint64_t>(b.vertices[v][i]))
        return false;
    }
  }
  return true;
}

/// `word` with its letters' case changed at random, at least one of them.
std::string miscased(std::string word, std::mt19937_64& rng) {
  std::vector<std::size_t> letters;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (std::isalpha(static_cast<unsigned char>(word[i]))) letters.push_back(i);
  }
  std::bernoulli_distribution flip(0.5);
  const std::size_t always =
      letters[std::uniform_int_distribution<std::size_t>(0, letters.size() - 1)(rng)];
  for (const std::size_t i : letters) {
    if (i == always || flip(rng)) word[i] = static_cast<char>(std::toupper(word[i]));
  }
  return word;
}

/// `word` after one or two typing errors: a letter added, dropped or changed, or two
/// neighbours swapped. (It may come back as it was: the caller checks.)
std::string misspelt(std::string word, std::mt19937_64& rng) {
  const int errors = std::uniform_int_distribution<int>(1, 2)(rng);
  std::uniform_int_distribution<char> letter('a', 'z');
  for (int e = 0; e < errors && !word.empty(); ++e) {
    const std::size_t at = std::uniform_int_distribution<std::size_t>(0, word.size() - 1)(rng);
    switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
      case 0:
        word.insert(word.begin() + static_cast<std::ptrdiff_t>(at), letter(rng));
        break;
      case 1:
        if (word.size() > 1) word.erase(at, 1);
        break;
      case 2:
        word[at] = letter(rng);
        break;
      default:
        if (at + 1 < word.size()) std::swap(word[at], word[at + 1]);
        break;
    }
  }
  return word;
}

/// The line with its first word replaced.
std::string with_first_word(const std::string& line, const std::string& word) {
  const std::size_t space = line.find(' ');
  return space == std::string::npos ? word : word + line.substr(space);
}

TEST(PlyHeader, AKeywordMiscasedOrMisspeltGivesTheMeshOrNamesItsLine) {
  std::mt19937_64 rng = testing::seeded_engine("PlyHeader.keywords");
  for (const char* format : kFormats) {
    for (const int extra_rows : {0, 3}) {
      const PlyFile file = triangle_file(format, extra_rows);
      const Outcome original = read(file.text());
      ASSERT_TRUE(original.mesh.has_value()) << original.error;
      // Every header line but the magic one (a miscased "PLY" is refused on its own).
      for (std::size_t line = 1; line < file.header.size(); ++line) {
        const std::string keyword = file.header[line].substr(0, file.header[line].find(' '));
        for (int variant = 0; variant < 12; ++variant) {
          const std::string word = variant < 4 ? miscased(keyword, rng) : misspelt(keyword, rng);
          if (word == keyword) continue;
          PlyFile changed = file;
          changed.header[line] = with_first_word(file.header[line], word);
          const Outcome outcome = read(changed.text());
          const std::string where = "t.ply:" + std::to_string(line + 1) + ":";
          if (outcome.mesh) {
            EXPECT_TRUE(same(*outcome.mesh, *original.mesh))
                << format << ", line " << line + 1 << " as '" << changed.header[line]
                << "': read as a different mesh";
          } else {
            EXPECT_EQ(outcome.error.rfind(where, 0), 0u)
                << format << ", line " << line + 1 << " as '" << changed.header[line]
                << "': " << outcome.error;
          }
        }
      }
    }
  }
}

TEST(PlyHeader, AMiscasedElementWhoseStridesAddUpIsRefused) {
  // The file: "Element extra 3" with its property, whose 3 floats make the
  // vertices' rows exactly long enough if "q" were a vertex property. Read as written, it
  // would give the vertices other coordinates and exit 0.
  for (const char* format : kFormats) {
    PlyFile file = triangle_file(format, 3);
    const auto element = std::find(file.header.begin(), file.header.end(), "element extra 3");
    ASSERT_NE(element, file.header.end());
    *element = "Element extra 3";
    const Outcome outcome = read(file.text());
    ASSERT_FALSE(outcome.mesh.has_value()) << format;
    EXPECT_EQ(outcome.error.rfind("t.ply:9:", 0), 0u) << outcome.error;
    EXPECT_NE(outcome.error.find("'element'"), std::string::npos) << outcome.error;
  }
}

TEST(PlyHeader, AnUnknownLineIsSkippedOnlyWhereNothingAfterItCouldBeItsOwn) {
  // An unknown line inserted at every place of the header: skipped (with a note naming it)
  // where no property follows it in its element and it has no property's shape there;
  // else refused, naming it.
  const std::vector<std::string> unknown_lines = {"Created by an exporter 2.1", "units mm",
                                                  "block extra 4", "colour float q",
                                                  "normals list uchar float n"};
  for (const char* format : kFormats) {
    const PlyFile file = triangle_file(format);
    const Outcome original = read(file.text());
    ASSERT_TRUE(original.mesh.has_value());
    for (std::size_t at = 2; at < file.header.size(); ++at) {  // after the format line
      for (const std::string& unknown : unknown_lines) {
        PlyFile changed = file;
        changed.header.insert(changed.header.begin() + static_cast<std::ptrdiff_t>(at), unknown);
        const bool in_element = at > 3;  // after "element vertex 3"
        const bool property_follows = changed.header[at + 1].rfind("property", 0) == 0;
        const bool property_shaped = unknown == "colour float q" || unknown.starts_with("normals");
        const bool refused = property_follows || (in_element && property_shaped);
        const std::string where = "t.ply:" + std::to_string(at + 1) + ":";
        const std::string next = "t.ply:" + std::to_string(at + 2) + ":";
        try {
          const LoadedMesh m = read_ply(changed.text(), "t.ply", {});
          EXPECT_FALSE(refused) << format << ": '" << unknown << "' at line " << at + 1;
          EXPECT_TRUE(same(m.mesh, *original.mesh));
          ASSERT_EQ(m.notes.size(), 1u);
          EXPECT_EQ(m.notes[0].rfind(where + " skipped header line", 0), 0u) << m.notes[0];
        } catch (const io::InputError& e) {
          const std::string message = e.what();
          EXPECT_TRUE(refused) << format << ": '" << unknown << "' at line " << at + 1 << ": "
                               << message;
          // Named where it is, or at the property after it, which names it.
          const bool named =
              message.rfind(where, 0) == 0 ||
              (message.rfind(next, 0) == 0 &&
               message.find("header line " + std::to_string(at + 1)) != std::string::npos);
          EXPECT_TRUE(named) << message;
        }
      }
    }
  }
}

TEST(PlyHeader, MessagesSayWhatWasMeant) {
  // The header's lines after "element vertex 3" (line 4): x y z on lines 5 to 7.
  const auto error_with = [](std::size_t line, const std::string& text) {
    PlyFile file = triangle_file("ascii");
    file.header.insert(file.header.begin() + static_cast<std::ptrdiff_t>(line - 1), text);
    return read(file.text()).error;
  };
  EXPECT_EQ(error_with(5, "propery float v")
                .rfind("t.ply:5: 'propery' is not a PLY keyword "
                       "(meant 'property'?",
                       0),
            0u);
  EXPECT_NE(error_with(11, "END_HEADER").find("(meant 'end_header'?"), std::string::npos);
  EXPECT_NE(error_with(5, "Created by x 3")
                .find("t.ply:6: this property follows header line 5, 'Created by x 3'"),
            std::string::npos);
  EXPECT_NE(error_with(5, "size float v")
                .find("t.ply:5: 'size float v' is not a PLY keyword line but has the shape of "
                      "a property of element 'vertex'"),
            std::string::npos);
  // A comment keyword in another case is a skipped line like any other.
  PlyFile file = triangle_file("binary_big_endian");
  file.header.insert(file.header.begin() + 8, "COMMENT from a scanner");
  const LoadedMesh m = read_ply(file.text(), "t.ply", {});
  ASSERT_EQ(m.notes.size(), 1u);
  EXPECT_EQ(m.notes[0].rfind("t.ply:9: skipped header line 'COMMENT from a scanner'", 0), 0u);
}

// ---------------------------------------------------------------------------------------
// Lines of no keyword, and the header's errors

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

// ---------------------------------------------------------------------------------------
// parse_ply_header itself

TEST(PlyHeader, TheParsedHeaderGivesTheLayoutAndWhereTheDataBegins) {
  const std::string header =
      "ply\r\nformat binary_big_endian 1.0\ncomment made by hand\nelement vertex 3\n"
      "property float32 x\nproperty double y\nproperty uchar z\nelement face 2\n"
      "property list uint8 int32 vertex_indices\nend_header\n";
  const internal::PlyHeader h = internal::parse_ply_header(header + "\x01\x02", "h.ply");
  EXPECT_EQ(h.format, internal::PlyFormat::binary_big_endian);
  EXPECT_EQ(h.data_offset, header.size());
  EXPECT_EQ(h.data_line, 11u);
  EXPECT_TRUE(h.skipped.empty());
  ASSERT_EQ(h.elements.size(), 2u);
  const internal::PlyElement& vertex = h.elements[0];
  EXPECT_EQ(vertex.name, "vertex");
  EXPECT_EQ(vertex.count, 3u);
  EXPECT_EQ(vertex.line, 4u);
  ASSERT_EQ(vertex.properties.size(), 3u);
  EXPECT_EQ(vertex.properties[0].name, "x");
  EXPECT_EQ(vertex.properties[0].type, internal::PlyType::float32);
  EXPECT_EQ(vertex.properties[1].type, internal::PlyType::float64);
  EXPECT_EQ(vertex.properties[2].type, internal::PlyType::uint8);
  EXPECT_EQ(vertex.properties[2].line, 7u);
  EXPECT_FALSE(vertex.properties[0].is_list);
  const internal::PlyElement& face = h.elements[1];
  EXPECT_EQ(face.count, 2u);
  ASSERT_EQ(face.properties.size(), 1u);
  EXPECT_TRUE(face.properties[0].is_list);
  EXPECT_EQ(face.properties[0].name, "vertex_indices");
  EXPECT_EQ(face.properties[0].count_type, internal::PlyType::uint8);
  EXPECT_EQ(face.properties[0].type, internal::PlyType::int32);
  for (const auto& [format, name] :
       {std::pair{internal::PlyFormat::ascii, "ply ascii"},
        std::pair{internal::PlyFormat::binary_little_endian, "ply binary little endian"},
        std::pair{internal::PlyFormat::binary_big_endian, "ply binary big endian"}}) {
    EXPECT_EQ(internal::ply_format_name(format), name);
  }
}

TEST(PlyHeader, EveryScalarTypeUnderBothNamesWithItsSize) {
  // PLY 1.0's eight scalar types, each under its first name and its sized one.
  struct Scalar {
    const char* name;
    const char* sized;
    std::size_t bytes;
    bool integer;
  };
  const Scalar scalars[] = {{"char", "int8", 1, true},      {"uchar", "uint8", 1, true},
                            {"short", "int16", 2, true},    {"ushort", "uint16", 2, true},
                            {"int", "int32", 4, true},      {"uint", "uint32", 4, true},
                            {"float", "float32", 4, false}, {"double", "float64", 8, false}};
  for (const Scalar& scalar : scalars) {
    for (const char* spelling : {scalar.name, scalar.sized}) {
      const std::string header =
          cat("ply\nformat ascii 1.0\nelement thing 1\nproperty ", spelling, " t\nend_header\n");
      const internal::PlyHeader h = internal::parse_ply_header(header, "t.ply");
      ASSERT_EQ(h.elements.size(), 1u);
      ASSERT_EQ(h.elements[0].properties.size(), 1u);
      const internal::PlyType type = h.elements[0].properties[0].type;
      EXPECT_EQ(internal::ply_type_size(type), scalar.bytes) << spelling;
      EXPECT_EQ(internal::ply_type_name(type), scalar.name) << spelling;
      EXPECT_EQ(internal::ply_type_is_integer(type), scalar.integer) << spelling;
    }
  }
}

}  // namespace
}  // namespace exactgeo::mesh
