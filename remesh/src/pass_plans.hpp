#pragma once

// The plans of a pass's operations (split.cpp, flip.cpp, collapse.cpp), in a header of
// their own so that a PassWorkspace (pass_workspace.hpp) can keep their arrays.

#include <array>
#include <cstddef>
#include <span>

#include "exactgeo/remesh/operations.hpp"
#include "operation_checks.hpp"

namespace exactgeo::remesh::internal {

/// A split: the edge's triangles, and once its geometry is checked the regions it sweeps
/// (none when the new vertex lies exactly on the edge, else one per triangle of the edge)
/// with their partners, held in place (a pass plans thousands).
struct SplitPlan {
  VertexIndex a = 0;
  VertexIndex b = 0;
  Point3 at{};
  EdgeTrianglesOfOne on_edge;
  std::array<std::array<RegionCorner, 4>, 2> region_storage{};
  std::array<VertexIndex, 2> partner_storage{};  ///< per region: the other side's corner
  std::size_t region_count = 0;

  void add_region(const std::array<RegionCorner, 4>& region, VertexIndex partner) noexcept {
    region_storage[region_count] = region;
    partner_storage[region_count] = partner;
    ++region_count;
  }
  std::span<const std::array<RegionCorner, 4>> regions() const noexcept {
    return std::span(region_storage).first(region_count);
  }
  std::span<const VertexIndex> partners() const noexcept {
    return std::span(partner_storage).first(region_count);
  }
};

/// A flip that passed its topology checks: its triangles, their replacements, the region
/// it sweeps (a, b, c, d).
struct FlipPlan {
  VertexIndex a = 0;
  VertexIndex b = 0;
  std::size_t t1 = 0;  ///< walks a -> b
  std::size_t t2 = 0;  ///< walks b -> a
  Triangle new1{};     ///< c a d
  Triangle new2{};     ///< d b c
  std::array<RegionCorner, 4> region{};
};

/// A collapse that passed its topology checks.
struct CollapsePlan {
  VertexIndex a = 0;
  VertexIndex b = 0;
  Point3 to{};
  EdgeTrianglesOfOne on_edge;  ///< the edge's triangles, removed
};

}  // namespace exactgeo::remesh::internal
