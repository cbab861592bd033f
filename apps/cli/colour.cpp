#include "cli/colour.hpp"

#include <cstdio>

namespace exactgeo::cli {

std::string hex_colour(Rgb c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.red, c.green, c.blue);
  return text;
}

}  // namespace exactgeo::cli
