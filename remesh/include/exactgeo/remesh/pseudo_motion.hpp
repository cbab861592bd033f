#pragma once

// An operation that moves vertices, checked as a motion: a collapse moves both ends of its
// edge to the new point, each on a straight line over one pseudo-time step while every
// other vertex stands (El Topo's pseudo-trajectories). (Relocations, whose pairs need no
// merging, go through the mesh broad phase instead: relocate_vertices.) The
// surface stays intersection free through the step when no vertex-face pair and no
// edge-edge pair that shares no vertex comes into contact: the first contact between two
// triangles that were apart is one of those (exact CCD decides each, ccd.hpp).

#include <optional>
#include <span>

#include "exactgeo/remesh/surface.hpp"
#include "exactgeo/remesh/swept_region.hpp"

namespace exactgeo::remesh {

/// A vertex's straight move over the pseudo-time step.
struct Move {
  VertexIndex vertex = kNoVertex;
  Point3 to{};
};

/// The first element hit while the moves happen together (the other vertices standing),
/// found by exact CCD on every vertex-face and edge-edge pair that shares no vertex and
/// has a moving corner: the triangle a moving vertex touches, the vertex a moving triangle
/// touches, or the edge a moving edge touches; nullopt when nothing is touched. When
/// `merged` names a collapsing edge, its two ends count as one vertex (pairs that share
/// one once merged meet there at the end of the step, which is the collapse itself).
/// A contact CCD could not rule out (a tangential touch at its depth limit) counts.
std::optional<Blocker> first_collision(const Surface& surface, std::span<const Move> moves,
                                       std::optional<Edge> merged = std::nullopt);

}  // namespace exactgeo::remesh
