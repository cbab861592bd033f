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
//  * otherwise the halves are tried, within a budget of splits and pieces; past it, the
//    piece is undecided (std::nullopt).
//
// "Root" says that the piece holds a collision, not where the earliest one is: it answers
// collision queries, not time-of-impact ones.

#include <cstdint>
#include <optional>

#include "exactgeo/ccd/internal/coplanarity.hpp"
#include "exactgeo/ccd/internal/slice_sides.hpp"

namespace exactgeo::ccd::internal {

/// What the polynomials prove about a piece; "undecided" is std::nullopt.
enum class PieceVerdict : std::uint8_t { no_root, root };

/// How far the decision may go: at most `depth` halvings and `pieces` pieces looked at in
/// all (polynomials that vanish on a whole stretch decide nothing, and a full tree of
/// halvings would be exponential).
struct DecisionBudget {
  int depth;
  int pieces;
};

template <std::size_t C>
std::optional<PieceVerdict> decide_by_polynomials(const Coplanarity& coplanarity,
                                                  const CoplanarityCoefficients& p,
                                                  const SliceSides<C>& sides,
                                                  const typename SliceSides<C>::Coefficients& s,
                                                  int depth, int& pieces_left) noexcept {
  --pieces_left;
  if (coplanarity.nonzero(p) || sides.origin_outside(s)) return PieceVerdict::no_root;
  if (coplanarity.changes_sign(p) && sides.origin_inside(s)) return PieceVerdict::root;
  if (depth == 0 || pieces_left < 2) return std::nullopt;
  const auto [p_left, p_right] = split_coefficients(p);
  const auto [s_left, s_right] = SliceSides<C>::split(s);
  const auto left =
      decide_by_polynomials<C>(coplanarity, p_left, sides, s_left, depth - 1, pieces_left);
  if (left == PieceVerdict::root) return left;
  if (pieces_left < 1) return std::nullopt;
  const auto right =
      decide_by_polynomials<C>(coplanarity, p_right, sides, s_right, depth - 1, pieces_left);
  if (right == PieceVerdict::root) return right;
  if (left == PieceVerdict::no_root && right == PieceVerdict::no_root) return PieceVerdict::no_root;
  return std::nullopt;
}

/// The whole step, within `budget`.
template <std::size_t C>
std::optional<PieceVerdict> decide_by_polynomials(const Coplanarity& coplanarity,
                                                  const SliceSides<C>& sides,
                                                  DecisionBudget budget) noexcept {
  int pieces_left = budget.pieces;
  return decide_by_polynomials<C>(coplanarity, coplanarity.whole_step(), sides, sides.whole_step(),
                                  budget.depth, pieces_left);
}

}  // namespace exactgeo::ccd::internal
