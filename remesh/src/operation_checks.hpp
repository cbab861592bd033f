#pragma once

// What the operations share (relocation.cpp, collapse.cpp, flip.cpp, split.cpp): the
// outcomes of a refusal, the topology checks of an edge.

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exactgeo/predicates/orient3d.hpp"
#include "exactgeo/predicates/segment_triangle.hpp"
#include "exactgeo/remesh/operations.hpp"

namespace exactgeo::remesh::internal {

inline Outcome topology(std::string reason) {
  return {Verdict::refused_topology, std::move(reason), std::nullopt, std::nullopt};
}

inline Outcome collision(const Blocker& blocker, std::string_view what) {
  std::string reason(what);
  reason.append(" would meet ").append(to_string(blocker));
  return {Verdict::refused_collision, std::move(reason), blocker, std::nullopt};
}

inline bool finite(const Point3& p) noexcept {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

inline bool has_zero_area(const Surface& s, const Triangle& t) noexcept {
  return collinear(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
}

/// The refusal of an operation whose new triangle `made` would turn over in the plane of
/// the triangle it replaces (turns_over_in_plane): a fold flat onto the surface around
/// `corner`, the operation's vertex where it folds.
inline Outcome turns_over(const std::string& operation, const Triangle& made, VertexIndex corner) {
  const Blocker blocker{Blocker::Kind::vertex, {corner, kNoVertex, kNoVertex}};
  return {Verdict::refused_collision,
          operation + " would turn new triangle " + std::to_string(made[0]) + " " +
              std::to_string(made[1]) + " " + std::to_string(made[2]) +
              " over, flat in the plane of the triangle it replaces, folding at " +
              to_string(blocker),
          blocker,
          {}};
}

/// "flipping edge 6-12": an operation named for its outcome's reason, in a string with room
/// for the rest of a reason, so that a pass's many deferrals cost one allocation each.
inline std::string operation_name(std::string_view verb, VertexIndex a, VertexIndex b) {
  std::array<char, 10> digits_a{}, digits_b{};  // a 32-bit number each
  char* end_a = std::to_chars(digits_a.data(), digits_a.data() + digits_a.size(), a).ptr;
  char* end_b = std::to_chars(digits_b.data(), digits_b.data() + digits_b.size(), b).ptr;
  std::string name;
  name.reserve(128);
  name.append(verb)
      .append(" edge ")
      .append(digits_a.data(), end_a)
      .append("-")
      .append(digits_b.data(), end_b);
  return name;
}

/// A pass's refusal of an operation that waits for the next pass: "flipping edge 6-12 " and
/// why, in one allocation of its size (a pass defers thousands).
inline Outcome deferred(std::string_view verb, VertexIndex a, VertexIndex b, std::string_view why) {
  std::array<char, 10> digits_a{}, digits_b{};  // a 32-bit number each
  const char* end_a = std::to_chars(digits_a.data(), digits_a.data() + digits_a.size(), a).ptr;
  const char* end_b = std::to_chars(digits_b.data(), digits_b.data() + digits_b.size(), b).ptr;
  const std::string_view number_a(digits_a.data(),
                                  static_cast<std::size_t>(end_a - digits_a.data()));
  const std::string_view number_b(digits_b.data(),
                                  static_cast<std::size_t>(end_b - digits_b.data()));
  constexpr std::string_view kEdge = " edge ";
  const std::array<std::string_view, 6> parts{verb, kEdge, number_a, "-", number_b, " "};
  std::size_t size = why.size();
  for (const std::string_view part : parts)
    size += part.size();
  std::string reason(size, ' ');  // one allocation, written in place
  auto out = reason.begin();
  for (const std::string_view part : parts)
    out = std::copy(part.begin(), part.end(), out);
  std::copy(why.begin(), why.end(), out);
  return {Verdict::deferred, std::move(reason), std::nullopt, std::nullopt};
}

/// The reason a vertex cannot be operated on, or nullopt.
inline std::optional<std::string> vertex_problem(const Surface& s, VertexIndex v) {
  if (v >= s.vertices.size()) return "vertex " + std::to_string(v) + " does not exist";
  if (s.is_fixed(v)) return "vertex " + std::to_string(v) + " is fixed";
  return std::nullopt;
}

/// The triangles on edge ab (found unless given), or the reason the edge cannot be
/// operated on (it has none, or more than two, or a triangle with a fixed corner).
inline std::optional<std::string> edge_problem(const Surface& s, VertexIndex a, VertexIndex b,
                                               std::vector<std::size_t>& on_edge) {
  for (const VertexIndex v : {a, b}) {
    if (auto why = vertex_problem(s, v)) return why;
  }
  if (on_edge.empty()) on_edge = s.triangles_on_edge(a, b);
  // Named only for a refusal (most edges a pass proposes have none).
  const auto name = [&] { return "edge " + std::to_string(a) + "-" + std::to_string(b); };
  if (a == b || on_edge.empty()) return name() + " is no edge of the surface";
  if (on_edge.size() > 2)
    return name() + " is used by " + std::to_string(on_edge.size()) + " triangles";
  for (const std::size_t t : on_edge) {
    const VertexIndex c = third_corner(s.triangles[t], a, b);
    if (s.is_fixed(c)) return name() + ": its triangle's corner " + std::to_string(c) + " is fixed";
  }
  return std::nullopt;
}

/// The one or two triangles of an edge an operation changes (edge_problem refuses an edge
/// of more), held in place: a pass plans thousands of operations.
class EdgeTrianglesOfOne {
 public:
  EdgeTrianglesOfOne() = default;
  /// Precondition: at most two.
  explicit EdgeTrianglesOfOne(const std::vector<std::size_t>& triangles) noexcept
      : size_(triangles.size()) {
    std::copy(triangles.begin(), triangles.end(), triangles_.begin());
  }
  std::size_t size() const noexcept { return size_; }
  std::size_t operator[](std::size_t i) const noexcept { return triangles_[i]; }
  const std::size_t* begin() const noexcept { return triangles_.data(); }
  const std::size_t* end() const noexcept { return triangles_.data() + size_; }

 private:
  std::array<std::size_t, 2> triangles_{};
  std::size_t size_ = 0;
};

/// Records, before an operation rewrites them in place, the triangles it rewrites (their
/// indices and corners) in a pass's report (TriangleChanges).
template <class Triangles>
void record_rewrites(const Surface& s, const Triangles& rewritten, TriangleChanges& changes) {
  for (const std::size_t t : rewritten)
    changes.rewritten.push_back({t, s.triangles[t]});
}

/// The report's rewritten triangles in index order (a pass applies its operations in the
/// order they were proposed; they share no triangle, so no index comes twice).
inline void sort_rewrites(TriangleChanges& changes) {
  std::sort(changes.rewritten.begin(), changes.rewritten.end(),
            [](const TriangleChanges::Was& x, const TriangleChanges::Was& y) {
              return x.triangle < y.triangle;
            });
}

}  // namespace exactgeo::remesh::internal
