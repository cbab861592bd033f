#pragma once

// The boundary term's first stage: plain double arithmetic and an a priori bound on its
// error, derived in boundary_term_filter.cpp. Twenty times cheaper than outward-rounded
// intervals; where its bound cannot settle both levels, the caller goes on to them.

#include <array>
#include <optional>
#include <span>

#include "exactgeo/predicates/boundary_term.hpp"

namespace exactgeo::internal {

/// The term of boundary_term.hpp with both levels settled (kind enclosed), or kind
/// ray_on_edge; nullopt when the bound cannot settle them. `apex` is -ray.
std::optional<BoundaryTerm> filtered_boundary_term(const Point3& p, const Vector3& apex,
                                                   std::span<const Point3> vertices,
                                                   std::span<const BoundaryEdge> edges,
                                                   std::array<double, 2> levels);

}  // namespace exactgeo::internal
