#pragma once

// Root parity over the corner images of a CCD domain, for any sign policy: the crossing
// parity predicate (exactgeo/predicates/crossing_parity.hpp) on the domain's faces, with
// the origin as the ray origin.

#include <array>
#include <cstddef>

#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "exactgeo/ccd/internal/ray_directions.hpp"
#include "exactgeo/ccd/root_parity.hpp"
#include "exactgeo/predicates/crossing_parity.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::ccd::internal {

template <class Signs, std::size_t C>
RootParityResult root_parity(const Signs& signs, const Offsets<C>& corners) noexcept {
  constexpr auto& faces = kDomainFaces<C>;
  const auto corner = [&corners](VertexIndex i) -> const Offset& { return corners[i]; };
  std::array<PatchSpan, faces.size()> frames;
  for (std::size_t f = 0; f < faces.size(); ++f)
    frames[f] = span_of_offsets(signs, faces[f], corner);
  const PreparedFaces prepared{faces, frames};
  const auto found = crossing_parity(kRayDirectionCount, [&](std::size_t k) {
    // Every det3 sign of a ray test is on corners and the direction: one static bound.
    const auto ray_signs = kernel::with_static_filter(signs, corners, kRayDirections[k]);
    return count_crossings(ray_signs, prepared, corner, Offset::vector(kRayDirections[k]));
  });
  // No clean ray is impossible for exact signs (ray_directions.hpp proves some direction
  // is clean); with plain double signs, a conservative "collision".
  if (!found) return {RootParity::odd, static_cast<std::uint8_t>(kRayDirectionCount)};
  const auto rays = static_cast<std::uint8_t>(found->rays);
  switch (found->parity) {
    case CrossingParity::even:
      return {RootParity::even, rays};
    case CrossingParity::odd:
      return {RootParity::odd, rays};
    case CrossingParity::on_surface:
      break;
  }
  return {RootParity::boundary_root, rays};
}

}  // namespace exactgeo::ccd::internal
