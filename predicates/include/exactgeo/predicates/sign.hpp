#pragma once

#include <cstdint>

namespace exactgeo {

/// The sign of an exactly evaluated quantity.
enum class Sign : std::int8_t { negative = -1, zero = 0, positive = 1 };

/// Sign of a double (branch-free). Precondition: `x` is not NaN.
constexpr Sign sign_of(double x) noexcept {
  return static_cast<Sign>((x > 0) - (x < 0));
}

constexpr Sign operator-(Sign s) noexcept {
  return static_cast<Sign>(-static_cast<int>(s));
}

/// Sign of a product from the signs of its factors.
constexpr Sign operator*(Sign a, Sign b) noexcept {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}

constexpr int to_int(Sign s) noexcept {
  return static_cast<int>(s);
}

}  // namespace exactgeo
