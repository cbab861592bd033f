#pragma once

// The classic floating-point CCD that exact methods replace: find the times in [0, 1] at
// which the four points are coplanar (the roots of a cubic in t), and at each such time
// test whether the primitives are within a distance `tolerance` of each other (Provot,
// "Collision and self-collision handling in cloth model dedicated to design garments",
// 1997; Bridson, Fedkiw, Anderson, "Robust treatment of collisions, contact and friction
// for cloth animation", SIGGRAPH 2002). Everything is in double precision with
// tolerances, so it both misses collisions and reports false ones; exactgeo ships it only
// as a baseline for measuring that trade.

#include "exactgeo/ccd/queries.hpp"

namespace exactgeo::ccd {

struct CubicOptions {
  /// Distance below which the primitives count as touching at a coplanarity time, in the
  /// queries' units; also how far outside [0, 1] a coplanarity time may lie.
  double tolerance = 1e-6;
};

bool vertex_face_cubic(const VertexFaceQuery& query, const CubicOptions& options = {}) noexcept;
bool edge_edge_cubic(const EdgeEdgeQuery& query, const CubicOptions& options = {}) noexcept;

}  // namespace exactgeo::ccd
