#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace exactgeo {

/// Which arithmetic evaluates a predicate. Only `exact` is what exactgeo promises; the
/// other two exist to measure the trade: `plain_double` runs the same algorithm with
/// every sign taken from a plain double evaluation (fast, sometimes wrong), `rational`
/// runs it with every sign computed in GMP rationals (exact, slow: the reference).
enum class Arithmetic : std::uint8_t { exact, plain_double, rational };

std::string_view to_string(Arithmetic a) noexcept;
/// Parses "exact", "double" or "rational".
std::optional<Arithmetic> parse_arithmetic(std::string_view name) noexcept;

}  // namespace exactgeo
