#pragma once

// Single numbers from Python, exactly or not at all. A coordinate is a double: a value that
// is not exactly one (a 64-bit integer with more than 53 significant bits, a long double
// between two doubles, a Python int of any size) is refused by name, never rounded.

#include <pybind11/pybind11.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>

namespace exactgeo::python {

namespace py = pybind11;

/// Whether a 64-bit integer is exactly a double: its binary digits from the highest 1 to
/// the lowest 1 fit the 53-bit significand (2^53 + 1 does not, 2^60 + 2^8 does). The
/// exponent range is never the limit: it reaches far beyond 2^64.
constexpr bool exactly_double(std::uint64_t value) {
  constexpr int kSignificandBits = std::numeric_limits<double>::digits;
  return value <= std::uint64_t{1} << kSignificandBits ||
         static_cast<int>(std::bit_width(value)) - std::countr_zero(value) <= kSignificandBits;
}

constexpr bool exactly_double(std::int64_t value) {
  // The magnitude in unsigned arithmetic, where -2^63 has one.
  const auto bits = static_cast<std::uint64_t>(value);
  return exactly_double(value < 0 ? 0 - bits : bits);
}

/// Whether a finite long double is exactly a double: inside the double range (converting a
/// value beyond it is undefined behaviour) and unchanged by the round trip through double.
bool exactly_double(long double value);

/// Where a number sits in its argument, for messages: the argument's name and the row (the
/// index along the first axis).
struct Where {
  std::string_view name;
  std::size_t row;

  /// "points[3]"
  std::string text() const;
};

/// Throws ValueError "points[3] has a non-finite coordinate (nan)".
[[noreturn]] void refuse_non_finite(const Where& where, const std::string& value);

/// Throws ValueError "points[3] has a coordinate that is not exactly a double: ..." for an
/// integer, with the rule and the way out (rounding it first).
[[noreturn]] void refuse_inexact_integer(const Where& where, const std::string& value);

/// A coordinate as a double. Throws ValueError naming the row for a NaN or an infinity, and
/// for a value that is not exactly a double. (Inline: called once per element of an array.)
inline double coordinate(double value, const Where& where) {
  if (!std::isfinite(value)) [[unlikely]]
    refuse_non_finite(where, std::to_string(value));
  return value;
}

template <typename Integer>
requires std::is_same_v<Integer, std::int64_t> || std::is_same_v<Integer, std::uint64_t>
inline double coordinate(Integer value, const Where& where) {
  if (!exactly_double(value)) [[unlikely]]
    refuse_inexact_integer(where, std::to_string(value));
  return static_cast<double>(value);
}

double coordinate(long double value, const Where& where);

/// The same for a Python object: an int, a float, or a NumPy number (a scalar or a 0-d
/// array) of an integer or floating dtype, each read as what it is. Anything else (a bool,
/// a complex, a string, a Fraction, a Decimal) is a TypeError naming the row.
double coordinate(py::handle value, const Where& where);

}  // namespace exactgeo::python
