#pragma once

// The image under F of the boundary of the CCD domain: the corner images, and the faces
// over them (SurfaceFace, for the crossing parity predicate).
//
// Vertex-face, F(t, u, v) = v(t) - [(1-u-v) f0(t) + u f1(t) + v f2(t)], t in [0,1], (u, v)
// in the unit triangle: the domain is a prism. Its corners map to c_tj = v(t) - fj(t)
// (index 3t + j); the faces t = 0 and t = 1 map to triangles, the three side faces to
// bilinear patches in (t, parameter along the triangle's edge).
//
// Edge-edge, F(t, u, v) = [(1-u) ea0(t) + u ea1(t)] - [(1-v) eb0(t) + v eb1(t)] on [0,1]^3:
// a cube whose corners map to c_tij = eai(t) - ebj(t) (index 4t + 2i + j) and whose six
// faces map to bilinear patches.
//
// F is affine in each parameter, so a face with two free parameters maps to the bilinear
// patch through its four corner images. Every corner is a difference of two input points:
// an Offset with the ray origin at 0.

#include <array>
#include <cstddef>

#include "exactgeo/ccd/queries.hpp"
#include "exactgeo/predicates/crossing_parity.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"

namespace exactgeo::ccd::internal {

using exactgeo::kernel::Offset;
using exactgeo::kernel::Offsets;

inline constexpr std::array<SurfaceFace, 5> kPrismFaces{{
    SurfaceFace::triangle(0, 1, 2),  // t = 0
    SurfaceFace::triangle(3, 4, 5),  // t = 1
    SurfaceFace::patch(0, 3, 4, 1),  // v = 0: edge f0 f1, parameters (t, u)
    SurfaceFace::patch(1, 4, 5, 2),  // u + v = 1: edge f1 f2
    SurfaceFace::patch(0, 3, 5, 2),  // u = 0: edge f0 f2, parameters (t, v)
}};

// The time slices of edge-edge are parallelograms whatever the input: c_t1j - c_t0j =
// ea1(t) - ea0(t) for both j. Exactly so for every piece of the step too (its corners are
// exact combinations of these), so their flatness is known without a volume sign.
inline constexpr SurfaceFace::Kind kParallelogram = SurfaceFace::Kind::parallelogram;
inline constexpr std::array<SurfaceFace, 6> kHexahedronFaces{{
    SurfaceFace::patch(0, 2, 3, 1, kParallelogram),  // t = 0, parameters (u, v)
    SurfaceFace::patch(4, 6, 7, 5, kParallelogram),  // t = 1
    SurfaceFace::patch(0, 4, 5, 1),                  // u = 0, parameters (t, v)
    SurfaceFace::patch(2, 6, 7, 3),                  // u = 1
    SurfaceFace::patch(0, 4, 6, 2),                  // v = 0, parameters (t, u)
    SurfaceFace::patch(1, 5, 7, 3),                  // v = 1
}};

/// The faces of the domain with C corners: the prism (6) or the hexahedron (8). Corners
/// 0 .. C/2 - 1 are at the start of the time interval, the others at its end.
template <std::size_t C>
inline constexpr auto kDomainFaces = [] {
  static_assert(C == 6 || C == 8);
  if constexpr (C == 6) {
    return kPrismFaces;
  } else {
    return kHexahedronFaces;
  }
}();

/// Corners of time slice `slice` (0: the start, 1: the end) in order around its polygon
/// (the time faces above), rounded to doubles.
template <std::size_t C>
std::array<Vector3, C / 2> slice_corners(const Offsets<C>& a, std::size_t slice) noexcept {
  constexpr std::size_t H = C / 2;
  constexpr std::array<std::size_t, H> kAround = [] {
    if constexpr (H == 3) {
      return std::array<std::size_t, 3>{0, 1, 2};
    } else {
      return std::array<std::size_t, 4>{0, 2, 3, 1};
    }
  }();
  std::array<Vector3, H> x;
  for (std::size_t k = 0; k < H; ++k)
    x[k] = a[slice * H + kAround[k]].rounded();
  return x;
}

/// The corner images, as views into the query's points: the query must outlive them.
inline Offsets<6> corner_images(const VertexFaceQuery& q) noexcept {
  return {Offset::between(q.f0_t0, q.v_t0), Offset::between(q.f1_t0, q.v_t0),
          Offset::between(q.f2_t0, q.v_t0), Offset::between(q.f0_t1, q.v_t1),
          Offset::between(q.f1_t1, q.v_t1), Offset::between(q.f2_t1, q.v_t1)};
}

inline Offsets<8> corner_images(const EdgeEdgeQuery& q) noexcept {
  // Corner 4t + 2i + j = eai(t) - ebj(t).
  return {Offset::between(q.eb0_t0, q.ea0_t0), Offset::between(q.eb1_t0, q.ea0_t0),
          Offset::between(q.eb0_t0, q.ea1_t0), Offset::between(q.eb1_t0, q.ea1_t0),
          Offset::between(q.eb0_t1, q.ea0_t1), Offset::between(q.eb1_t1, q.ea0_t1),
          Offset::between(q.eb0_t1, q.ea1_t1), Offset::between(q.eb1_t1, q.ea1_t1)};
}

}  // namespace exactgeo::ccd::internal
