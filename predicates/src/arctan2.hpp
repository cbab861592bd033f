#pragma once

// atan2 in plain doubles with a proven error bound, for the boundary term's filter
// (boundary_term_filter.cpp): the half angle of every far chord and near edge goes through
// it, and the C library's atan2 cost more than the rest of the filter's arithmetic. Its
// bound, kArctanError, is derived below from the rounding of each operation; the C
// library's atan2 was trusted instead (2^-40, a margin over its documented accuracy).
//
// For y = |num| and x = |den|, not both zero: the ratio t of the smaller to the larger
// lies in [0, 1]; atan t is reduced to the nearest eighth c = k/8 by the exact identity
// atan t = atan c + atan z, z = (t - c) / (1 + t c) (valid as t c > -1), with |z| at most
// a sixteenth, where the alternating series z - z^3/3 + ... + z^9/9 - z^11/11 leaves at
// most |z|^13 / 13 < 2^-55 (its terms decrease in magnitude, so the remainder is below the
// first term left out). Then pi/2 - a when y > x (atan(y/x) = pi/2 - atan(x/y)), pi - r
// when den < 0, and num's sign (atan2(-y, x) = -atan2(y, x), signed zeros included:
// atan2(+-0, x < 0) = +-pi).
//
// The error, u = 2^-53, |atan'| <= 1 throughout:
//  - t = fl(min / max) is within u t (or 2^-1075 where it underflows) of the exact ratio;
//  - 8t is exact and fl(8t + 1/2) <= 8.5 within 2^-50, so k = floor(fl(8t + 1/2)) has
//    |8t - k| <= 1/2 + 2^-50, |t - c| <= 2^-4 (1 + 2^-49), and |z| no more;
//  - z computed: t - c within u of itself, t c within u, 1 + t c within u (1 + t c), the
//    quotient within u: within 5u |z| <= 0.32u of (t - c) / (1 + t c);
//  - the series at the computed z: w = fl(z z) within u, the bracket h (|h| <= 0.335)
//    within 0.68u (its five coefficients each within u of themselves, w h's terms below
//    2^-8 of the sums), z w h within 2^-12 1.7u, the last sum within u |z + z w h|
//    <= 0.063u: 0.07u in all; the truncation 0.25u; z's own error 0.32u;
//  - kAtanEighths[k] within u atan c <= 0.79u of atan c, and their sum within
//    u (pi/4 + 0.063) <= 0.85u: atan t within 2.28u, atan of the exact ratio within
//    3.28u + 2^-1075;
//  - pi/2's double within 0.56u of pi/2, the difference within u pi/2 <= 1.58u: 5.42u;
//    pi's double within 1.11u of pi, the difference within u pi <= 3.15u: 9.68u.
// So the result is within 10u + 2^-1075 of atan2(num, den); kArctanError, 2^-48 = 32u,
// covers that three times over. The table's entries (atan(k/8) rounded to nearest) and
// the bound are checked against 512-bit MPFR by tests/predicates/arctan2_test.cpp.

#include <array>
#include <cmath>

namespace exactgeo::internal {

/// A bound, in radians, on |arctan2(num, den) - atan2(num, den)| (derived above).
inline constexpr double kArctanError = 0x1p-48;

/// atan(k / 8), k = 0, ..., 8, each the double nearest to it (within u of it).
inline constexpr std::array<double, 9> kAtanEighths{
    0.0,
    0x1.fd5ba9aac2f6ep-4,
    0x1.f5b75f92c80ddp-3,
    0x1.6f61941e4def1p-2,
    0x1.dac670561bb4fp-2,
    0x1.1e00babdefeb4p-1,
    0x1.4978fa3269ee1p-1,
    0x1.700a7c5784634p-1,
    0x1.921fb54442d18p-1,
};

/// atan t for 0 <= t <= 1, within 2.28u of it (above).
inline double arctan_unit(double t) {
  const int k = static_cast<int>(8 * t + 0.5);
  const double c = 0.125 * k;
  const double z = (t - c) / (1 + t * c);
  const double w = z * z;
  const double h = -1.0 / 3 + w * (1.0 / 5 + w * (-1.0 / 7 + w * (1.0 / 9 + w * (-1.0 / 11))));
  return kAtanEighths[static_cast<unsigned>(k)] + (z + (z * w) * h);
}

/// atan2(num, den) in (-pi, pi] within kArctanError, signed zeros as std::atan2 takes
/// them. Precondition: num and den finite, not both zero.
inline double arctan2(double num, double den) {
  constexpr double kHalfPi = 0x1.921fb54442d18p+0;  // pi / 2 rounded to nearest
  constexpr double kPi = 0x1.921fb54442d18p+1;      // pi rounded to nearest
  const double y = std::abs(num), x = std::abs(den);
  const double a = y <= x ? arctan_unit(y / x) : kHalfPi - arctan_unit(x / y);
  const double r = den < 0 ? kPi - a : a;
  return std::copysign(r, num);
}

}  // namespace exactgeo::internal
