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

}  // namespace exactgeo::inside::internal
