#pragma once

// Minimum separation: does the Euclidean distance between the two primitives drop to δ
// (> 0) at some time of the closed step? The features and their polynomial conditions
// are in features.hpp. Three tests, cheapest first:
//
//  1. separation_apart: two cheap proofs that the distance stays above δ.
//     - Boxes: on some axis the two primitives' boxes over the whole step (each the box
//       of its corners at both times) are more than δ apart. A distance is at least its
//       largest coordinate difference. One rounded subtraction per axis decides: fl is
//       monotone, so fl(lo_b - hi_a) > δ (a double) proves lo_b - hi_a > δ.
//     - A plane: the differences between the primitives' corners at both times (their
//       hull holds every difference of points of the two during the step) all lie more
//       than δ beyond a plane through the origin, certified in plain doubles with one
//       static bound (derived in min_separation.cpp).
//  2. separation_within, bounded doubles (bounded_double.hpp) on pieces of the step,
//     split at midpoints within a budget: a piece is apart by the plane above (on its
//     own corners, in bounded doubles); a feature is excluded on a piece when its gap polynomial is
//     certainly positive there, or one of its in-feature polynomials certainly negative; the query
//     is "within" when at a piece's end some feature's conditions all certainly hold; "apart" when
//     every piece is apart or has every feature excluded.
//  3. Exact roots (exact_roots.hpp, GMP): both ends of the step and the roots of
//     every gap polynomial decide, because the earliest time within δ has distance
//     exactly δ.
//
// Test 2 goes through pieces depth first, left half first, so when a piece is taken
// every time before it is proven apart: a feature holding at a piece's start makes that
// start the earliest time within δ, one holding at its end brackets the earliest time in
// the piece (split on to the width asked). Test 3 finds the earliest time among its
// candidates.
//
// δ = 0 is not decided here: it is the exact method's contact question, which runs
// between tests 1 and 2 when no time of impact is asked (a contact is within every δ).

#include <optional>

#include "exactgeo/ccd/queries.hpp"
#include "exactgeo/ccd/result.hpp"

namespace exactgeo::ccd::internal {

struct SeparationVerdict {
  bool within;
  DecidedBy decided_by;  ///< separation (test 2) or separation_roots (test 3)
  /// With a width and within: no time before start is within δ, some time by end is.
  std::optional<TimeInterval> earliest;
};

/// Test 1: true proves that the distance stays above delta. delta: finite and > 0;
/// coordinates finite (also for the functions below).
bool separation_apart(const VertexFaceQuery& query, double delta) noexcept;
bool separation_apart(const EdgeEdgeQuery& query, double delta) noexcept;

/// Tests 2 and 3: the answer, and with `width` the earliest time within δ, bracketed to
/// at most that width (or one double's spacing, where that is wider).
SeparationVerdict separation_within(const VertexFaceQuery& query, double delta,
                                    std::optional<double> width) noexcept;
SeparationVerdict separation_within(const EdgeEdgeQuery& query, double delta,
                                    std::optional<double> width) noexcept;

}  // namespace exactgeo::ccd::internal
