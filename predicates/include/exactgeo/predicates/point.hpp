#pragma once

#include <array>
#include <cstdint>
#include <limits>

namespace exactgeo {

static_assert(std::numeric_limits<double>::is_iec559,
              "exactgeo needs IEEE 754 binary64 doubles with round-to-nearest arithmetic");

/// A point or a vector in 3D, with coordinates exactly as given by the caller.
using Point3 = std::array<double, 3>;
using Vector3 = std::array<double, 3>;

/// The position of a point in a list of points (a mesh's vertices, a face set's corners).
using VertexIndex = std::uint32_t;
/// No vertex: a slot that holds none.
inline constexpr VertexIndex kNoVertex = std::numeric_limits<VertexIndex>::max();

/// The position of a face in a list of faces (a mesh's, a mesh step's triangles).
using FaceIndex = std::uint32_t;

}  // namespace exactgeo
