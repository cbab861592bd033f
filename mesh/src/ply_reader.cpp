#include "exactgeo/mesh/ply_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "binary_value.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/io/text_scan.hpp"
#include "ply_header.hpp"
#include "polygon.hpp"

namespace exactgeo::mesh {

using internal::FileFaces;
using internal::kMaxVertices;
using internal::load_value;
using internal::parse_ply_header;
using internal::ply_format_name;
using internal::ply_type_is_integer;
using internal::ply_type_name;
using internal::ply_type_size;
using internal::PlyElement;
using internal::PlyFormat;
using internal::PlyHeader;
using internal::PlyProperty;
using internal::PlyType;
using internal::swap_needed;
using internal::zero_based_index_problem;
using io::InputError;
using io::LineCursor;
using io::parse_float32;
using io::parse_integer;
using io::parse_number;
using io::printable;
using io::quoted;
using io::split_tokens;

namespace {

// What a property is for: a vertex coordinate, the face corners, or nothing (skipped).
enum class Role { skip, x, y, z, corners };

struct ElementPlan {
  const PlyElement* element = nullptr;
  std::vector<Role> roles;  // one per property
  bool is_vertex = false;
  bool is_face = false;
};

std::size_t axis_of(Role role) {
  return static_cast<std::size_t>(role) - 1;
}

// Calls f(T{}) with T the C++ type of a PLY scalar type.
template <class F>
auto with_scalar_type(PlyType type, F f) {
  switch (type) {
    case PlyType::int8:
      return f(std::int8_t{});
    case PlyType::uint8:
      return f(std::uint8_t{});
    case PlyType::int16:
      return f(std::int16_t{});
    case PlyType::uint16:
      return f(std::uint16_t{});
    case PlyType::int32:
      return f(std::int32_t{});
    case PlyType::uint32:
      return f(std::uint32_t{});
    case PlyType::float32:
      return f(float{});
    case PlyType::float64:
      return f(double{});
  }
  return f(double{});
}

// Every PLY scalar converts to double exactly (float32 widens, integers have <= 32 bits).
double load_double(PlyType type, const char* bytes, bool swap) {
  return with_scalar_type(
      type, [&](auto tag) { return static_cast<double>(load_value<decltype(tag)>(bytes, swap)); });
}

// Precondition: ply_type_is_integer(type).
std::int64_t load_integer(PlyType type, const char* bytes, bool swap) {
  return with_scalar_type(type, [&](auto tag) -> std::int64_t {
    using T = decltype(tag);
    if constexpr (std::is_integral_v<T>) {
      return load_value<T>(bytes, swap);
    } else {
      return 0;
    }
  });
}

/// One ASCII value read as its declared type, as a binary copy of the file would hold it:
/// an integer type's value must be an integer in its range ("0.5" or "300" for a uchar
/// are refused), a float is rounded once to float ("0.1" is 0.100000001490116...), a
/// double as every number. Else nullopt and the reason.
std::optional<double> ascii_value(PlyType type, std::string_view token, std::string& error) {
  if (type == PlyType::float64) return parse_number(token, error);
  if (type == PlyType::float32) return parse_float32(token, error);
  const std::optional<std::int64_t> n = parse_integer(token, error);
  if (!n) return std::nullopt;
  const bool in_range = with_scalar_type(type, [&](auto tag) {
    using T = decltype(tag);
    return *n >= static_cast<std::int64_t>(std::numeric_limits<T>::lowest()) &&
           *n <= static_cast<std::int64_t>(std::numeric_limits<T>::max());
  });
  if (!in_range) {
    error = quoted(token);
    error.append(" is outside the range of ");
    error.append(ply_type_name(type));
    return std::nullopt;
  }
  return static_cast<double>(*n);
}

std::string instance_name(const PlyElement& element, std::uint64_t index) {
  std::string name = printable(element.name);
  name.push_back(' ');
  name.append(std::to_string(index));
  return name;
}

class PlyReader {
 public:
  PlyReader(std::string_view data, const std::string& source, const LoadOptions& options)
      : data_(data), source_(source), options_(options) {}

  LoadedMesh read() {
    header_ = parse_ply_header(data_, source_);
    out_.format = ply_format_name(header_.format);
    out_.notes = header_.skipped;
    plan();
    if (header_.format == PlyFormat::ascii) {
      read_ascii();
    } else {
      read_binary();
    }
    faces_.finish(out_, source_, options_);
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail_header(const PlyElement& element, const std::string& what) const {
    std::string message = "element ";
    message.append(quoted(element.name));
    message.append(": ");
    message.append(what);
    throw InputError(source_, element.line, message);
  }

  // Finds the vertex and face elements and the properties the mesh needs.
  void plan() {
    const PlyElement* vertex = nullptr;
    const PlyElement* face = nullptr;
    for (const PlyElement& element : header_.elements) {
      ElementPlan p;
      p.element = &element;
      p.roles.assign(element.properties.size(), Role::skip);
      if (element.name == "vertex") {
        vertex = &element;
        p.is_vertex = true;
        plan_vertex(element, p);
      } else if (element.name == "face") {
        face = &element;
        p.is_face = true;
        plan_face(element, p);
      }
      plans_.push_back(std::move(p));
    }
    if (vertex == nullptr) {
      throw InputError(source_, header_.data_line - 1, "the header declares no 'vertex' element");
    }
    if (face == nullptr) {
      throw InputError(
          source_, header_.data_line - 1,
          "the header declares no 'face' element: the mesh has no faces, a point cloud rather "
          "than a surface");
    }
    if (vertex->count > kMaxVertices) fail_header(*vertex, "too many vertices");
    vertex_count_ = vertex->count;
  }

  void plan_vertex(const PlyElement& element, ElementPlan& p) const {
    constexpr std::array<std::string_view, 3> kAxes = {"x", "y", "z"};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const auto& props = element.properties;
      const auto it = std::find_if(props.begin(), props.end(),
                                   [&](const PlyProperty& q) { return q.name == kAxes[axis]; });
      std::string what = "property ";
      what.append(kAxes[axis]);
      if (it == props.end()) fail_header(element, what.append(" is missing"));
      if (it->is_list) throw InputError(source_, it->line, what.append(" is a list, not a number"));
      p.roles[static_cast<std::size_t>(it - props.begin())] = static_cast<Role>(axis + 1);
    }
  }

  void plan_face(const PlyElement& element, ElementPlan& p) const {
    const auto& props = element.properties;
    auto it = std::find_if(props.begin(), props.end(),
                           [](const PlyProperty& q) { return q.name == "vertex_indices"; });
    if (it == props.end()) {
      it = std::find_if(props.begin(), props.end(),
                        [](const PlyProperty& q) { return q.name == "vertex_index"; });
    }
    if (it == props.end()) fail_header(element, "no list property 'vertex_indices'");
    if (!it->is_list) {
      std::string what = "property ";
      what.append(quoted(it->name));
      what.append(" is not a list");
      throw InputError(source_, it->line, what);
    }
    if (!ply_type_is_integer(it->type)) {
      throw InputError(source_, it->line, "the vertex indices must have an integer type");
    }
    p.roles[static_cast<std::size_t>(it - props.begin())] = Role::corners;
  }

  // Reserves room for the element's instances, at most `bound` of them: a declared count is
  // trusted only as far as the bytes present could hold it.
  void reserve(const ElementPlan& p, std::uint64_t bound) {
    const std::uint64_t n = std::min(p.element->count, bound);
    if (p.is_vertex) out_.mesh.vertices.reserve(n);
    if (p.is_face) out_.mesh.faces.reserve(n);
  }

  static std::size_t corner_size(const ElementPlan& p) {
    for (std::size_t k = 0; k < p.roles.size(); ++k) {
      if (p.roles[k] == Role::corners) return ply_type_size(p.element->properties[k].type);
    }
    return 0;
  }

  void read_ascii() {
    LineCursor lines(data_, header_.data_offset, header_.data_line);
    for (const ElementPlan& p : plans_) {
      const PlyElement& element = *p.element;
      if (element.properties.empty()) continue;  // nothing to read, however many
      // Each value takes at least two bytes ("0 "); a face has at least 4 values.
      const std::size_t values = p.is_face ? 4 : element.properties.size();
      reserve(p, lines.remaining_bytes() / (2 * values));
      for (std::uint64_t i = 0; i < element.count; ++i) {
        bool found = false;
        while (const auto line = lines.next()) {
          split_tokens(*line, tokens_);
          if (!tokens_.empty()) {
            found = true;
            break;
          }
        }
        auto fail = [&](const std::string& what) {
          std::string message = instance_name(element, i);
          message.append(": ");
          message.append(what);
          throw InputError(source_, lines.line_number(), message);
        };
        if (!found) {
          std::string what = "the data ends here (the header declares ";
          what.append(std::to_string(element.count));
          what.append(")");
          fail(what);
        }
        line_ = lines.line_number();
        read_ascii_instance(p, fail);
      }
    }
    // Text after the last element is not read.
  }

  template <class Fail>
  void read_ascii_instance(const ElementPlan& p, const Fail& fail) {
    const auto& props = p.element->properties;
    std::size_t t = 0;  // the next token
    Point3 point{};
    std::string error;
    auto next_token = [&](const PlyProperty& property) {
      if (t >= tokens_.size()) {
        std::string what = "too few values: property ";
        what.append(quoted(property.name));
        what.append(" is missing");
        fail(what);
      }
      return tokens_[t++];
    };
    // Every value as its declared type, read or skipped alike.
    auto value = [&](PlyType type, std::string_view token, const PlyProperty& property) {
      const std::optional<double> x = ascii_value(type, token, error);
      if (!x) {
        std::string what = "property ";
        what.append(quoted(property.name));
        what.append(": ");
        what.append(error);
        fail(what);
      }
      return *x;
    };
    for (std::size_t k = 0; k < props.size(); ++k) {
      const Role role = p.roles[k];
      const std::string_view token = next_token(props[k]);
      if (!props[k].is_list) {
        const double x = value(props[k].type, token, props[k]);
        if (role != Role::skip) point[axis_of(role)] = x;
        continue;
      }
      // An integer (ascii_value checked it), so the conversion is exact.
      const auto n = static_cast<std::int64_t>(value(props[k].count_type, token, props[k]));
      if (static_cast<std::uint64_t>(n) > tokens_.size() - t) {
        std::string what = "the list ";
        what.append(quoted(props[k].name));
        what.append(" has length ");
        what.append(std::to_string(n));
        what.append(" but the line has ");
        what.append(std::to_string(tokens_.size() - t));
        what.append(" more values");
        fail(what);
      }
      if (role == Role::corners) corners_.clear();
      for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
        const double item = value(props[k].type, tokens_[t + j], props[k]);
        if (role != Role::corners) continue;
        // An integer type's value (plan() requires one for the corners): exact.
        const auto index = static_cast<std::int64_t>(item);
        if (auto why = zero_based_index_problem(index, vertex_count_)) fail(*why);
        corners_.push_back(static_cast<VertexIndex>(index));
      }
      if (role == Role::corners) {
        if (auto why = faces_.add(corners_, line_, out_)) fail(*why);
      }
      t += static_cast<std::size_t>(n);
    }
    if (t != tokens_.size()) {
      std::string what = "more values than the header declares (";
      what.append(std::to_string(tokens_.size()));
      what.append(" on the line, ");
      what.append(std::to_string(t));
      what.append(" expected)");
      fail(what);
    }
    if (p.is_vertex) out_.mesh.vertices.push_back(point);
  }

  void read_binary() {
    const bool file_is_big = header_.format == PlyFormat::binary_big_endian;
    const bool swap = swap_needed(file_is_big);
    std::size_t pos = header_.data_offset;
    for (const ElementPlan& p : plans_) {
      const PlyElement& element = *p.element;
      std::uint64_t min_bytes = 0;  // of one instance: every list empty
      for (const PlyProperty& q : element.properties) {
        min_bytes += ply_type_size(q.is_list ? q.count_type : q.type);
      }
      if (min_bytes == 0) continue;  // nothing to read, however many
      const std::uint64_t fit = (data_.size() - pos) / min_bytes;
      if (element.count > fit) {
        std::string what = "truncated: the data ends before ";
        what.append(instance_name(element, fit));
        what.append(" (the header declares ");
        what.append(std::to_string(element.count));
        what.append(")");
        fail_binary(what);
      }
      // A face has at least three corners.
      const std::uint64_t face_bytes = p.is_face ? 3 * corner_size(p) : 0;
      reserve(p, (data_.size() - pos) / (min_bytes + face_bytes));
      for (std::uint64_t i = 0; i < element.count; ++i) {
        pos = read_binary_instance(p, i, pos, swap);
      }
    }
    // Bytes after the last element are not read.
  }

  [[noreturn]] void fail_binary(const std::string& what) const {
    std::string message = source_;
    message.append(": ");
    message.append(what);
    throw InputError(message);
  }

  std::size_t read_binary_instance(const ElementPlan& p, std::uint64_t i, std::size_t pos,
                                   bool swap) {
    const PlyElement& element = *p.element;
    auto fail = [&](const std::string& what) {
      std::string message = instance_name(element, i);
      message.append(": ");
      message.append(what);
      fail_binary(message);
    };
    auto need = [&](std::uint64_t count, std::size_t size, const PlyProperty& property) {
      if (count > (data_.size() - pos) / size) {
        std::string what = "truncated: the data ends in property ";
        what.append(quoted(property.name));
        fail(what);
      }
    };
    Point3 point{};
    const auto& props = element.properties;
    for (std::size_t k = 0; k < props.size(); ++k) {
      const PlyProperty& property = props[k];
      const Role role = p.roles[k];
      if (!property.is_list) {
        const std::size_t size = ply_type_size(property.type);
        need(1, size, property);
        if (role != Role::skip) {
          const double x = load_double(property.type, data_.data() + pos, swap);
          if (!std::isfinite(x)) {
            std::string what = property.name;
            what.append(std::isnan(x) ? " is NaN" : " is infinite");
            fail(what);
          }
          point[axis_of(role)] = x;
        }
        pos += size;
        continue;
      }
      const std::size_t count_size = ply_type_size(property.count_type);
      need(1, count_size, property);
      const std::int64_t n = load_integer(property.count_type, data_.data() + pos, swap);
      pos += count_size;
      if (n < 0) {
        std::string what = "the list ";
        what.append(quoted(property.name));
        what.append(" has negative length ");
        what.append(std::to_string(n));
        fail(what);
      }
      const std::size_t size = ply_type_size(property.type);
      need(static_cast<std::uint64_t>(n), size, property);
      if (role == Role::corners) {
        corners_.clear();
        for (std::int64_t j = 0; j < n; ++j) {
          const std::int64_t index = load_integer(property.type, data_.data() + pos, swap);
          pos += size;
          if (auto why = zero_based_index_problem(index, vertex_count_)) fail(*why);
          corners_.push_back(static_cast<VertexIndex>(index));
        }
        if (auto why = faces_.add(corners_, 0, out_)) fail(*why);
      } else {
        pos += static_cast<std::size_t>(n) * size;
      }
    }
    if (p.is_vertex) out_.mesh.vertices.push_back(point);
    return pos;
  }

  std::string_view data_;
  const std::string& source_;
  const LoadOptions& options_;
  PlyHeader header_;
  std::vector<ElementPlan> plans_;
  std::uint64_t vertex_count_ = 0;
  LoadedMesh out_;
  std::vector<std::string_view> tokens_;
  std::vector<VertexIndex> corners_;
  FileFaces faces_;
  std::size_t line_ = 0;  ///< the line of the element instance being read (ASCII)
};

}  // namespace

LoadedMesh read_ply(std::string_view data, const std::string& source, const LoadOptions& options) {
  return PlyReader(data, source, options).read();
}

}  // namespace exactgeo::mesh
