#pragma once

// The broad phase of a step in which a few vertices move and the rest stand (a pass of
// collapses, collapse.cpp): the vertex-face and edge-edge pairs exact CCD is to decide,
// found around the moving vertices rather than by box trees over the whole mesh.
//
// The pairs the mesh broad phase (ccd/mesh/mesh_ccd.hpp) gives a step to its narrow phase
// that can collide are those that share no vertex, have a moving corner, do not move
// rigidly (all four corners by one and the same vector), and whose swept boxes meet (a
// corner's swept box is the box of its two positions; a primitive lies in the box of its
// corners' throughout the step, so a contact at any time is a point of both boxes). A
// pair with no moving corner keeps its distance, and the mesh broad phase drops it.
// moving_pairs finds exactly those pairs, by exact comparisons of the boxes, from each
// moving vertex x's star: the triangles around x, and `near`, every triangle whose swept
// box meets one of theirs. A pair with a moving corner x is one of
//   - x against a face f: f's box meets x's, which lies in the box of every triangle
//     around x, so f is near x;
//   - a standing vertex y against a face f around x: y is a corner of a triangle t
//     whose box holds y and so meets f's: t is near x, and y is among its corners;
//   - an edge e with end x against an edge e': e lies in a triangle around x, and e' in
//     a triangle t whose box meets it: t is near x, and e' is among its edges.
// So every such pair is met, and kept when it passes the rule; only those are kept.

#include <cstdint>
#include <span>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/surface/triangle_surface.hpp"

namespace exactgeo::remesh::internal {

/// A moving vertex, the triangles around it, and the triangles near them: every triangle
/// whose swept box meets the swept box of one around it (more may be listed, and repeats).
struct MovingStar {
  VertexIndex vertex = 0;
  std::vector<std::uint32_t> around;
  std::vector<std::uint32_t> near;
};

/// The pairs of the mesh (`triangles` over vertices at `start` and `end`) with a moving
/// corner, sharing no vertex, not moving rigidly, whose swept boxes meet; each once, in
/// the order of their operator<=> (MeshCcdCandidates' conventions: an edge's smaller
/// vertex first, a pair's smaller edge first). Every vertex is a corner of a triangle;
/// `stars`: one for every vertex whose end differs from its start.
ccd::MeshCcdCandidates moving_pairs(std::span<const Triangle> triangles,
                                    std::span<const Point3> start, std::span<const Point3> end,
                                    std::span<const MovingStar> stars);

}  // namespace exactgeo::remesh::internal
