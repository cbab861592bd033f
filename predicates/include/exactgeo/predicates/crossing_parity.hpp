#pragma once

// Crossing parity of rays with a set of faces: the one predicate behind both products.
//
// A closed surface of triangles and bilinear patches splits space in two; a point off the
// surface lies inside iff a ray from it crosses the surface an odd number of times
// (point-in-volume, exactgeo::inside). The image of a CCD domain's boundary is such a
// surface too, and the parity of its crossings by a ray from the origin is the parity of
// the roots inside the domain (root parity, exactgeo::ccd). Both ask the same question of
// the same kinds of faces, in three steps:
//
//   1. Prepare the faces once (PreparedFaces): corners as indices into a corner list,
//      patches in tensor order (bilinear_patch.hpp), and each patch's ray-independent
//      facts, its PatchSpan (skew with a volume sign, planar, or collinear).
//   2. For one ray, ask each candidate face whether the ray crosses it (cross_face) and
//      add up (count_crossings): an even or odd count, the ray's origin on a face, or a
//      degenerate ray (it meets a face's boundary, or lies in a flat face's plane). A
//      degenerate ray is an exact answer, not an undecided one: that ray cannot count.
//   3. Cast rays in the fixed direction sequence of ray_directions.hpp until one is not
//      degenerate (crossing_parity): its count is the parity. The sequence guarantees an
//      end: at most V + 2 (E + F) of its directions are degenerate for a set with V
//      corners, E edges and F faces.
//
// Counted by orientation instead (cross_face_signed, count_signed_crossings,
// winding_number), the same steps give the winding number: each face is oriented by its
// corner order, a crossing counts +1 where the ray passes to the side the face's normal
// points to and -1 the other way, and for a closed oriented surface the sum along any ray
// that is not degenerate is the winding number of the ray's origin, however the faces
// intersect or overlap. Its parity is the crossing parity; the parity functions are the
// signed ones read modulo 2, so both answer from the same signs.
//
// Corners are handed to steps 2 and 3 by a callable corner(i) returning the exact vector
// from the ray's origin to corner i, as a kernel::Offset: Offset::between(origin,
// points[i]) for a mesh, or the stored corner images for CCD, whose origin is 0. Signs come
// from any sign policy (kernel/signs.hpp); with the exact ones every answer is exact.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/internal/patch_span.hpp"
#include "exactgeo/predicates/internal/ray_patch_core.hpp"
#include "exactgeo/predicates/internal/ray_triangle_core.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"

namespace exactgeo {

/// A face of a surface, its corners given as indices into a list of corners.
struct SurfaceFace {
  enum class Kind : std::uint8_t {
    triangle,       ///< corners[0..2]
    patch,          ///< a bilinear patch, corners in tensor order
    parallelogram,  ///< a patch known by construction to be a parallelogram (so flat):
                    ///< its preparation skips the volume sign
  };
  Kind kind = Kind::triangle;
  /// triangle: a, b, c (and a again); patch: x0 = p00, x1 = p10, x2 = p01, x3 = p11.
  std::array<VertexIndex, 4> corners{};

  static constexpr SurfaceFace triangle(VertexIndex a, VertexIndex b, VertexIndex c) noexcept {
    return {Kind::triangle, {a, b, c, a}};
  }
  /// A patch from its corners in boundary order p00 -> p10 -> p11 -> p01.
  static constexpr SurfaceFace patch(VertexIndex p00, VertexIndex p10, VertexIndex p11,
                                     VertexIndex p01, Kind kind = Kind::patch) noexcept {
    return {kind, tensor_order(p00, p10, p11, p01)};
  }
  constexpr bool is_triangle() const noexcept { return kind == Kind::triangle; }
};

/// Faces ready for rays: spans[f] is the span of faces[f] (unused for a triangle).
struct PreparedFaces {
  std::span<const SurfaceFace> faces;
  std::span<const PatchSpan> spans;
};

/// The span of a face whose corners are points: found from differences of corners, so its
/// filters are relative to the face's own size, wherever it lies.
template <class Signs>
PatchSpan span_of(const Signs& signs, const SurfaceFace& face,
                  std::span<const Point3> points) noexcept {
  if (face.is_triangle()) return {};
  const auto& c = face.corners;
  return internal::patch_span(
      signs, std::array<Point3, 4>{points[c[0]], points[c[1]], points[c[2]], points[c[3]]});
}

/// The span of a face whose corners are known only relative to some origin, as offsets
/// corner(i) (CCD's corner images). The same span as span_of on the corners themselves.
template <class Signs, class CornerOffset>
PatchSpan span_of_offsets(const Signs& signs, const SurfaceFace& face,
                          const CornerOffset& corner) noexcept {
  if (face.is_triangle()) return {};
  const auto& c = face.corners;
  return internal::patch_span_from_offsets(
      signs, kernel::Offsets<4>{corner(c[0]), corner(c[1]), corner(c[2]), corner(c[3])},
      face.kind == SurfaceFace::Kind::parallelogram ? internal::KnownShape::parallelogram
                                                    : internal::KnownShape::none);
}

/// What one face contributes to a ray's crossing count.
enum class Crossing : std::uint8_t {
  none,        ///< an even number of crossings (none, for a triangle)
  crossed,     ///< an odd number of crossings
  origin_on,   ///< the ray's origin lies on the face
  degenerate,  ///< the ray meets an edge or a corner, or lies in a flat face's plane
};

/// The same, crossings counted by orientation: a face's signed count is -1, 0 or +1
/// (bilinear_patch.hpp), so `crossed` is a count of +1 or -1 and `none` a count of 0.
struct SignedCrossing {
  Crossing kind = Crossing::none;
  /// crossed: the sign of n . direction, n the face's normal from its corner order
  /// ((b - a) x (c - a) for a triangle (a, b, c)); otherwise zero.
  Sign sign = Sign::zero;
};

constexpr SignedCrossing crossing_of(const RayTriangleHit& hit) noexcept {
  switch (hit.kind) {
    case RayTriangle::miss:
      return {Crossing::none, Sign::zero};
    case RayTriangle::interior:
      return {Crossing::crossed, hit.turn};
    case RayTriangle::origin_on:
      return {Crossing::origin_on, Sign::zero};
    case RayTriangle::edge:
    case RayTriangle::vertex:
    case RayTriangle::coplanar:
      break;
  }
  return {Crossing::degenerate, Sign::zero};
}

constexpr SignedCrossing crossing_of(const RayPatchCrossings& crossings) noexcept {
  switch (crossings.parity) {
    case RayPatch::even:
      return {Crossing::none, Sign::zero};
    case RayPatch::odd:
      return {Crossing::crossed, crossings.signed_count};
    case RayPatch::origin_on_patch:
      return {Crossing::origin_on, Sign::zero};
    case RayPatch::degenerate:
      break;
  }
  return {Crossing::degenerate, Sign::zero};
}

/// How the ray from corner(.)'s origin along `direction` (nonzero) crosses one face,
/// counted by orientation. Exact signs go behind one static det3 bound for the face
/// (kernel::with_static_filter): every det3 sign of its ray test is on its corners and the
/// direction, so one bound from their magnitudes serves them all. A policy that has a
/// static bound already (the CCD's, per ray), and the others, are used as they are.
template <class Signs, class CornerOffset>
SignedCrossing cross_face_signed(const Signs& signs, const SurfaceFace& face, const PatchSpan& span,
                                 const CornerOffset& corner,
                                 const kernel::Offset& direction) noexcept {
  const auto& c = face.corners;
  if (face.is_triangle()) {
    const kernel::Offsets<3> x{corner(c[0]), corner(c[1]), corner(c[2])};
    const auto face_signs = kernel::with_static_filter(signs, x, direction.rounded());
    return crossing_of(
        internal::classify_ray_triangle_offsets(face_signs, x[0], x[1], x[2], direction));
  }
  const kernel::Offsets<4> x{corner(c[0]), corner(c[1]), corner(c[2]), corner(c[3])};
  const auto face_signs = kernel::with_static_filter(signs, x, direction.rounded());
  return crossing_of(internal::ray_patch_crossings_offsets(face_signs, span, x, direction));
}

/// The same, as a parity.
template <class Signs, class CornerOffset>
Crossing cross_face(const Signs& signs, const SurfaceFace& face, const PatchSpan& span,
                    const CornerOffset& corner, const kernel::Offset& direction) noexcept {
  return cross_face_signed(signs, face, span, corner, direction).kind;
}

/// What one ray says about a set of faces.
enum class RayCount : std::uint8_t {
  even,            ///< an even number of crossings in all
  odd,             ///< an odd number
  origin_on_face,  ///< the origin lies on a face
  degenerate,      ///< some face answered Crossing::degenerate: cast another ray
};

/// The same, crossings counted by orientation.
struct SignedRayCount {
  RayCount kind = RayCount::even;  ///< even or odd as `total` is
  std::int64_t total = 0;          ///< even, odd: the sum of the faces' signed crossings
};

/// The crossings of one ray with the faces listed in `candidates` (indices into
/// faces.faces; a superset of the faces the ray meets), counted by orientation. Stops at
/// the first face that decides the ray: an origin on it, or a degenerate crossing.
template <class Signs, class CornerOffset, class FaceIndices>
SignedRayCount count_signed_crossings(const Signs& signs, const PreparedFaces& faces,
                                      const FaceIndices& candidates, const CornerOffset& corner,
                                      const kernel::Offset& direction) noexcept {
  std::int64_t total = 0;
  for (const auto f : candidates) {
    const SignedCrossing crossing =
        cross_face_signed(signs, faces.faces[f], faces.spans[f], corner, direction);
    switch (crossing.kind) {
      case Crossing::none:
        break;
      case Crossing::crossed:
        total += to_int(crossing.sign);
        break;
      case Crossing::origin_on:
        return {RayCount::origin_on_face, 0};
      case Crossing::degenerate:
        return {RayCount::degenerate, 0};
    }
  }
  return {total % 2 == 0 ? RayCount::even : RayCount::odd, total};
}

/// The same, as a parity (a parity is a signed count modulo 2).
template <class Signs, class CornerOffset, class FaceIndices>
RayCount count_crossings(const Signs& signs, const PreparedFaces& faces,
                         const FaceIndices& candidates, const CornerOffset& corner,
                         const kernel::Offset& direction) noexcept {
  return count_signed_crossings(signs, faces, candidates, corner, direction).kind;
}

/// The indices 0, 1, ..., n - 1 as a range for a range-based for (std::views::iota does
/// not build with every toolchain the project supports: clang 14 on libstdc++ 12).
struct FirstIndices {
  struct Iterator {
    std::size_t i;
    std::size_t operator*() const noexcept { return i; }
    Iterator& operator++() noexcept {
      ++i;
      return *this;
    }
    bool operator!=(const Iterator& other) const noexcept { return i != other.i; }
  };
  std::size_t n;
  Iterator begin() const noexcept { return {0}; }
  Iterator end() const noexcept { return {n}; }
};

/// The same with every face a candidate.
template <class Signs, class CornerOffset>
RayCount count_crossings(const Signs& signs, const PreparedFaces& faces, const CornerOffset& corner,
                         const kernel::Offset& direction) noexcept {
  return count_crossings(signs, faces, FirstIndices{faces.faces.size()}, corner, direction);
}

template <class Signs, class CornerOffset>
SignedRayCount count_signed_crossings(const Signs& signs, const PreparedFaces& faces,
                                      const CornerOffset& corner,
                                      const kernel::Offset& direction) noexcept {
  return count_signed_crossings(signs, faces, FirstIndices{faces.faces.size()}, corner, direction);
}

enum class CrossingParity : std::uint8_t {
  even,        ///< an even number of crossings (outside; no root or an even number)
  odd,         ///< an odd number (inside; an odd number of roots)
  on_surface,  ///< the ray origin lies on a face
};

struct CrossingParityResult {
  CrossingParity parity = CrossingParity::even;
  std::size_t rays = 0;  ///< rays cast, the last one decisive
};

/// The ray loop: cast_ray(k) counts the crossings of ray k of the fixed sequence
/// (ray_direction(k)) and returns its RayCount; rays k = 0, 1, ... are cast until one is
/// not degenerate. nullopt when the first `max_rays` all are, which exact signs cannot
/// produce once max_rays exceeds V + 2 (E + F) (see ray_directions.hpp); plain double signs
/// can, and their callers decide what that means.
template <class CastRay>
std::optional<CrossingParityResult> crossing_parity(std::size_t max_rays, CastRay&& cast_ray) {
  for (std::size_t k = 0; k < max_rays; ++k) {
    switch (cast_ray(k)) {
      case RayCount::even:
        return CrossingParityResult{CrossingParity::even, k + 1};
      case RayCount::odd:
        return CrossingParityResult{CrossingParity::odd, k + 1};
      case RayCount::origin_on_face:
        return CrossingParityResult{CrossingParity::on_surface, k + 1};
      case RayCount::degenerate:
        break;
    }
  }
  return std::nullopt;
}

struct WindingNumberResult {
  /// The signed crossing count of the decisive ray; nullopt when the origin lies on a
  /// face, where no winding number is defined.
  std::optional<std::int64_t> winding;
  std::size_t rays = 0;  ///< rays cast, the last one decisive
};

/// The same loop, crossings counted by orientation: cast_ray(k) returns the
/// SignedRayCount of ray k. When the faces form a closed oriented surface (every oriented
/// edge used as often one way as the other, whatever the faces' intersections), every
/// ray that is not degenerate gives the same count, the winding number of its origin with
/// respect to the surface; for other face sets the count depends on the ray.
template <class CastRay>
std::optional<WindingNumberResult> winding_number(std::size_t max_rays, CastRay&& cast_ray) {
  for (std::size_t k = 0; k < max_rays; ++k) {
    const SignedRayCount count = cast_ray(k);
    switch (count.kind) {
      case RayCount::even:
      case RayCount::odd:
        return WindingNumberResult{count.total, k + 1};
      case RayCount::origin_on_face:
        return WindingNumberResult{std::nullopt, k + 1};
      case RayCount::degenerate:
        break;
    }
  }
  return std::nullopt;
}

}  // namespace exactgeo
