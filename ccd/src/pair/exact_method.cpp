#include "exactgeo/ccd/internal/exact_method.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>

#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/coplanarity.hpp"
#include "exactgeo/ccd/internal/culling.hpp"
#include "exactgeo/ccd/internal/polynomial_decision.hpp"
#include "exactgeo/ccd/internal/root_parity_core.hpp"
#include "exactgeo/ccd/internal/root_search.hpp"
#include "exactgeo/ccd/internal/slice_sides.hpp"
#include "exactgeo/ccd/internal/time_pieces.hpp"
#include "exactgeo/ccd/root_parity.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::ccd::internal {

namespace {

/// How far the polynomial decision may halve the step before it hands over to the search
/// with pieces: 16 halvings, 64 pieces in all.
constexpr DecisionBudget kPolynomialBudget{16, 64};

template <class Query>
Result any_root(const Query& query, const SearchLimits& limits) noexcept {
  const auto corners = corner_images(query);
  // The cheap cull first: most queries a broad phase proposes are near misses, which it
  // settles for a fraction of parity's cost. The other planes cost more and wait for an
  // even parity.
  if (culled_before_parity(corners)) return {false, DecidedBy::culled, 0, {}};
  const bool toi = limits.time_of_impact_width.has_value();
  const double width = toi ? *limits.time_of_impact_width : 1.0;
  auto collision = [toi](DecidedBy stage, int depth, TimeInterval when) {
    return Result{true, stage, static_cast<std::uint8_t>(depth),
                  toi ? std::optional<TimeInterval>(when) : std::nullopt};
  };
  // A coplanarity cubic without a zero proves that there is no root, for a few double
  // operations. With the slice's side quartics it often decides the whole question
  // (collision only, not where the earliest root is; polynomial_decision.hpp).
  constexpr std::size_t C = std::tuple_size_v<decltype(corners)>;
  const auto coplanarity = Coplanarity::of(corners);
  if (coplanarity && coplanarity->nonzero(coplanarity->whole_step())) {
    return {false, DecidedBy::culled, 0, {}};
  }
  auto decided_by_polynomials = [&]() -> std::optional<Result> {
    if (toi || !coplanarity) return std::nullopt;
    const auto sides = SliceSides<C>::of(corners);
    if (!sides) return std::nullopt;
    const auto verdict = decide_by_polynomials<C>(*coplanarity, *sides, kPolynomialBudget);
    if (!verdict) return std::nullopt;
    if (*verdict == PieceVerdict::root) return collision(DecidedBy::polynomials, 0, {});
    return Result{false, DecidedBy::polynomials, 0, {}};
  };
  // A cubic with the same sign at both ends of the step that may vanish in between
  // "dips": two coplanar moments. Then the primitives often pass through each other and
  // back, an even parity that would need a second one on a piece; the polynomials go
  // first. Otherwise (typically one coplanar moment) parity goes first: it decides most
  // collisions, and the polynomials cannot prove a touch at the step's ends.
  const bool dips = coplanarity && coplanarity->same_sign_ends(coplanarity->whole_step());
  if (dips) {
    if (const auto result = decided_by_polynomials()) return *result;
  }
  const RootParity parity = root_parity(exactgeo::kernel::ExactSigns{}, corners).parity;
  if (parity != RootParity::even && !toi) return collision(DecidedBy::parity, 0, {});
  if (parity == RootParity::even) {
    if (!dips) {
      if (const auto result = decided_by_polynomials()) return *result;
    }
    // Where the cubic dips, the planes of the whole step rarely separate: the search
    // splits first. Otherwise the planes are tried on the whole step.
    if (!dips && certainly_no_root(corners)) return {false, DecidedBy::culled, 0, {}};
  }
  const DecidedBy searched =
      parity == RootParity::even ? DecidedBy::subdivision : DecidedBy::parity;
  const auto piece = whole_step<C>(corners);
  if (!piece) {  // corners beyond exact storage: report the step, unproven if even
    return collision(parity == RootParity::even ? DecidedBy::depth_limit : DecidedBy::parity, 0,
                     {});
  }
  RootSearch<C> search(std::max(limits.max_depth, 0), width, coplanarity);
  const auto found = search.earliest(*piece, parity);
  if (!found) return {false, searched, static_cast<std::uint8_t>(search.deepest()), {}};
  return collision(found->conservative ? DecidedBy::depth_limit : searched, search.deepest(),
                   {found->start, found->end});
}

/// The 2012 method with exact signs, behind the exact method's cheap cull: the cull
/// proves that there is no root at all, so the answer is the one parity alone gives, for
/// far less on queries whose corner images are degenerate but far from the origin (on
/// the handcrafted set most of parity's time went there).
template <class Query>
Result culled_root_parity(const Query& query) noexcept {
  const auto corners = corner_images(query);
  if (culled_before_parity(corners)) return {false, DecidedBy::culled, 0, {}};
  const RootParity parity = root_parity(exactgeo::kernel::ExactSigns{}, corners).parity;
  return {parity != RootParity::even, DecidedBy::parity, 0, {}};
}

}  // namespace

Result exact_method(const VertexFaceQuery& query, const SearchLimits& limits) noexcept {
  return any_root(query, limits);
}

Result exact_method(const EdgeEdgeQuery& query, const SearchLimits& limits) noexcept {
  return any_root(query, limits);
}

Result parity_method(const VertexFaceQuery& query) noexcept {
  return culled_root_parity(query);
}

Result parity_method(const EdgeEdgeQuery& query) noexcept {
  return culled_root_parity(query);
}

}  // namespace exactgeo::ccd::internal
