#pragma once

// Certified space cells for an open surface: a grid over the box of the faces' corners
// whose cells carry a label where every point of the cell certainly has it, so that those
// points need neither a ray nor a boundary term.
//
// On an open surface the generalized winding number w is not constant on a cell, so a
// cell cannot take its label from one point, as space_cells.hpp's do. What holds instead:
// a closed box C that no face's corner box meets misses the surface (each face lies in
// its corners' box), and there w is smooth, with a gradient that the boundary alone
// bounds (the Biot-Savart law; exactgeo/predicates/boundary_tree.hpp, "Variation over a
// box"): |w(p) - w(c)| <= delta for every p of C, c a point of C and delta from the
// boundary tree. With w(c) enclosed as S + [lower, upper] (the signed crossing count of
// a ray from c and the certified boundary term along it, both as for a single point),
// every p of C has w(p) in S + [lower - delta, upper + delta]; where that interval lies
// strictly on one side of each of the rule's levels (+-1/2), every point of C has the
// label that side gives, and the per-point path would give it too (a w strictly away
// from 1/2 by a double's margin is settled by its stages). Otherwise (a box too near the
// boundary, or a level inside it) the box is split and its parts tried, down to single
// cells, which then stay unlabelled: their points take the per-point path.
//
// A cell is a closed box between the grid's planes (grid_axis.hpp), so a point on a
// plane lies in two cells, both labelled correctly for it if labelled at all. Whether
// a face reaches a cell is decided by exact comparisons of doubles.

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

/// What a box of the open space cells was found to be: the label of every point of it,
/// where certain; whether its parts are worth trying where it has none (false: the
/// boundary is so near that they would fail too; parts are tried anyway, except for boxes
/// of at most two cells a side); and whether the answer took a ray and a term (costly) or
/// only the bound. Costs only.
struct OpenBoxAnswer {
  std::optional<Location> label;
  bool try_parts = true;
  bool costly = true;
};

class OpenSpaceCells {
 public:
  using BoxAnswer = OpenBoxAnswer;
  /// The answer for the closed box [lower, upper], which no face reaches.
  using BoxLabel = std::function<BoxAnswer(const Point3& lower, const Point3& upper)>;

  /// The grid over `box` (the faces' corners' box) with about `cells` cells, shaped like
  /// the box; `label` is tried on boxes of cells that no face reaches, the largest first,
  /// while the tries pay for about `expected_points` points (nullopt: as many as there
  /// are cells, or more).
  OpenSpaceCells(const mesh::Mesh& mesh, const mesh::Box& box, const BoxLabel& label,
                 std::size_t cells, std::optional<std::size_t> expected_points = std::nullopt);

  /// The label of every point of a cell containing `p`, or nullopt where that cell has
  /// none. Precondition: p in the closed box.
  std::optional<Location> lookup(const Point3& p) const noexcept {
    const CellCode code =
        codes_[index(axes_[0].cell_of(p[0]), axes_[1].cell_of(p[1]), axes_[2].cell_of(p[2]))];
    if (code == CellCode::inside) return Location::inside;
    if (code == CellCode::outside) return Location::outside;
    return std::nullopt;
  }

  std::array<std::size_t, 3> resolution() const noexcept {
    return {axes_[0].cells(), axes_[1].cells(), axes_[2].cells()};
  }
  std::size_t cells() const noexcept { return codes_.size(); }
  /// Cells some face reaches.
  std::size_t surface_cells() const noexcept { return surface_cells_; }
  /// Cells with a label.
  std::size_t labelled_cells() const noexcept { return labelled_cells_; }
  /// Boxes the label was tried on.
  std::size_t boxes_tried() const noexcept { return boxes_tried_; }
  const std::vector<double>& planes(int axis) const noexcept { return axes_[axis].planes(); }

  /// The most boxes tried, per cell of the grid; and the build stops where a window of
  /// tries costing kWindowCost points has labelled cells holding fewer points than that:
  /// a try that casts a ray costs about what kTryCost points' rays and terms cost, one
  /// whose bound alone fails kBoundTryCost. With the points not known (the grid is then
  /// sized for the mesh, for many points) a costly try must label one cell, and the
  /// bound's failures count only against the cap. Costs only.
  static constexpr double kTriesPerCell = 0.125;
  static constexpr double kWindowCost = 256.0;
  static constexpr double kTryCost = 4.0;
  static constexpr double kBoundTryCost = 1.0;

 private:
  enum class CellCode : std::uint8_t { unknown, surface, inside, outside };
  /// Cells [first, last) per axis.
  struct Block {
    std::array<std::size_t, 3> first{}, last{};
  };

  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const noexcept {
    return (k * axes_[1].cells() + j) * axes_[0].cells() + i;
  }
  void mark_faces(const mesh::Mesh& mesh);
  void label_blocks(const BoxLabel& label, double cells_per_point, double bound_try_cost);

  std::array<GridAxis, 3> axes_;
  std::vector<CellCode> codes_;
  std::size_t surface_cells_ = 0;
  std::size_t labelled_cells_ = 0;
  std::size_t boxes_tried_ = 0;
};

}  // namespace exactgeo::inside::internal
