#pragma once

// What one face contributes to a crossing-parity count along a ray, the same for root
// parity (CCD) and point-in-volume: the detailed answers of the ray-triangle and
// ray-patch predicates, reduced to what a parity count needs.

#include <cstdint>

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"

namespace exactgeo {

enum class Crossing : std::uint8_t {
  none,       ///< an even number of crossings (none, for a triangle)
  crossed,    ///< an odd number of crossings
  origin_on,  ///< the ray's origin lies on the face
  ambiguous,  ///< the ray meets an edge or a vertex, or lies in a flat face's plane: recast
};

constexpr Crossing crossing_of(RayTriangle kind) noexcept {
  switch (kind) {
    case RayTriangle::miss:
      return Crossing::none;
    case RayTriangle::interior:
      return Crossing::crossed;
    case RayTriangle::origin_on:
      return Crossing::origin_on;
    case RayTriangle::edge:
    case RayTriangle::vertex:
    case RayTriangle::coplanar:
      break;
  }
  return Crossing::ambiguous;
}

constexpr Crossing crossing_of(RayPatch parity) noexcept {
  switch (parity) {
    case RayPatch::even:
      return Crossing::none;
    case RayPatch::odd:
      return Crossing::crossed;
    case RayPatch::origin_on_patch:
      return Crossing::origin_on;
    case RayPatch::degenerate:
      break;
  }
  return Crossing::ambiguous;
}

}  // namespace exactgeo
