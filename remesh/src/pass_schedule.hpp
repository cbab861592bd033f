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
#include <cstdint>
#include <span>
#include <vector>

#include "exactgeo/remesh/swept_region.hpp"

namespace exactgeo::remesh::internal {

/// What an operation of a pass asks of the others: the vertices it changes or whose
/// neighbourhood its plan read, and the regions it sweeps (none when nothing moves). A
/// region is the closed hull of its four corners (go_ahead), or its box (BoxSchedule).
struct Footprint {
  std::vector<VertexIndex> vertices;
  std::vector<std::array<RegionCorner, 4>> regions;
};

/// The schedule of a pass whose regions are taken as boxes (a pass of collapses, whose
/// regions are the swept boxes of its moving triangles: their hulls may be flat or
/// degenerate, and the boxes ask nothing of the corners), made one operation at a time
/// as the pass is planned: an operation goes ahead when it shares
/// no vertex with one going ahead and none of its regions' boxes meets one of theirs
/// (exact boxes of the regions' corners, touching counting). Each is checked against the
/// operations going ahead only, through the box around all of an operation's regions
/// first (two region boxes meet only inside both operations' boxes): a remesher proposes
/// thousands of collapses in a pass and applies tens.
class BoxSchedule {
 public:
  explicit BoxSchedule(std::size_t vertex_count) : taken_(vertex_count, 0) {}

  /// Whether v is a vertex of an operation going ahead.
  bool taken(VertexIndex v) const { return taken_[v] != 0; }
  /// Whether `operation` goes ahead (then it is taken: later ones are checked against it).
  bool take(const Footprint& operation);

 private:
  struct Box {
    Point3 lower{}, upper{};
  };
  static Box box_of(const std::array<RegionCorner, 4>& region) noexcept;
  static Box united(Box a, const Box& b) noexcept;
  static bool overlap(const Box& a, const Box& b) noexcept;

  std::vector<std::uint8_t> taken_;    ///< a byte per vertex: asked for every vertex around
                                       ///< each proposed collapse's ends
  std::vector<Box> going_;             ///< the box around each one's regions
  std::vector<std::size_t> first_{0};  ///< going_[g]'s region boxes: [first_[g], first_[g+1])
  std::vector<Box> region_;            ///< their regions' boxes
  std::vector<Box> own_;               ///< take's: the operation's region boxes
};

/// For each operation in order, whether it goes ahead: not when it shares a vertex with an
/// earlier one that goes ahead, or when one of its regions meets one of that one's
/// (regions_meet, for the pairs whose boxes a box tree finds overlapping). The
/// others wait for the next pass. `points` are the surface's vertices (a region's corners
/// index them).
std::vector<bool> go_ahead(std::span<const Footprint> operations, std::span<const Point3> points);

/// go_ahead for operations of at most four vertices and no regions (a flip's corners, a
/// split's edge and opposite corners; kNoVertex for none), with no vector per operation:
/// whether each shares no vertex with an earlier one that goes ahead.
std::vector<bool> share_no_vertex(std::span<const std::array<VertexIndex, 4>> operations,
                                  std::size_t vertex_count);

}  // namespace exactgeo::remesh::internal
