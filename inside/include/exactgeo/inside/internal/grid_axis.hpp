#pragma once

// One axis of a grid of closed cells over a box (the certified space cells of
// space_cells.hpp and open_space_cells.hpp): planes b_0 <= b_1 <= ... <= b_n, any
// nondecreasing doubles with b_0 and b_n the box's own bounds; cell k is the closed
// interval [b_k, b_k+1]. A point finds a cell holding it by exact comparisons (a
// multiplication only proposes one), so no rounding enters: a point on a plane lies in
// both neighbouring closed cells, and either is right for it.

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/mesh/check.hpp"

namespace exactgeo::inside::internal {

class GridAxis {
 public:
  GridAxis() = default;
  GridAxis(double lower, double upper, std::size_t cells);
  std::size_t cells() const noexcept { return planes_.size() - 1; }
  /// A cell k with planes[k] <= x <= planes[k + 1]. Precondition: x in [lower, upper].
  /// Inline: it runs three times for every point.
  std::size_t cell_of(double x) const noexcept {
    const std::size_t n = cells();
    if (cells_per_unit_ > 0.0) {
      // A proposal, confirmed exactly below (x - lower_ is finite: the width is).
      const double g = (x - lower_) * cells_per_unit_;
      const std::size_t k = g < static_cast<double>(n) ? static_cast<std::size_t>(g) : n - 1;
      if (planes_[k] <= x && x <= planes_[k + 1]) return k;
    }
    // The last plane at or below x (planes_[0] = lower <= x), within the cells.
    const auto above = std::upper_bound(planes_.begin(), planes_.end(), x);
    return std::min(static_cast<std::size_t>(above - planes_.begin()) - 1, n - 1);
  }
  /// The cells whose closed interval meets [lo, hi] (lo <= hi): first and last.
  std::array<std::size_t, 2> cells_meeting(double lo, double hi) const noexcept;
  /// A point of cell k's closed interval.
  double point_in(std::size_t k) const noexcept;
  const std::vector<double>& planes() const noexcept { return planes_; }

 private:
  std::vector<double> planes_;
  double lower_ = 0.0;
  double cells_per_unit_ = 0.0;  // 0: no usable division, search only
};

/// Cells per axis: about `target` in all, in proportion to the box's extents. An extent
/// below 1/1024 of the largest counts as 1/1024, so that a flat box still gets a grid.
std::array<std::size_t, 3> grid_resolution(const mesh::Box& box, std::size_t target);

/// Calls visit(i, j, k) for every cell that a face's corner box meets (a face lies in the
/// hull of its corners, bilinear patches included), face by face: the cells a face may
/// reach, which neither kind of space cell may label.
template <class Visit>
void for_each_face_cell(const std::array<GridAxis, 3>& axes, const mesh::Mesh& mesh,
                        Visit&& visit) {
  for (const mesh::Face& face : mesh.faces) {
    const auto [lo, hi] = corner_box(mesh, face);
    const auto x = axes[0].cells_meeting(lo[0], hi[0]);
    const auto y = axes[1].cells_meeting(lo[1], hi[1]);
    const auto z = axes[2].cells_meeting(lo[2], hi[2]);
    for (std::size_t k = z[0]; k <= z[1]; ++k) {
      for (std::size_t j = y[0]; j <= y[1]; ++j) {
        for (std::size_t i = x[0]; i <= x[1]; ++i)
          visit(i, j, k);
      }
    }
  }
}

}  // namespace exactgeo::inside::internal
