#pragma once

// The ray-independent facts about a patch with double corners (its PatchSpan), and its
// public shape classification. Computed from differences of corners, so the filters are
// relative to the patch's own size, not to its distance from any ray origin.

#include <array>
#include <optional>

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/internal/ray_patch_core.hpp"
#include "exactgeo/predicates/kernel/error_free.hpp"

namespace exactgeo::internal {

using kernel::Offset;
using kernel::Offsets;
using kernel::two_diff;
using kernel::TwoTerm;

/// The corners in tensor order (x0 = p00, x1 = p10, x2 = p01, x3 = p11).
inline std::array<Point3, 4> tensor_corners(const BilinearPatch& p) noexcept {
  return tensor_order(p.p00, p.p10, p.p11, p.p01);
}

/// Offsets x_i - origin.
inline Offsets<4> offsets_from(const Point3& origin, const std::array<Point3, 4>& x) noexcept {
  return {Offset::between(origin, x[0]), Offset::between(origin, x[1]),
          Offset::between(origin, x[2]), Offset::between(origin, x[3])};
}

/// The four triangles of the corners' tetrahedron (pair A, then pair B).
inline constexpr std::array<std::array<std::uint8_t, 3>, 4> kFaceTriples{
    {{0, 1, 2}, {1, 3, 2}, {0, 1, 3}, {0, 3, 2}}};

/// An axis k with ((x_j - x_i) x (x_l - x_i))_k != 0: the triangle is not degenerate and
/// dropping k projects its plane injectively. nullopt for a degenerate triangle.
template <class Signs>
std::optional<int> normal_axis(const Signs& signs, const std::array<Point3, 4>& x,
                               const std::array<std::uint8_t, 3>& t) noexcept {
  const Offset u = Offset::between(x[t[0]], x[t[1]]);
  const Offset v = Offset::between(x[t[0]], x[t[2]]);
  for (int axis = 0; axis < 3; ++axis) {
    if (signs.cross2(axis, u, v) != Sign::zero) return axis;
  }
  return std::nullopt;
}

template <class Signs>
PatchSpan patch_span(const Signs& signs, const std::array<Point3, 4>& x) noexcept {
  const Sign volume = signs.det3_by_axis(Offset::between(x[0], x[1]), Offset::between(x[0], x[2]),
                                         Offset::between(x[0], x[3]));
  if (volume != Sign::zero) return {PatchSpan::Kind::skew, volume, {}};
  for (const auto& triple : kFaceTriples) {
    if (normal_axis(signs, x, triple)) return {PatchSpan::Kind::planar, Sign::zero, triple};
  }
  return {PatchSpan::Kind::collinear, Sign::zero, {}};
}

/// (h1 - h0) == (h3 - h2) for certain: the same pairs of points, or the same exact
/// difference. Each difference is compared as its TwoDiff pair (rounded difference, exact
/// rounding error): for finite differences the pairs are equal iff the differences are,
/// since equal differences round alike. An overflowing difference gives an infinite head
/// and a NaN tail, which compares unequal: "not certain", never a wrong "equal". This
/// sees a primitive's rigid translation as well as standing points.
inline bool same_displacement(const Point3& h0, const Point3& h1, const Point3& h2,
                              const Point3& h3) noexcept {
  if (h1 == h3 && h0 == h2) return true;
  for (int axis = 0; axis < 3; ++axis) {
    const TwoTerm a = two_diff(h1[axis], h0[axis]);
    const TwoTerm b = two_diff(h3[axis], h2[axis]);
    if (a.head != b.head || a.tail != b.tail) return false;
  }
  return true;
}

/// x1 - x0 == x3 - x2 exactly, for corners that are all exact vectors (false otherwise).
inline bool exact_parallelogram(const Offsets<4>& a) noexcept {
  for (const Offset& o : a) {
    if (!o.is_exact_vector()) return false;
  }
  for (int axis = 0; axis < 3; ++axis) {
    const auto& x0 = a[0].exact_vector().exact[axis];
    const auto& x1 = a[1].exact_vector().exact[axis];
    const auto& x2 = a[2].exact_vector().exact[axis];
    const auto& x3 = a[3].exact_vector().exact[axis];
    if (!(x1 + x2 == x3 + x0)) return false;
  }
  return true;
}

/// Certainly a parallelogram, x1 - x0 == x3 - x2 (corner order x0 = p00, x1 = p10, x2 = p01,
/// x3 = p11), judged from the input points: each corner is head - tail, and equal head
/// displacements with equal tail displacements give equal corner displacements. This is
/// the common flat case in CCD, where a standing or translating primitive makes the side patches
/// parallelograms; recognising it spares an exact evaluation of a volume that is zero.
inline bool certainly_parallelogram(const Offsets<4>& a) noexcept {
  if (a[0].is_exact_vector() || a[1].is_exact_vector() || a[2].is_exact_vector() ||
      a[3].is_exact_vector()) {
    return exact_parallelogram(a);
  }
  const auto disp_equal = [&](int p, int q, int r, int s) {
    return same_displacement(a[p].head_point(), a[q].head_point(), a[r].head_point(),
                             a[s].head_point()) &&
           same_displacement(a[p].tail_point(), a[q].tail_point(), a[r].tail_point(),
                             a[s].tail_point());
  };
  return disp_equal(0, 1, 2, 3) || disp_equal(0, 2, 1, 3);  // along u, or along v
}

/// The span of a patch whose volume is zero: planar if some corner triple spans a plane,
/// else collinear.
template <class Signs>
PatchSpan flat_patch_span(const Signs& signs, const Offsets<4>& a) noexcept {
  for (const auto& t : kFaceTriples) {
    for (int axis = 0; axis < 3; ++axis) {
      if (signs.triangle_normal(axis, a[t[0]], a[t[1]], a[t[2]]) != Sign::zero) {
        return {PatchSpan::Kind::planar, Sign::zero, t};
      }
    }
  }
  return {PatchSpan::Kind::collinear, Sign::zero, {}};
}

/// Whether the patch is flat for a reason the caller knows (a parallelogram by
/// construction), or its volume has to be found.
enum class KnownShape { none, parallelogram };

/// The same span for corners known only relative to some origin (a_i = x_i - o), as in
/// continuous collision detection, where every corner is a difference of two inputs.
/// Equal to patch_span of the corners themselves; the filters are relative to |a_i|.
template <class Signs>
PatchSpan patch_span_from_offsets(const Signs& signs, const Offsets<4>& a,
                                  KnownShape known = KnownShape::none) noexcept {
  // Corners that are the same difference of the same points coincide: with at most two
  // distinct ones the patch is a segment or a point (no evaluation needed).
  int distinct = 0;
  std::array<int, 4> representative{};
  for (int i = 0; i < 4; ++i) {
    representative[i] = i;
    for (int j = 0; j < i; ++j) {
      if (representative[j] == j && a[i].same_points_as(a[j])) {
        representative[i] = j;
        break;
      }
    }
    distinct += representative[i] == i;
  }
  if (distinct <= 2) return {PatchSpan::Kind::collinear, Sign::zero, {}};
  if (distinct == 3) {
    // Flat; the three distinct corners are the only candidate non-collinear triple.
    std::array<std::uint8_t, 3> triple{};
    int n = 0;
    for (int i = 0; i < 4; ++i) {
      if (representative[i] == i) triple[n++] = static_cast<std::uint8_t>(i);
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (signs.triangle_normal(axis, a[triple[0]], a[triple[1]], a[triple[2]]) != Sign::zero) {
        return {PatchSpan::Kind::planar, Sign::zero, triple};
      }
    }
    return {PatchSpan::Kind::collinear, Sign::zero, {}};
  }
  if (known == KnownShape::parallelogram) return flat_patch_span(signs, a);
  const Sign volume = signs.tetrahedron_volume(a, [&] { return certainly_parallelogram(a); });
  if (volume != Sign::zero) return {PatchSpan::Kind::skew, volume, {}};
  return flat_patch_span(signs, a);
}

}  // namespace exactgeo::internal
