#pragma once

// Test 3 of the minimum-separation decision (min_separation.hpp): exact roots.
//
// The set of times within δ is closed (the distance is continuous in time). If neither end
// of the step is in it but some time is, its earliest time t* has distance exactly δ,
// attained by the feature whose relative interior holds the closest point: at t* that
// feature's weight is positive, its in-feature conditions hold and its gap is zero. So both
// ends and the roots in (0, 1) of every gap polynomial decide (features.hpp),
// in GMP rationals (real_roots.hpp). The roots are taken by clusters: Sturm's sequence
// counts them in an interval and one Tarski query per condition counts those where it is
// positive minus those where it is negative; a cluster where no root can satisfy the
// conditions, or where every root satisfies them strictly, is settled whole, the others
// are halved. A gap that vanishes identically (the feature's distance is δ wherever it is
// defined) has no isolated roots: its feature is tested at every root, and between every
// two roots, of the product of its other polynomials. Every candidate is a time within δ
// and the earliest time is among them, so their minimum is the time of impact.

#include <array>
#include <optional>

#include "exactgeo/ccd/result.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::ccd::internal {

/// The eight points of a query: four at t = 0, the same four at t = 1.
using QueryPoints = std::array<Point3, 8>;

struct ExactSeparation {
  bool within;
  /// With a width and within: no time before start is within δ, some time by end is (at
  /// most the width wide, or one double's spacing where that is wider).
  std::optional<TimeInterval> earliest;
};

/// x: the query's points (vertex-face: v, f0, f1, f2; edge-edge: a0, a1, b0, b1, at t = 0
/// then at t = 1). delta > 0, finite.
ExactSeparation exact_separation(const QueryPoints& x, bool vertex_face, double delta,
                                 std::optional<double> width);

}  // namespace exactgeo::ccd::internal
