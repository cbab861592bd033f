#include "polygon_triangulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#include "exactgeo/predicates/orient3d.hpp"
#include "polygon_certificate.hpp"
#include "polygon_ears.hpp"
#include "polygon_monotone.hpp"
#include "polygon_projection.hpp"
#include "polygon_sweep.hpp"
#include "polygon_walk.hpp"

namespace exactgeo::mesh::internal {

namespace {

constexpr std::array<int, 3> kAxes{0, 1, 2};

/// The first corner at another point than the first, or p.size().
std::size_t second_point(std::span<const Point3> p) {
  std::size_t second = 1;
  while (second < p.size() && p[second] == p[0])
    ++second;
  return second;
}

/// Every corner on one line (exact).
bool on_one_line(std::span<const Point3> p) {
  const std::size_t second = second_point(p);
  for (std::size_t third = second + 1; third < p.size(); ++third) {
    if (!collinear(p[0], p[second], p[third])) return false;
  }
  return true;
}

/// Every corner in the plane of the first corner, the first at another point, and the
/// first off their line (exact; any three that span give the same answer).
bool planar(std::span<const Point3> p) {
  // In a plane normal to an axis (caps, outlines at one height): equal coordinates say so
  // at once, where each orient3d would be an exact zero, the filter's slowest answer.
  for (int axis = 0; axis < 3; ++axis) {
    if (std::all_of(p.begin(), p.end(), [&](const Point3& q) { return q[axis] == p[0][axis]; })) {
      return true;
    }
  }
  const std::size_t second = second_point(p);
  for (std::size_t third = second + 1; third < p.size(); ++third) {
    const Point3& x = p[0];
    const Point3& y = p[second];
    const Point3& z = p[third];
    if (collinear(x, y, z)) continue;
    return std::all_of(p.begin(), p.end(),
                       [&](const Point3& d) { return orient3d(x, y, z, d) == Sign::zero; });
  }
  return true;  // collinear
}

/// The axes in the order to try them: by the size of the polygon's Newell normal's
/// component (twice the signed area of the projection), largest first. Only the order
/// depends on rounding; which projection is used is decided exactly by the sweep and the
/// certificate.
std::array<int, 3> axes_by_normal(std::span<const Point3> p) {
  std::array<double, 3> normal{};
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Point3& a = p[k];
    const Point3& b = p[k + 1 == p.size() ? 0 : k + 1];
    for (int axis = 0; axis < 3; ++axis) {
      const int i = (axis + 1) % 3;
      const int j = (axis + 2) % 3;
      normal[axis] += (a[i] - b[i]) * (a[j] + b[j]);
    }
  }
  std::array<int, 3> axes = kAxes;
  for (double& n : normal)
    n = std::isnan(n) ? 0.0 : std::abs(n);  // an overflow ranks first or last, never wrongly
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return normal[a] > normal[b]; });
  return axes;
}

/// Polygons of at most this many corners are split by ear clipping and certified pair by
/// pair (few_triangles_tile): for them the sweeps' setup costs more than the quadratic
/// work (a hexagon took 3 times as long through the sweeps).
constexpr std::size_t kFewCorners = 16;

/// A polygon of few corners split over its projection by ear clipping, certified pair by
/// pair. Its turn is that of its lowest corner, where every other corner lies on one side
/// of the corner's two edges; a polygon with a bridge may repeat that corner, so the
/// other turn is tried as well: the certificate decides.
bool split_few(std::span<const VertexIndex> corners, std::span<const Point3> p,
               std::span<const Point3> vertices, const Projection& plane, std::vector<Face>& out) {
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < p.size(); ++k) {
    if (plane.before(p[k], p[lowest])) lowest = k;
  }
  const Sign first_turn = plane.orientation(p[(lowest + p.size() - 1) % p.size()], p[lowest],
                                            p[(lowest + 1) % p.size()]);
  for (const Sign turn : {first_turn, -first_turn}) {
    if (turn == Sign::zero) continue;
    const std::size_t before = out.size();
    if (clip_ears(corners, p, plane, turn, out) &&
        few_triangles_tile(corners, std::span<const Face>(out).subspan(before), vertices, plane,
                           turn)) {
      return true;
    }
    out.resize(before);
  }
  return false;
}

/// The polygon split over its projection along `axis`, certified; false (nothing
/// appended) when its edges cross, touch or overlap in that projection, or no way of
/// splitting it passes the certificate.
bool split_over(std::span<const VertexIndex> corners, std::span<const Point3> p,
                const PolygonWalk& walk, std::span<const Point3> vertices, int axis,
                std::vector<Face>& out) {
  const Projection plane(axis);
  if (corners.size() <= kFewCorners) return split_few(corners, p, vertices, plane, out);
  const ScratchVector<std::uint32_t> order = sweep_order(walk, vertices, plane);
  ScratchVector<std::uint32_t> below;
  const std::optional<Sign> turn = region_turn(walk, order, vertices, plane, &below);
  if (!turn) return false;  // no tiling exists in this projection: nothing to try
  const std::size_t before = out.size();
  const auto certified = [&] {
    return triangles_fit(walk, std::span<const Face>(out).subspan(before), vertices, plane, *turn);
  };
  if (triangulate_by_sweep(walk, order, vertices, plane, *turn, below, out) && certified()) {
    return true;
  }
  out.resize(before);
  // Ear clipping, quadratic, is reached only by projections that touch themselves at a
  // corner, since the sweep above refused every one that crosses itself: corners that
  // project to one point, loops that meet at a corner (after a bridge's walks cancel),
  // a corner that only a spike walked there and back reaches. The sweep triangulation
  // declines those or its triangles fail the certificate (a figure eight is tiled by too
  // few), and ear clipping, which lets a triangle hold other occurrences of its own
  // corners, decides as it always has.
  if (clip_ears(corners, p, plane, *turn, out) && certified()) return true;
  out.resize(before);
  return false;
}

}  // namespace

void append_fan(std::span<const VertexIndex> corners, std::vector<Face>& out) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    out.push_back(make_triangle(corners[0], corners[k], corners[k + 1]));
  }
}

PolygonForm triangulate_polygon(std::span<const VertexIndex> corners_as_read,
                                std::span<const Point3> vertices, std::vector<Face>& out) {
  // A corner repeated next to itself makes an edge of zero length, which joins nothing.
  const ScratchVector<VertexIndex> corners = without_repeats(corners_as_read);
  ScratchVector<Point3> p(corners.size());
  std::transform(corners.begin(), corners.end(), p.begin(),
                 [&](VertexIndex c) { return vertices[c]; });
  if (corners.size() < 3 || on_one_line(p)) {
    append_fan(corners_as_read, out);
    return PolygonForm::zero_area;
  }
  const PolygonWalk walk = corners.size() <= kFewCorners ? PolygonWalk{} : walk_of(corners);
  for (const int axis : axes_by_normal(p)) {
    if (split_over(corners, p, walk, vertices, axis, out)) {
      return planar(p) ? PolygonForm::planar : PolygonForm::non_planar;
    }
  }
  return PolygonForm::self_crossing;
}

}  // namespace exactgeo::mesh::internal
