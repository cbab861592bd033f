#include "exactgeo/ccd/baselines/separation_box.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace exactgeo::ccd {

namespace {

struct ParameterBox {
  std::array<double, 3> lo;  // t, u, v
  std::array<double, 3> hi;
};

Point3 lerp(const Point3& a, const Point3& b, double s) noexcept {
  return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}

/// F at (t, u, v), plain doubles.
Point3 difference(const VertexFaceQuery& q, double t, double u, double v) noexcept {
  const Point3 p = lerp(q.v_t0, q.v_t1, t);
  const Point3 a = lerp(q.f0_t0, q.f0_t1, t);
  const Point3 b = lerp(q.f1_t0, q.f1_t1, t);
  const Point3 c = lerp(q.f2_t0, q.f2_t1, t);
  Point3 f;
  for (int k = 0; k < 3; ++k)
    f[k] = p[k] - (a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]));
  return f;
}

Point3 difference(const EdgeEdgeQuery& q, double t, double u, double v) noexcept {
  const Point3 a = lerp(lerp(q.ea0_t0, q.ea0_t1, t), lerp(q.ea1_t0, q.ea1_t1, t), u);
  const Point3 b = lerp(lerp(q.eb0_t0, q.eb0_t1, t), lerp(q.eb1_t0, q.eb1_t1, t), v);
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

enum class Meets { no, inside, partly };

template <class Query>
Meets meets_cube(const Query& q, const ParameterBox& box, double delta) noexcept {
  Point3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (int corner = 0; corner < 8; ++corner) {
    const Point3 f =
        difference(q, corner & 1 ? box.hi[0] : box.lo[0], corner & 2 ? box.hi[1] : box.lo[1],
                   corner & 4 ? box.hi[2] : box.lo[2]);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], f[k]);
      hi[k] = std::max(hi[k], f[k]);
    }
  }
  bool inside = true;
  for (int k = 0; k < 3; ++k) {
    if (lo[k] > delta || hi[k] < -delta) return Meets::no;
    inside = inside && lo[k] >= -delta && hi[k] <= delta;
  }
  return inside ? Meets::inside : Meets::partly;
}

template <class Query>
bool box_baseline(const Query& q, double delta, const SeparationBoxBaselineOptions& options,
                  bool triangle) noexcept {
  std::vector<ParameterBox> stack{{{0, 0, 0}, {1, 1, 1}}};
  std::size_t boxes = 0;
  while (!stack.empty()) {
    const ParameterBox box = stack.back();
    stack.pop_back();
    if (++boxes > options.max_boxes) return true;
    // Barycentric (u, v) of a face: the box must reach the triangle u + v <= 1.
    if (triangle && box.lo[1] + box.lo[2] > 1.0) continue;
    const Meets m = meets_cube(q, box, delta);
    if (m == Meets::no) continue;
    // Every point of the box maps into the cube, and (u, v) = (lo, lo) is in the domain.
    if (m == Meets::inside) return true;
    int widest = 0;
    for (int k = 1; k < 3; ++k) {
      if (box.hi[k] - box.lo[k] > box.hi[widest] - box.lo[widest]) widest = k;
    }
    if (box.hi[widest] - box.lo[widest] <= options.tolerance) return true;
    const double mid = 0.5 * (box.lo[widest] + box.hi[widest]);
    ParameterBox later = box, first = box;
    first.hi[widest] = mid;
    later.lo[widest] = mid;
    stack.push_back(later);
    stack.push_back(first);
  }
  return false;
}

}  // namespace

bool vertex_face_separation_box_baseline(const VertexFaceQuery& query, double delta,
                                         const SeparationBoxBaselineOptions& options) noexcept {
  return box_baseline(query, delta, options, true);
}

bool edge_edge_separation_box_baseline(const EdgeEdgeQuery& query, double delta,
                                       const SeparationBoxBaselineOptions& options) noexcept {
  return box_baseline(query, delta, options, false);
}

}  // namespace exactgeo::ccd
