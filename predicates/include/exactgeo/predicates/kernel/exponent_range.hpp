#pragma once

// When is expansion arithmetic exact, and how to make it so by scaling.
//
// Expansion arithmetic (error-free sums and products) is exact as long as nothing
// overflows and no product underflows. For a homogeneous polynomial of degree D in the
// inputs this is a condition on the inputs' exponents only:
//
//  * grain. Every nonzero input is an integer multiple of 2^grain, where grain is the
//    exponent of its last significant bit (at least ilogb(x) - 52, at least -1074). Then
//    every component of every partial result of degree k is a nonzero multiple of
//    2^(k grain), so a product of two components has exponents summing to at least
//    D grain. Dekker's TwoProduct is exact when that sum is at least e_min + p - 1 =
//    -1022 + 53 - 1 = -970 (Boldo, "Pitfalls of a full floating-point proof", IJCAR 2006);
//    we ask for -969, one binade of margin.
//  * top. Every input is below 2^top in magnitude, differences below 2^(top+1), and a
//    degree-D result with at most 2^kHeadroomBits terms' worth of growth below
//    2^(D (top + 1) + kHeadroomBits). Dekker's split needs every value below 2^996.
//
// Multiplying every input by 2^s (exact, given the same bounds) multiplies a homogeneous
// polynomial by 2^(D s) and keeps its sign. So if some s satisfies both conditions, the
// exact stage scales by it; if none does (inputs spanning more than about 1950 / D
// binades), the expansion stage leaves the sign undecided and the rational stage decides.

#include <algorithm>
#include <bit>
#include <climits>
#include <cstdint>
#include <optional>

namespace exactgeo::kernel {

class ExponentRange {
 public:
  static constexpr int kHeadroomBits = 16;

  [[gnu::always_inline]] void include(double x) noexcept {
    if (x == 0.0) return;
    // The biased exponent field, read from the bits (std::ilogb is a library call).
    const auto field = static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
    if (field == 0) {  // subnormal: below 2^-1022, a multiple of 2^-1074
      top_ = std::max(top_, -1022);
      grain_ = -1074;
    } else {  // 2^e <= |x| < 2^(e+1), a multiple of 2^(e-52)
      const int e = field - 1023;
      top_ = std::max(top_, e + 1);
      grain_ = std::min(grain_, e - 52);
    }
    nonzero_ = true;
  }

  /// The power of two to scale every input by so that a degree-`degree` polynomial is
  /// evaluated exactly with expansions (0 when no scaling is needed), or nullopt when no
  /// power of two works.
  std::optional<int> exact_scaling(int degree) const noexcept {
    if (!nonzero_) return 0;
    // degree * (grain + s) >= -969
    const int lowest = ceil_div(-969, degree) - grain_;
    // degree * (top + 1 + s) + kHeadroomBits <= 995
    const int highest = (995 - kHeadroomBits) / degree - top_ - 1;
    if (lowest > highest) return std::nullopt;
    return std::clamp(0, lowest, highest);
  }

 private:
  static constexpr int ceil_div(int a, int b) noexcept { return -((-a) / b); }  // b > 0, a <= 0

  int top_ = INT_MIN / 4;
  int grain_ = INT_MAX / 4;
  bool nonzero_ = false;
};

}  // namespace exactgeo::kernel
