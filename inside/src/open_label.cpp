#include "exactgeo/inside/internal/open_label.hpp"

#include <cmath>
#include <limits>

namespace exactgeo::inside::internal {
namespace {

/// The rule's verdict on a term compared with the levels -1/2 - S and 1/2 - S; nullopt
/// when the comparison it needs is unsure.
std::optional<Location> verdict(FillRule rule, const std::array<Versus, 2>& versus) {
  const Versus low = versus[0], high = versus[1];
  if (rule == FillRule::positive) {
    if (high == Versus::above) return Location::inside;
    if (high == Versus::below) return Location::outside;
    return std::nullopt;
  }
  // nonzero: |w| >= 1/2.
  if (high == Versus::above || low == Versus::below) return Location::inside;
  if (high == Versus::below && low == Versus::above) return Location::outside;
  return std::nullopt;
}

}  // namespace

std::optional<Location> open_label(FillRule rule, std::int64_t crossings, const Point3& point,
                                   const Vector3& ray, std::span<const Point3> vertices,
                                   std::span<const BoundaryEdge> boundary, Arithmetic arithmetic) {
  // Exact levels: S is far below 2^52.
  const auto s = static_cast<double>(crossings);
  const std::array<double, 2> levels{-0.5 - s, 0.5 - s};
  if (arithmetic == Arithmetic::plain_double) {
    const double term = boundary_term_double(point, ray, vertices, boundary);
    const auto versus = [&](double level) { return term < level ? Versus::below : Versus::above; };
    return verdict(rule, {versus(levels[0]), versus(levels[1])});
  }
  for (const unsigned bits : kBoundaryTermPrecisions) {
    const BoundaryTerm term = boundary_term(point, ray, vertices, boundary, bits, levels);
    switch (term.kind) {
      case BoundaryTermKind::ray_on_edge:
        return std::nullopt;
      case BoundaryTermKind::point_on_edge:
        return Location::boundary;
      case BoundaryTermKind::undecided:
        continue;
      case BoundaryTermKind::enclosed:
        if (const auto label = verdict(rule, term.versus)) return label;
        continue;
    }
  }
  return Location::undecided;
}

std::optional<Location> open_label_from_tree(FillRule rule, std::int64_t crossings,
                                             const Point3& point, const Vector3& ray,
                                             const BoundaryTree& tree,
                                             BoundaryTree::Refinement& scratch) {
  const auto s = static_cast<double>(crossings);
  const std::optional<BoundaryTerm> term = tree.term(point, ray, {-0.5 - s, 0.5 - s}, scratch);
  if (!term) return std::nullopt;
  return verdict(rule, term->versus);
}

Vector3 ray_away_from(const mesh::Box& box, const Point3& point) noexcept {
  Vector3 ray{0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i) {
    if (point[i] < box.lower[i] || point[i] > box.upper[i]) {
      ray[i] = point[i] < box.lower[i] ? -1.0 : 1.0;
      return ray;
    }
  }
  return ray;  // not reached for a point outside the box
}

}  // namespace exactgeo::inside::internal
