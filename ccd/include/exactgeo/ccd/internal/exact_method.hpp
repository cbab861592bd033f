#pragma once

// The two exact methods of the pair room, whole: what ccd.hpp's `exact` and `parity` run
// on a query (at the magnitude the dispatch gives it; the dispatch, src/dispatch/ccd.cpp,
// also chooses minimum separation and the baselines, which this room does not know).
//
//   exact_method   any root in the closed domain: the cheap cull, the coplanarity cubic,
//                  the polynomial decision where the cubic dips, root parity, the slice
//                  planes and the search over time pieces (docs/ccd.md, "The exact
//                  method: any root").
//   parity_method  root parity with exact signs behind the same cheap cull (the cull
//                  proves that there is no root at all, so the answer is parity's).

#include <optional>

#include "exactgeo/ccd/queries.hpp"
#include "exactgeo/ccd/result.hpp"

namespace exactgeo::ccd::internal {

/// How far the exact method goes: with a width, the earliest root bracketed to at most
/// that width; at most max_depth halvings of the step (negative: none).
struct SearchLimits {
  std::optional<double> time_of_impact_width;
  int max_depth = 64;
};

Result exact_method(const VertexFaceQuery& query, const SearchLimits& limits) noexcept;
Result exact_method(const EdgeEdgeQuery& query, const SearchLimits& limits) noexcept;

Result parity_method(const VertexFaceQuery& query) noexcept;
Result parity_method(const EdgeEdgeQuery& query) noexcept;

}  // namespace exactgeo::ccd::internal
