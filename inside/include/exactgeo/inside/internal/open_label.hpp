#pragma once

// The label of a point against an open surface, from its generalized winding number
// w = S + (boundary term) (exactgeo/predicates/boundary_term.hpp): inside where |w| >= 1/2
// (nonzero) or w >= 1/2 (positive), the open surface's analogues of the closed rules. The
// term is tried at each precision in turn until the rule's comparison is certain.

#include <cstdint>
#include <optional>
#include <span>

#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/boundary_term.hpp"
#include "exactgeo/predicates/boundary_tree.hpp"

namespace exactgeo::inside::internal {

/// The label of `point`, whose ray along `ray` meets the faces in `crossings` signed
/// crossings and lies on no face. nullopt when the ray meets a boundary edge (cast the
/// next one); boundary when the point lies on a boundary edge; undecided when no precision
/// settles the comparison (w equal to the level, or closer to it than 2048 bits see).
/// Arithmetic::plain_double compares a plain double term instead (the baseline; never
/// undecided). Precondition: rule is nonzero or positive.
std::optional<Location> open_label(FillRule rule, std::int64_t crossings, const Point3& point,
                                   const Vector3& ray, std::span<const Point3> vertices,
                                   std::span<const BoundaryEdge> boundary, Arithmetic arithmetic);

/// The same label from the boundary tree (exactgeo/predicates/boundary_tree.hpp): the
/// near edges' and the far nodes' cone terms, the far nodes' fans bounded. `point` and
/// `ray` are in the tree's coordinates. nullopt when that does not settle the label (or
/// the ray meets an edge): open_label over every edge then decides, exactly.
std::optional<Location> open_label_from_tree(FillRule rule, std::int64_t crossings,
                                             const Point3& point, const Vector3& ray,
                                             const BoundaryTree& tree,
                                             BoundaryTree::Refinement& scratch);

/// A direction whose ray from `point` (outside `box`) leaves the box behind: along the
/// axis on which the point lies outside it, away from it. It crosses no face and meets
/// no edge, so S = 0 along it.
Vector3 ray_away_from(const mesh::Box& box, const Point3& point) noexcept;

}  // namespace exactgeo::inside::internal
