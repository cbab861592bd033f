#include "exactgeo/remesh/pseudo_motion.hpp"

#include <algorithm>
#include <vector>

#include "exactgeo/boxes/exact_box.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "one_mover.hpp"

namespace exactgeo::remesh {

namespace {

class Step {
 public:
  Step(const Surface& surface, std::span<const Move> moves, std::optional<Edge> merged)
      : t0_(surface.vertices),
        t1_(surface.vertices),
        moving_(surface.vertices.size()),
        merged_(merged) {
    // A move to where the vertex is already moves nothing (a collapse into one end): the
    // pairs it alone would join stand still, and what stands still was apart before the
    // step, touching at most, as the mesh broad phase skips standing pairs.
    for (const Move& m : moves) {
      t1_[m.vertex] = m.to;
      moving_[m.vertex] = m.to != t0_[m.vertex];
    }
  }

  bool moving(VertexIndex v) const noexcept { return moving_[v]; }
  /// The vertex v counts as for adjacency: a collapsing edge's second end is its first.
  VertexIndex as(VertexIndex v) const noexcept {
    return merged_ && v == (*merged_)[1] ? (*merged_)[0] : v;
  }

  /// The box of the corners at t0 and t1: it holds the primitive all through the step.
  boxes::ExactBox box(std::initializer_list<VertexIndex> corners) const {
    boxes::ExactBox box = boxes::ExactBox::of(t0_[*corners.begin()]);
    for (const VertexIndex v : corners) {
      box.add(t0_[v]);
      box.add(t1_[v]);
    }
    return box;
  }

  // A pair with one moving corner whose swept hull a plane keeps apart needs no CCD
  // (one_mover.hpp).
  bool vertex_face_collides(VertexIndex v, const Triangle& t) const noexcept {
    const ccd::VertexFaceQuery q{t0_[v], t0_[t[0]], t0_[t[1]], t0_[t[2]],
                                 t1_[v], t1_[t[0]], t1_[t[1]], t1_[t[2]]};
    return !internal::one_mover_apart(q) && ccd::vertex_face_ccd(q).collision;
  }

  bool edge_edge_collides(const Edge& a, const Edge& b) const noexcept {
    const ccd::EdgeEdgeQuery q{t0_[a[0]], t0_[a[1]], t0_[b[0]], t0_[b[1]],
                               t1_[a[0]], t1_[a[1]], t1_[b[0]], t1_[b[1]]};
    return !internal::one_mover_apart(q) && ccd::edge_edge_ccd(q).collision;
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
  for (const Move& m : moves) {
    if (step.moving(m.vertex)) movers.push_back(m.vertex);
  }
  const auto collision = [&](VertexIndex v, const Triangle& t, const boxes::ExactBox& t_box) {
    return !shares(v, t) && t_box.meets(step.box({v})) && step.vertex_face_collides(v, t);
  };
  for (const Triangle& t : surface.triangles) {
    const boxes::ExactBox t_box = step.box({t[0], t[1], t[2]});
    if (step.moving(t[0]) || step.moving(t[1]) || step.moving(t[2])) {
      for (VertexIndex v = 0; v < surface.vertices.size(); ++v) {
        if (!used[v] || !collision(v, t, t_box)) continue;
        if (step.moving(v)) return Blocker{Blocker::Kind::triangle, t};
        return Blocker{Blocker::Kind::vertex, {v, kNoVertex, kNoVertex}};
      }
    } else {
      for (const VertexIndex v : movers) {
        if (collision(v, t, t_box)) return Blocker{Blocker::Kind::triangle, t};
      }
    }
  }
  // Edge-edge pairs with a moving end: the few moving edges against every edge (each
  // side of every triangle: an inner edge is tried twice, which only repeats a test).
  std::vector<Edge> moving_edges;
  for (const Triangle& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge_of(t[k], t[(k + 1) % 3]);
      if (step.moving(e[0]) || step.moving(e[1])) moving_edges.push_back(e);
    }
  }
  std::sort(moving_edges.begin(), moving_edges.end());
  moving_edges.erase(std::unique(moving_edges.begin(), moving_edges.end()), moving_edges.end());
  std::vector<boxes::ExactBox> moving_boxes;
  for (const Edge& a : moving_edges)
    moving_boxes.push_back(step.box({a[0], a[1]}));
  for (const Triangle& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Edge b = edge_of(t[k], t[(k + 1) % 3]);
      const boxes::ExactBox b_box = step.box({b[0], b[1]});
      const VertexIndex b0 = step.as(b[0]), b1 = step.as(b[1]);
      for (std::size_t i = 0; i < moving_edges.size(); ++i) {
        const Edge& a = moving_edges[i];
        const VertexIndex a0 = step.as(a[0]), a1 = step.as(a[1]);
        if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) continue;
        if (!moving_boxes[i].meets(b_box) || !step.edge_edge_collides(a, b)) continue;
        return Blocker{Blocker::Kind::edge, {b[0], b[1], kNoVertex}};
      }
    }
  }
  return std::nullopt;
}

}  // namespace exactgeo::remesh
