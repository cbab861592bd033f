#pragma once

// Minimum separation: does the Euclidean distance between the two primitives drop to δ
// (> 0) at some time of the closed step? The features and their polynomial conditions
// are in separation_features.hpp. The decision runs, cheapest first:
//
//  1. Boxes: on some axis the two primitives' boxes over the whole step (each the box of
//     its corners at both times) are more than δ apart. A distance is at least its
//     largest coordinate difference, so they never come within δ. Decided with one
//     rounded subtraction per axis: fl is monotone, so fl(lo_b - hi_a) > δ (a double)
//     proves lo_b - hi_a > δ.
//  2. Bounded doubles (bounded_double.hpp) on pieces of the step, split at midpoints
//     within a budget: a feature is excluded on a piece when its gap polynomial is
//     certainly positive there, or one of its inside polynomials certainly negative; the
//     query is "within" when at a piece's end some feature's conditions all certainly
//     hold; "apart" when every feature is excluded on every piece.
//  3. Exact (real_roots.hpp, GMP). The set of times within δ is closed (the distance is
//     continuous in time). If neither end of the step is in it but some time is, its
//     earliest time t* has distance exactly δ, realized by the feature whose relative
//     interior holds the closest point: that feature's conditions hold at t* with its
//     weight positive and its gap zero. So it suffices to test both ends and every root
//     in (0, 1) of every gap polynomial. A gap that vanishes identically (the feature's
//     distance is δ wherever it is defined) has no isolated roots; its feature is tested
//     at every root, and between every two roots, of the product of its other
//     polynomials, which between them keep their signs.
//
// δ = 0 is not decided here: it is the exact method's contact question.

#include <cstdint>

#include "exactgeo/ccd/queries.hpp"

namespace exactgeo::ccd::internal {

enum class SeparationStage : std::uint8_t { boxes, bounded_doubles, exact_roots };

struct SeparationVerdict {
  bool within;
  SeparationStage stage;
};

/// delta: finite and > 0; coordinates finite.
SeparationVerdict vertex_face_within(const VertexFaceQuery& query, double delta) noexcept;
SeparationVerdict edge_edge_within(const EdgeEdgeQuery& query, double delta) noexcept;

}  // namespace exactgeo::ccd::internal
