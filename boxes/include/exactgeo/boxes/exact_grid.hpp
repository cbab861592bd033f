#pragma once

// The pairs of groups of points whose exact boxes (ExactBox: the least and greatest of
// their coordinates, closed) meet, for a few groups against many: the few binned in a
// uniform grid over their own box, and each of the many looked up in the cells its box
// covers. No float box is made (no rounding of each point outward) and no tree is built;
// the overlap is decided on the exact boxes, so the pairs are exactly those whose exact
// boxes meet, each once.
//
// Why every such pair is found, and once. A point's cell along an axis is a non-decreasing
// function of its coordinate (GridAxis::cell). Two boxes that meet share, along each axis,
// the coordinate m = max(lower_a, lower_b) <= min(upper_a, upper_b); its cell, max of the
// two lower cells (a non-decreasing function takes a maximum to a maximum), lies in both
// boxes' cell ranges. So the cell (along the three axes) of the meeting boxes' lower
// corner holds the few group and is looked up for the many one; the pair is reported
// there only, where the cell is the maximum of the two lower cells.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "exactgeo/boxes/exact_box.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::boxes {

/// One axis of a grid: `count` cells over [lower, upper].
class GridAxis {
 public:
  GridAxis() = default;
  GridAxis(double lower, double upper, std::uint32_t count) noexcept : origin_(lower) {
    const double per_cell = count / (upper - lower);
    // A span of zero, or one that overflows, or one cell: a single cell, every x in it.
    if (count > 1 && std::isfinite(per_cell) && per_cell > 0.0) {
      per_cell_ = per_cell;
      last_ = count - 1;
    }
  }

  /// x's cell, non-decreasing in x: x - origin rounds monotonically (a correctly rounded
  /// difference with a constant keeps the order of its exact values), and so does its
  /// product with per_cell_ > 0 (finite; an overflow to an infinity keeps its side), and
  /// the truncation of t > 0 clamped to last_ is non-decreasing. t is then no NaN: x is
  /// finite (a group's coordinate), so x - origin is finite or infinite. With one cell,
  /// per_cell_ is 0 and every x goes to cell 0 (t is 0, or NaN for an infinite
  /// difference: not above 0 either way).
  std::uint32_t cell(double x) const noexcept {
    const double t = (x - origin_) * per_cell_;
    if (!(t > 0.0)) return 0;
    if (t >= last_) return last_;
    return static_cast<std::uint32_t>(t);
  }
  std::uint32_t count() const noexcept { return last_ + 1; }

 private:
  double origin_ = 0.0;
  double per_cell_ = 0.0;
  std::uint32_t last_ = 0;
};

/// The memory of overlapping_groups_by_grid, kept by a caller that asks many times (every
/// member is filled anew before it is read).
struct GridScratch {
  std::vector<ExactBox> boxes;                         ///< of the few groups
  std::vector<std::array<std::uint32_t, 3>> low_cell;  ///< of the few groups' lower corners
  std::vector<std::uint32_t> first;                    ///< per cell: where its groups start
  std::vector<std::uint32_t> members;                  ///< the few groups, bucketed by cell
  std::vector<std::uint8_t> beyond;                    ///< per point: outside the grid's box
};

/// The exact box of a group of points.
template <std::size_t N>
ExactBox exact_box_of(std::span<const Point3> points, const std::array<VertexIndex, N>& g) {
  ExactBox box = ExactBox::of(points[g[0]]);
  for (std::size_t c = 1; c < N; ++c)
    box.add(points[g[c]]);
  return box;
}

/// visit(i, j) for every group i of `a` (the few, indices into `points_a`) and j of `b`
/// (the many, indices into `points_b`) whose exact boxes meet, each pair once, in the
/// order of j (the header says why every pair is found, once). Points finite.
/// `cells_per_group`: about how many cells the grid has per group of `a` (a choice of cost
/// only). The few may have points of their own (a pass's regions, with their new points),
/// so that the many's (a surface's vertices) need not be copied to append them.
template <std::size_t NA, std::size_t NB, class Visit>
void overlapping_groups_by_grid(std::span<const Point3> points_a,
                                std::span<const std::array<VertexIndex, NA>> a,
                                std::span<const Point3> points_b,
                                std::span<const std::array<VertexIndex, NB>> b, Visit&& visit,
                                GridScratch& scratch, double cells_per_group = 2.0) {
  if (a.empty() || b.empty()) return;
  const std::span<const Point3> points = points_b;
  std::vector<ExactBox>& boxes = scratch.boxes;
  boxes.resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    boxes[i] = exact_box_of<NA>(points_a, a[i]);
  ExactBox root = boxes[0];
  for (const ExactBox& box : boxes)
    root.add(box);
  // The cells: about cells_per_group per group, each about as wide along every axis (the
  // groups' mean largest side, where the grid's box allows; a choice of cost only).
  double mean_side = 0.0;
  for (const ExactBox& box : boxes) {
    double side = 0.0;
    for (int k = 0; k < 3; ++k)
      side = std::max(side, box.upper[k] - box.lower[k]);
    mean_side += side / static_cast<double>(boxes.size());
  }
  const double budget = cells_per_group * static_cast<double>(a.size()) + 1.0;
  std::array<double, 3> span{};
  for (int k = 0; k < 3; ++k)
    span[k] = root.upper[k] - root.lower[k];
  // Cells of about side w along each axis, w the larger of the mean side and the side of
  // a cube (a square, a segment, over the axes the box spans) of the box's volume per cell
  // of the budget, so that their count stays near the budget.
  double volume = 1.0;
  int spread = 0;  // the axes the box spans
  for (int k = 0; k < 3; ++k) {
    if (span[k] > 0.0) {
      volume *= span[k];
      ++spread;
    }
  }
  const double per_cell = spread == 0 ? 0.0 : std::pow(volume / budget, 1.0 / spread);
  const double side = std::max(mean_side, per_cell);
  std::array<std::uint32_t, 3> counts{};
  for (int k = 0; k < 3; ++k) {
    const double n = side > 0.0 ? std::clamp(span[k] / side, 1.0, 1024.0) : 1.0;
    counts[k] = std::isfinite(n) ? static_cast<std::uint32_t>(n) : 1u;
  }
  // At most a few times the budget (rounding of tiny sides can ask for many more).
  const auto cells = [&] { return static_cast<double>(counts[0]) * counts[1] * counts[2]; };
  while (cells() > 4.0 * budget + 64.0) {
    std::uint32_t& most = *std::max_element(counts.begin(), counts.end());
    most = (most + 1) / 2;
  }
  std::array<GridAxis, 3> axes;
  for (int k = 0; k < 3; ++k)
    axes[k] = GridAxis(root.lower[k], root.upper[k], counts[k]);
  const std::uint32_t nx = axes[0].count(), ny = axes[1].count(), nz = axes[2].count();
  const auto cell_index = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    return (static_cast<std::size_t>(z) * ny + y) * nx + x;
  };
  const auto cell_of = [&](const Point3& p) {
    return std::array<std::uint32_t, 3>{axes[0].cell(p[0]), axes[1].cell(p[1]), axes[2].cell(p[2])};
  };
  // The few groups, bucketed by the cells their boxes cover (a counting sort).
  std::vector<std::array<std::uint32_t, 3>>& low = scratch.low_cell;
  low.resize(a.size());
  std::vector<std::uint32_t>& first = scratch.first;
  first.assign(static_cast<std::size_t>(nx) * ny * nz + 1, 0);
  const auto for_cells = [&](const std::array<std::uint32_t, 3>& lo,
                             const std::array<std::uint32_t, 3>& hi, const auto& f) {
    for (std::uint32_t z = lo[2]; z <= hi[2]; ++z)
      for (std::uint32_t y = lo[1]; y <= hi[1]; ++y)
        for (std::uint32_t x = lo[0]; x <= hi[0]; ++x)
          f(x, y, z);
  };
  for (std::size_t i = 0; i < a.size(); ++i) {
    low[i] = cell_of(boxes[i].lower);
    for_cells(low[i], cell_of(boxes[i].upper),
              [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
                ++first[cell_index(x, y, z) + 1];
              });
  }
  for (std::size_t c = 1; c < first.size(); ++c)
    first[c] += first[c - 1];
  std::vector<std::uint32_t>& members = scratch.members;
  members.resize(first.back());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for_cells(low[i], cell_of(boxes[i].upper),
              [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
                members[first[cell_index(x, y, z)]++] = static_cast<std::uint32_t>(i);
              });
  }
  for (std::size_t c = first.size() - 1; c > 0; --c)  // the fill moved each start one cell on
    first[c] = first[c - 1];
  first[0] = 0;
  // Per point, the sides of the grid's box it lies strictly beyond: bit k below it along
  // axis k, bit 3 + k above it. A group of `b` whose points have a bit in common misses
  // the box, and so every group of `a`, and is passed over with no box made.
  std::vector<std::uint8_t>& beyond = scratch.beyond;
  beyond.resize(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    unsigned bits = 0;
    for (int k = 0; k < 3; ++k) {
      bits |= points[p][k] < root.lower[k] ? 1u << k : 0u;
      bits |= root.upper[k] < points[p][k] ? 8u << k : 0u;
    }
    beyond[p] = static_cast<std::uint8_t>(bits);
  }
  for (std::size_t j = 0; j < b.size(); ++j) {
    unsigned common = beyond[b[j][0]];
    for (std::size_t c = 1; c < NB; ++c)
      common &= beyond[b[j][c]];
    if (common != 0) continue;
    const ExactBox box = exact_box_of<NB>(points, b[j]);
    const std::array<std::uint32_t, 3> lo = cell_of(box.lower), hi = cell_of(box.upper);
    if (lo == hi) {  // one cell: each group in it met once
      const std::size_t c = cell_index(lo[0], lo[1], lo[2]);
      for (std::uint32_t m = first[c]; m < first[c + 1]; ++m) {
        if (boxes[members[m]].meets(box)) visit(static_cast<std::size_t>(members[m]), j);
      }
      continue;
    }
    for_cells(lo, hi, [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
      const std::size_t c = cell_index(x, y, z);
      for (std::uint32_t m = first[c]; m < first[c + 1]; ++m) {
        const std::uint32_t i = members[m];
        // Reported in the cell of the two lower corners' maximum only: once.
        if (x != std::max(lo[0], low[i][0]) || y != std::max(lo[1], low[i][1]) ||
            z != std::max(lo[2], low[i][2])) {
          continue;
        }
        if (boxes[i].meets(box)) visit(static_cast<std::size_t>(i), j);
      }
    });
  }
}

/// The same with the groups of `a` and `b` over one set of points.
template <std::size_t NA, std::size_t NB, class Visit>
void overlapping_groups_by_grid(std::span<const Point3> points,
                                std::span<const std::array<VertexIndex, NA>> a,
                                std::span<const std::array<VertexIndex, NB>> b, Visit&& visit,
                                GridScratch& scratch, double cells_per_group = 2.0) {
  overlapping_groups_by_grid<NA, NB>(points, a, points, b, std::forward<Visit>(visit), scratch,
                                     cells_per_group);
}

}  // namespace exactgeo::boxes
