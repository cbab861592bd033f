#pragma once

// Ray vs bilinear patch crossing parity (Brochu, Edwards, Bridson, "Efficient
// Geometrically Exact Continuous Collision Detection", SIGGRAPH 2012, Algorithm 1), with
// every flat shape decided exactly.
//
// Corners, in the order used throughout: x0 = p00, x1 = p10, x2 = p01, x3 = p11; the
// boundary is x0 -> x1 -> x3 -> x2 -> x0. The corners' tetrahedron T has two triangle
// pairs with the patch's boundary:
//   pair A = (x0, x1, x2), (x1, x3, x2)   diagonal x1 x2
//   pair B = (x0, x1, x3), (x0, x3, x2)   diagonal x0 x3
// each oriented consistently with the boundary. Patch + pair A and patch + pair B bound
// the two halves of T.
//
// Skew patch (orient3d(x0, x1, x2, x3) = V != 0):
//  * o outside closed T: o is outside both closed surfaces, so the crossing parity with
//    the patch equals that with either pair.
//  * o in T: with g_pqr(o) = orient3d(x_p, x_q, x_r, o), in T g012 and g132 have the sign
//    of V and g013, g032 the opposite sign, so both products in
//    phi = g012 g132 - g013 g032 are >= 0. Near faces 012/132 (the half bounded by pair A)
//    phi < 0; near 013/032 phi > 0. So phi < 0: o is inside patch + A and outside
//    patch + B: count pair B; phi > 0: count pair A; phi = 0: o is on the quadric inside
//    T, which for a nondegenerate hyperbolic paraboloid is exactly the patch.
//
// Counting crossings with a pair: an interior crossing counts 1; a crossing through a
// vertex or a boundary edge, or a ray in a triangle's plane meeting it, is "degenerate"
// (the pair's boundary is the patch's boundary; a ray in a pair triangle's plane meeting
// it must enter it through the boundary, since o is never on the chosen pair). A crossing
// through the open diagonal is seen by both triangles; it crosses the pair's surface iff
// the ray turns the same way around both consistently oriented triangles (equal `turn`),
// else it only touches it (count 0 or 2).
//
// Signed crossings. Orient the patch by n = dp/du x dp/dv (its boundary x0 -> x1 -> x3 ->
// x2 counter-clockwise seen from the side n points to) and count each crossing as the sign
// of n . d. The pair triangles carry the same orientation, so the patch minus the chosen
// pair is a closed surface, and o lies outside the region it bounds (that is how the pair
// was chosen). A closed surface's signed crossings by a ray from a point are the point's
// winding number with respect to it, here 0: the signed count through the patch equals
// the signed count through the pair, each triangle crossing counting its `turn`, a
// crossing through the diagonal the common turn (and 0 where the turns differ). The same
// argument gives the parity above (a parity is a signed count modulo 2). The signed count
// is -1, 0 or +1: the two triangles of a skew patch's pair are two faces of the convex
// tetrahedron T, consistently oriented, so a line crossing both enters T through one and
// leaves through the other, with opposite turns; the fan of a flat patch overlaps itself
// only where its triangles have opposite orientations. So "odd" is "+1 or -1" and "even"
// is "0".
//
// Planar patch (V = 0, corners not collinear): with o off the plane, the parity is the
// number of preimages of the ray's crossing point, i.e. (degree theory) the winding
// parity of the boundary around it, which the same pair count computes (the fan of two
// triangles; a degenerate fan triangle lies on boundary edges). With o in the plane: o is
// on the patch iff it is on a boundary edge, or the winding parity around it is odd, or
// it is in a fold (segment_sweep.hpp); otherwise a ray in the plane meeting the corners'
// hull is reported degenerate, and any other ray crosses nothing.
//
// Collinear patch (a segment or a point): its image is the corners' hull.

#include <array>
#include <cassert>
#include <cstdint>
#include <optional>

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/internal/coplanar.hpp"
#include "exactgeo/predicates/internal/ray_triangle_core.hpp"
#include "exactgeo/predicates/internal/segment_sweep.hpp"

namespace exactgeo::internal {

using kernel::Offset;
using kernel::Offsets;

struct TrianglePair {
  std::array<std::array<std::uint8_t, 3>, 2> triangles;
  std::array<std::uint8_t, 2> diagonal_edge;  // edge index within each triangle
};
inline constexpr TrianglePair kPairA{{{{0, 1, 2}, {1, 3, 2}}}, {1, 2}};
inline constexpr TrianglePair kPairB{{{{0, 1, 3}, {0, 3, 2}}}, {2, 0}};

constexpr RayPatchCrossings kPatchDegenerate{RayPatch::degenerate, Sign::zero};
constexpr RayPatchCrossings kPatchOriginOn{RayPatch::origin_on_patch, Sign::zero};
constexpr RayPatchCrossings kPatchMissed{RayPatch::even, Sign::zero};

/// A signed count of -1, 0 or +1 as an answer (see the header).
constexpr RayPatchCrossings counted(int signed_count) noexcept {
  assert(signed_count >= -1 && signed_count <= 1);
  return {signed_count == 0 ? RayPatch::even : RayPatch::odd, static_cast<Sign>(signed_count)};
}

template <class Signs>
RayPatchCrossings count_pair_crossings(
    const Signs& signs, const TrianglePair& pair, const Offsets<4>& a, const Offset& d,
    const std::array<std::optional<Sign>, 2>& plane_sides) noexcept {
  // Edge signs det[a_p, a_q, d]; the diagonal is shared (with opposite orientation).
  std::array<std::array<Sign, 3>, 2> edges;
  const auto& t0 = pair.triangles[0];
  const auto& t1 = pair.triangles[1];
  for (int i = 0; i < 3; ++i) {
    edges[0][i] = signs.det3_by_vector(a[t0[i]], a[t0[(i + 1) % 3]], d);
  }
  for (int i = 0; i < 3; ++i) {
    edges[1][i] = i == pair.diagonal_edge[1]
                      ? -edges[0][pair.diagonal_edge[0]]
                      : signs.det3_by_vector(a[t1[i]], a[t1[(i + 1) % 3]], d);
  }
  int signed_count = 0;
  std::array<Sign, 2> diagonal_turn{Sign::zero, Sign::zero};
  for (int t = 0; t < 2; ++t) {
    const auto& tri = pair.triangles[t];
    const RayTriangleHit hit = classify_from_edge_signs(signs, a[tri[0]], a[tri[1]], a[tri[2]], d,
                                                        edges[t], plane_sides[t]);
    switch (hit.kind) {
      case RayTriangle::miss:
        break;
      case RayTriangle::interior:
        signed_count += to_int(hit.turn);
        break;
      case RayTriangle::edge:
        if (hit.feature != pair.diagonal_edge[t]) return kPatchDegenerate;
        diagonal_turn[t] = hit.turn;
        break;
      case RayTriangle::origin_on:  // impossible for the pair chosen (see header)
        assert(false && "origin on an auxiliary triangle");
        return kPatchDegenerate;
      case RayTriangle::vertex:
      case RayTriangle::coplanar:
        return kPatchDegenerate;
    }
  }
  if (diagonal_turn[0] != Sign::zero || diagonal_turn[1] != Sign::zero) {
    // Both triangles contain the crossing point on their common edge.
    assert(diagonal_turn[0] != Sign::zero && diagonal_turn[1] != Sign::zero);
    if (diagonal_turn[0] == Sign::zero || diagonal_turn[1] == Sign::zero) return kPatchDegenerate;
    if (diagonal_turn[0] == diagonal_turn[1]) signed_count += to_int(diagonal_turn[0]);
  }
  return counted(signed_count);
}

template <class Signs>
RayPatchCrossings skew_patch_crossings(const Signs& signs, Sign volume, const Offsets<4>& a,
                                       const Offset& d) noexcept {
  // det[a_p, a_q, a_r] = -g_pqr(o): in T, det012 and det132 are -V or 0, det013 and det032
  // are V or 0.
  const Sign det012 = signs.det3_by_axis(a[0], a[1], a[2]);
  const Sign det132 = signs.det3_by_axis(a[1], a[3], a[2]);
  bool in_tetrahedron = det012 != volume && det132 != volume;
  std::optional<Sign> det013;
  std::optional<Sign> det032;
  if (in_tetrahedron) {
    det013 = signs.det3_by_axis(a[0], a[1], a[3]);
    det032 = signs.det3_by_axis(a[0], a[3], a[2]);
    in_tetrahedron = *det013 != -volume && *det032 != -volume;
  }
  if (in_tetrahedron) {
    const Sign phi = signs.phi(a);
    if (phi == Sign::zero) return kPatchOriginOn;
    if (phi == Sign::negative) return count_pair_crossings(signs, kPairB, a, d, {det013, det032});
  }
  return count_pair_crossings(signs, kPairA, a, d, {det012, det132});
}

/// Is o on the planar patch, o in its plane? (Boundary edges, winding parity, fold.)
template <class Signs>
bool origin_on_planar_patch(const Signs& signs, const Offsets<4>& a) noexcept {
  const std::array<const Offset*, 4> corners{&a[0], &a[1], &a[2], &a[3]};
  const std::optional<Projection> projection = find_projection(signs, corners);
  // o in the plane of non-collinear corners: two offsets span the plane.
  if (!projection || projection->kind != Projection::Kind::plane) return true;
  const int k = projection->axis;
  constexpr std::array<std::array<int, 2>, 4> kBoundary{{{0, 1}, {1, 3}, {3, 2}, {2, 0}}};
  for (const auto& [p, q] : kBoundary) {
    if (origin_on_segment(signs, k, a[p], a[q])) return true;
  }
  // Winding parity from the fan of pair A, i.e. triangles (x0, x1, x2) and (x1, x3, x2).
  const Sign c01 = signs.cross2(k, a[0], a[1]);
  const Sign c12 = signs.cross2(k, a[1], a[2]);
  const Sign c20 = signs.cross2(k, a[2], a[0]);
  const Sign c13 = signs.cross2(k, a[1], a[3]);
  const Sign c32 = signs.cross2(k, a[3], a[2]);
  bool odd_winding;
  if (c12 == Sign::zero && signs.dot3(a[1], a[2]) == Sign::negative) {
    // o on the open diagonal: inside the fan's union iff x0 and x3 are on opposite sides of
    // the diagonal's line, which passes through o (neither is on it: that would put o on a
    // boundary edge, handled above).
    odd_winding = c20 == c32;  // sides: (a2 x a0) and (a2 x a3) = -(a3 x a2)
  } else {
    odd_winding = strictly_inside(c01, c12, c20) != strictly_inside(c13, c32, -c12);
  }
  if (odd_winding) return true;
  if (!origin_in_hull(signs, corners)) return false;
  // Even winding inside the hull: o is on the patch only if the patch folds over it.
  return origin_on_planar_patch_by_sweep(signs.numbers(a), k);
}

template <class Signs>
RayPatchCrossings planar_patch_crossings(const Signs& signs,
                                         const std::array<std::uint8_t, 3>& triple,
                                         const Offsets<4>& a, const Offset& d) noexcept {
  if (signs.det3_by_axis(a[triple[0]], a[triple[1]], a[triple[2]]) != Sign::zero) {
    return count_pair_crossings(signs, kPairA, a, d, {std::nullopt, std::nullopt});
  }
  if (origin_on_planar_patch(signs, a)) return kPatchOriginOn;
  const std::array<const Offset*, 4> corners{&a[0], &a[1], &a[2], &a[3]};
  return coplanar_ray_meets_hull(signs, corners, d) ? kPatchDegenerate : kPatchMissed;
}

template <class Signs>
RayPatchCrossings collinear_patch_crossings(const Signs& signs, const Offsets<4>& a,
                                            const Offset& d) noexcept {
  const std::array<const Offset*, 4> corners{&a[0], &a[1], &a[2], &a[3]};
  if (origin_in_hull(signs, corners)) return kPatchOriginOn;
  return coplanar_ray_meets_hull(signs, corners, d) ? kPatchDegenerate : kPatchMissed;
}

/// The ray test proper, crossings counted by orientation (the parity is their `parity`).
/// `a` are the corners minus the origin (x0..x3 order), `d` the direction (nonzero),
/// `span` the patch's shape.
template <class Signs>
RayPatchCrossings ray_patch_crossings_offsets(const Signs& signs, const PatchSpan& span,
                                              const Offsets<4>& a, const Offset& d) noexcept {
  switch (span.kind) {
    case PatchSpan::Kind::skew:
      return skew_patch_crossings(signs, span.volume, a, d);
    case PatchSpan::Kind::planar:
      return planar_patch_crossings(signs, span.plane_triple, a, d);
    case PatchSpan::Kind::collinear:
      break;
  }
  return collinear_patch_crossings(signs, a, d);
}

template <class Signs>
RayPatch ray_patch_parity_offsets(const Signs& signs, const PatchSpan& span, const Offsets<4>& a,
                                  const Offset& d) noexcept {
  return ray_patch_crossings_offsets(signs, span, a, d).parity;
}

}  // namespace exactgeo::internal
