#include "exactgeo/mesh/weld.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace exactgeo::mesh {

namespace {

using Key = std::array<std::uint64_t, 3>;

// Equal keys for equal coordinates: -0 becomes +0. (Coordinates are finite.)
Key key_of(const Point3& p) {
  Key key;
  for (std::size_t i = 0; i < 3; ++i) {
    key[i] = std::bit_cast<std::uint64_t>(p[i] == 0.0 ? 0.0 : p[i]);
  }
  return key;
}

struct KeyHash {
  std::size_t operator()(const Key& key) const noexcept {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (const std::uint64_t k : key) {
      h ^= k + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
      h *= 0xbf58476d1ce4e5b9ULL;
      h ^= h >> 31;
    }
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

std::vector<VertexIndex> merge_equal_positions(std::vector<Point3>& vertices) {
  const std::size_t n = vertices.size();
  std::unordered_map<Key, VertexIndex, KeyHash> first;
  first.reserve(n);
  std::vector<VertexIndex> new_index(n);
  std::vector<Point3> merged;
  merged.reserve(n);
  for (std::size_t v = 0; v < n; ++v) {
    const auto [it, inserted] =
        first.try_emplace(key_of(vertices[v]), static_cast<VertexIndex>(merged.size()));
    if (inserted) merged.push_back(vertices[v]);
    new_index[v] = it->second;
  }
  if (merged.size() == n) return {};
  vertices = std::move(merged);
  return new_index;
}

std::size_t weld_vertices(Mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  const std::vector<VertexIndex> new_index = merge_equal_positions(mesh.vertices);
  if (new_index.empty()) return 0;
  for (Face& face : mesh.faces) {
    for (VertexIndex& c : face.corners) {
      if (c != kNoVertex) c = new_index[c];
    }
  }
  return n - mesh.vertices.size();
}

namespace {

/// Every edge used by an even number of faces (repeated corners join nothing).
bool every_edge_even(const Mesh& mesh) {
  std::vector<std::pair<VertexIndex, VertexIndex>> edges;
  edges.reserve(4 * mesh.faces.size());
  for (const Face& face : mesh.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      const VertexIndex a = face.corner(i), b = face.corner(i + 1);
      if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t begin = 0; begin < edges.size();) {
    std::size_t end = begin + 1;
    while (end < edges.size() && edges[end] == edges[begin])
      ++end;
    if ((end - begin) % 2 != 0) return false;
    begin = end;
  }
  return true;
}

}  // namespace

std::optional<std::size_t> vertices_welding_closes(const Mesh& mesh) {
  if (every_edge_even(mesh)) return std::nullopt;
  Mesh welded = mesh;
  const std::size_t merged = weld_vertices(welded);
  if (merged == 0 || !every_edge_even(welded)) return std::nullopt;
  return merged;
}

}  // namespace exactgeo::mesh
