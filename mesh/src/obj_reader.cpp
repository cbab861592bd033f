#include "exactgeo/mesh/obj_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <optional>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/io/text_scan.hpp"
#include "polygon.hpp"

namespace exactgeo::mesh {

using internal::FileFaces;
using internal::kMaxVertices;
using io::InputError;
using io::LineCursor;
using io::parse_integer;
using io::parse_number;
using io::quoted;
using io::skip_utf8_bom;
using io::split_tokens;
using io::strip_comment;

namespace {

std::string valid_range(std::size_t vertex_count) {
  if (vertex_count == 0) return "no vertex is defined";
  std::string range = "valid: 1..";
  range.append(std::to_string(vertex_count));
  range.append(" or -1..-");
  range.append(std::to_string(vertex_count));
  range.append(" (relative)");
  return range;
}

std::string out_of_range(std::int64_t index, std::size_t vertex_count) {
  std::string what = "vertex index ";
  what.append(std::to_string(index));
  what.append(" is out of range: ");
  what.append(valid_range(vertex_count));
  return what;
}

/// Whether a literal parse_number accepts denotes exactly 1, decided on its digits (a
/// rounded value would take "1.00000000000000000001" for 1): the significant digits,
/// stripped of leading and trailing zeros, are one digit d, and d times the literal's
/// power of the base is 1 (decimal: d = 1 at 10^0; hexadecimal: d = 2^k at 2^-k).
bool denotes_one(std::string_view token) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty() || token[0] == '-') return false;
  const bool hex = token.size() > 1 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X');
  if (hex) token.remove_prefix(2);
  const std::size_t marker = token.find_first_of(hex ? "pP" : "eE");
  const std::string_view mantissa = token.substr(0, marker);
  long exponent = 0;  // of the base 2 (hex) or 10 (decimal); at most a few thousand in range
  if (marker != std::string_view::npos) {
    std::string error;
    const auto e = io::parse_integer(token.substr(marker + 1), error);
    if (!e || *e < -100000 || *e > 100000) return false;
    exponent = static_cast<long>(*e);
  }
  // The digits as an integer D times base^(-fraction digits): keep the significant ones.
  std::string digits;
  long fraction = 0;
  bool after_point = false;
  for (const char c : mantissa) {
    if (c == '.') {
      after_point = true;
      continue;
    }
    if (digits.empty() && c == '0') {
      fraction += after_point ? 1 : 0;
      continue;
    }
    digits.push_back(c);
    fraction += after_point ? 1 : 0;
  }
  while (!digits.empty() && digits.back() == '0') {
    digits.pop_back();
    --fraction;
  }
  if (digits.size() != 1) return false;
  if (!hex) return digits[0] == '1' && exponent - fraction == 0;
  // One hexadecimal digit 2^k times 16^-fraction times 2^exponent.
  const std::string_view powers_of_two = "1248";
  const std::size_t k = powers_of_two.find(digits[0]);
  return k != std::string_view::npos && static_cast<long>(k) - 4 * fraction + exponent == 0;
}

/// The vertex or face keyword `word` is in another case ("V", "F", "Fo", "FO"), if it is one.
std::optional<std::string_view> keyword_in_another_case(std::string_view word) {
  for (const std::string_view keyword : {"v", "f", "fo"}) {
    const bool same_letters =
        std::equal(word.begin(), word.end(), keyword.begin(), keyword.end(),
                   [](char w, char k) { return std::tolower(static_cast<unsigned char>(w)) == k; });
    if (same_letters && word != keyword) return keyword;
  }
  return std::nullopt;
}

class ObjParser {
 public:
  ObjParser(std::string_view text, const std::string& source, const LoadOptions& options)
      : lines_(skip_utf8_bom(text)), source_(source), options_(options) {
    out_.format = "obj";
    out_.numbering.first = 1;
  }

  LoadedMesh parse() {
    while (const auto line = lines_.next()) {
      split_tokens(strip_comment(*line), tokens_);
      if (tokens_.empty()) continue;
      if (tokens_[0] == "v") {
        read_vertex();
      } else if (tokens_[0] == "f" || tokens_[0] == "fo") {
        read_face();
      } else if (const auto meant = keyword_in_another_case(tokens_[0])) {
        // Keywords are lower case; skipping a "V" line would make every face after it
        // point at other vertices, and skipping an "F" line would lose a face.
        std::string what = quoted(tokens_[0]);
        what.append(" is not an OBJ keyword: keywords are lower case (");
        what.append(quoted(*meant));
        what.append(")");
        fail(what);
      }
      // Anything else carries no polygon geometry: texture coordinates, normals, groups,
      // materials, smoothing, lines, points, free-form curves and surfaces.
    }
    const std::size_t n = out_.mesh.vertices.size();
    if (forward_line_ != 0 && static_cast<std::uint64_t>(forward_index_) > n) {
      throw InputError(source_, forward_line_, out_of_range(forward_index_, n));
    }
    faces_.finish(out_, source_, options_);
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_, lines_.line_number(), what);
  }

  double number(std::string_view token) const {
    std::string error;
    const std::optional<double> x = parse_number(token, error);
    if (!x) fail(error);
    return *x;
  }

  void read_vertex() {
    const std::size_t values = tokens_.size() - 1;
    if (values != 3 && values != 4 && values != 6) {
      std::string what = "a vertex needs x y z (and optionally w, or r g b), found ";
      what.append(std::to_string(values));
      what.append(values == 1 ? " value" : " values");
      fail(what);
    }
    const Point3 p{number(tokens_[1]), number(tokens_[2]), number(tokens_[3])};
    for (std::size_t i = 4; i < tokens_.size(); ++i) {
      (void)number(tokens_[i]);  // a number, whatever it is for
      if (values == 4 && !denotes_one(tokens_[i])) {
        // Dividing x, y, z by w would round: refuse rather than change the geometry.
        std::string what = "w = ";
        what.append(tokens_[i]);
        what.append(": homogeneous coordinates with w other than 1 are not supported");
        fail(what);
      }
    }
    if (out_.mesh.vertices.size() >= kMaxVertices) fail("too many vertices");
    out_.mesh.vertices.push_back(p);
  }

  // The position index of one corner ("i", "i/t", "i//n", "i/t/n"), 0-based. The texture
  // and normal indices are not used, but each must be an integer (or absent).
  VertexIndex corner_index(std::string_view token) {
    const std::string_view position = token.substr(0, token.find('/'));
    check_other_indices(token);
    if (position.empty()) {
      std::string what = "face corner ";
      what.append(quoted(token));
      what.append(" has no vertex index");
      fail(what);
    }
    std::string error;
    const std::optional<std::int64_t> index = parse_integer(position, error);
    if (!index) fail(error);
    const std::size_t defined = out_.mesh.vertices.size();
    if (*index == 0) fail("vertex index 0 is invalid: OBJ indices start at 1");
    if (*index < 0) {
      // Relative: -1 is the last vertex defined so far.
      if (static_cast<std::uint64_t>(-(*index + 1)) >= defined) {
        std::string what = "relative vertex index ";
        what.append(std::to_string(*index));
        what.append(" reaches before the first vertex: ");
        what.append(std::to_string(defined));
        what.append(defined == 1 ? " vertex is" : " vertices are");
        what.append(" defined before this line");
        fail(what);
      }
      return static_cast<VertexIndex>(static_cast<std::int64_t>(defined) + *index);
    }
    const auto one_based = static_cast<std::uint64_t>(*index);
    if (one_based > kMaxVertices) fail(out_of_range(*index, defined));
    if (one_based > defined && *index > forward_index_) {
      // A vertex defined later in the file; checked once every vertex is known.
      forward_index_ = *index;
      forward_line_ = lines_.line_number();
    }
    return static_cast<VertexIndex>(one_based - 1);
  }

  void check_other_indices(std::string_view token) {
    std::size_t slash = token.find('/');
    for (int part = 0; slash != std::string_view::npos; ++part) {
      const std::size_t next = token.find('/', slash + 1);
      const std::string_view index = token.substr(slash + 1, next - slash - 1);
      std::string error;
      if (part >= 2 || (!index.empty() && !parse_integer(index, error))) {
        std::string what = "face corner ";
        what.append(quoted(token));
        what.append(" is not 'v', 'v/vt', 'v//vn' or 'v/vt/vn' with integer indices");
        fail(what);
      }
      slash = next;
    }
  }

  void read_face() {
    corners_.clear();
    for (std::size_t i = 1; i < tokens_.size(); ++i) {
      corners_.push_back(corner_index(tokens_[i]));
    }
    if (auto why = faces_.add(corners_, lines_.line_number(), out_)) fail(*why);
  }

  LineCursor lines_;
  const std::string& source_;
  const LoadOptions& options_;
  LoadedMesh out_;
  std::vector<std::string_view> tokens_;
  std::vector<VertexIndex> corners_;
  FileFaces faces_;
  std::int64_t forward_index_ = 0;  // the largest index beyond the vertices defined so far
  std::size_t forward_line_ = 0;    // and its line
};

}  // namespace

LoadedMesh read_obj(std::string_view text, const std::string& source, const LoadOptions& options) {
  const std::optional<std::string> utf8 = io::utf16_as_utf8(text, source);
  return ObjParser(utf8 ? std::string_view(*utf8) : text, source, options).parse();
}

}  // namespace exactgeo::mesh
