#pragma once

// Exact root parity CCD (Brochu, Edwards, Bridson, "Efficient Geometrically Exact
// Continuous Collision Detection", SIGGRAPH 2012).
//
// A collision is a root of F(t, u, v) = (point on primitive a at t) - (point on primitive b
// at t) in the closed domain [0,1] x (triangle or square). If F has a root on the domain's
// boundary, that is a collision (touching at t = 0 or 1, or at a primitive's edge or
// vertex). Otherwise the number of crossings of a ray from the origin with the image of
// the boundary has the parity of the number of interior roots. So this method reports
// every boundary root and every odd number of interior roots, and by design cannot see an
// even number (for example two: primitives passing right through each other).
//
// Exact for every finite input. Deterministic: rays come from a fixed sequence (see
// internal/ray_directions.hpp for why it always ends).

#include <cstdint>

#include "exactgeo/ccd/queries.hpp"
#include "exactgeo/predicates/arithmetic.hpp"

namespace exactgeo::ccd {

enum class RootParity : std::uint8_t {
  even,           ///< no boundary root and an even number (maybe 0) of interior roots
  odd,            ///< no boundary root and an odd number of interior roots
  boundary_root,  ///< F vanishes on the domain's boundary
};

struct RootParityResult {
  RootParity parity = RootParity::even;
  std::uint8_t rays = 0;  ///< rays cast (more than 1 when a ray met a face's boundary)

  /// The root parity method's answer: a boundary root or an odd number of roots.
  bool collision() const noexcept { return parity != RootParity::even; }
};

/// Preconditions: finite coordinates.
RootParityResult vertex_face_root_parity(const VertexFaceQuery& query,
                                         Arithmetic arithmetic = Arithmetic::exact) noexcept;
RootParityResult edge_edge_root_parity(const EdgeEdgeQuery& query,
                                       Arithmetic arithmetic = Arithmetic::exact) noexcept;

}  // namespace exactgeo::ccd
