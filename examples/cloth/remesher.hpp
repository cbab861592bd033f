#pragma once

// Adaptive remeshing of the sheets between time steps, every operation collision safe
// (exactgeo/remesh/operations.hpp decides each one exactly against the whole mesh,
// obstacles included, which are fixed).
//
// Sizing: the sheets should turn by at most `turn_per_edge` radians across an edge. An
// inner edge whose two triangles meet at dihedral angle theta over an edge of length L
// asks for edges of L * turn_per_edge / theta around it; a vertex takes the smallest ask
// of its edges, clamped to [min_length, max_length], and an edge the smaller of its ends'.
// Lengths are rest lengths (material coordinates), which the model keeps the sheets near.
//
// A remesh is: split passes (edges longer than 4/3 of their size, at their midpoint,
// longest first), collapse passes (edges shorter than 4/5 of their size, shortest first,
// when no edge made would be split again and no triangle turns over in the material; an
// end that is a corner of a sheet's outline stays), then flip passes (inner edges that are
// not Delaunay in the material). A new vertex takes the midpoint's material coordinates
// and velocity; a collapse keeps the surviving end's. Then the unused vertices go, the
// sheets' vertices and faces first again.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "sheet_edges.hpp"

namespace exactgeo::cloth {

/// The simulated mesh: sheet vertices (those with material coordinates) first, then the
/// obstacles'; sheet faces first.
struct ClothMesh {
  std::vector<double> positions;                ///< 3 per vertex
  std::vector<double> velocity;                 ///< 3 per sheet vertex
  std::vector<std::array<double, 2>> material;  ///< per sheet vertex
  std::vector<ccd::Triangle> faces;
  std::size_t sheet_faces = 0;

  std::size_t sheet_vertices() const noexcept { return material.size(); }
  std::size_t vertex_count() const noexcept { return positions.size() / 3; }
};

struct RemeshParameters {
  double max_length = 0.0;  ///< metres of rest length
  double min_length = 0.0;
  double turn_per_edge = 0.5;  ///< radians
  int passes = 2;              ///< of each kind per remesh
};

/// Operations of one kind, by verdict.
struct VerdictCounts {
  std::size_t applied = 0;
  std::size_t refused_topology = 0;
  std::size_t refused_collision = 0;
  std::size_t deferred = 0;

  void add(remesh::Verdict verdict) noexcept;
  VerdictCounts& operator+=(const VerdictCounts& c) noexcept;
};

struct RemeshCounts {
  VerdictCounts split;
  VerdictCounts collapse;
  VerdictCounts flip;
  double seconds = 0.0;

  RemeshCounts& operator+=(const RemeshCounts& c) noexcept;
};

/// The sheet edge table one remesh leaves for the next (sheet_edges.hpp): that of the mesh
/// it wrote back, which the next remesh given it takes instead of building its own when
/// the mesh's faces and its numbers of vertices and sheet vertices are still the ones
/// written (a time step moves the vertices, not the faces). Caller-owned, kept for a run.
class KeptSheetEdges {
 public:
  /// The table kept for `mesh` (taken out), or none when `mesh` is not the one it was
  /// kept for.
  std::optional<SheetEdgeTable> take_for(const ClothMesh& mesh);
  /// Keeps `table`, the sheet edge table of `mesh`.
  void keep(SheetEdgeTable table, const ClothMesh& mesh);

 private:
  std::optional<SheetEdgeTable> table_;
  std::vector<ccd::Triangle> faces_;  ///< the mesh's it is the table of
  std::size_t vertices_ = 0;
  std::size_t sheet_vertices_ = 0;
};

/// Remeshes the sheets of `mesh` (intersection free, as every operation keeps it).
/// `workspace`: the passes' memory (remesh::PassWorkspace), kept by the caller from one
/// remesh to the next so that each pass reuses it; none, and each pass makes its own.
/// `kept`: the sheet edge table the last remesh left (KeptSheetEdges), taken when it is
/// still the mesh's, and the one of the mesh written back left there; none, and each
/// remesh builds its own. The same operations either way.
RemeshCounts remesh(ClothMesh& mesh, const RemeshParameters& parameters,
                    remesh::PassWorkspace* workspace = nullptr, KeptSheetEdges* kept = nullptr);

}  // namespace exactgeo::cloth
