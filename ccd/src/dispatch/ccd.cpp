#include "exactgeo/ccd/ccd.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <utility>

#include "exactgeo/ccd/baselines/cubic.hpp"
#include "exactgeo/ccd/baselines/separation_box.hpp"
#include "exactgeo/predicates/kernel/unit_magnitude.hpp"
#include "exactgeo/ccd/internal/exact_method.hpp"
#include "exactgeo/ccd/root_parity.hpp"
#include "exactgeo/ccd/separation/internal/min_separation.hpp"

// The dispatch: the room above the methods (docs/architecture.md, "ccd/"). It brings a
// query to magnitude 1 and hands it to the method asked for: the exact and parity methods
// (pair, internal/exact_method.hpp), minimum separation (separation/, with the exact
// method's contact question in front), root parity in other arithmetics, the baselines.

namespace exactgeo::ccd {

namespace {

/// How deep the contact question may split before a minimum-separation query goes on to
/// the distance's own conditions.
constexpr int kSeparationContactDepth = 8;

/// The arithmetic of the parity algorithm run as it is, without a cull: the baseline and
/// the slow reference.
Arithmetic unculled_parity_arithmetic(Method m) noexcept {
  return m == Method::rational ? Arithmetic::rational : Arithmetic::plain_double;
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
    const Result touch = internal::exact_method(
        query, {std::nullopt, std::min(options.max_depth, kSeparationContactDepth)});
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

template <class Query, class ParityFn, class CubicFn>
Result dispatch_as_given(const Query& query, const Options& options, ParityFn parity_fn,
                         CubicFn cubic_fn) noexcept {
  switch (options.method) {
    case Method::exact:
      if (options.min_separation > 0.0) return separation_ccd(query, options);
      return internal::exact_method(query, {options.time_of_impact_width, options.max_depth});
    case Method::parity:
      return internal::parity_method(query);
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

/// The query at magnitude 1 (predicates/kernel/unit_magnitude.hpp: why, and when), with the
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
  if (!kernel::scale_to_unit_magnitude(x)) return std::nullopt;
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

}  // namespace exactgeo::ccd
