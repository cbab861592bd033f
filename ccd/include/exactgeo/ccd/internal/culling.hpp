#pragma once

// Conservative culling: proofs that the origin lies outside the convex hull of the corner
// images, hence outside the image of the whole domain (F is affine in each parameter, so
// every value of F is a convex combination of corner values) and there is no root.
// "true" is a proof; "false" only means "no proof found".
//
// Two tests, cheapest first, each decided by certified signs only:
//
//  * bounding box: on some axis all corners are strictly positive (or all strictly
//    negative). The rounded coordinates have the exact signs.
//  * slice planes: a plane through the origin with every corner strictly on one side,
//    from a few candidate normals, then a plane turning with time
//    (separated_by_slice_planes, separated_by_turning_plane).
//
// The second takes the filter's sign, and where it cannot certify one, an exact sign with
// expansions (a dot product with a double normal: a few TwoProducts); when even that is
// out of range the sign counts as "not strict". Its candidate normals are plain-double
// estimates (common/internal/closest_direction.hpp, which minimum separation shares).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "exactgeo/ccd/common/internal/closest_direction.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/predicates/kernel/expansion.hpp"
#include "exactgeo/predicates/kernel/filter.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::ccd::internal {

template <std::size_t C>
bool outside_bounding_box(const kernel::Offsets<C>& a) noexcept {
  // fl(head - tail) has the sign of head - tail (a difference of doubles rounds to zero
  // only when it is zero), so the rounded coordinates' extremes decide exactly.
  for (int axis = 0; axis < 3; ++axis) {
    double lowest = a[0].head(axis) - a[0].tail(axis);
    double highest = lowest;
    for (std::size_t k = 1; k < C; ++k) {
      const double x = a[k].head(axis) - a[k].tail(axis);
      lowest = std::min(lowest, x);
      highest = std::max(highest, x);
    }
    if (lowest > 0.0 || highest < 0.0) return true;
  }
  return false;
}

/// All signs certified, nonzero and equal.
class StrictSide {
 public:
  void add(std::optional<Sign> s) noexcept {
    if (!s || *s == Sign::zero || (side_ != Sign::zero && *s != side_)) {
      strict_ = false;
    } else {
      side_ = *s;
    }
  }
  bool holds() const noexcept { return strict_; }

 private:
  Sign side_ = Sign::zero;
  bool strict_ = true;
};

/// n . p exactly, with expansions: the exact coordinates of p times the doubles n_k
/// (TwoProduct), summed. TwoProduct is exact when neither factor reaches 2^996 (Dekker's
/// split multiplies by 2^27 + 1 and would overflow), the product stays below 2^1002 and
/// its factors' exponents sum to at least -969 (no partial product underflows); sums of
/// three such products stay finite. nullopt outside those ranges (culling may always
/// leave a sign undecided): never a sign computed from an overflow.
inline std::optional<kernel::Expansion<48>> expansion_dot(const kernel::Offset& p,
                                                          const Vector3& n) noexcept {
  constexpr int kSplitLimit = 995;  // ilogb(a) <= 995: |a| < 2^996
  std::array<kernel::Expansion<16>, 3> terms;
  for (int axis = 0; axis < 3; ++axis) {
    kernel::Expansion<8> x;
    if (p.is_exact_vector()) {
      x = p.exact_vector().exact[axis];
    } else {
      if (std::fabs(p.head(axis)) >= 0x1p1021 || std::fabs(p.tail(axis)) >= 0x1p1021) {
        return std::nullopt;
      }
      x = kernel::Expansion<2>::difference(p.head(axis), p.tail(axis));
    }
    if (n[axis] != 0.0) {
      // Expansion components are never zero, so ilogb is finite.
      const int e = std::ilogb(n[axis]);
      if (e > kSplitLimit) return std::nullopt;
      for (int i = 0; i < x.size(); ++i) {
        const int exponent = std::ilogb(x.data()[i]);
        if (exponent > kSplitLimit || exponent + e < -960 || exponent + e > 1000) {
          return std::nullopt;
        }
      }
    }
    terms[axis] = kernel::scale(x, n[axis]);
  }
  return terms[0] + terms[1] + terms[2];
}

/// The sign of n . p: the filter's, else the expansion's, else undecided.
inline std::optional<Sign> dot_sign(const kernel::Offset& p, const Vector3& n) noexcept {
  const kernel::Offset normal = kernel::Offset::vector(n);
  if (const auto s = kernel::filtered_sign<kernel::Dot3Formula, kernel::Grouping::by_vector>(
          kernel::Offsets<2>{p, normal}, 0)) {
    return s;
  }
  if (const auto d = expansion_dot(p, n)) return d->sign();
  return std::nullopt;
}

/// Every corner strictly on the positive side of the plane n . x = 0, or every corner on
/// the negative side, each side certified (filter, then expansions).
template <std::size_t C>
bool on_one_side(const kernel::Offsets<C>& a, const Vector3& n) noexcept {
  StrictSide side;
  for (std::size_t k = 0; k < C && side.holds(); ++k)
    side.add(dot_sign(a[k], n));
  return side.holds();
}

/// A plane that turns with time: normal n(s) = (1 - s) n0 + s n1 over the piece (s its
/// local time). With F(s, .) = sum_k w_k ((1 - s) L_k + s R_k) (w_k >= 0, L_k and R_k the
/// corners at its start and end), n(s) . F is, for each k, the degree-2 Bernstein
/// polynomial with coefficients n0 . L_k, (n0 . R_k + n1 . L_k) / 2, n1 . R_k. All of them
/// strictly of one sign prove n(s) . F != 0 everywhere: no root. The middle coefficient
/// differs from the mean of the outer two by (n0 - n1) . (R_k - L_k) / 2, quadratic in the
/// piece's length, where a fixed plane's error is linear: pieces can be far longer.
template <std::size_t C>
bool separated_by_turning_plane(const kernel::Offsets<C>& a, const Vector3& n0,
                                const Vector3& n1) noexcept {
  constexpr std::size_t H = C / 2;
  StrictSide side;
  for (std::size_t k = 0; k < H && side.holds(); ++k) {
    side.add(dot_sign(a[k], n0));
    side.add(dot_sign(a[H + k], n1));
    const auto cross_start = expansion_dot(a[k], n1);
    const auto cross_end = expansion_dot(a[H + k], n0);
    side.add(cross_start && cross_end ? std::optional<Sign>((*cross_start + *cross_end).sign())
                                      : std::nullopt);
  }
  return side.holds();
}

inline Vector3 cross(const Vector3& a, const Vector3& b) noexcept {
  return {kernel::cross2(0, a, b), kernel::cross2(1, a, b), kernel::cross2(2, a, b)};
}

/// The cheapest slice plane alone: orthogonal to the direction of the t0 slice's closest
/// point, every corner strictly on its positive side, certified by the filter only. It
/// settles most near misses (primitives that stay apart side by side) for one dot product
/// and one compare per corner, so it runs before root parity; at the first corner the
/// filter cannot place (a collision, a touch) it gives up. The other planes, with exact
/// fallbacks, wait for an even parity.
template <std::size_t C>
bool separated_by_closest_direction(const kernel::Offsets<C>& a) noexcept {
  const Vector3 n = closest_direction(slice_corners(a, 0));
  if (!usable(n)) return false;
  // The dot product's filter with one bound for all corners: its analysis holds for any
  // upper bounds on the two groups' magnitudes within the guard (kernel/roundoff.hpp), so
  // the largest coordinate of all corners serves every corner. A corner it leaves
  // undecided means "no proof", as with a bound per corner.
  kernel::VectorArray<double, C> x;
  double largest = 0.0;
  for (std::size_t k = 0; k < C; ++k) {
    x[k] = a[k].rounded();
    largest = std::max({largest, std::fabs(x[k][0]), std::fabs(x[k][1]), std::fabs(x[k][2])});
  }
  const std::array<double, 2> maxima{largest,
                                     std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])})};
  // The t0 slice's corners lie on the plane's positive side (up to rounding: the slice is
  // convex and the normal points to its closest point); the t1 corners decide, first.
  for (std::size_t i = 0; i < C; ++i) {
    const std::size_t k = (C / 2 + i) % C;
    const double value = kernel::Dot3Formula::evaluate(kernel::VectorArray<double, 2>{x[k], n}, 0);
    constexpr auto& dot3 =
        kernel::kFilterConstant<kernel::Dot3Formula, kernel::Grouping::by_vector>;
    if (!(value > 0.0) || !kernel::filter_certifies<dot3>(value, maxima)) return false;
  }
  return true;
}

/// The cull that runs before root parity, in the exact and the parity methods: the
/// bounding box (exact coordinate signs, a few nanoseconds), then the closest direction's
/// plane. Either proves that the origin is outside the hull of the corner images, so
/// there is no root in the closed domain: no collision, and an even root parity with no
/// boundary root, so the parity method's answer is the same with or without it.
template <std::size_t C>
bool culled_before_parity(const kernel::Offsets<C>& a) noexcept {
  return outside_bounding_box(a) || separated_by_closest_direction(a);
}

/// A normal facing a slice that spans no plane (a segment or a point: a degenerate
/// primitive, or primitives lying along one line): the plane through the origin parallel
/// to the line through the slice, perpendicular to the plane of that line and the origin.
/// The line passes through x[0] with direction e, the slice's longest extent, or, for a
/// slice that is a point, the corner's own motion to `other` (the same corner in the
/// other slice). (e x x0) x e = |e|^2 p, with p the component of x0 orthogonal to e,
/// points from the origin to the line, as closest_direction does. Computed as two cross
/// products, not as x0 minus its projection on e: that difference cancels to the
/// distance d of the line from the origin and leaves the direction off by about u |x0| /
/// d, which tilts the plane across corners |x0| away once d falls below about
/// sqrt(u) |x0|; the rounding of e x x0 enters the plane's side of the line's points only
/// at second order, so this plane separates down to distances near u |x0|.
template <std::size_t H>
Vector3 line_facing_normal(const std::array<Vector3, H>& x, const Vector3& other) noexcept {
  Vector3 e = kernel::difference(other, x[0]);
  double longest = 0.0;
  for (std::size_t k = 1; k < H; ++k) {
    const Vector3 edge = kernel::difference(x[k], x[0]);
    const double length = kernel::dot3(edge, edge);
    if (length > longest) {
      longest = length;
      e = edge;
    }
  }
  return cross(cross(e, x[0]), e);
}

/// The image of one time slice is flat: a triangle (vertex-face) or a parallelogram
/// (edge-edge). Candidate separating planes through the origin: orthogonal to the
/// direction of the slice's point closest to the origin, parallel to the slice's plane
/// (the origin off that plane), or parallel to a plane through one of its edges and
/// orthogonal to it (the origin beside the polygon); for a slice that spans no plane (a
/// segment or a point), parallel to its line instead (line_facing_normal); last, the
/// plane turning from one slice's facing normal to the other's. As a piece of the step
/// shrinks, its corners approach one slice and one of these planes separates unless the
/// origin is on the image. The normals are computed in plain doubles from the rounded
/// corners: any normal will do, because the side of every corner is then certified. With
/// `Planes::all`, also the plane turning between the slices' own plane normals (below).
enum class Planes : std::uint8_t {
  usual,  ///< enough to decide whether a step holds a root
  all,    ///< also for pieces next to a contact, where a time of impact is bracketed
};

template <std::size_t C>
bool separated_by_slice_planes(const kernel::Offsets<C>& a,
                               Planes planes = Planes::usual) noexcept {
  constexpr std::size_t H = C / 2;
  const std::array<std::array<Vector3, H>, 2> slices{slice_corners(a, 0), slice_corners(a, 1)};
  std::array<Vector3, 2> facing{};  // per slice, a normal pointing from the origin to it
  std::array<Vector3, 2> plane{};   // per slice, its plane's normal (zero if it spans none)
  for (std::size_t slice = 0; slice < 2; ++slice) {
    const std::array<Vector3, H>& x = slices[slice];
    facing[slice] = closest_direction(x);
    if (usable(facing[slice]) && on_one_side(a, facing[slice])) return true;
    const Vector3 normal =
        H == 3 ? cross(kernel::difference(x[1], x[0]), kernel::difference(x[2], x[0]))
               : cross(kernel::difference(x[2], x[0]), kernel::difference(x[3], x[1]));
    if (!usable(normal)) {
      const Vector3 along_line = line_facing_normal(x, slices[1 - slice][0]);
      if (!usable(along_line)) continue;
      facing[slice] = along_line;
      if (on_one_side(a, along_line)) return true;
      continue;
    }
    plane[slice] = normal;
    if (on_one_side(a, normal)) return true;
    for (std::size_t k = 0; k < H; ++k) {
      const Vector3 lateral = cross(kernel::difference(x[(k + 1) % H], x[k]), normal);
      if (usable(lateral) && on_one_side(a, lateral)) return true;
    }
  }
  if (usable(facing[0]) && usable(facing[1]) &&
      separated_by_turning_plane(a, facing[0], facing[1])) {
    return true;
  }
  // The slices' own planes turning from one to the other (the same formula orients both
  // alike): next to a transversal contact the origin is off the slice planes by about
  // the time to the contact, and n(s) . F(s) is then the coplanarity cubic up to a term
  // quadratic in the piece's length, with normals exact to rounding, where the closest
  // directions above lose half the digits. It settles pieces the others leave beside a
  // contact, where a bracket is narrowed, and otherwise rarely pays its cost: only a time
  // of impact asks for it (docs/ccd.md, "Time of impact").
  return planes == Planes::all && usable(plane[0]) && usable(plane[1]) &&
         separated_by_turning_plane(a, plane[0], plane[1]);
}

/// Both tests; `filterable` false (a piece whose rounded corners are not within the
/// filter's input model) leaves only the exact bounding-box test.
template <std::size_t C>
bool certainly_no_root(const kernel::Offsets<C>& a, bool filterable = true,
                       Planes planes = Planes::usual) noexcept {
  if (outside_bounding_box(a)) return true;
  return filterable && separated_by_slice_planes(a, planes);
}

}  // namespace exactgeo::ccd::internal
