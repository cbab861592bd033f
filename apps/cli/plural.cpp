#include "cli/plural.hpp"

namespace exactgeo::cli {

std::string plural(std::size_t count, std::string_view singular, std::string_view many) {
  std::string s = std::to_string(count);
  s.append(" ");
  s.append(count == 1 ? singular : many);
  return s;
}

}  // namespace exactgeo::cli
