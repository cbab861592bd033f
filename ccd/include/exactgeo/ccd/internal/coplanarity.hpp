#pragma once

// The coplanarity certificate: a root needs the origin in the plane of its time slice.
//
//  * vertex-face: the slice at time t is the triangle c0(t), c1(t), c2(t); a root puts the
//    origin on it, so det[c0, c1, c2] = 0;
//  * edge-edge: the slice is the parallelogram c00 + u (c10 - c00) + v (c01 - c00); a root
//    puts the origin on it, so det[c01 - c00, c10 - c00, -c00] = -det[c00, c01, c10] = 0.
//
// Either way p(t) = det[x(t), y(t), z(t)] for three corner trajectories, each affine in t:
// the classic coplanarity cubic. p != 0 on a closed piece of the step proves that the
// piece holds no root. This settles what separating planes settle slowly: primitives that
// pass very close without touching (a near-double root of p), where planes need pieces
// of width ~ sqrt(gap) and each piece costs exact corners, while p needs nothing but
// doubles.
//
// Bernstein form. With x_i = x(i) (i = 0, 1) and D_ijk = det[x_i, y_j, z_k], the product
// of three affine factors has the degree-3 Bernstein coefficients (times 3)
//   beta = (3 D000, D100 + D010 + D001, D110 + D101 + D011, 3 D111),
// and on a piece the coefficients follow by de Casteljau at midpoints. All four strictly
// of one sign prove p != 0 on the closed piece: at every t, p is their convex combination.
//
// Error bound, one for every piece of a search (derived here; u = 2^-53):
//  * each D~ (det3 of the rounded corners in double) is within E0 = eps M_x M_y M_z of the
//    exact D, eps being the det3 filter's constant (roundoff.hpp) and M_a the largest
//    |coordinate a| of the six corners, when every M_a is within the filter's guard;
//  * beta~ costs two more roundings, each at most u 3 Dmax (Dmax = max |D~|): within
//    3 E0 + 7 u Dmax of beta; all |beta~| <= B = 3 Dmax (1 + u)^2;
//  * a de Casteljau split computes each child coefficient through at most three levels
//    of fl(fl(a + b) * 0.5): a level keeps existing error bounds (it averages) and adds at
//    most u B' + 2^-1075 (rounding, then halving a subnormal), B' <= B (1 + 2^-40) the
//    magnitude of convex combinations plus errors;
//  * so after d <= kMaxSearchDepth = 200 splits the error is at most
//    3 E0 + (7 + 600 * 3.01) u Dmax + 600 * 2^-1075 < 3 E0 + 2^-42 Dmax + 2^-1064.
// The threshold adds a factor (1 + 2^-40) for the rounding of its own computation.

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

#include "exactgeo/predicates/kernel/filter.hpp"
#include "exactgeo/predicates/kernel/formula_descriptors.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"

namespace exactgeo::ccd::internal {

/// The deepest split any search may make (the error bound below counts on it).
inline constexpr int kMaxSearchDepth = 200;

/// p on one piece of the step, in Bernstein form (times 3).
using CoplanarityCoefficients = std::array<double, 4>;

/// The coefficients of the two halves of a piece (de Casteljau at the midpoint).
inline std::pair<CoplanarityCoefficients, CoplanarityCoefficients> split_coefficients(
    const CoplanarityCoefficients& b) noexcept {
  const double b01 = (b[0] + b[1]) * 0.5;
  const double b12 = (b[1] + b[2]) * 0.5;
  const double b23 = (b[2] + b[3]) * 0.5;
  const double b012 = (b01 + b12) * 0.5;
  const double b123 = (b12 + b23) * 0.5;
  const double middle = (b012 + b123) * 0.5;
  return {{b[0], b01, b012, middle}, {middle, b123, b23, b[3]}};
}

/// p's coefficients over the whole step and the error bound valid for every piece.
class Coplanarity {
 public:
  /// From the corners of the whole step (C = 6: vertex-face, 8: edge-edge); nullopt when
  /// the corners are beyond the filter's guard (no certificate then).
  template <std::size_t C>
  static std::optional<Coplanarity> of(const exactgeo::kernel::Offsets<C>& corners) noexcept {
    constexpr std::size_t H = C / 2;
    // x, y, z: corners 0, 1, 2 (vertex-face) or c00, c01, c10 (edge-edge), at t0 and t1.
    const std::array<std::array<Vec3, 2>, 3> v{{{corners[0].rounded(), corners[H].rounded()},
                                                {corners[1].rounded(), corners[H + 1].rounded()},
                                                {corners[2].rounded(), corners[H + 2].rounded()}}};
    std::array<double, 3> largest{};
    for (const auto& trajectory : v) {
      for (const Vec3& x : trajectory) {
        for (int a = 0; a < 3; ++a)
          largest[a] = std::max(largest[a], std::fabs(x[a]));
      }
    }
    constexpr auto& filter =
        kernel::kFilterConstant<kernel::Det3Formula, kernel::Grouping::by_axis>;
    for (const double m : largest) {
      if (!(m >= filter.guard_low && m <= filter.guard_high)) return std::nullopt;
    }
    auto d = [&](int i, int j, int k) { return kernel::det3(v[0][i], v[1][j], v[2][k]); };
    const std::array<double, 8> dets{d(0, 0, 0), d(1, 0, 0), d(0, 1, 0), d(0, 0, 1),
                                     d(1, 1, 0), d(1, 0, 1), d(0, 1, 1), d(1, 1, 1)};
    double largest_det = 0.0;
    for (const double x : dets)
      largest_det = std::max(largest_det, std::fabs(x));
    const double e0 = filter.epsilon * largest[0] * largest[1] * largest[2];
    Coplanarity c;
    c.whole_step_ = {3.0 * dets[0], dets[1] + dets[2] + dets[3], dets[4] + dets[5] + dets[6],
                     3.0 * dets[7]};
    c.threshold_ = (3.0 * e0 + 0x1p-42 * largest_det) * (1.0 + 0x1p-40) + 0x1p-1064;
    return c;
  }

  const CoplanarityCoefficients& whole_step() const noexcept { return whole_step_; }
  /// The error bound every computed coefficient of every piece is within.
  double threshold() const noexcept { return threshold_; }

  /// p certainly has no zero on the closed piece with these coefficients.
  bool nonzero(const CoplanarityCoefficients& b) const noexcept {
    return (b[0] > threshold_ && b[1] > threshold_ && b[2] > threshold_ && b[3] > threshold_) ||
           (b[0] < -threshold_ && b[1] < -threshold_ && b[2] < -threshold_ && b[3] < -threshold_);
  }

  /// p certainly has the same sign at the piece's two ends.
  bool same_sign_ends(const CoplanarityCoefficients& b) const noexcept {
    return (b[0] > threshold_ && b[3] > threshold_) || (b[0] < -threshold_ && b[3] < -threshold_);
  }

  /// p certainly has opposite signs at the piece's two ends: a coplanarity root inside,
  /// where a crossing is likely.
  bool changes_sign(const CoplanarityCoefficients& b) const noexcept {
    return (b[0] > threshold_ && b[3] < -threshold_) || (b[0] < -threshold_ && b[3] > threshold_);
  }

 private:
  using Vec3 = exactgeo::kernel::Vec3<double>;

  CoplanarityCoefficients whole_step_{};
  double threshold_ = 0.0;
};

}  // namespace exactgeo::ccd::internal
