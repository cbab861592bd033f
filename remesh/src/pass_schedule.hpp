#pragma once

// Which operations of a pass go ahead together. Each is planned, and checked, on the
// surface as it is before the pass; several can then be made at once when none can see
// what another makes. That holds for two operations that share no vertex and whose swept
// regions are apart: what an operation makes lies in its region (a flip's and a split's
// new triangles are spanned by the region's corners), which the other's region does not
// reach, and what it removes the other did not count on (it was no element of the
// other's, sharing no vertex with it). So each is checked, and made, as if alone on the
// surface before the pass, and the pass agrees with the operations one by one on every
// operation it does not defer.
//
// A pass of collapses is checked as one motion (collapse.cpp); there the regions are the
// boxes each moving triangle sweeps, so that no moving triangle of one collapse comes near
// a triangle of another, moving or standing, and each collapse meets in the pass what it
// meets alone.
//
// Shared vertices and meeting regions are a finer test than one box around each
// operation's triangles, which on a curved sheet overlap for operations far apart along it.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "exactgeo/remesh/swept_region.hpp"

namespace exactgeo::remesh::internal {

/// What an operation of a pass asks of the others: the vertices it changes or whose
/// neighbourhood its plan read, and the regions it sweeps (none when nothing moves). A
/// region is the closed hull of its four corners; `by_boxes` takes each region's box
/// instead (the swept box of a collapse's moving triangle, whose hull may be flat or
/// degenerate: a coarser test that asks nothing of the corners).
struct Footprint {
  std::vector<VertexIndex> vertices;
  std::vector<std::array<RegionCorner, 4>> regions;
  bool by_boxes = false;
};

/// For each operation in order, whether it goes ahead: not when it shares a vertex with an
/// earlier one that goes ahead, or when one of its regions meets one of that one's
/// (regions_meet, for the pairs whose boxes a box tree finds overlapping; the boxes alone
/// when either footprint is by_boxes; when every one is, each operation is checked in
/// order against the boxes of those going ahead, not by a tree of every region). The
/// others wait for the next pass. `points` are the surface's vertices (a region's corners
/// index them).
std::vector<bool> go_ahead(std::span<const Footprint> operations, std::span<const Point3> points);

/// go_ahead for operations of at most four vertices and no regions (a flip's corners, a
/// split's edge and opposite corners; kNoVertex for none), with no vector per operation:
/// whether each shares no vertex with an earlier one that goes ahead.
std::vector<bool> share_no_vertex(std::span<const std::array<VertexIndex, 4>> operations,
                                  std::size_t vertex_count);

}  // namespace exactgeo::remesh::internal
