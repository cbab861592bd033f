#pragma once

// Counts in report text: "1 vertex", "8 vertices".

#include <cstddef>
#include <string>
#include <string_view>

namespace exactgeo::cli {

/// `count`, a space, then `singular` when count is 1, else `many`.
std::string plural(std::size_t count, std::string_view singular, std::string_view many);

}  // namespace exactgeo::cli
