#pragma once

// Deciding a piece of the step by polynomials alone: the coplanarity cubic
// (coplanarity.hpp) and the side quartics of the time slice (slice_sides.hpp), split at
// midpoints up to a small depth. No exact corners and no ray is needed, so it costs a few
// thousand floating-point operations where the search would build pieces and compute
// parities.
//
//  * no root on a piece: the cubic has no zero there, or the origin is outside one edge
//    of the slice throughout;
//  * a root on a piece: the cubic changes sign between its ends while the origin is
//    strictly inside every edge throughout;
//  * otherwise the halves are tried, up to `depth` more splits.
//
// "Root" says that the piece holds a collision, not where the earliest one is: it answers
// collision queries, not time-of-impact ones.

#include "exactgeo/ccd/internal/coplanarity.hpp"
#include "exactgeo/ccd/internal/slice_sides.hpp"

namespace exactgeo::ccd::internal {

enum class PieceVerdict { no_root, root, unknown };

template <std::size_t C>
PieceVerdict decide_by_polynomials(const Coplanarity& coplanarity, const CoplanarityCoefficients& p,
                                   const typename SliceSides<C>::Coefficients& sides,
                                   int depth) noexcept {
  if (coplanarity.nonzero(p) || SliceSides<C>::origin_outside(sides)) {
    return PieceVerdict::no_root;
  }
  if (coplanarity.changes_sign(p) && SliceSides<C>::origin_inside(sides)) {
    return PieceVerdict::root;
  }
  if (depth == 0) return PieceVerdict::unknown;
  const auto [p_left, p_right] = split_coefficients(p);
  const auto [sides_left, sides_right] = SliceSides<C>::split(sides);
  const PieceVerdict left = decide_by_polynomials<C>(coplanarity, p_left, sides_left, depth - 1);
  if (left == PieceVerdict::root) return left;
  const PieceVerdict right = decide_by_polynomials<C>(coplanarity, p_right, sides_right, depth - 1);
  if (right == PieceVerdict::root || left == PieceVerdict::unknown) {
    return right == PieceVerdict::root ? right : PieceVerdict::unknown;
  }
  return right;
}

}  // namespace exactgeo::ccd::internal
