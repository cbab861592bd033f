#pragma once

// A polygon's walk as the sweeps and the certificate read it: its distinct corners
// numbered from 0 (local numbers, in the order of their vertex indices), and its edges as
// a 1-chain: each pair of vertices the walk joins, once, with its net coefficient (the
// times walked from the lower local number to the higher minus the times walked back). A
// bridge to a hole walked there and back has coefficient 0: as a chain it bounds nothing.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "polygon_projection.hpp"
#include "scratch_vector.hpp"

namespace exactgeo::mesh::internal {

/// One pair of vertices of a chain (local numbers, low < high) and its coefficient.
struct ChainEdge {
  std::uint32_t low;
  std::uint32_t high;
  std::int32_t coefficient;
  friend bool operator==(const ChainEdge&, const ChainEdge&) = default;
};

/// An edge of a chain as it is met: from `from` to `to` (local numbers, different).
struct ChainUse {
  std::uint32_t from;
  std::uint32_t to;
};

struct PolygonWalk {
  ScratchVector<VertexIndex> vertices;  ///< local number -> vertex index, ascending
  ScratchVector<ChainEdge> edges;       ///< every pair the walk joins, by (low, high)
  std::size_t corners = 0;              ///< the walk's length
};

/// The corners without those repeated next to themselves (the last is next to the
/// first): an edge of zero length joins nothing.
ScratchVector<VertexIndex> without_repeats(std::span<const VertexIndex> corners);

/// The walk of these corners, each to the next and the last to the first. Precondition:
/// no corner next to an occurrence of itself (the caller drops such repeats).
PolygonWalk walk_of(std::span<const VertexIndex> corners);

/// The local number of vertex `v`, or nullopt when it is not one of the walk's corners.
std::optional<std::uint32_t> local_number(const PolygonWalk& walk, VertexIndex v);

/// The chain of these uses (local numbers below `vertex_count`): each pair once, by
/// (low, high), with its net coefficient (coefficient 0 kept: a pair walked both ways).
ScratchVector<ChainEdge> chain_of(std::span<const ChainUse> uses, std::size_t vertex_count);

/// The walk's local numbers in sweep order (polygon_projection.hpp) of their projections;
/// vertices at one projected position are next to each other, in no particular order.
ScratchVector<std::uint32_t> sweep_order(const PolygonWalk& walk, std::span<const Point3> vertices,
                                         const Projection& plane);

}  // namespace exactgeo::mesh::internal
