#pragma once

// Root parity over a boundary image, for any sign policy: cast rays from the origin in the
// fixed direction sequence until one meets no face's boundary, and count its crossings.

#include <array>
#include <cstddef>

#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/ray_directions.hpp"
#include "exactgeo/ccd/root_parity.hpp"
#include "exactgeo/predicates/crossing.hpp"
#include "exactgeo/predicates/internal/patch_frame.hpp"
#include "exactgeo/predicates/internal/ray_patch_core.hpp"
#include "exactgeo/predicates/internal/ray_triangle_core.hpp"

namespace exactgeo::ccd::internal {

namespace in = exactgeo::internal;

/// A patch face's corners in the order of the ray-patch core (p00, p10, p01, p11).
template <std::size_t C>
Offsets<4> patch_corners(const Offsets<C>& corners, const Face& face) noexcept {
  return {corners[face.corners[0]], corners[face.corners[1]], corners[face.corners[3]],
          corners[face.corners[2]]};
}

template <class Signs, std::size_t C>
Crossing cross_face(const Signs& signs, const Offsets<C>& corners, const Face& face,
                    const in::PatchFrame& frame, const Offset& direction) noexcept {
  if (face.kind == Face::Kind::triangle) {
    return crossing_of(in::classify_ray_triangle_offsets(signs, corners[face.corners[0]],
                                                         corners[face.corners[1]],
                                                         corners[face.corners[2]], direction)
                           .kind);
  }
  return crossing_of(
      in::ray_patch_parity_offsets(signs, frame, patch_corners(corners, face), direction));
}

template <class Signs, std::size_t C, std::size_t F>
RootParityResult root_parity(const Signs& signs, const BoundaryImage<C, F>& image) noexcept {
  std::array<in::PatchFrame, F> frames{};
  for (std::size_t f = 0; f < F; ++f) {
    if (image.faces[f].kind != Face::Kind::triangle) {
      frames[f] = in::patch_frame_from_offsets(signs, patch_corners(image.corners, image.faces[f]),
                                               image.faces[f].kind == Face::Kind::parallelogram
                                                   ? in::KnownShape::parallelogram
                                                   : in::KnownShape::none);
    }
  }
  for (std::size_t k = 0; k < kRayDirectionCount; ++k) {
    const Offset direction = Offset::vector(kRayDirections[k]);
    const auto rays = static_cast<std::uint8_t>(k + 1);
    // Every det3 sign of a ray test is on corners and the direction: one static bound.
    const auto ray_signs = kernel::with_static_filter(signs, image.corners, kRayDirections[k]);
    int crossings = 0;
    bool clean = true;
    for (std::size_t f = 0; f < F && clean; ++f) {
      switch (cross_face(ray_signs, image.corners, image.faces[f], frames[f], direction)) {
        case Crossing::none:
          break;
        case Crossing::crossed:
          ++crossings;
          break;
        case Crossing::origin_on:
          return {RootParity::boundary_root, rays};
        case Crossing::ambiguous:
          clean = false;
          break;
      }
    }
    if (clean) return {crossings % 2 == 1 ? RootParity::odd : RootParity::even, rays};
  }
  // Unreachable for exact signs (ray_directions.hpp proves some direction is clean); with
  // plain double signs, a conservative "collision".
  return {RootParity::odd, static_cast<std::uint8_t>(kRayDirectionCount)};
}

}  // namespace exactgeo::ccd::internal
