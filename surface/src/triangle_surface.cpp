#include "exactgeo/surface/triangle_surface.hpp"

#include <algorithm>

namespace exactgeo {

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

EdgeTriangles::EdgeTriangles(std::span<const Triangle> triangles, std::size_t vertex_count) {
  assign(triangles, vertex_count);
}

void EdgeTriangles::assign(std::span<const Triangle> triangles, std::size_t vertex_count) {
  first_.assign(vertex_count + 1, 0);
  sides_.resize(3 * triangles.size());
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k)
      ++first_[std::min(t[k], t[(k + 1) % 3]) + 1];
  }
  for (std::size_t v = 1; v < first_.size(); ++v)
    first_[v] += first_[v - 1];
  next_.assign(first_.begin(), first_.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge_of(triangles[t][k], triangles[t][(k + 1) % 3]);
      sides_[next_[e[0]]++] = {e[1], t};  // in triangle order within each bucket
    }
  }
}

void EdgeTriangles::assign_marked(std::span<const Triangle> triangles, std::size_t vertex_count,
                                  std::span<const std::uint8_t> marked) {
  // The marked triangles in triangle order, then assign's counting sort over them alone.
  chosen_.clear();
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& c = triangles[t];
    if ((marked[c[0]] | marked[c[1]] | marked[c[2]]) != 0) chosen_.push_back(t);
  }
  first_.assign(vertex_count + 1, 0);
  sides_.resize(3 * chosen_.size());
  for (const std::size_t t : chosen_) {
    const Triangle& c = triangles[t];
    for (int k = 0; k < 3; ++k)
      ++first_[std::min(c[k], c[(k + 1) % 3]) + 1];
  }
  for (std::size_t v = 1; v < first_.size(); ++v)
    first_[v] += first_[v - 1];
  next_.assign(first_.begin(), first_.end() - 1);
  for (const std::size_t t : chosen_) {
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge_of(triangles[t][k], triangles[t][(k + 1) % 3]);
      sides_[next_[e[0]]++] = {e[1], t};  // in triangle order within each bucket
    }
  }
}

std::vector<std::size_t> EdgeTriangles::on(VertexIndex a, VertexIndex b) const {
  std::vector<std::size_t> found;
  on(a, b, found);
  return found;
}

void EdgeTriangles::on(VertexIndex a, VertexIndex b, std::vector<std::size_t>& found) const {
  const Edge e = edge_of(a, b);
  found.clear();
  if (std::size_t{e[0]} + 1 >= first_.size()) return;
  for (std::size_t i = first_[e[0]]; i < first_[e[0] + 1]; ++i) {
    if (sides_[i].other == e[1]) found.push_back(sides_[i].triangle);
  }
}

bool EdgeTriangles::has(VertexIndex a, VertexIndex b) const noexcept {
  const Edge e = edge_of(a, b);
  if (std::size_t{e[0]} + 1 >= first_.size()) return false;
  for (std::size_t i = first_[e[0]]; i < first_[e[0] + 1]; ++i) {
    if (sides_[i].other == e[1]) return true;
  }
  return false;
}

VertexTriangles::VertexTriangles(std::span<const Triangle> triangles, std::size_t vertex_count) {
  assign(triangles, vertex_count);
}

void VertexTriangles::assign(std::span<const Triangle> triangles, std::size_t vertex_count) {
  first_.assign(vertex_count + 1, 0);
  for (const Triangle& t : triangles) {
    for (const VertexIndex v : t)
      ++first_[v + 1];
  }
  for (std::size_t v = 1; v < first_.size(); ++v)
    first_[v] += first_[v - 1];
  triangles_.resize(first_.back());  // every entry written below
  next_.assign(first_.begin(), first_.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (const VertexIndex v : triangles[t])
      triangles_[next_[v]++] = t;
  }
}

std::vector<Edge> edges_of(std::span<const Triangle> triangles, std::size_t vertex_count) {
  // Bucketed by the smaller end, then sorted within each bucket (a vertex's few sides).
  std::vector<std::size_t> first(vertex_count + 1, 0);
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k)
      ++first[std::min(t[k], t[(k + 1) % 3]) + 1];
  }
  for (std::size_t v = 1; v < first.size(); ++v)
    first[v] += first[v - 1];
  std::vector<VertexIndex> larger(first.back());
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge_of(t[k], t[(k + 1) % 3]);
      larger[next[e[0]]++] = e[1];
    }
  }
  std::vector<Edge> edges;
  edges.reserve(larger.size() / 2 + 1);
  for (std::size_t v = 0; v + 1 < first.size(); ++v) {
    const auto begin = larger.begin() + static_cast<std::ptrdiff_t>(first[v]);
    const auto end = larger.begin() + static_cast<std::ptrdiff_t>(first[v + 1]);
    std::sort(begin, end);
    for (auto it = begin; it != end; ++it) {
      if (it == begin || *it != *(it - 1)) edges.push_back({static_cast<VertexIndex>(v), *it});
    }
  }
  return edges;
}

}  // namespace exactgeo
