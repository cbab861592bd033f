#include "exactgeo/remesh/operations.hpp"

#include <algorithm>
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

std::size_t TriangleChanges::index_after(std::size_t t) const noexcept {
  const auto below = std::partition_point(removed.begin(), removed.end(),
                                          [t](const Was& r) { return r.triangle < t; });
  return t - static_cast<std::size_t>(below - removed.begin());
}

void TriangleChanges::reset(std::size_t triangles) noexcept {
  triangles_before = triangles;
  removed.clear();
  rewritten.clear();
  moved.clear();
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
