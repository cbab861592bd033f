#pragma once

// An 8-bit RGB colour, as the pictures and the marked meshes use it.

#include <cstdint>
#include <string>

namespace exactgeo::cli {

struct Rgb {
  std::uint8_t red = 0;
  std::uint8_t green = 0;
  std::uint8_t blue = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

/// "#e6194b"
std::string hex_colour(Rgb colour);

}  // namespace exactgeo::cli
