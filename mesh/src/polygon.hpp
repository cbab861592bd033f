#pragma once

// A file's faces as its reader meets them: triangles and quads are kept as they are;
// faces of more than four corners wait until every vertex is read, then become triangles
// (polygon_triangulation.hpp), and messages keep the file's face numbers.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "exactgeo/mesh/loaded_mesh.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh::internal {

/// The most vertices a mesh can index: every index is below kNoVertex.
inline constexpr std::size_t kMaxVertices = kNoVertex;

class FileFaces {
 public:
  /// Adds the file's next face, whose corners are indices already checked to be in range
  /// (or, in OBJ, checked before finish); `line` is its line in a text file, 0 in a
  /// binary one. Returns nullopt, or the reason the face is refused (fewer than three
  /// corners) for the caller to report with its place.
  std::optional<std::string> add(std::span<const VertexIndex> corners, std::size_t line,
                                 LoadedMesh& out);

  /// Once every vertex is read: welds the vertices when options.weld asks (before the
  /// polygons are split, so that a polygon's corners written twice at one position are one
  /// corner), splits each polygon of more than four corners into
  /// triangles in place, exactly when it is flat, else into a fan when
  /// options.split_polygons asks (with a note in out.notes), and keeps the file's face
  /// numbers in out.numbering. Throws io::InputError naming `source`, the face and its
  /// line for a polygon refused, or when the file has no face.
  void finish(LoadedMesh& out, const std::string& source, const LoadOptions& options);

 private:
  /// merge_equal_positions on the vertices, with every face and polygon re-indexed.
  void weld(LoadedMesh& out);

  struct Polygon {
    std::size_t face;   ///< its place among the file's faces, from 0
    std::size_t line;   ///< 0 in a binary file
    std::size_t begin;  ///< its corners: corners_[begin, end)
    std::size_t end;
  };
  std::vector<VertexIndex> corners_;
  std::vector<Polygon> polygons_;
};

/// nullopt when a 0-based vertex index (OFF, PLY) names one of `vertex_count` vertices,
/// else the reason it does not, for the caller to report with its place.
std::optional<std::string> zero_based_index_problem(std::int64_t index, std::uint64_t vertex_count);

/// Throws InputError("<source>: ... no faces") when the mesh has no face.
void require_faces(const LoadedMesh& loaded, const std::string& source);

}  // namespace exactgeo::mesh::internal
