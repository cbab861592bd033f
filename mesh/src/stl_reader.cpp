#include "exactgeo/mesh/stl_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "binary_value.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/io/text_scan.hpp"
#include "exactgeo/mesh/weld.hpp"
#include "polygon.hpp"

namespace exactgeo::mesh {

using internal::kMaxVertices;
using internal::load_value;
using internal::require_faces;
using internal::swap_needed;
using io::InputError;
using io::LineCursor;
using io::parse_number;
using io::quoted;
using io::skip_utf8_bom;
using io::split_tokens;

namespace {

constexpr std::size_t kHeaderBytes = 84;  // 80 bytes of header, the uint32 triangle count
constexpr std::size_t kRecordBytes = 50;  // normal, three corners (12 float32), uint16

constexpr const char* kOrdinal[3] = {"first", "second", "third"};

/// What follows "1.#" in MSVC's old spellings of infinity, NaN and signalling NaN.
constexpr std::string_view kMsvcKinds[] = {"inf", "ind", "qnan", "snan"};

/// The pieces, appended (`"literal" + std::string` trips a false GCC 12 -Wrestrict warning).
std::string cat(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (const std::string_view part : parts)
    s.append(part);
  return s;
}

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/// `token` is `keyword` (lower case) in any case.
bool is_keyword(std::string_view token, std::string_view keyword) {
  return std::equal(token.begin(), token.end(), keyword.begin(), keyword.end(), [](char t, char k) {
    return std::tolower(static_cast<unsigned char>(t)) == k;
  });
}

/// NaN or infinity as C runtimes print a float (the STL format's normal is one, written
/// by printf or the like): glibc and MSVC since 2015 ("nan", "-nan", "inf", "INF",
/// "-nan(ind)", "nan(snan)", C99's "nan(chars)"), MSVC before 2015 ("1.#INF00",
/// "-1.#IND00", "1.#QNAN0", "1.#SNAN", with %e "1.#INF00e+000"), Java ("NaN",
/// "Infinity"), in any case.
bool spells_non_finite(std::string_view token) {
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) token.remove_prefix(1);
  const auto lower = [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  };
  std::string t(token.size(), '\0');
  std::transform(token.begin(), token.end(), t.begin(), lower);
  if (t == "nan" || t == "inf" || t == "infinity") return true;
  if (t.starts_with("nan(") && t.ends_with(")")) {
    const std::string_view chars = std::string_view(t).substr(4, t.size() - 5);
    return std::all_of(chars.begin(), chars.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
  }
  // MSVC's "1.#" spellings: a kind, then the padding digits of the precision, then an
  // optional exponent as %e writes it.
  if (!t.starts_with("1.#")) return false;
  std::string_view rest = std::string_view(t).substr(3);
  const bool kind =
      std::any_of(std::begin(kMsvcKinds), std::end(kMsvcKinds), [&](std::string_view k) {
        if (!rest.starts_with(k)) return false;
        rest.remove_prefix(k.size());
        return true;
      });
  if (!kind) return false;
  const auto is_digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  while (!rest.empty() && is_digit(rest.front()))
    rest.remove_prefix(1);
  if (rest.empty()) return true;
  if (rest.front() != 'e') return false;
  rest.remove_prefix(1);
  if (!rest.empty() && (rest.front() == '+' || rest.front() == '-')) rest.remove_prefix(1);
  return !rest.empty() && std::all_of(rest.begin(), rest.end(), is_digit);
}

/// The first word (after a byte order mark and blanks) is "solid", in any case.
bool begins_with_solid(std::string_view bytes) {
  bytes = skip_utf8_bom(bytes);
  const auto first = std::find_if_not(bytes.begin(), bytes.end(), is_blank);
  bytes.remove_prefix(static_cast<std::size_t>(first - bytes.begin()));
  return is_keyword(bytes.substr(0, 5), "solid") && (bytes.size() == 5 || is_blank(bytes[5]));
}

std::uint32_t declared_triangles(std::string_view bytes) {
  return load_value<std::uint32_t>(bytes.data() + 80, swap_needed(false));
}

/// The size is exactly that of the binary STL its bytes 80..83 declare.
bool has_binary_size(std::string_view bytes) {
  return bytes.size() >= kHeaderBytes &&
         bytes.size() - kHeaderBytes == kRecordBytes * std::uint64_t{declared_triangles(bytes)};
}

class AsciiStl {
 public:
  AsciiStl(std::string_view text, const std::string& source)
      : lines_(skip_utf8_bom(text)), source_(source) {
    out_.format = "stl ascii";
  }

  LoadedMesh parse() {
    while (const auto token = next()) {
      if (!is_keyword(*token, "solid")) {
        fail(cat({"expected 'solid' or the end of the file, found ", quoted(*token)}));
      }
      skip_line();  // the solid's name
      read_solid();
    }
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_, lines_.line_number(), what);
  }

  /// "facet 3: " + what: the facet being read (numbered from 0 in the file).
  [[noreturn]] void fail_facet(const std::string& what) const {
    fail(cat({"facet ", std::to_string(out_.mesh.faces.size()), ": ", what}));
  }

  /// The next token, across lines; nullopt at the end of the text.
  std::optional<std::string_view> next() {
    while (next_ == tokens_.size()) {
      const auto line = lines_.next();
      if (!line) return std::nullopt;
      split_tokens(*line, tokens_);
      next_ = 0;
    }
    return tokens_[next_++];
  }

  void skip_line() { next_ = tokens_.size(); }

  /// The next token inside a facet, where `what` should be.
  std::string_view require(const std::string& what) {
    const auto token = next();
    if (!token) fail_facet(cat({"the file ends where ", what, " should be"}));
    return *token;
  }

  void expect(std::string_view keyword, const char* note = "") {
    const std::string name = cat({"'", keyword, "'"});
    const std::string_view token = require(name);
    if (!is_keyword(token, keyword))
      fail_facet(cat({"expected ", name, note, ", found ", quoted(token)}));
  }

  void read_solid() {
    while (true) {
      const auto token = next();
      if (!token) fail("the file ends inside a solid: 'endsolid' is missing");
      if (is_keyword(*token, "endsolid")) {
        skip_line();  // the solid's name again
        return;
      }
      if (!is_keyword(*token, "facet")) {
        fail(cat({"expected 'facet' or 'endsolid', found ", quoted(*token)}));
      }
      read_facet();
    }
  }

  void read_facet() {
    expect("normal");
    std::string error;
    for (std::size_t i = 0; i < 3; ++i) {
      // The normal is not used: any float a writer can print is taken, even one beyond
      // the double range, and only a token that is no float at all is refused.
      const std::string_view token = require("the normal");
      if (!io::is_number_literal(token) && !spells_non_finite(token)) {
        fail_facet(cat({"the normal: ", quoted(token), " is not a number"}));
      }
    }
    expect("outer");
    expect("loop");
    auto& vertices = out_.mesh.vertices;
    if (vertices.size() > kMaxVertices - 3) fail_facet("too many vertices");
    const auto first = static_cast<VertexIndex>(vertices.size());
    for (const char* ordinal : kOrdinal) {
      expect("vertex", " (a facet has three vertices)");
      Point3 p{};
      for (double& x : p) {
        const std::optional<double> value = parse_number(require("a coordinate"), error);
        if (!value) fail_facet(cat({"the ", ordinal, " vertex: ", error}));
        x = *value;
      }
      vertices.push_back(p);
    }
    expect("endloop", " (a facet has three vertices)");
    expect("endfacet");
    out_.mesh.faces.push_back(make_triangle(first, first + 1, first + 2));
  }

  LineCursor lines_;
  const std::string& source_;
  LoadedMesh out_;
  std::vector<std::string_view> tokens_;
  std::size_t next_ = 0;  ///< the next token of tokens_
};

/// `why_binary` says why a file whose size does not fit was read as binary, for the message.
LoadedMesh read_binary(std::string_view bytes, const std::string& source,
                       const std::string& why_binary) {
  auto fail = [&](const std::string& what) { throw InputError(cat({source, ": ", what})); };
  const std::string as_binary = cat({"binary STL (", why_binary, ")"});
  if (bytes.size() < kHeaderBytes) {
    fail(cat({std::to_string(bytes.size()), " bytes, too few for ", as_binary,
              ": its header and triangle count take 84"}));
  }
  const std::uint32_t count = declared_triangles(bytes);
  const std::uint64_t expected = kHeaderBytes + kRecordBytes * std::uint64_t{count};
  const std::string sizes =
      cat({": the header declares ", std::to_string(count), " triangles, 84 + 50 * ",
           std::to_string(count), " = ", std::to_string(expected), " bytes, the file has ",
           std::to_string(bytes.size()), " (", as_binary, ")"});
  if (bytes.size() < expected) {
    const std::size_t whole = (bytes.size() - kHeaderBytes) / kRecordBytes;
    const std::size_t into = (bytes.size() - kHeaderBytes) % kRecordBytes;
    fail(cat({"triangle ", std::to_string(whole), ": the file ends ", std::to_string(into),
              " bytes into it", sizes}));
  }
  if (bytes.size() > expected) {
    const std::string after = count == 0
                                  ? std::string("the header")
                                  : cat({"the last triangle (", std::to_string(count - 1), ")"});
    fail(cat({std::to_string(bytes.size() - expected), " bytes follow ", after, sizes}));
  }
  if (count > kMaxVertices / 3) fail(cat({"too many triangles: ", std::to_string(count)}));

  LoadedMesh out;
  out.format = "stl binary";
  out.mesh.vertices.reserve(3 * std::size_t{count});
  out.mesh.faces.reserve(count);
  const bool swap = swap_needed(false);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* corner = bytes.data() + kHeaderBytes + kRecordBytes * t + 12;  // past the normal
    const auto first = static_cast<VertexIndex>(out.mesh.vertices.size());
    for (const char* ordinal : kOrdinal) {
      Point3 p{};
      for (std::size_t i = 0; i < 3; ++i, corner += 4) {
        p[i] = load_value<float>(corner, swap);  // widening is exact
        if (!std::isfinite(p[i])) {
          fail(cat({"triangle ", std::to_string(t), ": the ", ordinal,
                    " vertex: ", std::string_view("xyz").substr(i, 1),
                    std::isnan(p[i]) ? " is NaN" : " is infinite"}));
        }
      }
      out.mesh.vertices.push_back(p);
    }
    out.mesh.faces.push_back(make_triangle(first, first + 1, first + 2));
  }
  return out;
}

LoadedMesh read_ascii_or_binary(std::string_view bytes, const std::string& source) {
  const bool solid = begins_with_solid(bytes);
  if (has_binary_size(bytes)) {
    if (solid) {
      try {
        return AsciiStl(bytes, source).parse();
      } catch (const InputError&) {
        // A binary header that begins with "solid": read as binary.
      }
    }
    return read_binary(bytes, source, "its size fits the triangle count");
  }
  if (solid && bytes.find('\0') == std::string_view::npos) return AsciiStl(bytes, source).parse();
  return read_binary(
      bytes, source,
      solid ? "it holds NUL bytes, which text does not" : "it does not begin with 'solid'");
}

}  // namespace

LoadedMesh read_stl(std::string_view bytes, const std::string& source, const LoadOptions&) {
  LoadedMesh out = read_ascii_or_binary(bytes, source);
  require_faces(out, source);
  out.welded_vertices = weld_vertices(out.mesh);
  return out;
}

}  // namespace exactgeo::mesh
