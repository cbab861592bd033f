#include "moving_pairs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>

#include "exactgeo/boxes/exact_box.hpp"
#include "exactgeo/predicates/kernel/error_free.hpp"
#include "pair_order.hpp"

namespace exactgeo::remesh::internal {

namespace {

constexpr std::uint32_t kUnseen = std::numeric_limits<std::uint32_t>::max();

/// Boxes compared exactly, closed (touching counts).
using Box = boxes::ExactBox;

Box united(Box a, const Box& b) noexcept {
  a.add(b);
  return a;
}

bool has(const Triangle& t, VertexIndex v) noexcept {
  return t[0] == v || t[1] == v || t[2] == v;
}

Edge edge(VertexIndex u, VertexIndex w) noexcept {
  return u < w ? Edge{u, w} : Edge{w, u};
}

bool before(const Edge& a, const Edge& b) noexcept {
  return a[0] != b[0] ? a[0] < b[0] : a[1] < b[1];
}

bool same(const ccd::EdgeEdgePair& p, const ccd::EdgeEdgePair& q) noexcept {
  return p.a[0] == q.a[0] && p.a[1] == q.a[1] && p.b[0] == q.b[0] && p.b[1] == q.b[1];
}

/// The step's vertices: their swept boxes and whether they move, made once for all.
class Step {
 public:
  Step(std::span<const Point3> start, std::span<const Point3> end)
      : start_(start),
        end_(end),
        boxes_(std::make_unique_for_overwrite<Box[]>(start.size())),
        moving_(std::make_unique_for_overwrite<bool[]>(start.size())) {
    for (std::size_t v = 0; v < start.size(); ++v) {
      for (std::size_t k = 0; k < 3; ++k) {
        boxes_[v].lower[k] = std::min(start[v][k], end[v][k]);
        boxes_[v].upper[k] = std::max(start[v][k], end[v][k]);
      }
      moving_[v] = start[v][0] != end[v][0] || start[v][1] != end[v][1] || start[v][2] != end[v][2];
    }
  }

  const Box& box(VertexIndex v) const noexcept { return boxes_[v]; }
  Box box(const Triangle& t) const noexcept {
    return united(united(box(t[0]), box(t[1])), box(t[2]));
  }
  Box box(VertexIndex u, VertexIndex w) const noexcept { return united(box(u), box(w)); }

  bool moves(VertexIndex v) const noexcept { return moving_[v]; }

  /// Whether the four corners move by one and the same vector, as the mesh broad phase
  /// rules (ccd/src/mesh/broad_phase.cpp): the exact differences, head and tail, equal
  /// and finite. Standing still counts too, but a pair asked here has a moving corner.
  bool rigid(const std::array<VertexIndex, 4>& corners) const noexcept {
    for (const VertexIndex v : corners) {
      if (!moves(v)) return false;  // and a corner moves: not one vector
    }
    for (std::size_t k = 0; k < 3; ++k) {
      const auto first = kernel::two_diff(end_[corners[0]][k], start_[corners[0]][k]);
      if (!std::isfinite(first.head)) return false;
      for (std::size_t c = 1; c < 4; ++c) {
        const auto d = kernel::two_diff(end_[corners[c]][k], start_[corners[c]][k]);
        if (d.head != first.head || d.tail != first.tail) return false;
      }
    }
    return true;
  }

 private:
  std::span<const Point3> start_;
  std::span<const Point3> end_;
  std::unique_ptr<Box[]> boxes_;
  std::unique_ptr<bool[]> moving_;
};

/// The pairs met around one moving vertex after another (the header's argument), kept
/// by the rule. A star asks each near triangle and each of their corners once, and each
/// of their edges once unless asked_before forgets it; the repeats left (those, and a pair
/// met from the stars of two of its corners) are dropped once at the end.
class Finder {
 public:
  Finder(std::span<const Triangle> triangles, const Step& step, std::size_t vertex_count)
      : triangles_(triangles),
        step_(step),
        triangle_seen_(triangles.size(), kUnseen),
        vertex_seen_(vertex_count, kUnseen),
        asked_(kAskedSlots) {}

  void around(std::uint32_t star_index, const MovingStar& star) {
    const VertexIndex x = star.vertex;
    const Box x_box = step_.box(x);
    faces_.clear();
    others_.clear();
    star_box_ = x_box;
    for (const std::uint32_t f : star.around) {
      const Triangle& t = triangles_[f];
      faces_.push_back({f, step_.box(t)});
      star_box_ = united(star_box_, faces_.back().box);
      for (const VertexIndex c : t)
        if (c != x) others_.push_back(c);
    }
    std::sort(others_.begin(), others_.end());
    others_.erase(std::unique(others_.begin(), others_.end()), others_.end());
    edges_.clear();
    for (const VertexIndex o : others_)
      edges_.push_back({o, step_.box(x, o)});
    // Everything around x lies in star_box_: a near triangle none of whose box meets it
    // pairs with nothing of the star.
    for (const std::uint32_t n : star.near) {
      if (triangle_seen_[n] == star_index) continue;
      triangle_seen_[n] = star_index;
      const Triangle& t = triangles_[n];
      const Box t_box = step_.box(t);
      if (!t_box.meets(star_box_)) continue;
      if (!has(t, x) && x_box.meets(t_box)) add_vertex_face(x, n, t);
      for (const VertexIndex y : t)
        corner_against_faces(star_index, y);
      for (std::size_t j = 0; j < 3; ++j)
        edge_against_edges(star_index, x, t[j], t[(j + 1) % 3]);
    }
  }

  ccd::MeshCcdCandidates pairs() && {
    sort_pairs(found_);
    auto& vf = found_.vertex_face;
    vf.erase(std::unique(vf.begin(), vf.end(),
                         [](const auto& p, const auto& q) {
                           return p.vertex == q.vertex && p.face == q.face;
                         }),
             vf.end());
    auto& ee = found_.edge_edge;
    ee.erase(std::unique(ee.begin(), ee.end(), same), ee.end());
    return std::move(found_);
  }

 private:
  struct Around {
    std::uint32_t index;
    Box box;
  };
  struct EdgeAt {
    VertexIndex other;
    Box box;
  };
  struct Asked {
    std::uint32_t star = kUnseen;
    Edge edge{};
  };
  static constexpr std::size_t kAskedSlots = 512;  // a choice of cost only

  void corner_against_faces(std::uint32_t star_index, VertexIndex y) {
    if (vertex_seen_[y] == star_index) return;
    vertex_seen_[y] = star_index;
    const Box y_box = step_.box(y);
    if (!y_box.meets(star_box_)) return;
    for (const Around& f : faces_) {
      const Triangle& face = triangles_[f.index];
      if (!has(face, y) && y_box.meets(f.box)) add_vertex_face(y, f.index, face);
    }
  }

  void edge_against_edges(std::uint32_t star_index, VertexIndex x, VertexIndex u, VertexIndex w) {
    if (u == x || w == x) return;  // an edge at x shares x with every edge at x
    if (asked_before(star_index, edge(u, w))) return;
    const Box e_box = step_.box(u, w);
    if (!e_box.meets(star_box_)) return;
    for (const EdgeAt& e : edges_) {
      if (e.other == u || e.other == w || !e_box.meets(e.box)) continue;
      if (step_.rigid({x, e.other, u, w})) continue;
      const Edge a = edge(x, e.other), b = edge(u, w);
      found_.edge_edge.push_back(before(a, b) ? ccd::EdgeEdgePair{a, b} : ccd::EdgeEdgePair{b, a});
    }
  }

  /// Whether edge e was asked in this star already (as it is from its other triangle),
  /// by the slot its ends hash to, which remembers the last edge that fell in it: a
  /// repeat whose slot another edge took in between is asked again, and its pairs, found
  /// twice, are dropped at the end. Asking an edge again finds the same pairs, so passing
  /// over a repeat loses none.
  bool asked_before(std::uint32_t star_index, const Edge& e) noexcept {
    const std::uint32_t hash = e[0] * 0x9E3779B1u ^ e[1] * 0x85EBCA77u;
    Asked& slot = asked_[(hash >> 16 ^ hash) & (kAskedSlots - 1)];
    if (slot.star == star_index && slot.edge == e) return true;
    slot = {star_index, e};
    return false;
  }

  void add_vertex_face(VertexIndex v, std::uint32_t f, const Triangle& face) {
    if (step_.rigid({v, face[0], face[1], face[2]})) return;
    found_.vertex_face.push_back({v, f});
  }

  std::span<const Triangle> triangles_;
  const Step& step_;
  std::vector<std::uint32_t> triangle_seen_;  ///< per triangle: the last star it was near
  std::vector<std::uint32_t> vertex_seen_;    ///< per vertex: the last star it was asked in
  std::vector<Asked> asked_;                  ///< edges asked lately (asked_before)
  std::vector<Around> faces_;                 ///< the star's triangles and their boxes
  std::vector<VertexIndex> others_;           ///< its vertices but x, each once
  std::vector<EdgeAt> edges_;                 ///< its edges at x
  Box star_box_;                              ///< the box around all of the star
  ccd::MeshCcdCandidates found_;
};

}  // namespace

ccd::MeshCcdCandidates moving_pairs(std::span<const Triangle> triangles,
                                    std::span<const Point3> start, std::span<const Point3> end,
                                    std::span<const MovingStar> stars) {
  const Step step(start, end);
  Finder finder(triangles, step, start.size());
  for (std::size_t s = 0; s < stars.size(); ++s)
    finder.around(static_cast<std::uint32_t>(s), stars[s]);
  return std::move(finder).pairs();
}

}  // namespace exactgeo::remesh::internal
