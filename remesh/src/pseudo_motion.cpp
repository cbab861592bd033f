#include "exactgeo/remesh/pseudo_motion.hpp"

#include <algorithm>
#include <vector>

#include "exactgeo/ccd/ccd.hpp"

namespace exactgeo::remesh {

namespace {

/// The box of points at both ends of the step (closed).
struct SweptBox {
  Point3 lower;
  Point3 upper;

  template <class Points>
  SweptBox(const Points& ends) : lower(*ends.begin()), upper(*ends.begin()) {
    for (const Point3& p : ends) {
      for (int k = 0; k < 3; ++k) {
        lower[k] = std::min(lower[k], p[k]);
        upper[k] = std::max(upper[k], p[k]);
      }
    }
  }

  bool meets(const SweptBox& other) const noexcept {
    for (int k = 0; k < 3; ++k) {
      if (upper[k] < other.lower[k] || other.upper[k] < lower[k]) return false;
    }
    return true;
  }
};

class Step {
 public:
  Step(const Surface& surface, std::span<const Move> moves, std::optional<Edge> merged)
      : t0_(surface.vertices),
        t1_(surface.vertices),
        moving_(surface.vertices.size()),
        merged_(merged) {
    for (const Move& m : moves) {
      t1_[m.vertex] = m.to;
      moving_[m.vertex] = true;
    }
  }

  bool moving(VertexIndex v) const noexcept { return moving_[v]; }
  /// The vertex v counts as for adjacency: a collapsing edge's second end is its first.
  VertexIndex as(VertexIndex v) const noexcept {
    return merged_ && v == (*merged_)[1] ? (*merged_)[0] : v;
  }

  SweptBox box(std::initializer_list<VertexIndex> corners) const {
    std::vector<Point3> ends;
    for (const VertexIndex v : corners) {
      ends.push_back(t0_[v]);
      ends.push_back(t1_[v]);
    }
    return SweptBox(ends);
  }

  bool vertex_face_collides(VertexIndex v, const Triangle& t) const noexcept {
    const ccd::VertexFaceQuery q{t0_[v], t0_[t[0]], t0_[t[1]], t0_[t[2]],
                                 t1_[v], t1_[t[0]], t1_[t[1]], t1_[t[2]]};
    return ccd::vertex_face_ccd(q).collision;
  }

  bool edge_edge_collides(const Edge& a, const Edge& b) const noexcept {
    const ccd::EdgeEdgeQuery q{t0_[a[0]], t0_[a[1]], t0_[b[0]], t0_[b[1]],
                               t1_[a[0]], t1_[a[1]], t1_[b[0]], t1_[b[1]]};
    return ccd::edge_edge_ccd(q).collision;
  }

 private:
  std::vector<Point3> t0_;
  std::vector<Point3> t1_;
  std::vector<bool> moving_;
  std::optional<Edge> merged_;
};

}  // namespace

std::optional<Blocker> first_collision(const Surface& surface, std::span<const Move> moves,
                                       std::optional<Edge> merged) {
  const Step step(surface, moves, merged);
  const auto shares = [&](VertexIndex v, const Triangle& t) {
    return std::any_of(t.begin(), t.end(), [&](VertexIndex c) { return step.as(c) == step.as(v); });
  };
  std::vector<bool> used(surface.vertices.size());
  for (const Triangle& t : surface.triangles) {
    for (const VertexIndex v : t)
      used[v] = true;
  }
  // Vertex-face pairs with a moving vertex or a moving triangle (each pair once: a moving
  // vertex against standing triangles, then every vertex against moving triangles).
  std::vector<VertexIndex> movers;
  for (const Move& m : moves)
    movers.push_back(m.vertex);
  const auto collision = [&](VertexIndex v, const Triangle& t) {
    return !shares(v, t) && step.box({t[0], t[1], t[2]}).meets(step.box({v})) &&
           step.vertex_face_collides(v, t);
  };
  for (const Triangle& t : surface.triangles) {
    if (step.moving(t[0]) || step.moving(t[1]) || step.moving(t[2])) {
      for (VertexIndex v = 0; v < surface.vertices.size(); ++v) {
        if (!used[v] || !collision(v, t)) continue;
        if (step.moving(v)) return Blocker{Blocker::Kind::triangle, t};
        return Blocker{Blocker::Kind::vertex, {v, kNoVertex, kNoVertex}};
      }
    } else {
      for (const VertexIndex v : movers) {
        if (collision(v, t)) return Blocker{Blocker::Kind::triangle, t};
      }
    }
  }
  // Edge-edge pairs with a moving end.
  const std::vector<Edge> edges = surface.edges();
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& a = edges[i];
    if (!step.moving(a[0]) && !step.moving(a[1])) continue;
    const SweptBox a_box = step.box({a[0], a[1]});
    for (std::size_t j = 0; j < edges.size(); ++j) {
      const Edge& b = edges[j];
      if (j == i || (j < i && (step.moving(b[0]) || step.moving(b[1])))) continue;  // once
      const VertexIndex a0 = step.as(a[0]), a1 = step.as(a[1]);
      const VertexIndex b0 = step.as(b[0]), b1 = step.as(b[1]);
      if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) continue;
      if (!a_box.meets(step.box({b[0], b[1]})) || !step.edge_edge_collides(a, b)) continue;
      return Blocker{Blocker::Kind::edge, {b[0], b[1], kNoVertex}};
    }
  }
  return std::nullopt;
}

}  // namespace exactgeo::remesh
