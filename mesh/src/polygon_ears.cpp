#include "polygon_ears.hpp"

#include <cstddef>

namespace exactgeo::mesh::internal {

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

}  // namespace exactgeo::mesh::internal
