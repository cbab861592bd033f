#pragma once

// What a PassWorkspace (operations.hpp) holds: the passes' arrays, each cleared or filled
// anew by the pass that uses it before it is read, so that nothing carries over from one
// pass to the next but storage.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "exactgeo/predicates/sign.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "pass_plans.hpp"
#include "region_points.hpp"

namespace exactgeo::remesh {

struct PassWorkspace::Arrays {
  /// split_edges', flip_edges' table of the edges of the triangles around the vertices
  /// `marked` (EdgeTriangles::assign_marked): those the pass's operations ask about.
  EdgeTriangles edges;
  std::vector<std::uint8_t> marked;  ///< per vertex: the edge table holds its triangles
  VertexTriangles around;  ///< a pass of collapses' table of the triangles around each vertex
  std::vector<internal::SplitPlan> split_plans;
  std::vector<internal::FlipPlan> flip_plans;
  std::vector<internal::CollapsePlan> collapse_plans;
  std::vector<std::size_t> operation_of_plan;           ///< per plan: its operation's index
  std::vector<std::array<VertexIndex, 4>> by_vertices;  ///< per plan: its vertices
  std::vector<std::size_t> candidates;                  ///< plans whose geometry passed
  std::vector<std::size_t> checked;                     ///< plans whose regions are checked
  std::vector<std::array<RegionCorner, 4>> regions;     ///< the checked plans' regions
  std::vector<VertexIndex> partners;                    ///< and their partners
  std::vector<Sign> volumes;                            ///< and their volumes' signs
  internal::RegionQuery region_query;                   ///< first_in_regions' arrays
};

/// The workspace's arrays, or `own`'s (a pass's own workspace) when the caller gave none.
inline PassWorkspace::Arrays& arrays_of(PassWorkspace* workspace, PassWorkspace& own) {
  return workspace != nullptr ? workspace->arrays() : own.arrays();
}

}  // namespace exactgeo::remesh
