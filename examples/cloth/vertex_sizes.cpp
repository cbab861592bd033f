#include "vertex_sizes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "float_shortcuts.hpp"

namespace exactgeo::cloth {

namespace {

using remesh::Surface;
using remesh::VertexIndex;

std::array<double, 3> normal(const Surface& s, const remesh::Triangle& t) {
  const Point3 &p = s.vertices[t[0]], &q = s.vertices[t[1]], &r = s.vertices[t[2]];
  const double ux = q[0] - p[0], uy = q[1] - p[1], uz = q[2] - p[2];
  const double vx = r[0] - p[0], vy = r[1] - p[1], vz = r[2] - p[2];
  return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

/// What inner edge e asks for, from its triangles' normals n1 and n2, or nothing (it asks
/// for no less than the largest size, or its triangles do not turn).
std::optional<double> ask_of(std::span<const Material> material, const SheetEdge& e,
                             const std::array<double, 3>& n1, const std::array<double, 3>& n2,
                             const RemeshParameters& p) {
  const std::array<double, 3> c{n1[1] * n2[2] - n1[2] * n2[1], n1[2] * n2[0] - n1[0] * n2[2],
                                n1[0] * n2[1] - n1[1] * n2[0]};
  const double dot = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
  const Material &ma = material[e.a], &mb = material[e.b];
  const double dx = mb[0] - ma[0], dy = mb[1] - ma[1];
  if (asks_no_less_than_max(c, dot, dx * dx + dy * dy, p.max_length, p.turn_per_edge))
    return std::nullopt;
  const double theta = std::atan2(std::hypot(c[0], c[1], c[2]), dot);
  if (!(theta > 0.0)) return std::nullopt;
  return std::hypot(dx, dy) * p.turn_per_edge / theta;
}

}  // namespace

std::vector<double> vertex_sizes(const Surface& s, std::span<const Material> material,
                                 const std::vector<SheetEdge>& edges, const RemeshParameters& p) {
  std::vector<double> size(s.vertices.size(), p.max_length);
  // Each triangle's normal, worked out once for its (up to three) inner edges.
  std::vector<std::array<double, 3>> normals(s.triangles.size());
  std::vector<char> known(s.triangles.size(), 0);
  const auto normal_of = [&](std::size_t t) -> const std::array<double, 3>& {
    if (!known[t]) {
      normals[t] = normal(s, s.triangles[t]);
      known[t] = 1;
    }
    return normals[t];
  };
  for (const SheetEdge& e : edges) {
    if (!e.right) continue;
    const std::optional<double> ask =
        ask_of(material, e, normal_of(e.left), normal_of(*e.right), p);
    if (!ask) continue;
    size[e.a] = std::min(size[e.a], *ask);
    size[e.b] = std::min(size[e.b], *ask);
  }
  for (double& x : size)
    x = std::clamp(x, p.min_length, p.max_length);
  return size;
}

bool update_vertex_sizes(std::vector<double>& size, const Surface& s,
                         std::span<const Material> material, const std::vector<SheetEdge>& edges,
                         const RemeshParameters& p, std::span<const VertexIndex> touched,
                         std::span<const VertexIndex> moved, std::vector<char>& marks) {
  constexpr char kAgain = 1;  // worked out again
  constexpr char kMoved = 2;
  const std::size_t before = size.size();
  size.resize(s.vertices.size());
  marks.assign(s.vertices.size(), 0);
  for (const VertexIndex v : touched)
    marks[v] = kAgain;
  for (std::size_t v = before; v < s.vertices.size(); ++v)
    marks[v] = kAgain;
  for (const VertexIndex v : moved)
    marks[v] |= kMoved;
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    if (marks[v] & kAgain) size[v] = p.max_length;
  // A vertex not worked out again has the edges and triangles it had, so their asks.
  for (const SheetEdge& e : edges) {
    const char m = static_cast<char>(marks[e.a] | marks[e.b]);
    if (m == 0) continue;
    if (m & kMoved) return false;
    if (!e.right) continue;
    const std::optional<double> ask =
        ask_of(material, e, normal(s, s.triangles[e.left]), normal(s, s.triangles[*e.right]), p);
    if (!ask) continue;
    if (marks[e.a] & kAgain) size[e.a] = std::min(size[e.a], *ask);
    if (marks[e.b] & kAgain) size[e.b] = std::min(size[e.b], *ask);
  }
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    if (marks[v] & kAgain) size[v] = std::clamp(size[v], p.min_length, p.max_length);
  return true;
}

}  // namespace exactgeo::cloth
