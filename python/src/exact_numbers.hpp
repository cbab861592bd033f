#pragma once

// Single numbers from Python, exactly or not at all. A coordinate is a double: a value that
// is not exactly one (a 64-bit integer with more than 53 significant bits, a long double
// between two doubles, a Python int of any size) is refused by name, never rounded. A vertex
// index is an integer: a float, a Fraction or a Decimal is refused whatever its value, never
// truncated, and an index out of range is reported as given, never wrapped.

#include <pybind11/pybind11.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "exactgeo/predicates/point.hpp"

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

/// Where a number sits, for messages: the argument's name and the row (the index along the
/// first axis) of an array, or an option's name alone (no row).
struct Where {
  std::string_view name;
  std::optional<std::size_t> row;

  /// "points[3]", or "min_separation"
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

/// The valid vertex indices of a faces argument, 0 <= index < end, and how a message says
/// so ("the vertices are 0..7").
struct IndexRange {
  std::uint64_t end;
  std::string text;
};

/// The indices of `vertex_count` vertices, or when that is not known, every index a vertex
/// can have (up to 2^32 - 2: 2^32 - 1 marks a missing corner).
IndexRange vertex_range(std::optional<std::uint64_t> vertex_count);

/// Throws ValueError "faces[0] has corner index 18446744073709551615, but the vertices are
/// 0..7": the index as it was given.
[[noreturn]] void refuse_corner(const Where& where, std::string_view given,
                                const IndexRange& range);

/// An integer corner index, checked against `range` exactly whatever its type (a uint64 of
/// 2^63 or more is itself, not a negative int64).
template <typename Integer>
VertexIndex corner_index(Integer value, const Where& where, const IndexRange& range) {
  if (std::cmp_less(value, 0) || std::cmp_greater_equal(value, range.end)) {
    refuse_corner(where, std::to_string(value), range);
  }
  return static_cast<VertexIndex>(value);
}

/// A corner index from a Python object: an int, a NumPy integer or anything else with
/// __index__, except a bool. A float (Python or NumPy, integral or not), a Fraction or a
/// Decimal is a ValueError naming the row and the value, never truncated.
VertexIndex corner_index(py::handle corner, const Where& where, const IndexRange& range);

/// A numeric option (min_separation=, toi_width=, ...) by the rules of a coordinate: an
/// int, a float or a NumPy number, finite and exactly a double (2**53 + 1 is refused, not
/// rounded); a TypeError naming the option for anything else (a bool, a Fraction, a
/// Decimal, a string), a ValueError for a value that is not finite or not a double. Range
/// checks are the caller's.
double option_number(py::handle value, std::string_view name);

/// An integer from a Python object (a vertex count), by the rules of corner_index: a
/// TypeError for what is not an integer, a ValueError outside 0..`largest`.
std::uint64_t count_of(py::handle value, std::string_view name, std::uint64_t largest);

}  // namespace exactgeo::python
