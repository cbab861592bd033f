#pragma once

// Where a point lies with respect to a mesh: the answer of every point-in-volume
// classifier, exact (classifier.hpp) or not (float_ray_parity.hpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace exactgeo::inside {

/// undecided: an open surface whose generalized winding number no precision the
/// classifier allows can compare with the rule's level (internal/open_label.hpp).
enum class Location : std::uint8_t { outside, inside, boundary, undecided };
std::string_view to_string(Location location) noexcept;
/// The location to_string names so; nullopt for any other word.
std::optional<Location> location_named(std::string_view word) noexcept;

/// How many points got each location.
class LocationCounts {
 public:
  void add(Location location) noexcept { ++counts_[static_cast<std::size_t>(location)]; }
  std::size_t operator[](Location location) const noexcept {
    return counts_[static_cast<std::size_t>(location)];
  }

 private:
  std::array<std::size_t, 4> counts_{};
};

}  // namespace exactgeo::inside
