#include "exactgeo/remesh/surface.hpp"

#include <algorithm>

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
  return edges_of(triangles, vertices.size());
}

}  // namespace exactgeo::remesh
