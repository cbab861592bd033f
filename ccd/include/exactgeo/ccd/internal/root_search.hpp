#pragma once

// The exact method's search for the earliest root, by dyadic time splitting.
//
// Invariant: the search enters a piece only when no root lies before its start time, and
// knows the piece's root parity (boundary_root and odd mean "some root"; even means none
// or an even number). It splits the piece at its midpoint and visits the left half first:
//
//  * a half whose corner images provably do not surround the origin (culling.hpp) holds
//    no root;
//  * otherwise the left half's parity is computed; the right half's parity then follows
//    without work (the two add up to the parent's when neither has a boundary root: a
//    root on the shared middle slice makes the left half's parity boundary_root), except
//    after a parent boundary root, where it is computed.
//
// A piece with some root and width at most the requested one is the answer: no root
// before its start, a root within it. With no width requested (collision only) the first
// piece known to hold a root ends the search. A piece that still has even parity at the
// depth limit is reported as a root, conservatively: it cannot be culled even at width
// 2^-max_depth, which happens for tangential contacts (a double root of the coplanarity
// cubic) and for near misses closer than the depth resolves. It never misses a root:
// every piece is either proven empty or explored.

#include <algorithm>
#include <cstddef>
#include <optional>

#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/culling.hpp"
#include "exactgeo/ccd/internal/root_parity_core.hpp"
#include "exactgeo/ccd/internal/time_pieces.hpp"
#include "exactgeo/predicates/internal/sign_policies.hpp"

namespace exactgeo::ccd::internal {

struct FoundRoot {
  double start;
  double end;
  bool conservative;  ///< at the depth limit (or corners beyond exact storage), not proven
};

template <std::size_t C>
class RootSearch {
 public:
  /// width: stop at a piece with a root at most this wide (>= 1: the first one found).
  RootSearch(int max_depth, double width) noexcept : max_depth_(max_depth), width_(width) {}

  std::optional<FoundRoot> earliest(const TimePiece<C>& piece, RootParity parity) noexcept {
    deepest_ = std::max(deepest_, piece.depth);
    const bool some_root = parity != RootParity::even;
    if (some_root && piece.t_end - piece.t_start <= width_) {
      return FoundRoot{piece.t_start, piece.t_end, false};
    }
    if (piece.depth >= max_depth_) return FoundRoot{piece.t_start, piece.t_end, !some_root};
    const auto halves = split(piece);
    if (!halves) return FoundRoot{piece.t_start, piece.t_end, !some_root};
    const auto& [left, right] = *halves;
    if (!culled(left)) {
      if (auto found = earliest(left, parity_of(left))) return found;
    }
    // No root in the left half, on its boundary either.
    if (culled(right)) return std::nullopt;
    return earliest(right, parity == RootParity::boundary_root ? parity_of(right) : parity);
  }

  int deepest() const noexcept { return deepest_; }

 private:
  static bool culled(const TimePiece<C>& piece) noexcept {
    return certainly_no_root(piece.offsets(), piece.filterable());
  }

  static RootParity parity_of(const TimePiece<C>& piece) noexcept {
    const BoundaryImage<C, kDomainFaces<C>.size()> image{piece.offsets(), kDomainFaces<C>};
    if (piece.filterable()) return root_parity(exactgeo::internal::ExactSigns{}, image).parity;
    return root_parity(exactgeo::internal::RationalSigns{}, image).parity;
  }

  int max_depth_;
  double width_;
  int deepest_ = 0;
};

}  // namespace exactgeo::ccd::internal
