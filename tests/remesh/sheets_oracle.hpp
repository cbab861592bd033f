#pragma once

// Whether the triangles of a surface meet anywhere but in the hull of the corners they
// share (a touch counts, a flat overlap counts whichever way they face): the rule for
// sheets that must stay apart, decided from its definition with the GMP oracles of
// tests/support, no code of the library's self-intersection finder.
//
// Two closed triangles meet outside the hull H of their shared corners exactly when their
// intersection I (convex, holding H) has a point outside H, and then it has an extreme
// point y outside H; y lies on an edge of one triangle and in the other. So it is enough to
// ask each triangle's edges about the other triangle: with no corner shared, every edge;
// with a corner s shared, the edges at s beyond s and the edge across from s; with an edge
// uv shared, the edges at u and v other than uv beyond their shared end (which meet line
// uv only there). Precondition: no triangle of zero area, no two alike.

#include <algorithm>
#include <array>
#include <cstddef>

#include "exactgeo/remesh/surface.hpp"
#include "support/segment_triangle_oracle.hpp"

namespace exactgeo::testing {

/// Triangles s a b and s c d (s shared, nothing else) meet at a point other than s.
inline bool meet_beyond_corner(const Point3& s, const Point3& a, const Point3& b, const Point3& c,
                               const Point3& d) {
  return segment_meets_triangle_beyond_oracle(s, a, c, d) ||
         segment_meets_triangle_beyond_oracle(s, b, c, d) ||
         segment_meets_triangle_beyond_oracle(s, c, a, b) ||
         segment_meets_triangle_beyond_oracle(s, d, a, b) ||
         segment_meets_triangle_oracle(a, b, s, c, d) ||
         segment_meets_triangle_oracle(c, d, s, a, b);
}

/// Two triangles of the surface meet outside the hull of their shared corners.
inline bool triangles_meet_oracle(const remesh::Surface& surface, const remesh::Triangle& t,
                                  const remesh::Triangle& u) {
  const auto& p = surface.vertices;
  std::array<VertexIndex, 3> shared{};
  std::size_t k = 0;
  for (const VertexIndex v : t)
    if (std::find(u.begin(), u.end(), v) != u.end()) shared[k++] = v;
  const auto others = [&](const remesh::Triangle& x) {  // x's corners not shared, in order
    std::array<VertexIndex, 3> out{};
    std::size_t n = 0;
    for (const VertexIndex v : x)
      if (std::find(shared.begin(), shared.begin() + k, v) == shared.begin() + k) out[n++] = v;
    return out;
  };
  const auto ot = others(t), ou = others(u);
  if (k == 0) {
    for (int i = 0; i < 3; ++i) {
      if (segment_meets_triangle_oracle(p[t[i]], p[t[(i + 1) % 3]], p[u[0]], p[u[1]], p[u[2]]) ||
          segment_meets_triangle_oracle(p[u[i]], p[u[(i + 1) % 3]], p[t[0]], p[t[1]], p[t[2]])) {
        return true;
      }
    }
    return false;
  }
  if (k == 1) return meet_beyond_corner(p[shared[0]], p[ot[0]], p[ot[1]], p[ou[0]], p[ou[1]]);
  if (k == 2) {
    const Point3 &a = p[shared[0]], &b = p[shared[1]], &c = p[ot[0]], &d = p[ou[0]];
    return segment_meets_triangle_beyond_oracle(a, c, b, d) ||
           segment_meets_triangle_beyond_oracle(b, c, a, d) ||
           segment_meets_triangle_beyond_oracle(a, d, b, c) ||
           segment_meets_triangle_beyond_oracle(b, d, a, c);
  }
  return true;  // one triangle twice
}

/// Some two triangles of the surface meet outside the hull of their shared corners.
inline bool sheets_meet_oracle(const remesh::Surface& surface) {
  const auto& t = surface.triangles;
  for (std::size_t i = 0; i < t.size(); ++i)
    for (std::size_t j = i + 1; j < t.size(); ++j)
      if (triangles_meet_oracle(surface, t[i], t[j])) return true;
  return false;
}

}  // namespace exactgeo::testing
