#pragma once

// The exact method's search for the earliest root, by dyadic time splitting.
//
// Invariant: the search enters a piece only when no root lies before its start time. It
// may know the piece's root parity (boundary_root and odd mean "some root"; even means
// none or an even number). It splits the piece at its midpoint and visits the left half
// first. A half is settled, cheapest first:
//
//  * it holds no root if the coplanarity cubic has no zero on it (coplanarity.hpp: a few
//    double operations, no corners needed);
//  * when an earliest root is asked for and that cubic changes sign on the half, a
//    crossing is likely: the half's parity is computed first, and an odd one is searched
//    at once;
//  * a half with "some root" parity is searched without trying to cull it;
//  * otherwise it holds no root if its corner images provably do not surround the origin
//    (culling.hpp), else it is searched.
//
// Parity is what proves a root, and it costs several times a cull (a ray against the
// corner images, with exact signs near degeneracy). A search that ends without a root,
// the common case on degenerate near misses, never needs it: every piece there is culled
// or split. So a piece's parity is computed only at every kParityEvery-th depth, at the
// depth limit, and where the piece is narrow enough to be the answer; a collision is then
// confirmed at most kParityEvery - 1 levels below the first piece that could have shown
// it. The right half's parity follows without work when the parent's is known: the two
// add up to the parent's when neither has a boundary root, and a root on the shared
// middle slice makes the left half's parity boundary_root (after a parent boundary root
// it is unknown).
//
// Only halves that survive the coplanarity test get exact corners (time_pieces.hpp).
//
// A piece with some root and width at most the requested one is the answer: no root
// before its start, a root within it. With no width requested (collision only) the first
// piece known to hold a root ends the search. A piece one double spacing wide cannot be
// split (its midpoint is not a double): with some root it is the answer, whatever width
// was asked. A piece that still has even parity at the depth limit, or at one double
// spacing, is reported as a root, conservatively: it cannot be culled even there, which
// happens for tangential contacts (a double root of the coplanarity cubic), for near
// misses closer than the depth resolves, and next to a contact closer than the culling
// planes' double normals resolve (docs/ccd.md, "Time of impact", has where that begins on
// the public queries). It never misses a root: every piece is either proven empty or
// explored.

#include <algorithm>
#include <cstddef>
#include <optional>

#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/coplanarity.hpp"
#include "exactgeo/ccd/internal/culling.hpp"
#include "exactgeo/ccd/internal/root_parity_core.hpp"
#include "exactgeo/ccd/internal/time_pieces.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::ccd::internal {

struct FoundRoot {
  double start;
  double end;
  bool conservative;  ///< at the depth limit (or corners beyond exact storage), not proven
};

/// Parity is computed at depths 0, 8, 16, ... (and where needed to answer): searches that
/// end without a root never need it, and 8 keeps a collision's confirmation within 7
/// levels (docs/ccd.md, "Parity only where it can answer", has the instruction counts).
inline constexpr int kParityEvery = 8;

template <std::size_t C>
class RootSearch {
 public:
  /// width: stop at a piece with a root at most this wide (>= 1: the first one found).
  /// max_depth: at most kMaxSearchDepth. coplanarity: the step's certificate, if any.
  RootSearch(int max_depth, double width, std::optional<Coplanarity> coplanarity) noexcept
      : max_depth_(std::min(max_depth, kMaxSearchDepth)),
        width_(width),
        coplanarity_(coplanarity) {}

  /// The whole step's search, its parity known.
  std::optional<FoundRoot> earliest(const TimePiece<C>& step, RootParity parity) noexcept {
    return earliest(step, parity, coplanarity_ ? coplanarity_->whole_step() : Coefficients{});
  }

  int deepest() const noexcept { return deepest_; }

 private:
  using Coefficients = CoplanarityCoefficients;

  std::optional<FoundRoot> earliest(const TimePiece<C>& piece, std::optional<RootParity> parity,
                                    const Coefficients& p) noexcept {
    deepest_ = std::max(deepest_, piece.depth);
    // The last level: the depth limit, or a piece one double spacing wide.
    const bool last = piece.depth >= max_depth_ || !splittable(piece);
    const bool answer_width = piece.t_end - piece.t_start <= width_;
    if (!parity &&
        ((earliest_asked() && answer_width) || last || piece.depth % kParityEvery == 0)) {
      parity = parity_of(piece);
    }
    const bool some_root = parity && *parity != RootParity::even;
    if (some_root && (answer_width || last)) return FoundRoot{piece.t_start, piece.t_end, false};
    if (last) return FoundRoot{piece.t_start, piece.t_end, true};
    const auto [p_left, p_right] = split_coefficients(p);
    bool unsplittable = false;
    auto found = visit(piece, Half::left, p_left, std::nullopt, unsplittable);
    if (!found && !unsplittable) {
      // No root in the closed left half.
      const auto right_parity = parity == RootParity::boundary_root ? std::nullopt : parity;
      found = visit(piece, Half::right, p_right, right_parity, unsplittable);
    }
    if (unsplittable) return FoundRoot{piece.t_start, piece.t_end, !some_root};
    return found;
  }

  /// Settles one half of `parent`: nullopt when it holds no root (proven, or searched).
  /// Sets `unsplittable` when its corners cannot be stored: the parent is then reported,
  /// whatever the half's search found.
  std::optional<FoundRoot> visit(const TimePiece<C>& parent, Half which, const Coefficients& p,
                                 std::optional<RootParity> parity, bool& unsplittable) noexcept {
    if (coplanarity_ && coplanarity_->nonzero(p)) return std::nullopt;
    const auto piece = half(parent, which);
    if (!piece) {
      unsplittable = true;
      return std::nullopt;
    }
    if (!parity && earliest_asked() && coplanarity_ && coplanarity_->changes_sign(p)) {
      parity = parity_of(*piece);
    }
    if (parity && *parity != RootParity::even) return earliest(*piece, parity, p);
    const Planes planes = earliest_asked() ? Planes::all : Planes::usual;
    if (certainly_no_root(piece->offsets(), piece->filterable(), planes)) return std::nullopt;
    return earliest(*piece, parity, p);
  }

  /// A time of impact is asked for (a width below the whole step's), not only whether.
  bool earliest_asked() const noexcept { return width_ < 1.0; }

  static RootParity parity_of(const TimePiece<C>& piece) noexcept {
    const Offsets<C> corners = piece.offsets();
    if (piece.filterable()) return root_parity(exactgeo::kernel::ExactSigns{}, corners).parity;
    return root_parity(exactgeo::kernel::RationalSigns{}, corners).parity;
  }

  int max_depth_;
  double width_;
  std::optional<Coplanarity> coplanarity_;
  int deepest_ = 0;
};

}  // namespace exactgeo::ccd::internal
