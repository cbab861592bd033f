#include "exactgeo/inside/internal/space_cells.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace exactgeo::inside::internal {

std::size_t SpaceCells::cell_count(std::size_t faces, std::optional<std::size_t> expected_points) {
  const std::size_t by_faces = std::clamp(kCellsPerFace * faces, kMinCells, kMaxCells);
  if (!expected_points) return by_faces;
  return std::min(by_faces, std::max(kMinCellsForFewPoints, kCellsPerPoint * *expected_points));
}

SpaceCells::SpaceCells(const mesh::Mesh& mesh, const mesh::Box& box, const ExactWinding& winding,
                       std::optional<std::size_t> expected_points) {
  const auto cells = grid_resolution(box, cell_count(mesh.faces.size(), expected_points));
  for (int i = 0; i < 3; ++i)
    axes_[i] = GridAxis(box.lower[i], box.upper[i], cells[i]);
  // Everything margin, then each row's inner cells unknown.
  codes_.assign(padded(0) * padded(1) * padded(2), kMargin);
  for (std::size_t k = 0; k < cells[2]; ++k) {
    for (std::size_t j = 0; j < cells[1]; ++j) {
      const auto row = codes_.begin() + static_cast<std::ptrdiff_t>(index(0, j, k));
      std::fill(row, row + static_cast<std::ptrdiff_t>(cells[0]), kUnknown);
    }
  }
  mark_faces(mesh);
  label_components(winding);
}

void SpaceCells::mark_faces(const mesh::Mesh& mesh) {
  for_each_face_cell(axes_, mesh, [&](std::size_t i, std::size_t j, std::size_t k) {
    codes_[index(i, j, k)] = kSurface;
  });
}

SpaceCells::Code SpaceCells::code_of(std::int64_t w) {
  const auto found = std::find(windings_.begin(), windings_.end(), w);
  if (found != windings_.end())
    return static_cast<Code>(kFirstWinding + (found - windings_.begin()));
  if (windings_.size() == kMaxWindings) return kSurface;
  windings_.push_back(w);
  return static_cast<Code>(kFirstWinding + windings_.size() - 1);
}

void SpaceCells::label_components(const ExactWinding& winding) {
  const std::size_t row = padded(0);
  const std::size_t slice = padded(0) * padded(1);
  std::vector<std::uint32_t> stack;
  for (std::size_t seed = 0; seed < codes_.size(); ++seed) {
    if (codes_[seed] != kUnknown) continue;
    // One exact winding number for the seed's whole component (a point of the seed cell
    // lies on no face; a boundary answer would be a broken invariant: the cells then stay
    // "surface", which only costs rays).
    const std::size_t i = seed % row - 1;
    const std::size_t j = seed / row % padded(1) - 1;
    const std::size_t k = seed / slice - 1;
    const std::optional<std::int64_t> w =
        winding({axes_[0].point_in(i), axes_[1].point_in(j), axes_[2].point_in(k)});
    const Code fill = w ? code_of(*w) : kSurface;
    ++components_;
    // A scanline fill: a popped cell grows into its whole unknown run along x; the runs
    // beside it (four neighbouring rows) are pushed once per run. The margin is never
    // unknown, so the fill stays in the grid without bounds checks.
    stack.assign(1, static_cast<std::uint32_t>(seed));
    while (!stack.empty()) {
      const std::size_t start = stack.back();
      stack.pop_back();
      if (codes_[start] != kUnknown) continue;
      std::size_t first = start;
      std::size_t last = start;
      while (codes_[first - 1] == kUnknown)
        --first;
      while (codes_[last + 1] == kUnknown)
        ++last;
      std::fill(codes_.begin() + static_cast<std::ptrdiff_t>(first),
                codes_.begin() + static_cast<std::ptrdiff_t>(last) + 1, fill);
      for (const std::size_t offset : {row, slice}) {
        for (const std::size_t beside : {first - offset, first + offset}) {
          bool in_run = false;
          for (std::size_t cell = beside; cell <= beside + (last - first); ++cell) {
            const bool unknown = codes_[cell] == kUnknown;
            if (unknown && !in_run) stack.push_back(static_cast<std::uint32_t>(cell));
            in_run = unknown;
          }
        }
      }
    }
  }
  surface_cells_ = static_cast<std::size_t>(std::count(codes_.begin(), codes_.end(), kSurface));
}

}  // namespace exactgeo::inside::internal
