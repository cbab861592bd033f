#pragma once

// A triangle surface, as every library that works on one sees it: the positions of its
// vertices and its triangles, each three vertex indices (corner order gives its facing),
// with the edges they make and which triangles meet at each. Mesh CCD takes the triangles
// (ccd::MeshCcd), the remesher changes the surface (remesh::Surface adds which vertices
// are fixed), the self-intersection finder checks it (mesh::find_self_intersections), and
// exactgeo-cloth simulates it: one picture of a surface for all of them. (mesh::Mesh, the
// point-in-volume mesh, also holds quads.)

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo {

/// Three vertex indices, in the order that gives the triangle its facing.
using Triangle = std::array<VertexIndex, 3>;
/// An edge: two vertex indices, the smaller first.
using Edge = std::array<VertexIndex, 2>;

inline Edge edge_of(VertexIndex a, VertexIndex b) noexcept {
  return a < b ? Edge{a, b} : Edge{b, a};
}

struct TriangleSurface {
  std::vector<Point3> vertices;
  std::vector<Triangle> triangles;
};

/// A triangle's corner other than a and b. Precondition: a and b are corners of t.
VertexIndex third_corner(const Triangle& t, VertexIndex a, VertexIndex b) noexcept;

/// Whether the triangle is a, b, c in this cyclic order (a walks to b).
bool walks(const Triangle& t, VertexIndex a, VertexIndex b) noexcept;

/// The triangles' edges, each once, sorted. `vertex_count` bounds the indices (a counting
/// sort by the smaller end: linear in the triangles).
std::vector<Edge> edges_of(std::span<const Triangle> triangles, std::size_t vertex_count);

/// The triangles at every edge, found from the edge's smaller end: each triangle's sides
/// bucketed by their smaller vertex (a counting sort, linear in the triangles), so that
/// one edge is looked up among its smaller end's few sides.
class EdgeTriangles {
 public:
  /// No triangles (assign gives it some).
  EdgeTriangles() = default;
  /// Precondition: every index below vertex_count.
  EdgeTriangles(std::span<const Triangle> triangles, std::size_t vertex_count);
  /// The table of `triangles` in place of this one's, in this one's storage (a caller that
  /// builds one per pass keeps it). Precondition: as the constructor's.
  void assign(std::span<const Triangle> triangles, std::size_t vertex_count);
  /// The table of those of `triangles` with a marked corner (marked[v] != 0), the others
  /// left out, in this one's storage: a caller that asks about a few edges (a pass of
  /// operations) marks an end of each and builds no table of the whole surface. on(a, b)
  /// and has(a, b) answer as the whole table's for every edge with a marked end (each
  /// triangle on it has that corner). Precondition: as assign's, and marked.size() at
  /// least vertex_count.
  void assign_marked(std::span<const Triangle> triangles, std::size_t vertex_count,
                     std::span<const std::uint8_t> marked);

  /// The triangles with corners a and b, in triangle order (none for indices out of range).
  std::vector<std::size_t> on(VertexIndex a, VertexIndex b) const;
  /// The same into `found` (cleared first), whose storage a caller asking for many edges
  /// reuses.
  void on(VertexIndex a, VertexIndex b, std::vector<std::size_t>& found) const;
  /// Whether some triangle has corners a and b (on(a, b) not empty, with no vector made).
  bool has(VertexIndex a, VertexIndex b) const noexcept;

 private:
  std::vector<std::size_t> first_;  ///< per vertex: where its sides start in sides_
  struct Side {
    VertexIndex other;  ///< the larger end
    std::size_t triangle;
  };
  std::vector<Side> sides_;
  std::vector<std::size_t> next_;    ///< assign's fill cursor per vertex, kept for its storage
  std::vector<std::size_t> chosen_;  ///< assign_marked's triangles, kept for its storage
};

/// The triangles around every vertex, by index in triangle order: one array bucketed by
/// vertex (a counting sort, linear in the triangles; a vector per vertex would cost an
/// allocation each).
class VertexTriangles {
 public:
  VertexTriangles() = default;
  /// Precondition: every index below vertex_count.
  VertexTriangles(std::span<const Triangle> triangles, std::size_t vertex_count);

  /// These triangles' table in place of the one held, in the same storage (a caller that
  /// makes one per pass clears no array of the surface's size but the vertices' starts).
  void assign(std::span<const Triangle> triangles, std::size_t vertex_count);

  /// The triangles with corner v, in triangle order. Precondition: v < vertex_count.
  std::span<const std::size_t> operator[](VertexIndex v) const noexcept {
    return std::span(triangles_).subspan(first_[v], first_[v + 1] - first_[v]);
  }

 private:
  std::vector<std::size_t> first_;      ///< per vertex: where its triangles start
  std::vector<std::size_t> triangles_;  ///< triangle indices, bucketed by vertex
  std::vector<std::size_t> next_;       ///< assign's fill cursor per vertex, kept for its storage
};

}  // namespace exactgeo
