#pragma once

// The boundary term's first stage: plain double arithmetic and an a priori bound on its
// error, derived in boundary_term_filter.cpp: far cheaper than outward-rounded intervals
// (docs/inside.md, "Open surfaces", measures it); where its bound cannot settle both
// levels, the caller goes on to them.

#include <array>
#include <optional>
#include <span>

#include "exactgeo/predicates/boundary_term.hpp"

namespace exactgeo::internal {

/// How far the C library's atan2 is trusted, in radians, by the outward-rounded stage
/// (boundary_term.cpp): 2^11 ulps of pi (whose ulp is 2^-51), where every libm in use is
/// within a few. The filter's half angles take arctan2.hpp's instead, whose error bound
/// is derived there.
inline constexpr double kAtan2Error = 0x1p-40;

/// One edge's half angle theta(p; a, b, p + apex) in plain doubles, and a bound on its
/// error (radians, per unit of multiplicity): kind enclosed, or ray_on_edge (the ray meets
/// the edge exactly); nullopt when the filter cannot bound it (p near the edge's line, or
/// on a corner). `d` is `apex` scaled by normalized_apex and `ld` its length.
struct HalfAngle {
  BoundaryTermKind kind = BoundaryTermKind::enclosed;
  double theta = 0.0;
  double error = 0.0;
};
std::optional<Vector3> normalized_apex(const Vector3& apex);
std::optional<HalfAngle> half_angle(const Point3& p, const Vector3& d, double ld, const Point3& pa,
                                    const Point3& pb, const Vector3& apex);

/// The filter's bounds on offset + sum m theta over the edges (theta = Omega / 2, the half
/// angles, in radians), `slack` (an upper bound, in the same unit, on how far that is
/// from what is to be enclosed) included: kind enclosed with lower <= exact <= upper, or
/// kind ray_on_edge (both bounds 0); nullopt when the bound cannot be made. `apex` is
/// -ray.
struct FilteredSum {
  BoundaryTermKind kind = BoundaryTermKind::enclosed;
  double lower = 0.0;
  double upper = 0.0;
};
std::optional<FilteredSum> filtered_sum(const Point3& p, const Vector3& apex,
                                        std::span<const Point3> vertices,
                                        std::span<const BoundaryEdge> edges, double offset,
                                        double slack);

/// The sum against the levels (in turns): kind enclosed with both settled, or the sum's
/// ray_on_edge; nullopt when a level lies within the bounds.
std::optional<BoundaryTerm> settled(const FilteredSum& sum, std::array<double, 2> levels);

/// The sum's bounds in turns (divided by 2 pi), rounded outward.
Enclosure turns_of(const FilteredSum& sum);

/// The term of boundary_term.hpp with both levels settled (kind enclosed), or kind
/// ray_on_edge; nullopt when the bound cannot settle them. `apex` is -ray.
std::optional<BoundaryTerm> filtered_boundary_term(const Point3& p, const Vector3& apex,
                                                   std::span<const Point3> vertices,
                                                   std::span<const BoundaryEdge> edges,
                                                   std::array<double, 2> levels);

}  // namespace exactgeo::internal
