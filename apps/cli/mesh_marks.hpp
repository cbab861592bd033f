#pragma once

// What the `--mark OUT.ply` pictures colour, and in which colours: the findings of
// `exactgeo info` on every face, and the colliding vertices, edges and faces of
// `exactgeo ccd-mesh`. The colours are far apart in hue and lightness, and none is close
// to the light grey of an unmarked face.

#include <optional>
#include <span>

#include "cli/marked_ply.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/self_intersection.hpp"

namespace exactgeo::cli {

/// Each face gets the colour of the first of these that applies to it: intersects
/// another face, self-intersection undecided, degenerate, on a non-manifold edge, on a
/// boundary edge, an exactly non-planar quad (a bilinear patch: not a defect, shown
/// because it is what a triangulating tool would change), none of these.
/// `self` is nullopt when the self-intersection check could not run.
MarkedMesh info_marks(const mesh::Mesh& mesh, const mesh::MeshCheck& check,
                      const std::optional<mesh::SelfIntersections>& self);

/// Frame 0 as the triangles the step ran on: the faces of colliding vertex-face pairs,
/// their vertices, the edges of colliding edge-edge pairs (PLY edge elements) and those
/// edges' vertices coloured; everything else grey.
MarkedMesh collision_marks(std::span<const Point3> vertices, std::span<const mesh::Face> triangles,
                           const ccd::MeshCcdResult& result);

}  // namespace exactgeo::cli
