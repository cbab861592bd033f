#include "exactgeo/remesh/operations.hpp"

#include <memory>

#include "pass_workspace.hpp"

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

PassWorkspace::PassWorkspace() = default;
PassWorkspace::~PassWorkspace() = default;
PassWorkspace::PassWorkspace(PassWorkspace&&) noexcept = default;
PassWorkspace& PassWorkspace::operator=(PassWorkspace&&) noexcept = default;

PassWorkspace::Arrays& PassWorkspace::arrays() {
  if (!arrays_) arrays_ = std::make_unique<Arrays>();
  return *arrays_;
}

}  // namespace exactgeo::remesh
