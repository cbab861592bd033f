#include "exactgeo/ccd/result.hpp"

namespace exactgeo::ccd {

std::string_view to_string(DecidedBy s) noexcept {
  switch (s) {
    case DecidedBy::culled:
      return "culled";
    case DecidedBy::parity:
      return "parity";
    case DecidedBy::subdivision:
      return "subdivision";
    case DecidedBy::depth_limit:
      return "depth_limit";
    case DecidedBy::cubic:
      return "cubic";
    case DecidedBy::polynomials:
      return "polynomials";
    case DecidedBy::separation:
      return "separation";
    case DecidedBy::separation_roots:
      return "separation_roots";
    case DecidedBy::box_test:
      return "box_test";
  }
  return "?";
}

}  // namespace exactgeo::ccd
