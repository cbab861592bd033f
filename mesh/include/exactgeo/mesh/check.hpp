#pragma once

// Facts about a mesh that decide whether point-in-volume classification is defined for
// it, and that `exactgeo info` reports. Every geometric fact is exact (orient3d and the
// exact patch classification), every combinatorial one is counted over undirected edges.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/boxes/exact_box.hpp"
#include "exactgeo/mesh/loaded_mesh.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/surface/triangle_surface.hpp"

namespace exactgeo::mesh {

/// How many of something, and the first few of them (indices into the mesh).
template <class T>
struct Examples {
  static constexpr std::size_t kKept = 5;
  std::size_t count = 0;
  std::vector<T> first;  ///< at most kKept, in index order

  void add(const T& item) {
    if (first.size() < kKept) first.push_back(item);
    ++count;
  }
};

using exactgeo::Edge;  // surface/triangle_surface.hpp: smaller index first

using Box = boxes::ExactBox;  ///< a mesh's bounding box (exact doubles)

/// What the checks found about one face (a face can have several of these).
struct FaceFindings {
  bool boundary_edge = false;      ///< one of its edges is used by no other face
  bool non_manifold_edge = false;  ///< one of its edges is used by more than two faces
  bool degenerate = false;         ///< as in MeshCheck::degenerate_faces
  bool zero_area = false;          ///< as in MeshCheck::zero_area_faces
  bool non_planar = false;         ///< a quad whose corners are not coplanar (exact)
};

struct MeshCheck {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t quads = 0;
  std::size_t triangles = 0;
  std::optional<Box> bounding_box;           ///< of the finite vertices; none if there are none
  Examples<std::size_t> out_of_range_faces;  ///< faces with a corner index >= vertices
  /// The corner index that is out of range in the first such face (for the message).
  VertexIndex first_out_of_range_corner = kNoVertex;
  Examples<std::size_t> non_finite_vertices;
  Examples<Edge> boundary_edges;      ///< used by exactly one face
  Examples<Edge> non_manifold_edges;  ///< used by more than two faces
  Examples<Edge> odd_edges;           ///< used by an odd number of faces (subset of the two above)
  /// Used more often in one direction than in the other (a superset of the odd edges).
  /// None: the faces form a closed oriented surface, whose winding numbers are defined,
  /// however they intersect (an edge of four faces, two each way, is balanced).
  Examples<Edge> unbalanced_edges;
  /// Run the same way by at least two more faces than the other way (a subset of the
  /// unbalanced edges): on a closed surface, faces on either side of it face opposite
  /// ways; on an open one, that or a boundary the surface runs twice.
  Examples<Edge> misoriented_edges;
  Examples<std::size_t> degenerate_faces;  ///< a repeated corner index, or zero area (exact)
  /// Of zero area (exact): a segment or a point. They bound nothing, so classification
  /// drops them (after the edge counts, which they keep balanced).
  Examples<std::size_t> zero_area_faces;
  /// A repeated corner index in a face that still spans an area (a quad a, b, c, c is a
  /// triangle written as a quad), which classification does not take.
  Examples<std::size_t> repeated_corner_faces;
  Examples<std::size_t> non_planar_quads;  ///< corners not coplanar (exact orient3d)
  std::size_t unreferenced_vertices = 0;
  std::size_t components = 0;  ///< connected through shared vertices
  /// Every edge used once in each direction; none when some edge is not shared by two faces.
  std::optional<bool> consistently_oriented;
  /// One per face, in face order (faces with an out-of-range corner have none set).
  std::vector<FaceFindings> face_findings;

  bool closed() const noexcept { return boundary_edges.count == 0 && odd_edges.count == 0; }
  bool manifold() const noexcept { return non_manifold_edges.count == 0; }
  /// Every corner index in range and every coordinate finite: the exact predicates'
  /// preconditions, so geometric checks beyond these (self-intersection) can run.
  bool geometry_checkable() const noexcept {
    return out_of_range_faces.count == 0 && non_finite_vertices.count == 0;
  }
};

/// Checks every face and edge. Runs in O(faces log faces).
MeshCheck check_mesh(const Mesh& mesh);

/// What keeps the mesh from bounding a solid that crossing parity can classify points
/// against (exactgeo::inside), as one message with counts and the first few indices, or
/// nullopt if nothing does: no out-of-range index,
/// finite coordinates, at least one face of nonzero area, no repeated corner in a face
/// with an area (faces of zero area are dropped, not refused), every edge shared by an
/// even number of faces, and (unless allow_non_manifold) by exactly two. Vertices and
/// faces are named by `numbering` in the message (from 0, as in the Mesh, by default).
std::optional<std::string> closed_surface_problem(const MeshCheck& check,
                                                  bool allow_non_manifold = false,
                                                  const FileNumbering& numbering = {});

/// What keeps the mesh from having a winding number (closed) or a generalized one (open)
/// that means what its faces say: closed_surface_problem's conditions on indices,
/// coordinates and faces, and, for a closed surface, no misoriented edge (on an open one,
/// a boundary run twice looks the same, so it is taken as given). Boundary and
/// non-manifold edges are fine. nullopt if nothing.
std::optional<std::string> orientable_surface_problem(const MeshCheck& check,
                                                      const FileNumbering& numbering = {});

/// The same message for a mesh read from a file, in the file's own numbering
/// (LoadedMesh::numbering: OBJ counts vertices and faces from 1; OFF, PLY and exactgeo's
/// Mesh from 0; a split polygon's triangles bear its number), saying which.
std::optional<std::string> closed_surface_problem(const MeshCheck& check, const LoadedMesh& loaded,
                                                  bool allow_non_manifold = false);
std::optional<std::string> orientable_surface_problem(const MeshCheck& check,
                                                      const LoadedMesh& loaded);

/// What classification does with the faces of zero area, if there are any: "3 faces of
/// zero area (first: 4, 9, 11) bound nothing: dropped", named by `numbering` (saying how).
std::optional<std::string> zero_area_note(const Examples<std::size_t>& zero_area_faces,
                                          const FileNumbering& numbering);

/// What find_self_intersections found, as one message with faces named by `numbering`
/// (LoadedMesh::numbering: the file's own), e.g. "3 pairs of faces intersect (first: 1-2,
/// 1-5, 4-9); 1 pair undecided (first: 2-3) (faces numbered from 1, as in the file)";
/// nullopt when no pair intersects or is undecided.
std::optional<std::string> self_intersection_problem(const SelfIntersections& found,
                                                     const FileNumbering& numbering);

}  // namespace exactgeo::mesh
