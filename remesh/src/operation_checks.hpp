#pragma once

// What the operations share (operations.cpp, collapse.cpp, batch_relocation.cpp): the
// outcomes of a refusal, the topology checks of an edge, closed boxes, and positions as
// MeshCcd takes them.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exactgeo/remesh/operations.hpp"

namespace exactgeo::remesh::checks {

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
  return zero_area(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
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

/// A pass's refusal of an operation that waits for the next pass.
inline Outcome deferred(const std::string& operation, std::string_view why) {
  std::string reason = operation;
  reason.append(" ").append(why);
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
  const std::string name = "edge " + std::to_string(a) + "-" + std::to_string(b);
  if (a == b || on_edge.empty()) return name + " is no edge of the surface";
  if (on_edge.size() > 2)
    return name + " is used by " + std::to_string(on_edge.size()) + " triangles";
  for (const std::size_t t : on_edge) {
    const VertexIndex c = third_corner(s.triangles[t], a, b);
    if (s.is_fixed(c)) return name + ": its triangle's corner " + std::to_string(c) + " is fixed";
  }
  return std::nullopt;
}

/// The triangles on every edge of a surface: each triangle's sides bucketed by their
/// smaller vertex (a counting sort, linear in the triangles), so that one edge is looked
/// up in its smaller end's few sides, not by a scan of every triangle per operation.
class EdgeTriangles {
 public:
  explicit EdgeTriangles(const Surface& s) : first_(s.vertices.size() + 1, 0) {
    for (const Triangle& t : s.triangles) {
      for (int k = 0; k < 3; ++k)
        ++first_[std::min(t[k], t[(k + 1) % 3]) + 1];
    }
    for (std::size_t v = 1; v < first_.size(); ++v)
      first_[v] += first_[v - 1];
    sides_.resize(3 * s.triangles.size());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      const Triangle& tri = s.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const Edge e = edge_of(tri[k], tri[(k + 1) % 3]);
        sides_[next[e[0]]++] = {e[1], t};  // in triangle order within each bucket
      }
    }
  }

  /// The triangles with corners a and b, in triangle order.
  std::vector<std::size_t> on(VertexIndex a, VertexIndex b) const {
    const Edge e = edge_of(a, b);
    std::vector<std::size_t> found;
    if (e[0] + std::size_t{1} >= first_.size()) return found;  // no such vertex
    for (std::size_t i = first_[e[0]]; i < first_[e[0] + 1]; ++i) {
      if (sides_[i].first == e[1]) found.push_back(sides_[i].second);
    }
    return found;
  }

 private:
  std::vector<std::size_t> first_;  ///< per vertex: where its sides start in sides_
  std::vector<std::pair<VertexIndex, std::size_t>> sides_;  ///< (larger end, triangle)
};

/// The closed box of points.
template <class Points>
std::array<Point3, 2> box_of(const Points& points) {
  std::array<Point3, 2> box{*points.begin(), *points.begin()};
  for (const Point3& q : points) {
    for (int k = 0; k < 3; ++k) {
      box[0][k] = std::min(box[0][k], q[k]);
      box[1][k] = std::max(box[1][k], q[k]);
    }
  }
  return box;
}

inline bool boxes_meet(const std::array<Point3, 2>& x, const std::array<Point3, 2>& y) noexcept {
  for (int k = 0; k < 3; ++k) {
    if (x[1][k] < y[0][k] || y[1][k] < x[0][k]) return false;
  }
  return true;
}

/// x, y, z of every point in turn (ccd::StepPositions' layout).
inline std::vector<double> flat(const std::vector<Point3>& points) {
  std::vector<double> out;
  out.reserve(3 * points.size());
  for (const Point3& p : points)
    out.insert(out.end(), p.begin(), p.end());
  return out;
}

}  // namespace exactgeo::remesh::checks
