#pragma once

// Which side of its time slice's edges the origin lies on, as polynomials in time.
//
// A time slice is a convex polygon P_0 .. P_{H-1} (vertex-face: the triangle c0, c1, c2;
// edge-edge: the parallelogram c00, c10, c11, c01), with normal N = (P_1 - P_0) x
// (P_{H-1} - P_0). For each edge, s_i = (P_i x P_{i+1}) . N. When the origin lies in the
// slice's plane (the coplanarity cubic p vanishes, coplanarity.hpp) and N != 0, it is on
// the closed polygon iff every s_i >= 0, and strictly inside iff every s_i > 0. So, on a
// piece of the step:
//
//  * some s_i < 0 throughout: the origin is never on the slice, the piece holds no root
//    (where N = 0, s_i = 0: never certified negative);
//  * every s_i > 0 throughout and p of opposite signs at the piece's two ends: at the time
//    t* in between where p = 0, the origin is strictly inside the slice, so F has a root.
//
// The second proves a collision without corners or parity: a pass through the face, which
// root parity cannot see (two roots), settled by polynomials alone.
//
// Each corner moves affinely, so P_i x P_j and N are quadratics and s_i a quartic in t.
// In Bernstein form over the step, with W_a and N_b the quadratics' coefficients
// (W_0 = A_i x A_j, W_1 = (A_i x B_j + B_i x A_j) / 2, W_2 = B_i x B_j; A at t0, B at t1),
// the quartic's coefficients times 12, written with W1' = 2 W1 and N1' = 2 N1 so that
// nothing is divided, are
//   12 W0.N0,  3 (W0.N1' + W1'.N0),  2 (W0.N2 + W1'.N1' + W2.N0),  3 (W1'.N2 + W2.N1'),
//   12 W2.N2.
// On a piece they follow by de Casteljau at midpoints; all five strictly of one sign
// prove that sign throughout.
//
// Error bound, one for every piece of a search. The formula is evaluated at compile time
// on the forward-error number type of the filters (predicates/internal/roundoff.hpp),
// with every corner coordinate a rounded difference in one group whose run-time maximum
// M is the largest |coordinate| of the corners: each coefficient is then within eps M^4
// of its exact value and at most B M^4 in magnitude (eps, B: the largest over the
// coefficients; M within the guard 2^+-161 of a degree-4 formula). A midpoint split runs
// four levels of fl(fl(a + b) * 0.5), each adding at most u B M^4 (plus 2^-1075 when a
// halving underflows) while keeping earlier errors (it averages); so after at most
// kMaxSearchDepth = 200 splits every coefficient is within
//   (eps + 800 u B) M^4 + 800 * 2^-1075,
// and the threshold adds a factor (1 + 2^-40) for its own rounding and 2^-1064.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/coplanarity.hpp"
#include "exactgeo/predicates/kernel/formulas.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"
#include "exactgeo/predicates/kernel/roundoff.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::ccd::internal {

using exactgeo::kernel::Vec3;

template <class T>
constexpr Vec3<T> vector_sum(const Vec3<T>& a, const Vec3<T>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

template <class T>
constexpr Vec3<T> vector_cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// x(t) x y(t) for affine x, y (x_a at the start, x_b at the end): Bernstein coefficients
/// with the middle one doubled.
template <class T>
constexpr std::array<Vec3<T>, 3> cross_quadratic(const Vec3<T>& x_a, const Vec3<T>& x_b,
                                                 const Vec3<T>& y_a, const Vec3<T>& y_b) {
  return {vector_cross(x_a, y_a), vector_sum(vector_cross(x_a, y_b), vector_cross(x_b, y_a)),
          vector_cross(x_b, y_b)};
}

template <class T>
constexpr T twice(const T& x) {
  return x + x;
}
template <class T>
constexpr T thrice(const T& x) {
  return x + x + x;
}

/// The side quartics' Bernstein coefficients times 12, for a polygon with H corners given
/// at the start (a) and the end (b) of the step.
template <class T, std::size_t H>
constexpr std::array<std::array<T, 5>, H> side_quartics(const std::array<Vec3<T>, H>& a,
                                                        const std::array<Vec3<T>, H>& b) {
  using exactgeo::kernel::difference;
  using exactgeo::kernel::dot3;
  const auto n = cross_quadratic(difference(a[1], a[0]), difference(b[1], b[0]),
                                 difference(a[H - 1], a[0]), difference(b[H - 1], b[0]));
  std::array<std::array<T, 5>, H> sides{};
  for (std::size_t i = 0; i < H; ++i) {
    const std::size_t j = (i + 1) % H;
    const auto w = cross_quadratic(a[i], b[i], a[j], b[j]);
    sides[i] = {twice(twice(thrice(dot3(w[0], n[0])))), thrice(dot3(w[0], n[1]) + dot3(w[1], n[0])),
                twice(dot3(w[0], n[2]) + dot3(w[1], n[1]) + dot3(w[2], n[0])),
                thrice(dot3(w[1], n[2]) + dot3(w[2], n[1])),
                twice(twice(thrice(dot3(w[2], n[2]))))};
  }
  return sides;
}

struct SideBound {
  double epsilon;    ///< error of a coefficient, in units of M^4
  double magnitude;  ///< magnitude of a coefficient, in units of M^4
  double guard_low;
  double guard_high;
};

template <std::size_t H>
inline constexpr SideBound kSideBound = [] {
  using R = exactgeo::kernel::Roundoff<1>;
  std::array<Vec3<R>, H> a{};
  std::array<Vec3<R>, H> b{};
  for (std::size_t k = 0; k < H; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      a[k][axis] = R::input(0, R::InputError::one_rounding);
      b[k][axis] = R::input(0, R::InputError::one_rounding);
    }
  }
  SideBound bound{0.0, 0.0, 0.0, 0.0};
  for (const auto& quartic : side_quartics<R, H>(a, b)) {
    for (const R& coefficient : quartic) {
      const auto filter = exactgeo::kernel::derive_filter(coefficient);
      bound.epsilon = std::max(bound.epsilon, filter.epsilon);
      bound.magnitude =
          std::max(bound.magnitude, coefficient.magnitude().upper_bound_at_unit_roundoff());
      bound.guard_low = filter.guard_low;
      bound.guard_high = filter.guard_high;
    }
  }
  return bound;
}();

/// The side quartics of a step with C corners (6: vertex-face, 8: edge-edge).
template <std::size_t C>
class SliceSides {
 public:
  static constexpr std::size_t H = C / 2;
  using Quartic = std::array<double, 5>;
  using Coefficients = std::array<Quartic, H>;

  /// From the step's corners (rounded differences); nullopt beyond the guard.
  static std::optional<SliceSides> of(const exactgeo::kernel::Offsets<C>& corners) noexcept {
    const std::array<Vec3, H> start = slice_corners(corners, 0);
    const std::array<Vec3, H> end = slice_corners(corners, 1);
    double largest = 0.0;
    for (std::size_t k = 0; k < H; ++k) {
      for (int axis = 0; axis < 3; ++axis)
        largest = std::max({largest, std::fabs(start[k][axis]), std::fabs(end[k][axis])});
    }
    constexpr auto& bound = kSideBound<H>;
    if (!(largest >= bound.guard_low && largest <= bound.guard_high)) return std::nullopt;
    SliceSides sides;
    sides.whole_step_ = side_quartics<double, H>(start, end);
    const double m2 = largest * largest;
    sides.threshold_ =
        (bound.epsilon + 800 * 0x1p-53 * bound.magnitude) * (m2 * m2) * (1 + 0x1p-40) + 0x1p-1064;
    static_assert(kMaxSearchDepth <= 200, "the threshold counts 4 levels for each of 200 splits");
    return sides;
  }

  const Coefficients& whole_step() const noexcept { return whole_step_; }

  /// The bound on every coefficient's error, on any piece of a search.
  double threshold() const noexcept { return threshold_; }

  /// The coefficients on the two halves of a piece (de Casteljau at 1/2: the left half
  /// takes the first entry of each level, the right half the last).
  static std::pair<Coefficients, Coefficients> split(const Coefficients& c) noexcept {
    std::pair<Coefficients, Coefficients> halves;
    for (std::size_t i = 0; i < H; ++i) {
      Quartic b = c[i];
      for (int level = 0; level <= 4; ++level) {
        halves.first[i][level] = b[0];
        halves.second[i][4 - level] = b[4 - level];
        for (int k = 0; k < 4 - level; ++k)
          b[k] = (b[k] + b[k + 1]) * 0.5;
      }
    }
    return halves;
  }

  /// Some edge's quartic is certainly negative on the whole piece: no root there.
  bool origin_outside(const Coefficients& c) const noexcept {
    for (const Quartic& q : c) {
      if (all_beyond(q, Sign::negative)) return true;
    }
    return false;
  }

  /// Every edge's quartic is certainly positive on the whole piece.
  bool origin_inside(const Coefficients& c) const noexcept {
    for (const Quartic& q : c) {
      if (!all_beyond(q, Sign::positive)) return false;
    }
    return true;
  }

 private:
  using Vec3 = exactgeo::kernel::Vec3<double>;

  bool all_beyond(const Quartic& q, Sign s) const noexcept {
    for (const double b : q) {
      if (s == Sign::positive ? !(b > threshold_) : !(b < -threshold_)) return false;
    }
    return true;
  }

  Coefficients whole_step_{};
  double threshold_ = 0.0;
};

}  // namespace exactgeo::ccd::internal
