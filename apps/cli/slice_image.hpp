#pragma once

// `exactgeo inside MESH --slice z=0.3 --image out.png`: a picture of a plane cross-section.
// Each pixel is coloured by the exact label of its centre (the command's classifier, so
// inside / outside / boundary are exact for that double point), and the mesh's
// cross-section curve is drawn over it, one pixel wide.
//
// The picture covers the mesh's bounding box in the plane's two other axes, grown by
// 1/32 of its longer side on every side, with square pixels; the longer side has
// `resolution` pixels. Axes: z=c: x to the right, y up; x=c: y right, z up; y=c: x right,
// z up. The first image row is the top (largest vertical coordinate), so up is up.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "cli/colour.hpp"
#include "cli/png_image.hpp"
#include "cli/slice_options.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::cli {

/// The coordinate indices drawn to the right and upward for a plane normal to `axis`.
struct ImageAxes {
  std::size_t horizontal;
  std::size_t vertical;
};
ImageAxes image_axes(Axis axis) noexcept;

/// The pixel grid: pixel (column, row) is the square [left + column * pixel, left +
/// (column + 1) * pixel] x [top - (row + 1) * pixel, top - row * pixel] of the plane.
struct SliceGrid {
  SlicePlane plane;
  std::size_t width = 0;
  std::size_t height = 0;
  double left = 0.0;   ///< the horizontal coordinate of the picture's left edge
  double top = 0.0;    ///< the vertical coordinate of its top edge
  double pixel = 0.0;  ///< a pixel's side
  /// The mesh's extent along the plane's axis: a plane outside it meets nothing.
  double axis_lower = 0.0;
  double axis_upper = 0.0;

  /// The centre of pixel (column, row), in the plane (its axis coordinate is the value).
  Point3 pixel_centre(std::size_t column, std::size_t row) const noexcept;
  std::size_t pixels() const noexcept { return width * height; }
};

/// The grid for `mesh` (at least one vertex). Throws std::invalid_argument if the mesh's
/// box is too large for its sides to be doubles.
SliceGrid slice_grid(const mesh::Mesh& mesh, SlicePlane plane, unsigned resolution);

/// Labels a span of points (the command's classifier and threads: inside::classify_batch).
using ClassifyPoints =
    std::function<void(std::span<const Point3> points, std::span<inside::Location> locations)>;

/// The label of every pixel's centre, row by row from the top, classified in blocks of
/// whole rows so that memory stays at one byte per pixel plus one block of points.
std::vector<inside::Location> classify_pixels(const SliceGrid& grid,
                                              const ClassifyPoints& classify);

/// One byte per pixel, row by row from the top: 1 where some face's intersection with the
/// plane passes through the pixel, else 0. Drawn in plain doubles (a picture, not a
/// predicate): a pixel beside the curve may be marked, or a grazing touch missed.
std::vector<std::uint8_t> outline_pixels(const SliceGrid& grid, const mesh::Mesh& mesh);

/// What a pixel shows: its centre's label, except that the outline covers inside and
/// outside pixels (never boundary ones, which are exact and rare).
enum class PixelKind : std::uint8_t { outside, inside, boundary, undecided, outline };
PixelKind pixel_kind(inside::Location label, bool on_outline) noexcept;

/// The palette (Okabe and Ito's colour-blind-safe colours): outside white, inside sky blue
/// (86, 180, 233), boundary vermillion (213, 94, 0), undecided reddish purple (204, 121,
/// 167), outline black.
Rgb colour_of(PixelKind kind) noexcept;

/// The picture. Precondition: labels and outline have grid.pixels() entries.
RgbImage draw_slice(const SliceGrid& grid, std::span<const inside::Location> labels,
                    std::span<const std::uint8_t> outline);

}  // namespace exactgeo::cli
