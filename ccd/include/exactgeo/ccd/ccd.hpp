#pragma once

// Continuous collision detection, one entry point per query type for every method.
//
//   exact        any root in the closed domain (the default). Culling, then root parity;
//                when the parity is even and culling cannot exclude a root, dyadic time
//                splitting decides (internal/root_search.hpp). Never misses a root; it
//                reports a root without proof only where a piece cannot be culled at the
//                depth limit (a tangential contact, or a near miss closer than 2^-max_depth
//                of the step resolves): decided_by == depth_limit says so. It can also
//                bracket the earliest root (time of impact).
//   parity       the 2012 root parity algorithm: a boundary root or an odd number of
//                interior roots (root_parity.hpp). Blind to two roots, by design. The
//                exact method's cheap cull runs first (decided_by == culled): it proves
//                that there is no root, so the answer is root parity's.
//   plain_double the same parity algorithm with plain double signs (no filter, no exact
//                fallback): the non-exact baseline.
//   rational     the parity algorithm with every sign in GMP rationals: the slow reference.
//   cubic        coplanarity times plus a distance tolerance (cubic.hpp): what simulators
//                used before exact methods.
//
// Preconditions: finite coordinates. Every function is noexcept, keeps no state and is
// safe to call from many threads.
//
// The answer's words (Result, DecidedBy, TimeInterval) are result.hpp's, included here.
// This header and src/dispatch/ccd.cpp are the room above the methods: pair/ (exact,
// parity), separation/ and baselines/ each decide queries without knowing of the others,
// and the dispatch chooses among them (docs/architecture.md, "ccd/").

#include <cstdint>
#include <optional>
#include <string_view>

#include "exactgeo/ccd/queries.hpp"
#include "exactgeo/ccd/result.hpp"

namespace exactgeo::ccd {

/// The methods are the arithmetics of exactgeo/predicates/arithmetic.hpp applied to the
/// same algorithms, plus the baselines: `parity`, `plain_double` and `rational` are root
/// parity with exact, plain double and rational signs (Arithmetic's exact, plain_double and
/// rational), `exact` is the exact algorithm (any root), `cubic` the tolerance baseline.
/// The shared names are Arithmetic's ("exact", "double", "rational"), and to_string and
/// parse have Arithmetic's shape.
enum class Method : std::uint8_t { exact, parity, plain_double, rational, cubic };

/// The name of every enumerator: "exact", "parity", "double", "rational" or "cubic" (the
/// command line's and Python's spelling); "?" for a value that is no enumerator.
std::string_view to_string(Method m) noexcept;
/// The method whose name (to_string) is exactly `name`; nullopt for any other string.
std::optional<Method> parse_method(std::string_view name) noexcept;

struct Options {
  Method method = Method::exact;
  /// exact only: also return an interval of at most this width that contains the earliest
  /// root, with no root before its start. Unset: collision yes/no only.
  std::optional<double> time_of_impact_width;
  /// exact only: at most this many halvings of the step (a piece of width 2^-max_depth).
  int max_depth = 64;
  /// exact: the separation δ. A collision is a time of the closed step at which the
  /// Euclidean distance between the two primitives is at most δ (0: they touch), and the
  /// time of impact is the earliest such time. δ^2 is taken exactly. Precondition: finite
  /// and >= 0 (is_valid_min_separation). double: with δ > 0 the baseline per-axis box
  /// test in plain doubles (baselines/separation_box.hpp). The other methods ignore it.
  double min_separation = 0.0;
  /// cubic only: the distance tolerance (cubic.hpp).
  double cubic_tolerance = 1e-6;
};

/// Whether `delta` may be Options::min_separation: finite and >= 0.
bool is_valid_min_separation(double delta) noexcept;

Result vertex_face_ccd(const VertexFaceQuery& query, const Options& options = {}) noexcept;
Result edge_edge_ccd(const EdgeEdgeQuery& query, const Options& options = {}) noexcept;

}  // namespace exactgeo::ccd
