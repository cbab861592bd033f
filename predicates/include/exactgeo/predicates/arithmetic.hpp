#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace exactgeo {

/// Which arithmetic evaluates a predicate. Only `exact` is what exactgeo promises; the
/// other two exist to measure the trade: `plain_double` runs the same algorithm with
/// every sign taken from a plain double evaluation (fast, sometimes wrong), `rational`
/// runs it with every sign computed in GMP rationals (exact, slow: the reference).
///
/// ccd::Method (exactgeo/ccd/ccd.hpp) is these arithmetics applied to the CCD algorithms,
/// plus the baselines (its comment says which is which): the names the two share
/// ("exact", "double", "rational") name the same arithmetic, and their to_string and parse
/// have one shape.
enum class Arithmetic : std::uint8_t { exact, plain_double, rational };

/// The name of every enumerator: "exact", "double" or "rational" (the command line's and
/// Python's spelling); "?" for a value that is no enumerator.
std::string_view to_string(Arithmetic a) noexcept;
/// The arithmetic whose name (to_string) is exactly `name`; nullopt for any other string.
std::optional<Arithmetic> parse_arithmetic(std::string_view name) noexcept;

}  // namespace exactgeo
