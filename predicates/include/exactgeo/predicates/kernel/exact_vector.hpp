#pragma once

// The third input kind, next to head - tail of two doubles: a vector known exactly as a
// short expansion per coordinate. Exact CCD needs it: splitting the time step at dyadic
// times gives corner images like (x0 - y0) + (x1 - y1), which are not differences of two
// doubles but are short sums of them.
//
// An Offset can view an ExactVector (offset.hpp) at no cost to the hot path: its head
// points at `rounded`, its tail at a zero point that marks the kind, so the filter reads
// rounded - 0 = rounded like any other input. The filter constants stay valid because
// `rounded` satisfies the same input model as a rounded difference,
//
//   |rounded - exact| <= u |rounded|  per coordinate  (u = 2^-53),
//
// whenever `filterable` is true (see make_exact_vector). The exact stages read `exact`.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "exactgeo/predicates/kernel/expansion.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::kernel {

struct ExactVector {
  /// Enough for a dyadic combination of four doubles: four blocks of at most 53 + 52 bits,
  /// two components each.
  static constexpr int kCapacity = 8;
  using Coordinate = Expansion<kCapacity>;

  /// First member: an Offset viewing this vector points here (pointer-interconvertible).
  Point3 rounded{};
  std::array<Coordinate, 3> exact{};
  /// rounded is within u |rounded| of exact in every coordinate; when false the filter
  /// must not be used (the value is then only the sign-correct largest component).
  bool filterable = true;
};

namespace internal {

/// Half an ulp of a normal double s: ulp(s) / 2 = 2^(ilogb(s) - 53) <= u |s|.
inline double half_ulp(double s) noexcept {
  return std::ldexp(1.0, std::ilogb(s) - 53);
}

}  // namespace internal

/// A double within half an ulp of the (compressed, nonzero) expansion e, if e is in the
/// normal range; nullopt otherwise. Starts from the recursive sum (within a few ulps) and
/// steps toward e until an exact comparison confirms the half-ulp bound.
template <int K>
std::optional<double> within_half_ulp(const Expansion<K>& e) noexcept {
  if (e.size() == 2) {
    // x = h + l exactly; if fl(h + l) == h, h is the double nearest to x.
    const double l = e.data()[0];
    const double h = e.data()[1];
    if (h + l == h && std::isfinite(h) && std::fabs(h) >= 0x1p-1021) return h;
  }
  double s = 0.0;
  for (int i = 0; i < e.size(); ++i)
    s += e.data()[i];
  for (int attempt = 0; attempt < 8; ++attempt) {
    if (!std::isfinite(s) || std::fabs(s) < 0x1p-1021) return std::nullopt;
    const Expansion<K + 1> error = e - Expansion<1>(s);
    if (error.is_zero()) return s;
    const double half = internal::half_ulp(s);
    const Expansion<K + 1> magnitude = error.sign() == Sign::positive ? error : -error;
    if ((magnitude - Expansion<1>(half)).sign() != Sign::positive) return s;
    s = std::nextafter(s, error.sign() == Sign::positive ? INFINITY : -INFINITY);
  }
  return std::nullopt;
}

/// Certainly different exact values, judged from the rounded ones alone. Filterable
/// coordinates are within u |rounded| of the exact ones, so equal exact coordinates have
/// rounded values at most u (|r| + |s|) <= 2^-52 max(|r|, |s|) apart; the computed
/// |r - s| is exact when r and s are within a factor 2 (Sterbenz) and far above that bound
/// otherwise, and 2^-52 max is exact while max >= 2^-960 (below, no claim).
inline bool certainly_different(const ExactVector& a, const ExactVector& b) noexcept {
  if (!a.filterable || !b.filterable) return false;
  for (int axis = 0; axis < 3; ++axis) {
    const double r = a.rounded[axis];
    const double s = b.rounded[axis];
    const double largest = std::max(std::fabs(r), std::fabs(s));
    if (largest >= 0x1p-960 && std::fabs(r - s) > 0x1p-52 * largest) return true;
  }
  return false;
}

/// Completes an ExactVector whose exact coordinates are set: compresses them and sets
/// `rounded` and `filterable`. `rounded` is exact for one-component coordinates, within
/// half an ulp for the others when they are normal; otherwise it is the largest component
/// (correct sign, zero only for zero) and the vector is not filterable.
inline void complete_exact_vector(ExactVector& v) noexcept {
  v.filterable = true;
  for (int axis = 0; axis < 3; ++axis) {
    ExactVector::Coordinate& x = v.exact[axis];
    x.compress();
    if (x.size() <= 1) {
      v.rounded[axis] = x.head();
    } else if (const std::optional<double> r = within_half_ulp(x)) {
      v.rounded[axis] = *r;
    } else {
      v.rounded[axis] = x.head();
      v.filterable = false;
    }
  }
}

/// An ExactVector from exact coordinates (see complete_exact_vector).
inline ExactVector make_exact_vector(const std::array<ExactVector::Coordinate, 3>& exact) noexcept {
  ExactVector v;
  v.exact = exact;
  complete_exact_vector(v);
  return v;
}

}  // namespace exactgeo::kernel
