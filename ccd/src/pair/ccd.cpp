#include "exactgeo/ccd/ccd.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

#include "exactgeo/ccd/baselines/cubic.hpp"
#include "exactgeo/ccd/baselines/separation_box.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/coplanarity.hpp"
#include "exactgeo/ccd/internal/culling.hpp"
#include "exactgeo/ccd/internal/polynomial_decision.hpp"
#include "exactgeo/ccd/internal/root_parity_core.hpp"
#include "exactgeo/ccd/internal/root_search.hpp"
#include "exactgeo/ccd/internal/time_pieces.hpp"
#include "exactgeo/ccd/internal/unit_magnitude.hpp"
#include "exactgeo/ccd/root_parity.hpp"
#include "exactgeo/ccd/separation/internal/min_separation.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::ccd {

namespace {

/// How far the polynomial decision may halve the step before it hands over to the search
/// with pieces: 16 halvings, 64 pieces in all.
constexpr internal::DecisionBudget kPolynomialBudget{16, 64};

/// How deep the contact question may split before a minimum-separation query goes on to
/// the distance's own conditions.
constexpr int kSeparationContactDepth = 8;

/// The arithmetic of the parity algorithm run as it is, without a cull: the baseline and
/// the slow reference.
Arithmetic unculled_parity_arithmetic(Method m) noexcept {
  return m == Method::rational ? Arithmetic::rational : Arithmetic::plain_double;
}

template <class Query>
Result exact_ccd(const Query& query, const Options& options) noexcept {
  const auto corners = internal::corner_images(query);
  // The cheap cull first: most queries a broad phase proposes are near misses, which it
  // settles for a fraction of parity's cost. The other planes cost more and wait for an
  // even parity.
  if (internal::culled_before_parity(corners)) return {false, DecidedBy::culled, 0, {}};
  const bool toi = options.time_of_impact_width.has_value();
  const double width = toi ? *options.time_of_impact_width : 1.0;
  auto collision = [toi](DecidedBy stage, int depth, TimeInterval when) {
    return Result{true, stage, static_cast<std::uint8_t>(depth),
                  toi ? std::optional<TimeInterval>(when) : std::nullopt};
  };
  // A coplanarity cubic without a zero proves that there is no root, for a few double
  // operations. With the slice's side quartics it often decides the whole question
  // (collision only, not where the earliest root is; polynomial_decision.hpp).
  constexpr std::size_t C = std::tuple_size_v<decltype(corners)>;
  const auto coplanarity = internal::Coplanarity::of(corners);
  if (coplanarity && coplanarity->nonzero(coplanarity->whole_step())) {
    return {false, DecidedBy::culled, 0, {}};
  }
  auto decided_by_polynomials = [&]() -> std::optional<Result> {
    if (toi || !coplanarity) return std::nullopt;
    const auto sides = internal::SliceSides<C>::of(corners);
    if (!sides) return std::nullopt;
    const auto verdict =
        internal::decide_by_polynomials<C>(*coplanarity, *sides, kPolynomialBudget);
    if (!verdict) return std::nullopt;
    if (*verdict == internal::PieceVerdict::root) return collision(DecidedBy::polynomials, 0, {});
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
  const RootParity parity = internal::root_parity(exactgeo::kernel::ExactSigns{}, corners).parity;
  if (parity != RootParity::even && !toi) return collision(DecidedBy::parity, 0, {});
  if (parity == RootParity::even) {
    if (!dips) {
      if (const auto result = decided_by_polynomials()) return *result;
    }
    // Where the cubic dips, the planes of the whole step rarely separate: the search
    // splits first. Otherwise the planes are tried on the whole step.
    if (!dips && internal::certainly_no_root(corners)) return {false, DecidedBy::culled, 0, {}};
  }
  const DecidedBy searched =
      parity == RootParity::even ? DecidedBy::subdivision : DecidedBy::parity;
  const auto piece = internal::whole_step<C>(corners);
  if (!piece) {  // corners beyond exact storage: report the step, unproven if even
    return collision(parity == RootParity::even ? DecidedBy::depth_limit : DecidedBy::parity, 0,
                     {});
  }
  internal::RootSearch<C> search(std::max(options.max_depth, 0), width, coplanarity);
  const auto found = search.earliest(*piece, parity);
  if (!found) return {false, searched, static_cast<std::uint8_t>(search.deepest()), {}};
  return collision(found->conservative ? DecidedBy::depth_limit : searched, search.deepest(),
                   {found->start, found->end});
}

/// Minimum separation δ > 0 (separation/internal/min_separation.hpp): the cheap proofs of distance
/// above δ; for a yes/no answer the contact question next (a contact is within every δ;
/// its culls and parity settle most collisions); then the distance's own conditions,
/// which also bracket the earliest time within δ.
template <class Query>
Result separation_ccd(const Query& query, const Options& options) noexcept {
  const double delta = options.min_separation;
  if (internal::separation_apart(query, delta)) return {false, DecidedBy::culled, 0, {}};
  const std::optional<double> width = options.time_of_impact_width;
  if (!width) {
    // Only the contact question's cheap stages: a near miss it would search deeply is
    // within δ, which the distance's own conditions show sooner. A depth-limit answer
    // is no proof of contact; the conditions decide everything alone.
    Options contact = options;
    contact.min_separation = 0.0;
    contact.max_depth = std::min(options.max_depth, kSeparationContactDepth);
    const Result touch = exact_ccd(query, contact);
    if (touch.collision && touch.decided_by != DecidedBy::depth_limit) return touch;
  }
  const internal::SeparationVerdict verdict = internal::separation_within(query, delta, width);
  return {verdict.within, verdict.decided_by, 0,
          width && verdict.within ? verdict.earliest : std::nullopt};
}

bool box_baseline(const VertexFaceQuery& q, double delta) noexcept {
  return vertex_face_separation_box_baseline(q, delta);
}
bool box_baseline(const EdgeEdgeQuery& q, double delta) noexcept {
  return edge_edge_separation_box_baseline(q, delta);
}

/// The 2012 method with exact signs, behind the exact method's cheap cull: the cull
/// proves that there is no root at all, so the answer is the one parity alone gives, for
/// far less on queries whose corner images are degenerate but far from the origin (on
/// the handcrafted set most of parity's time went there).
template <class Query>
Result parity_ccd(const Query& query) noexcept {
  const auto corners = internal::corner_images(query);
  if (internal::culled_before_parity(corners)) return {false, DecidedBy::culled, 0, {}};
  const RootParity parity = internal::root_parity(exactgeo::kernel::ExactSigns{}, corners).parity;
  return {parity != RootParity::even, DecidedBy::parity, 0, {}};
}

template <class Query, class ParityFn, class CubicFn>
Result dispatch_as_given(const Query& query, const Options& options, ParityFn parity_fn,
                         CubicFn cubic_fn) noexcept {
  switch (options.method) {
    case Method::exact:
      if (options.min_separation > 0.0) return separation_ccd(query, options);
      return exact_ccd(query, options);
    case Method::parity:
      return parity_ccd(query);
    case Method::cubic:
      return {cubic_fn(query, CubicOptions{options.cubic_tolerance}), DecidedBy::cubic, 0, {}};
    case Method::plain_double:
      if (options.min_separation > 0.0) {
        return {box_baseline(query, options.min_separation), DecidedBy::box_test, 0, {}};
      }
      break;
    case Method::rational:
      break;
  }
  return {parity_fn(query, unculled_parity_arithmetic(options.method)).collision(),
          DecidedBy::parity,
          0,
          {}};
}

/// The query at magnitude 1 (internal/unit_magnitude.hpp: why, and when), with the
/// separation scaled alike (distances scale with the coordinates), or nullopt when it is
/// near 1 already or cannot be scaled exactly.
template <class Query>
std::optional<std::pair<Query, Options>> at_unit_magnitude(const Query& query,
                                                           const Options& options) noexcept {
  static_assert(sizeof(Query) == 24 * sizeof(double), "a query is 8 points, nothing else");
  std::array<double, 25> x;
  const auto coordinates = std::bit_cast<std::array<double, 24>>(query);
  std::copy(coordinates.begin(), coordinates.end(), x.begin());
  x[24] = options.min_separation;
  if (!internal::scale_to_unit_magnitude(x)) return std::nullopt;
  std::array<double, 24> scaled;
  std::copy(x.begin(), x.begin() + 24, scaled.begin());
  Options o = options;
  o.min_separation = x[24];
  return std::pair{std::bit_cast<Query>(scaled), o};
}

template <class Query, class ParityFn, class CubicFn>
Result dispatch(const Query& query, const Options& options, ParityFn parity_fn,
                CubicFn cubic_fn) noexcept {
  // Scaling keeps the answers of the exact and parity methods, not the rounding of plain
  // doubles (the baseline as it is) nor the cubic method's absolute tolerance.
  const bool scale_invariant = options.method == Method::exact ||
                               options.method == Method::parity ||
                               options.method == Method::rational;
  if (scale_invariant) {
    if (const auto unit = at_unit_magnitude(query, options)) {
      return dispatch_as_given(unit->first, unit->second, parity_fn, cubic_fn);
    }
  }
  return dispatch_as_given(query, options, parity_fn, cubic_fn);
}

}  // namespace

bool is_valid_min_separation(double delta) noexcept {
  return std::isfinite(delta) && delta >= 0.0;
}

Result vertex_face_ccd(const VertexFaceQuery& query, const Options& options) noexcept {
  return dispatch(query, options, vertex_face_root_parity, vertex_face_cubic);
}

Result edge_edge_ccd(const EdgeEdgeQuery& query, const Options& options) noexcept {
  return dispatch(query, options, edge_edge_root_parity, edge_edge_cubic);
}

std::string_view to_string(Method m) noexcept {
  switch (m) {
    case Method::exact:
      return "exact";
    case Method::parity:
      return "parity";
    case Method::plain_double:
      return "double";
    case Method::rational:
      return "rational";
    case Method::cubic:
      return "cubic";
  }
  return "?";
}

std::optional<Method> parse_method(std::string_view name) noexcept {
  for (const Method m :
       {Method::exact, Method::parity, Method::plain_double, Method::rational, Method::cubic}) {
    if (name == to_string(m)) return m;
  }
  return std::nullopt;
}

std::string_view to_string(DecidedBy s) noexcept {
  switch (s) {
    case DecidedBy::culled:
      return "culled";
    case DecidedBy::parity:
      return "parity";
    case DecidedBy::subdivision:
      return "subdivision";
    case DecidedBy::depth_limit:
      return "depth_limit";
    case DecidedBy::cubic:
      return "cubic";
    case DecidedBy::polynomials:
      return "polynomials";
    case DecidedBy::separation:
      return "separation";
    case DecidedBy::separation_roots:
      return "separation_roots";
    case DecidedBy::box_test:
      return "box_test";
  }
  return "?";
}

}  // namespace exactgeo::ccd
