#include "edge_method.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "exactgeo/predicates/crossing_parity.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::mesh::internal {

namespace {

using kernel::Offset;

/// The other face as the ray tests read it: corners 0..n-1 of `geometry`.
struct RayTarget {
  const FaceGeometry* geometry;
  SurfaceFace face;
  PatchSpan span;

  explicit RayTarget(const FaceGeometry& g) noexcept
      : geometry(&g),
        face(g.n == 3 ? SurfaceFace::triangle(0, 1, 2) : SurfaceFace::patch(0, 1, 2, 3)),
        span(span_of(kernel::ExactSigns{}, face, std::span<const Point3>(g.p.data(), g.n))) {}

  /// How the ray {origin + s (to - from) : s > 0} crosses the face. The direction is
  /// the exact difference of the two points, so rays from both ends of an edge run along
  /// one line.
  Crossing ray(const Point3& origin, const Offset& direction) const noexcept {
    const auto corner = [&](VertexIndex i) { return Offset::between(origin, geometry->p[i]); };
    return cross_face(kernel::ExactSigns{}, face, span, corner, direction);
  }

  bool has_edge(const Point3& x, const Point3& y) const noexcept {
    for (std::size_t i = 0; i < geometry->n; ++i) {
      const Point3& u = geometry->corner(i);
      const Point3& v = geometry->corner(i + 1);
      if ((u == x && v == y) || (u == y && v == x)) return true;
    }
    return false;
  }
};

enum class EdgeCrossing : std::uint8_t { even, odd, undecided };

/// Parity of the crossings of the open segment (from, to) with the face: the crossings
/// of the ray from `from` through `to`, minus those of the ray from `to` onward (`to`
/// itself is not on the face when both rays are decided). nullopt when either ray starts
/// on the face or meets its boundary (or lies in a flat face's plane).
std::optional<bool> segment_parity(const Point3& from, const Point3& to,
                                   const RayTarget& target) noexcept {
  const Offset direction = Offset::between(from, to);
  const Crossing near = target.ray(from, direction);
  if (near == Crossing::origin_on || near == Crossing::degenerate) return std::nullopt;
  const Crossing far = target.ray(to, direction);
  if (far == Crossing::origin_on || far == Crossing::degenerate) return std::nullopt;
  return (near == Crossing::crossed) != (far == Crossing::crossed);
}

EdgeCrossing edge_crossing(const Point3& x, const Point3& y, const RayTarget& target) noexcept {
  if (x == y) return EdgeCrossing::even;  // an empty open segment
  // A shared edge lies on the boundary of an injective face, off its interior.
  if (target.has_edge(x, y))
    return target.geometry->injective() ? EdgeCrossing::even : EdgeCrossing::undecided;
  // A ray that meets the boundary beyond one end may miss it beyond the other.
  std::optional<bool> odd = segment_parity(x, y, target);
  if (!odd) odd = segment_parity(y, x, target);
  if (!odd) return EdgeCrossing::undecided;
  return *odd ? EdgeCrossing::odd : EdgeCrossing::even;
}

}  // namespace

FaceContact edge_method(const FaceGeometry& a, const FaceGeometry& b) noexcept {
  bool undecided = false;
  for (const auto& [f, g] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    const RayTarget target(*g);
    for (std::size_t i = 0; i < f->n; ++i) {
      switch (edge_crossing(f->corner(i), f->corner(i + 1), target)) {
        case EdgeCrossing::odd:
          return FaceContact::intersecting;
        case EdgeCrossing::undecided:
          undecided = true;
          break;
        case EdgeCrossing::even:
          break;
      }
    }
  }
  return undecided ? FaceContact::undecided : FaceContact::apart;
}

}  // namespace exactgeo::mesh::internal
