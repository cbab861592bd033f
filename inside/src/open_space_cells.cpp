#include "exactgeo/inside/internal/open_space_cells.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

namespace exactgeo::inside::internal {
namespace {

/// Counts of cells some face reaches in every box [0, i) x [0, j) x [0, k) of cells, so
/// that a block's count takes eight lookups.
class SurfaceCounts {
 public:
  template <class IsSurface>
  SurfaceCounts(std::array<std::size_t, 3> n, const IsSurface& surface)
      : n_(n), sums_((n[0] + 1) * (n[1] + 1) * (n[2] + 1), 0) {
    for (std::size_t k = 0; k < n[2]; ++k) {
      for (std::size_t j = 0; j < n[1]; ++j) {
        for (std::size_t i = 0; i < n[0]; ++i) {
          const std::uint32_t own = surface((k * n[1] + j) * n[0] + i) ? 1 : 0;
          at(i + 1, j + 1, k + 1) = own + at(i, j + 1, k + 1) + at(i + 1, j, k + 1) +
                                    at(i + 1, j + 1, k) - at(i, j, k + 1) - at(i, j + 1, k) -
                                    at(i + 1, j, k) + at(i, j, k);
        }
      }
    }
  }
  /// Cells some face reaches in [f0, l0) x [f1, l1) x [f2, l2).
  std::uint32_t in(const std::array<std::size_t, 3>& f, const std::array<std::size_t, 3>& l) const {
    return get(l[0], l[1], l[2]) - get(f[0], l[1], l[2]) - get(l[0], f[1], l[2]) -
           get(l[0], l[1], f[2]) + get(f[0], f[1], l[2]) + get(f[0], l[1], f[2]) +
           get(l[0], f[1], f[2]) - get(f[0], f[1], f[2]);
  }

 private:
  std::uint32_t& at(std::size_t i, std::size_t j, std::size_t k) {
    return sums_[(k * (n_[1] + 1) + j) * (n_[0] + 1) + i];
  }
  std::uint32_t get(std::size_t i, std::size_t j, std::size_t k) const {
    return sums_[(k * (n_[1] + 1) + j) * (n_[0] + 1) + i];
  }
  std::array<std::size_t, 3> n_;
  std::vector<std::uint32_t> sums_;
};

}  // namespace

OpenSpaceCells::OpenSpaceCells(const mesh::Mesh& mesh, const mesh::Box& box, const BoxLabel& label,
                               std::size_t cells, std::optional<std::size_t> expected_points) {
  const auto n = grid_resolution(box, cells);
  for (int i = 0; i < 3; ++i)
    axes_[i] = GridAxis(box.lower[i], box.upper[i], n[i]);
  codes_.assign(n[0] * n[1] * n[2], CellCode::unknown);
  mark_faces(mesh);
  // Cells per point from the points expected; without them, as if a costly try paid
  // with one cell, and a bound's failure cost nothing (the cap bounds those).
  const double cells_per_point = expected_points
                                     ? static_cast<double>(codes_.size()) /
                                           std::max(1.0, static_cast<double>(*expected_points))
                                     : 1.0 / kTryCost;
  const double bound_try_cost = expected_points ? kBoundTryCost : 0.0;
  if (surface_cells_ < codes_.size()) label_blocks(label, cells_per_point, bound_try_cost);
}

void OpenSpaceCells::mark_faces(const mesh::Mesh& mesh) {
  for_each_face_cell(axes_, mesh, [&](std::size_t i, std::size_t j, std::size_t k) {
    codes_[index(i, j, k)] = CellCode::surface;
  });
  surface_cells_ =
      static_cast<std::size_t>(std::count(codes_.begin(), codes_.end(), CellCode::surface));
}

void OpenSpaceCells::label_blocks(const BoxLabel& label, double cells_per_point,
                                  double bound_try_cost) {
  const std::array<std::size_t, 3> n = resolution();
  const SurfaceCounts surface(n,
                              [&](std::size_t cell) { return codes_[cell] == CellCode::surface; });
  // Blocks of the grid, halved on every axis until a block free of faces takes a label
  // or is one cell; the largest first (a queue), until kTriesPerCell of the cells' count
  // have been tried.
  std::deque<Block> queue{{{0, 0, 0}, n}};
  const auto most_tries = static_cast<std::size_t>(kTriesPerCell * static_cast<double>(cells()));
  // The window: what its tries cost, in points' rays and terms, and what they labelled.
  double window_cost = 0.0;
  std::size_t labelled_before_window = 0;
  while (!queue.empty() && boxes_tried_ < most_tries) {
    const Block b = queue.front();
    queue.pop_front();
    const std::array<std::size_t, 3> size{b.last[0] - b.first[0], b.last[1] - b.first[1],
                                          b.last[2] - b.first[2]};
    const bool one_cell = size[0] == 1 && size[1] == 1 && size[2] == 1;
    const bool small = size[0] <= 2 && size[1] <= 2 && size[2] <= 2;
    const std::uint32_t faces = surface.in(b.first, b.last);
    if (faces == size[0] * size[1] * size[2]) continue;  // no cell free of faces
    if (faces == 0) {
      const Point3 lower{planes(0)[b.first[0]], planes(1)[b.first[1]], planes(2)[b.first[2]]};
      const Point3 upper{planes(0)[b.last[0]], planes(1)[b.last[1]], planes(2)[b.last[2]]};
      ++boxes_tried_;
      const BoxAnswer answer = label(lower, upper);
      const std::size_t labelled_before = labelled_cells_;
      if (const std::optional<Location> known = answer.label) {
        const CellCode code = *known == Location::inside ? CellCode::inside : CellCode::outside;
        for (std::size_t k = b.first[2]; k < b.last[2]; ++k) {
          for (std::size_t j = b.first[1]; j < b.last[1]; ++j) {
            for (std::size_t i = b.first[0]; i < b.last[0]; ++i)
              codes_[index(i, j, k)] = code;
          }
        }
        labelled_cells_ += size[0] * size[1] * size[2];
      }
      // The window: stop where its cells hold fewer points than its tries cost.
      window_cost += answer.costly ? kTryCost : bound_try_cost;
      if (window_cost >= kWindowCost) {
        const auto labelled = static_cast<double>(labelled_cells_ - labelled_before_window);
        if (labelled < cells_per_point * window_cost) break;
        window_cost = 0.0;
        labelled_before_window = labelled_cells_;
      }
      if (labelled_cells_ > labelled_before || (!answer.try_parts && small)) continue;
    }
    if (one_cell) continue;
    // The eight (or fewer) halves.
    std::array<std::array<std::size_t, 3>, 3> cuts{};  // first, middle, last per axis
    for (int a = 0; a < 3; ++a)
      cuts[a] = {b.first[a], b.first[a] + (b.last[a] - b.first[a] + 1) / 2, b.last[a]};
    for (int z = 0; z < 2; ++z) {
      for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 2; ++x) {
          const std::array<int, 3> side{x, y, z};
          Block part;
          for (int a = 0; a < 3; ++a) {
            part.first[a] = cuts[a][side[a]];
            part.last[a] = cuts[a][side[a] + 1];
          }
          if (part.first[0] < part.last[0] && part.first[1] < part.last[1] &&
              part.first[2] < part.last[2]) {
            queue.push_back(part);
          }
        }
      }
    }
  }
}

}  // namespace exactgeo::inside::internal
