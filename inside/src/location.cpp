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

}  // namespace exactgeo::inside
