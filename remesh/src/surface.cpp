#include "exactgeo/remesh/surface.hpp"

#include <algorithm>

#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::remesh {

namespace {

bool has_corner(const Triangle& t, VertexIndex v) noexcept {
  return t[0] == v || t[1] == v || t[2] == v;
}

}  // namespace

std::vector<std::size_t> Surface::triangles_on_edge(VertexIndex a, VertexIndex b) const {
  std::vector<std::size_t> found;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (has_corner(triangles[t], a) && has_corner(triangles[t], b)) found.push_back(t);
  }
  return found;
}

std::vector<std::size_t> Surface::triangles_around(VertexIndex v) const {
  std::vector<std::size_t> found;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (has_corner(triangles[t], v)) found.push_back(t);
  }
  return found;
}

std::vector<Edge> Surface::edges() const {
  std::vector<Edge> all;
  all.reserve(3 * triangles.size());
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k)
      all.push_back(edge_of(t[k], t[(k + 1) % 3]));
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

VertexIndex third_corner(const Triangle& t, VertexIndex a, VertexIndex b) noexcept {
  for (const VertexIndex c : t) {
    if (c != a && c != b) return c;
  }
  return kNoVertex;
}

bool walks(const Triangle& t, VertexIndex a, VertexIndex b) noexcept {
  for (int k = 0; k < 3; ++k) {
    if (t[k] == a && t[(k + 1) % 3] == b) return true;
  }
  return false;
}

bool zero_area(const Point3& p, const Point3& q, const Point3& r) noexcept {
  return orient2d_along(0, p, q, r) == Sign::zero && orient2d_along(1, p, q, r) == Sign::zero &&
         orient2d_along(2, p, q, r) == Sign::zero;
}

}  // namespace exactgeo::remesh
