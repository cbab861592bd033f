#include "exactgeo/remesh/operations.hpp"

namespace exactgeo::remesh {

std::string_view to_string(Verdict v) noexcept {
  switch (v) {
    case Verdict::applied:
      return "applied";
    case Verdict::refused_topology:
      return "refused (topology)";
    case Verdict::refused_collision:
      return "refused (collision)";
    case Verdict::deferred:
      return "deferred";
  }
  return "?";
}

}  // namespace exactgeo::remesh
