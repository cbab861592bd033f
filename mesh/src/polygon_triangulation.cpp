#include "polygon_triangulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>

#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::mesh::internal {

namespace {

constexpr std::array<int, 3> kAxes{0, 1, 2};

/// The polygon seen along one coordinate axis: its points with that coordinate dropped.
/// For a planar polygon whose normal has a non-zero component along the axis the
/// projection is one-to-one on the plane, so every orientation below is the polygon's own.
class Projection {
 public:
  explicit Projection(int axis) noexcept : axis_(axis), i_((axis + 1) % 3), j_((axis + 2) % 3) {}

  /// The sign of ((b - a) x (c - a)) along the dropped axis, exactly.
  Sign orientation(const Point3& a, const Point3& b, const Point3& c) const noexcept {
    return orient2d_along(axis_, a, b, c);
  }

  /// Coordinate k (0 or 1) of p's projection.
  double coordinate(const Point3& p, int k) const noexcept { return p[k == 0 ? i_ : j_]; }

  /// p in the closed triangle abc, whose orientation is `turn` (not zero). The box test
  /// first spares the orientations for most points.
  bool in_triangle(const Point3& a, const Point3& b, const Point3& c, Sign turn,
                   const Point3& p) const noexcept {
    for (const int k : {i_, j_}) {
      if (p[k] < std::min({a[k], b[k], c[k]}) || p[k] > std::max({a[k], b[k], c[k]})) return false;
    }
    return orientation(a, b, p) != -turn && orientation(b, c, p) != -turn &&
           orientation(c, a, p) != -turn;
  }

  /// (p_i, p_j) lexicographically smaller than (q_i, q_j).
  bool lower(const Point3& p, const Point3& q) const noexcept {
    return p[i_] < q[i_] || (p[i_] == q[i_] && p[j_] < q[j_]);
  }

 private:
  int axis_;
  int i_;
  int j_;
};

/// Every corner on one line (exact).
bool collinear(std::span<const Point3> p) {
  std::size_t second = 1;
  while (second < p.size() && p[second] == p[0])
    ++second;
  for (std::size_t third = second + 1; third < p.size(); ++third) {
    for (int axis = 0; axis < 3; ++axis) {
      if (Projection(axis).orientation(p[0], p[second], p[third]) != Sign::zero) return false;
    }
  }
  return true;
}

/// Every corner in the plane of the first three that are not collinear (exact).
bool planar(std::span<const Point3> p) {
  for (std::size_t b = 1; b < p.size(); ++b) {
    for (std::size_t c = b + 1; c < p.size(); ++c) {
      const Point3 &x = p[0], &y = p[b], &z = p[c];
      const bool spanning = std::any_of(kAxes.begin(), kAxes.end(), [&](int axis) {
        return Projection(axis).orientation(x, y, z) != Sign::zero;
      });
      if (!spanning) continue;
      return std::all_of(p.begin(), p.end(),
                         [&](const Point3& d) { return orient3d(x, y, z, d) == Sign::zero; });
    }
  }
  return true;  // collinear
}

/// The axes in the order to try them: by the size of the polygon's Newell normal's
/// component (twice the signed area of the projection), largest first. Only the order
/// depends on rounding; which projection is used is decided exactly by `simple`.
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

/// Ear clipping in a projection: a corner is an ear when it turns as `turn` (strictly)
/// and no other remaining corner lies in the closed triangle it makes with its
/// neighbours, except another occurrence of one of the triangle's own vertices (a polygon
/// with a hole, written with a bridge walked both ways, repeats the bridge's ends).
/// Appends the n - 2 triangles, oriented as the polygon is walked, each turning as `turn`;
/// false when no ear is left before the end (a polygon whose edges cross).
bool clip_ears(std::span<const VertexIndex> corners, std::span<const Point3> p,
               const Projection& plane, Sign turn, std::vector<Face>& out) {
  const std::size_t n = p.size();
  std::vector<std::size_t> prev(n);
  std::vector<std::size_t> next(n);
  for (std::size_t k = 0; k < n; ++k) {
    prev[k] = (k + n - 1) % n;
    next[k] = (k + 1) % n;
  }
  const auto is_ear = [&](std::size_t v) {
    const Point3& a = p[prev[v]];
    const Point3& b = p[v];
    const Point3& c = p[next[v]];
    if (plane.orientation(a, b, c) != turn) return false;
    for (std::size_t u = next[next[v]]; u != prev[v]; u = next[u]) {
      const VertexIndex w = corners[u];
      if (w == corners[prev[v]] || w == corners[v] || w == corners[next[v]]) continue;
      if (plane.in_triangle(a, b, c, turn, p[u])) return false;
    }
    return true;
  };

  enum class Ear : signed char { unknown, yes, no };
  std::vector<Ear> ear(n, Ear::unknown);
  std::size_t v = 0;
  for (std::size_t remaining = n; remaining > 3; --remaining) {
    std::size_t tried = 0;
    for (; tried < remaining; ++tried, v = next[v]) {
      if (ear[v] == Ear::unknown) ear[v] = is_ear(v) ? Ear::yes : Ear::no;
      if (ear[v] == Ear::yes) break;
    }
    if (tried == remaining) return false;
    out.push_back(make_triangle(corners[prev[v]], corners[v], corners[next[v]]));
    next[prev[v]] = next[v];
    prev[next[v]] = prev[v];
    ear[prev[v]] = Ear::unknown;
    ear[next[v]] = Ear::unknown;
    v = next[v];
  }
  if (plane.orientation(p[prev[v]], p[v], p[next[v]]) != turn) return false;
  out.push_back(make_triangle(corners[prev[v]], corners[v], corners[next[v]]));
  return true;
}

/// The certificate that ear clipping made a surface that does not fold over itself: the
/// projections of the triangles (each turning as `turn`) have pairwise disjoint interiors.
/// Two triangles' interiors are disjoint exactly when the line through some edge of one
/// has the other on its closed outer side (convex sets in the plane), tested for every
/// pair whose boxes overlap, found by a sweep along the first projected coordinate.
bool interiors_disjoint(std::span<const Face> triangles, std::span<const Point3> vertices,
                        const Projection& plane, Sign turn) {
  using Corners = std::array<const Point3*, 3>;
  const auto corners_of = [&](const Face& f) {
    return Corners{&vertices[f.corners[0]], &vertices[f.corners[1]], &vertices[f.corners[2]]};
  };
  const auto outside_an_edge = [&](const Corners& t, const Corners& u) {
    for (std::size_t e = 0; e < 3; ++e) {
      const Point3& a = *t[e];
      const Point3& b = *t[(e + 1) % 3];
      if (std::all_of(u.begin(), u.end(),
                      [&](const Point3* x) { return plane.orientation(a, b, *x) != turn; })) {
        return true;
      }
    }
    return false;
  };
  struct Span2 {
    std::array<double, 2> lower;
    std::array<double, 2> upper;
  };
  std::vector<Span2> boxes(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Corners c = corners_of(triangles[t]);
    for (int k = 0; k < 2; ++k) {
      const auto coordinate = [&](const Point3* x) { return plane.coordinate(*x, k); };
      boxes[t].lower[k] = std::min({coordinate(c[0]), coordinate(c[1]), coordinate(c[2])});
      boxes[t].upper[k] = std::max({coordinate(c[0]), coordinate(c[1]), coordinate(c[2])});
    }
  }
  std::vector<std::size_t> order(triangles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].lower[0] < boxes[b].lower[0]; });
  for (std::size_t x = 0; x < order.size(); ++x) {
    const Span2& box = boxes[order[x]];
    for (std::size_t y = x + 1; y < order.size(); ++y) {
      const Span2& other = boxes[order[y]];
      if (other.lower[0] >= box.upper[0]) break;  // boxes meeting at most on a line
      if (other.lower[1] >= box.upper[1] || box.lower[1] >= other.upper[1]) continue;
      const Corners t = corners_of(triangles[order[x]]);
      const Corners u = corners_of(triangles[order[y]]);
      if (!outside_an_edge(t, u) && !outside_an_edge(u, t)) return false;
    }
  }
  return true;
}

/// The polygon split over its projection along `axis`, certified; false (nothing
/// appended) when ear clipping gets stuck or its triangles overlap, for either turn.
bool split_over(std::span<const VertexIndex> corners, std::span<const Point3> p,
                std::span<const Point3> vertices, int axis, std::vector<Face>& out) {
  const Projection plane(axis);
  // The turn of a simple polygon is that of its lowest corner, where every other corner
  // lies on one side of the corner's two edges; a polygon with a bridge may repeat that
  // corner, so the other turn is tried as well: the certificate decides.
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < p.size(); ++k) {
    if (plane.lower(p[k], p[lowest])) lowest = k;
  }
  const Sign first_turn = plane.orientation(p[(lowest + p.size() - 1) % p.size()], p[lowest],
                                            p[(lowest + 1) % p.size()]);
  for (const Sign turn : {first_turn, -first_turn}) {
    if (turn == Sign::zero) continue;
    const std::size_t before = out.size();
    if (clip_ears(corners, p, plane, turn, out) &&
        interiors_disjoint(std::span(out).subspan(before), vertices, plane, turn)) {
      return true;
    }
    out.resize(before);
  }
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
  std::vector<VertexIndex> corners;
  for (std::size_t k = 0; k < corners_as_read.size(); ++k) {
    const VertexIndex before = corners_as_read[k == 0 ? corners_as_read.size() - 1 : k - 1];
    if (corners_as_read[k] != before) corners.push_back(corners_as_read[k]);
  }
  std::vector<Point3> p(corners.size());
  std::transform(corners.begin(), corners.end(), p.begin(),
                 [&](VertexIndex c) { return vertices[c]; });
  if (corners.size() < 3 || collinear(p)) {
    append_fan(corners_as_read, out);
    return PolygonForm::zero_area;
  }
  for (const int axis : axes_by_normal(p)) {
    if (split_over(corners, p, vertices, axis, out)) {
      return planar(p) ? PolygonForm::planar : PolygonForm::non_planar;
    }
  }
  return PolygonForm::self_crossing;
}

}  // namespace exactgeo::mesh::internal
