#include "exactgeo/inside/location.hpp"

namespace exactgeo::inside {

std::string_view to_string(Location location) noexcept {
  switch (location) {
    case Location::outside:
      return "outside";
    case Location::inside:
      return "inside";
    case Location::boundary:
      return "boundary";
    case Location::undecided:
      return "undecided";
  }
  return "?";
}

std::optional<Location> location_named(std::string_view word) noexcept {
  for (const Location l :
       {Location::outside, Location::inside, Location::boundary, Location::undecided}) {
    if (word == to_string(l)) return l;
  }
  return std::nullopt;
}

}  // namespace exactgeo::inside
