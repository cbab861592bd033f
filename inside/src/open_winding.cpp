#include "exactgeo/inside/internal/open_winding.hpp"

#include <cmath>
#include <limits>

namespace exactgeo::inside::internal {
namespace {

/// The rounding error of a + b: the exact sum is (a + b rounded) + error (Knuth's TwoSum,
/// exact when nothing overflows).
double sum_error(double a, double b, double sum) noexcept {
  const double b_part = sum - a;
  return (a - (sum - b_part)) + (b - b_part);
}

}  // namespace

double add_down(double a, double b) noexcept {
  const double sum = a + b;
  return sum_error(a, b, sum) < 0 ? std::nextafter(sum, -std::numeric_limits<double>::infinity())
                                  : sum;
}

double add_up(double a, double b) noexcept {
  const double sum = a + b;
  return sum_error(a, b, sum) > 0 ? std::nextafter(sum, std::numeric_limits<double>::infinity())
                                  : sum;
}

OpenWinding open_winding(std::int64_t crossings, const Point3& point, const Vector3& ray,
                         std::span<const Point3> vertices, std::span<const BoundaryEdge> boundary,
                         Arithmetic arithmetic) {
  const auto s = static_cast<double>(crossings);  // exact: S is far below 2^52
  if (arithmetic == Arithmetic::plain_double) {
    const double w = s + boundary_term_double(point, ray, vertices, boundary);
    return {OpenWindingKind::enclosed, {w, w}};
  }
  bool enclosed = false;
  Enclosure term;
  for (const unsigned bits : kBoundaryTermPrecisions) {
    const BoundaryTerm found = boundary_term(point, ray, vertices, boundary, bits);
    if (found.kind == BoundaryTermKind::ray_on_edge) return {OpenWindingKind::ray_on_edge, {}};
    if (found.kind == BoundaryTermKind::point_on_edge) return {OpenWindingKind::on_edge, {}};
    if (found.kind != BoundaryTermKind::enclosed) continue;
    enclosed = true;
    term = found.turns;
    if (term.upper - term.lower <= kWindingWidth) break;
  }
  if (!enclosed) {
    // |Omega| < 2 pi for each triangle of the decomposition: less than half a turn a use.
    double uses = 0.0;
    for (const BoundaryEdge& e : boundary)
      uses += static_cast<double>(e.multiplicity);
    term = {-0.5 * uses, 0.5 * uses};
  }
  return {OpenWindingKind::enclosed, {add_down(s, term.lower), add_up(s, term.upper)}};
}

}  // namespace exactgeo::inside::internal
