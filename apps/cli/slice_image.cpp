#include "cli/slice_image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace exactgeo::cli {
namespace {

std::size_t index_of(Axis axis) noexcept {
  return static_cast<std::size_t>(axis);
}

/// Points per classification block: whole rows, about 1.5 MB of points.
constexpr std::size_t kBlockPoints = std::size_t{1} << 16;

/// Pixels per side of the outline's leaf cells: their pieces of curve are short enough
/// that marking the pixels of their ends leaves an 8-connected line.
constexpr double kLeafPixels = 0.5;
/// A bound on the subdivision (a face 2^30 pixels wide is far outside any picture).
constexpr int kMaxDepth = 30;

/// A point in pixel units: x to the right from the left edge, y down from the top edge.
struct PixelPoint {
  double x, y;
};

PixelPoint lerp(const PixelPoint& a, const PixelPoint& b, double t) noexcept {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

/// The outline's raster and the map from the plane to pixel units.
class OutlineRaster {
 public:
  explicit OutlineRaster(const SliceGrid& grid)
      : grid_(grid), axes_(image_axes(grid.plane.axis)), marks_(grid.pixels(), 0) {}

  PixelPoint to_pixels(const Point3& p) const noexcept {
    return {(p[axes_.horizontal] - grid_.left) / grid_.pixel,
            (grid_.top - p[axes_.vertical]) / grid_.pixel};
  }

  /// Marks the pixel holding `p`, if it is in the picture.
  void mark(const PixelPoint& p) noexcept {
    // Written so that NaN fails too.
    if (!(p.x >= 0.0 && p.y >= 0.0 && p.x < double(grid_.width) && p.y < double(grid_.height))) {
      return;
    }
    const auto column = std::min(static_cast<std::size_t>(p.x), grid_.width - 1);
    const auto row = std::min(static_cast<std::size_t>(p.y), grid_.height - 1);
    marks_[row * grid_.width + column] = 1;
  }

  /// Marks the pixels along the segment a-b, at most kLeafPixels apart.
  void mark_segment(const PixelPoint& a, const PixelPoint& b) noexcept {
    const double length = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y));
    if (!(length < 4.0 * double(grid_.width + grid_.height))) return;  // huge, or NaN
    const auto steps = static_cast<std::size_t>(std::ceil(length / kLeafPixels));
    for (std::size_t i = 0; i <= steps; ++i) {
      mark(steps == 0 ? a : lerp(a, b, double(i) / double(steps)));
    }
  }

  std::vector<std::uint8_t> take() && { return std::move(marks_); }

 private:
  const SliceGrid& grid_;
  ImageAxes axes_;
  std::vector<std::uint8_t> marks_;
};

/// One face as the bilinear patch p(u, v) = (1-u)(1-v) p00 + u(1-v) p10 + uv p11 +
/// (1-u)v p01 (a triangle as the patch {a, b, c, c}, which covers it), with the plane's
/// function f(u, v) = p(u, v)[axis] - value, bilinear with the corners' values.
///
/// The cross-section is the zero set of f. A bilinear function on a rectangle takes its
/// extremes at the corners, so a parameter cell whose corner values are all > 0, or all
/// < 0, holds none of it; the others are split in four until their image is at most
/// kLeafPixels wide. On a cell's edge (u or v fixed) both p and f are linear, so where f
/// changes sign along it the zero is found by linear interpolation, and it is a point of
/// the curve; a leaf marks those points and its corners where f is 0. The curve between
/// two of them stays inside the leaf's box, so no pixel it crosses is far from a mark.
class PatchTracer {
 public:
  PatchTracer(const std::array<Point3, 4>& corners, const SlicePlane& plane, OutlineRaster& raster)
      : corners_(corners), plane_(plane), raster_(raster) {}

  void trace(double u0, double u1, double v0, double v1, int depth) {
    // Corners in boundary order: (u0, v0), (u1, v0), (u1, v1), (u0, v1).
    const std::array<std::array<double, 2>, 4> uv{{{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}};
    std::array<double, 4> f;
    std::array<PixelPoint, 4> q;
    for (std::size_t i = 0; i < 4; ++i) {
      const Point3 p = at(uv[i][0], uv[i][1]);
      f[i] = p[index_of(plane_.axis)] - plane_.value;
      q[i] = raster_.to_pixels(p);
    }
    const bool all_positive = std::min({f[0], f[1], f[2], f[3]}) > 0.0;
    const bool all_negative = std::max({f[0], f[1], f[2], f[3]}) < 0.0;
    if (all_positive || all_negative) return;

    const auto [x_low, x_high] = std::minmax({q[0].x, q[1].x, q[2].x, q[3].x});
    const auto [y_low, y_high] = std::minmax({q[0].y, q[1].y, q[2].y, q[3].y});
    const double width = std::max(x_high - x_low, y_high - y_low);
    if (width > kLeafPixels && depth < kMaxDepth) {
      const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
      trace(u0, um, v0, vm, depth + 1);
      trace(um, u1, v0, vm, depth + 1);
      trace(u0, um, vm, v1, depth + 1);
      trace(um, u1, vm, v1, depth + 1);
      return;
    }
    for (std::size_t i = 0; i < 4; ++i) {
      const std::size_t j = (i + 1) % 4;
      if (f[i] == 0.0) raster_.mark(q[i]);
      if ((f[i] < 0.0 && f[j] > 0.0) || (f[i] > 0.0 && f[j] < 0.0)) {
        raster_.mark(lerp(q[i], q[j], f[i] / (f[i] - f[j])));
      }
    }
  }

 private:
  Point3 at(double u, double v) const noexcept {
    const auto& [p00, p10, p11, p01] = corners_;
    Point3 p;
    for (std::size_t c = 0; c < 3; ++c) {
      p[c] = (1 - v) * ((1 - u) * p00[c] + u * p10[c]) + v * ((1 - u) * p01[c] + u * p11[c]);
    }
    return p;
  }

  const std::array<Point3, 4>& corners_;
  const SlicePlane& plane_;
  OutlineRaster& raster_;
};

}  // namespace

ImageAxes image_axes(Axis axis) noexcept {
  switch (axis) {
    case Axis::x:
      return {1, 2};
    case Axis::y:
      return {0, 2};
    case Axis::z:
      break;
  }
  return {0, 1};
}

Point3 SliceGrid::pixel_centre(std::size_t column, std::size_t row) const noexcept {
  const ImageAxes axes = image_axes(plane.axis);
  Point3 p;
  p[index_of(plane.axis)] = plane.value;
  p[axes.horizontal] = left + (double(column) + 0.5) * pixel;
  p[axes.vertical] = top - (double(row) + 0.5) * pixel;
  return p;
}

SliceGrid slice_grid(const mesh::Mesh& mesh, SlicePlane plane, unsigned resolution) {
  if (mesh.vertices.empty()) throw std::invalid_argument("the mesh has no vertices");
  Point3 lower = mesh.vertices[0], upper = lower;
  for (const Point3& v : mesh.vertices) {
    for (std::size_t c = 0; c < 3; ++c) {
      lower[c] = std::min(lower[c], v[c]);
      upper[c] = std::max(upper[c], v[c]);
    }
  }
  const ImageAxes axes = image_axes(plane.axis);
  const std::size_t h = axes.horizontal, v = axes.vertical;
  const double extent_h = upper[h] - lower[h], extent_v = upper[v] - lower[v];
  double longer = std::max(extent_h, extent_v);
  if (!std::isfinite(longer)) {
    throw std::invalid_argument("the mesh's box is too large to draw (its sides overflow double)");
  }
  if (longer == 0.0) longer = 1.0;  // a mesh flat in both directions: any scale shows it
  const double margin = longer / 32;
  SliceGrid grid;
  grid.plane = plane;
  grid.pixel = (longer + 2 * margin) / resolution;
  // The longer side gets `resolution` pixels; the other as many as its extent needs.
  const auto pixels_for = [&](double extent) {
    if (extent == std::max(extent_h, extent_v)) return std::size_t{resolution};
    const double n = std::ceil((extent + 2 * margin) / grid.pixel);
    return std::clamp(static_cast<std::size_t>(n), std::size_t{1}, std::size_t{resolution});
  };
  grid.width = pixels_for(extent_h);
  grid.height = pixels_for(extent_v);
  // Centred on the box (halves first: the sum could overflow).
  grid.left = (lower[h] / 2 + upper[h] / 2) - double(grid.width) * grid.pixel / 2;
  grid.top = (lower[v] / 2 + upper[v] / 2) + double(grid.height) * grid.pixel / 2;
  grid.axis_lower = lower[index_of(plane.axis)];
  grid.axis_upper = upper[index_of(plane.axis)];
  return grid;
}

std::vector<inside::Location> classify_pixels(const SliceGrid& grid,
                                              const ClassifyPoints& classify) {
  std::vector<inside::Location> labels(grid.pixels());
  const std::size_t rows_per_block = std::max<std::size_t>(1, kBlockPoints / grid.width);
  std::vector<Point3> points;
  for (std::size_t first = 0; first < grid.height; first += rows_per_block) {
    const std::size_t last = std::min(grid.height, first + rows_per_block);
    points.clear();
    for (std::size_t row = first; row < last; ++row) {
      for (std::size_t column = 0; column < grid.width; ++column) {
        points.push_back(grid.pixel_centre(column, row));
      }
    }
    classify(points, std::span(labels).subspan(first * grid.width, points.size()));
  }
  return labels;
}

std::vector<std::uint8_t> outline_pixels(const SliceGrid& grid, const mesh::Mesh& mesh) {
  OutlineRaster raster(grid);
  const std::size_t axis = index_of(grid.plane.axis);
  const double value = grid.plane.value;
  for (const mesh::Face& face : mesh.faces) {
    const BilinearPatch patch = mesh::patch_of(mesh, face);
    const std::array<Point3, 4> corners{patch.p00, patch.p10, patch.p11, patch.p01};
    // The face lies in its corners' hull: it meets the plane only if they straddle it.
    double lowest = corners[0][axis], highest = lowest;
    for (const Point3& c : corners) {
      lowest = std::min(lowest, c[axis]);
      highest = std::max(highest, c[axis]);
    }
    if (lowest > value || highest < value) continue;
    if (lowest == value && highest == value) {
      // The face lies in the plane: its cross-section is the face itself; draw its
      // edges (the pixel centres on it are boundary, which shows the inside).
      for (std::size_t i = 0; i < face.size(); ++i) {
        const Point3& a = mesh.vertices[face.corner(i)];
        const Point3& b = mesh.vertices[face.corner(i + 1)];
        raster.mark_segment(raster.to_pixels(a), raster.to_pixels(b));
      }
      continue;
    }
    PatchTracer(corners, grid.plane, raster).trace(0.0, 1.0, 0.0, 1.0, 0);
  }
  return std::move(raster).take();
}

PixelKind pixel_kind(inside::Location label, bool on_outline) noexcept {
  switch (label) {
    case inside::Location::boundary:
      return PixelKind::boundary;
    case inside::Location::undecided:
      return PixelKind::undecided;
    case inside::Location::inside:
      return on_outline ? PixelKind::outline : PixelKind::inside;
    case inside::Location::outside:
      break;
  }
  return on_outline ? PixelKind::outline : PixelKind::outside;
}

Rgb colour_of(PixelKind kind) noexcept {
  switch (kind) {
    case PixelKind::inside:
      return {86, 180, 233};
    case PixelKind::boundary:
      return {213, 94, 0};
    case PixelKind::undecided:
      return {204, 121, 167};
    case PixelKind::outline:
      return {0, 0, 0};
    case PixelKind::outside:
      break;
  }
  return {255, 255, 255};
}

RgbImage draw_slice(const SliceGrid& grid, std::span<const inside::Location> labels,
                    std::span<const std::uint8_t> outline) {
  if (labels.size() != grid.pixels() || outline.size() != grid.pixels()) {
    throw std::invalid_argument("draw_slice: one label and one outline mark per pixel are needed");
  }
  RgbImage image{grid.width, grid.height, std::vector<std::uint8_t>(grid.pixels() * 3)};
  for (std::size_t i = 0; i < grid.pixels(); ++i) {
    const Rgb c = colour_of(pixel_kind(labels[i], outline[i] != 0));
    image.pixels[3 * i] = c.red;
    image.pixels[3 * i + 1] = c.green;
    image.pixels[3 * i + 2] = c.blue;
  }
  return image;
}

}  // namespace exactgeo::cli
