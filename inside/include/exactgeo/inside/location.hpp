#pragma once

// Where a point lies with respect to a closed mesh: the answer of every point-in-volume
// classifier, exact (classifier.hpp) or not (float_ray_parity.hpp).

#include <cstdint>
#include <string_view>

namespace exactgeo::inside {

enum class Location : std::uint8_t { outside, inside, boundary };
std::string_view to_string(Location location) noexcept;

}  // namespace exactgeo::inside
