#include "exactgeo/inside/internal/grid_axis.hpp"

#include <algorithm>
#include <cmath>

namespace exactgeo::inside::internal {

std::array<std::size_t, 3> grid_resolution(const mesh::Box& box, std::size_t target) {
  std::array<double, 3> extent{};
  for (int i = 0; i < 3; ++i)
    extent[i] = box.upper[i] / 2 - box.lower[i] / 2;  // halves: cannot overflow
  const double largest = std::max({extent[0], extent[1], extent[2]});
  if (!(largest > 0.0)) return {1, 1, 1};
  std::array<double, 3> relative{};
  for (int i = 0; i < 3; ++i)
    relative[i] = std::max(extent[i] / largest, 1.0 / 1024);
  const double scale =
      std::cbrt(static_cast<double>(target) / (relative[0] * relative[1] * relative[2]));
  std::array<std::size_t, 3> cells{};
  for (int i = 0; i < 3; ++i)
    cells[i] = static_cast<std::size_t>(std::clamp(std::llround(relative[i] * scale), 1LL, 1024LL));
  return cells;
}

GridAxis::GridAxis(double lower, double upper, std::size_t cells)
    : planes_(cells + 1), lower_(lower) {
  // Any nondecreasing planes from lower to upper make a valid grid; these are evenly
  // spaced up to rounding, and clamped so that rounding cannot break the order.
  const double width = upper - lower;  // infinite for a box wider than DBL_MAX
  planes_[0] = lower;
  for (std::size_t k = 1; k < cells; ++k) {
    const double t = static_cast<double>(k) / static_cast<double>(cells);
    const double x =
        std::isfinite(width) ? lower + width * t : 2 * (lower / 2 + (upper / 2 - lower / 2) * t);
    planes_[k] = std::clamp(x, planes_[k - 1], upper);
  }
  planes_[cells] = upper;
  const double per_unit = static_cast<double>(cells) / width;
  cells_per_unit_ = width > 0.0 && std::isfinite(per_unit) ? per_unit : 0.0;
}

std::array<std::size_t, 2> GridAxis::cells_meeting(double lo, double hi) const noexcept {
  const std::size_t n = cells();
  // First: the first cell whose upper plane is at or above lo.
  const auto first_plane = std::lower_bound(planes_.begin() + 1, planes_.end(), lo);
  const std::size_t first =
      std::min(static_cast<std::size_t>(first_plane - planes_.begin()) - 1, n - 1);
  // Last: the last cell whose lower plane is at or below hi.
  const auto above = std::upper_bound(planes_.begin(), planes_.end() - 1, hi);
  const auto last = static_cast<std::size_t>(above - planes_.begin());
  return {first, last == 0 ? 0 : last - 1};
}

double GridAxis::point_in(std::size_t k) const noexcept {
  // Halves: the sum could overflow. The clamp keeps the rounded midpoint in the cell.
  return std::clamp(planes_[k] / 2 + planes_[k + 1] / 2, planes_[k], planes_[k + 1]);
}

}  // namespace exactgeo::inside::internal
