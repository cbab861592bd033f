#include "exactgeo/mesh/off_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/io/text_scan.hpp"
#include "polygon.hpp"

namespace exactgeo::mesh {

using internal::FileFaces;
using internal::kMaxVertices;
using internal::zero_based_index_problem;
using io::InputError;
using io::LineCursor;
using io::parse_integer;
using io::parse_number;
using io::quoted;
using io::skip_utf8_bom;
using io::split_tokens;
using io::strip_comment;

namespace {

bool is_integer_token(std::string_view token) {
  return !token.empty() && std::all_of(token.begin(), token.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  });
}

/// The values a vertex line holds after the keyword's prefixes: x y z, then a normal
/// (N: 3), a colour (C: RGB or RGBA), texture coordinates (ST: 2).
struct VertexColumns {
  bool normal = false;
  bool colour = false;
  bool texture = false;

  bool allows(std::size_t values) const noexcept {
    const std::size_t fixed = 3 + (normal ? 3 : 0) + (texture ? 2 : 0);
    return colour ? values == fixed + 3 || values == fixed + 4 : values == fixed;
  }
  /// "x y z", "x y z nx ny nz r g b [a]", ...
  std::string expected() const {
    std::string s = "x y z";
    if (normal) s.append(" nx ny nz");
    if (colour) s.append(" r g b [a]");
    if (texture) s.append(" s t");
    return s;
  }
};

class OffParser {
 public:
  OffParser(std::string_view text, const std::string& source, const LoadOptions& options)
      : lines_(skip_utf8_bom(text)), source_(source), options_(options) {
    out_.format = "off";
  }

  LoadedMesh parse() {
    read_header();
    read_vertices();
    read_faces();
    // Whatever follows the faces (some writers add edges or notes) is not read.
    faces_.finish(out_, source_, options_);
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_, lines_.line_number(), what);
  }

  // The next line with a token (comments and blank lines skipped); false at the end.
  bool next_record() {
    while (const auto line = lines_.next()) {
      split_tokens(strip_comment(*line), tokens_);
      if (!tokens_.empty()) return true;
    }
    return false;
  }

  // Most writers put a face on one line (its indices, then optional colour values);
  // some wrap long faces over several lines. Appends the following records' tokens
  // until there are `needed`. A wrapped face must end exactly at the end of a line: a
  // face line that is merely short would otherwise swallow the next face as its colour.
  bool gather(std::size_t needed) {
    if (tokens_.size() >= needed) return true;
    while (tokens_.size() < needed) {
      const std::vector<std::string_view> so_far = tokens_;
      if (!next_record()) return false;
      tokens_.insert(tokens_.begin(), so_far.begin(), so_far.end());
    }
    return tokens_.size() == needed;
  }

  void require_record(const char* expected) {
    if (!next_record()) {
      std::string what = "the file ends where ";
      what.append(expected);
      what.append(" should be");
      fail(what);
    }
  }

  std::uint64_t count(std::string_view token, const char* what) const {
    std::string error;
    const std::optional<std::int64_t> n = parse_integer(token, error);
    if (!n) {
      std::string message = what;
      message.append(": ");
      message.append(error);
      fail(message);
    }
    if (*n < 0) {
      std::string message = what;
      message.append(" is negative");
      fail(message);
    }
    return static_cast<std::uint64_t>(*n);
  }

  // "[ST][C][N]OFF", or nothing (the keyword is optional). The prefixes say which columns
  // follow x y z on a vertex line: N a normal (3 values), C a colour (RGB or RGBA: 3 or 4
  // values), ST texture coordinates (2 values), in that order.
  void read_keyword(std::string_view keyword) {
    keyword_ = keyword;
    std::string_view k = keyword;
    if (k.substr(0, 2) == "ST") {
      columns_.texture = true;
      k.remove_prefix(2);
    }
    if (k.substr(0, 1) == "C") {
      columns_.colour = true;
      k.remove_prefix(1);
    }
    if (k.substr(0, 1) == "N") {
      columns_.normal = true;
      k.remove_prefix(1);
    }
    if (k == "4OFF" || k == "nOFF" || k == "4nOFF") {
      std::string what = quoted(keyword);
      what.append(": 4D and n-dimensional OFF are not supported");
      fail(what);
    }
    if (k != "OFF") {
      std::string what = "not an OFF file: the header is ";
      what.append(quoted(keyword));
      what.append(", expected OFF (or COFF, NOFF, CNOFF, STOFF, ...)");
      fail(what);
    }
  }

  void read_header() {
    require_record("the OFF header");
    std::size_t first = 0;  // first token of the counts
    if (!is_integer_token(tokens_[0])) {
      read_keyword(tokens_[0]);
      if (tokens_.size() > 1 && tokens_[1] == "BINARY") fail("binary OFF is not supported");
      first = 1;
      if (tokens_.size() == 1) {
        require_record("the counts 'vertices faces edges'");
        first = 0;
      }
    }
    const std::size_t n = tokens_.size() - first;
    if (n != 2 && n != 3) {
      fail("expected the counts 'vertices faces edges' (3 integers; the edge count may be absent)");
    }
    vertex_count_ = count(tokens_[first], "the vertex count");
    face_count_ = count(tokens_[first + 1], "the face count");
    if (n == 3) (void)count(tokens_[first + 2], "the edge count");
    if (vertex_count_ > kMaxVertices) fail("too many vertices");
  }

  double number(std::size_t i) const {
    std::string error;
    const std::optional<double> x = parse_number(tokens_[i], error);
    if (!x) fail(error);
    return *x;
  }

  void read_vertices() {
    auto& vertices = out_.mesh.vertices;
    // Grow with the data, never by the declared count alone: a line holds at least 6 bytes.
    vertices.reserve(std::min<std::uint64_t>(vertex_count_, lines_.remaining_bytes() / 6));
    for (std::uint64_t v = 0; v < vertex_count_; ++v) {
      if (!next_record()) {
        std::string what = "the file ends after ";
        what.append(std::to_string(v));
        what.append(" of ");
        what.append(std::to_string(vertex_count_));
        what.append(" vertices");
        fail(what);
      }
      if (!columns_.allows(tokens_.size())) {
        std::string what = "vertex ";
        what.append(std::to_string(v));
        what.append(": expected ");
        what.append(columns_.expected());
        what.append(keyword_.empty() ? std::string(" (no keyword)") : " under " + quoted(keyword_));
        what.append(", found ");
        what.append(std::to_string(tokens_.size()));
        what.append(tokens_.size() == 1 ? " value" : " values");
        fail(what);
      }
      vertices.push_back({number(0), number(1), number(2)});
      for (std::size_t i = 3; i < tokens_.size(); ++i)
        (void)number(i);  // normal, colour and texture values: numbers, not read
    }
  }

  [[noreturn]] void fail_face(std::uint64_t face, const std::string& what) const {
    std::string message = "face ";
    message.append(std::to_string(face));
    message.append(": ");
    message.append(what);
    fail(message);
  }

  void read_faces() {
    out_.mesh.faces.reserve(std::min<std::uint64_t>(face_count_, lines_.remaining_bytes() / 8));
    for (std::uint64_t f = 0; f < face_count_; ++f) {
      if (!next_record()) {
        std::string what = "the file ends after ";
        what.append(std::to_string(f));
        what.append(" of ");
        what.append(std::to_string(face_count_));
        what.append(" faces");
        fail(what);
      }
      std::string error;
      const std::optional<std::int64_t> n = parse_integer(tokens_[0], error);
      if (!n) fail_face(f, "the corner count: " + error);
      if (*n < 0) fail_face(f, "the corner count is negative");
      if (*n > 1 << 20 || !gather(1 + static_cast<std::size_t>(*n))) {
        std::string what = "the corner count is ";
        what.append(std::to_string(*n));
        what.append(", but the indices do not fill the line and whole following lines (");
        what.append(std::to_string(tokens_.size() - 1));
        what.append(" values)");
        fail_face(f, what);
      }
      corners_.clear();
      for (std::size_t i = 1; i <= static_cast<std::size_t>(*n); ++i) {
        const std::optional<std::int64_t> index = parse_integer(tokens_[i], error);
        if (!index) fail_face(f, error);
        if (auto why = zero_based_index_problem(*index, vertex_count_)) fail_face(f, *why);
        corners_.push_back(static_cast<VertexIndex>(*index));
      }
      // Values after the corners are the face's colour: not used, but numbers.
      for (std::size_t i = static_cast<std::size_t>(*n) + 1; i < tokens_.size(); ++i) {
        if (!io::is_number_literal(tokens_[i])) {
          fail_face(f, "the colour after the corners: " + quoted(tokens_[i]) + " is not a number");
        }
      }
      if (auto why = faces_.add(corners_, lines_.line_number(), out_)) fail_face(f, *why);
    }
  }

  LineCursor lines_;
  const std::string& source_;
  const LoadOptions& options_;
  LoadedMesh out_;
  std::vector<std::string_view> tokens_;
  std::vector<VertexIndex> corners_;
  FileFaces faces_;
  VertexColumns columns_;
  std::string_view keyword_;  ///< as written; empty when the file has none
  std::uint64_t vertex_count_ = 0;
  std::uint64_t face_count_ = 0;
};

}  // namespace

LoadedMesh read_off(std::string_view text, const std::string& source, const LoadOptions& options) {
  const std::optional<std::string> utf8 = io::utf16_as_utf8(text, source);
  return OffParser(utf8 ? std::string_view(*utf8) : text, source, options).parse();
}

}  // namespace exactgeo::mesh
