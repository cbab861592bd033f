#pragma once

// Certified space cells: a uniform grid over the mesh's box in which every cell that no
// face can reach carries the label of all of its points, so that most points of a uniform
// query set need a lookup instead of a ray.
//
// Why a cell's label is certified. Each face lies in the convex hull of its corners,
// hence in the box of its corners. A closed cell box that meets no face's corner box is
// disjoint from the surface; it is convex, so connected, and the winding number (of a
// closed oriented surface; the crossing parity of any closed one) is constant on every
// connected set that misses the surface. Two such cells that share a closed facet form a
// connected set missing the surface too, so a whole face-connected component of them has
// one winding number: it is found once, by the exact classifier at one point of one of its
// cells. A cell holds a one-byte code: unknown, surface, margin, or an index into the few
// distinct winding numbers the components have (beyond 253 distinct ones, which no real
// mesh has, further components stay "surface" and their points cast rays: still exact).
//
// No rounding enters. The grid's planes are any doubles b_0 <= b_1 <= ... <= b_n per
// axis, with b_0 and b_n the box's own bounds; cell k is the closed interval
// [b_k, b_k+1]. A face marks every cell whose closed box meets its corners' box, found by
// comparing doubles with doubles (exact). A point finds a cell containing it the same way:
// a multiplication proposes an index, exact comparisons confirm it (or a binary search finds
// it). A point on a plane between two cells lies in both closed cells, and either one's
// label is right for it.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "exactgeo/inside/internal/grid_axis.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::inside::internal {

class SpaceCells {
 public:
  /// The exact winding number of a point that lies on no face (for a closed surface that
  /// is not oriented, a signed crossing count whose parity is the crossing parity);
  /// nullopt would say the point is on a face.
  using ExactWinding = std::function<std::optional<std::int64_t>(const Point3&)>;

  /// The grid over `box` (the mesh's bounding box) with about cell_count(faces,
  /// expected_points) cells, shaped like the box; `winding` is called once per component of
  /// cells no face reaches.
  SpaceCells(const mesh::Mesh& mesh, const mesh::Box& box, const ExactWinding& winding,
             std::optional<std::size_t> expected_points = std::nullopt);

  /// How many cells to aim for: kCellsPerFace per face, between kMinCells and kMaxCells;
  /// and where the number of points to classify is known, at most kCellsPerPoint per point
  /// (but kMinCellsForFewPoints at least). A cell costs its build about what a point costs
  /// its lookup, and a point saves a ray only where its cell is free of faces: a grid much
  /// finer than the points are many is built and never read.
  static std::size_t cell_count(std::size_t faces, std::optional<std::size_t> expected_points);

  /// The winding number of every point of a cell containing `p`, or nullopt when a face
  /// may reach that cell (cast a ray). Precondition: p in the closed box.
  std::optional<std::int64_t> lookup(const Point3& p) const noexcept {
    const Code code =
        codes_[index(axes_[0].cell_of(p[0]), axes_[1].cell_of(p[1]), axes_[2].cell_of(p[2]))];
    if (code < kFirstWinding) return std::nullopt;
    return windings_[code - kFirstWinding];
  }

  std::array<std::size_t, 3> resolution() const noexcept {
    return {axes_[0].cells(), axes_[1].cells(), axes_[2].cells()};
  }
  std::size_t cells() const noexcept {
    return axes_[0].cells() * axes_[1].cells() * axes_[2].cells();
  }
  /// Cells some face reaches.
  std::size_t surface_cells() const noexcept { return surface_cells_; }
  /// Connected components of the other cells (one exact label each).
  std::size_t components() const noexcept { return components_; }
  /// The grid's planes on `axis`: b_0 (the box's lower bound) to b_n (its upper bound).
  const std::vector<double>& planes(int axis) const noexcept { return axes_[axis].planes(); }

  static constexpr std::size_t kCellsPerFace = 16;
  static constexpr std::size_t kMinCells = std::size_t{1} << 18;  // 64^3
  static constexpr std::size_t kMaxCells = std::size_t{1} << 21;  // 128^3
  static constexpr std::size_t kCellsPerPoint = 2;
  static constexpr std::size_t kMinCellsForFewPoints = std::size_t{1} << 12;  // 16^3

 private:
  /// A cell's code. `kMargin`: a layer of cells around the grid, so that the flood fill
  /// needs no bounds checks (and no divisions to find them); never looked up.
  /// kFirstWinding + i: the winding number windings_[i].
  using Code = std::uint8_t;
  static constexpr Code kUnknown = 0, kSurface = 1, kMargin = 2, kFirstWinding = 3;
  static constexpr std::size_t kMaxWindings = 256 - kFirstWinding;

  /// Cells per axis with the margin.
  std::size_t padded(int axis) const noexcept { return axes_[axis].cells() + 2; }
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const noexcept {
    return ((k + 1) * padded(1) + (j + 1)) * padded(0) + (i + 1);
  }
  void mark_faces(const mesh::Mesh& mesh);
  void label_components(const ExactWinding& winding);
  /// The code of a component of winding number w, or kSurface when all codes are taken.
  Code code_of(std::int64_t w);

  std::array<GridAxis, 3> axes_;
  std::vector<Code> codes_;
  std::vector<std::int64_t> windings_;  ///< the components' distinct winding numbers
  std::size_t surface_cells_ = 0;
  std::size_t components_ = 0;
};

}  // namespace exactgeo::inside::internal
