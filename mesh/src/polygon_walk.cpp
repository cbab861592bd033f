#include "polygon_walk.hpp"

#include <algorithm>
#include <numeric>

namespace exactgeo::mesh::internal {

namespace {

/// The distinct values of `corners`, ascending. Files mostly number a polygon's corners
/// in one run, or nearly: a range at most twice their count is marked off in one pass,
/// anything else sorted.
ScratchVector<VertexIndex> distinct_ascending(std::span<const VertexIndex> corners) {
  const auto [least, most] = std::minmax_element(corners.begin(), corners.end());
  const std::size_t range = static_cast<std::size_t>(*most - *least) + 1;
  ScratchVector<VertexIndex> distinct;
  if (range <= 2 * corners.size()) {
    ScratchVector<char> used(range, 0);
    for (const VertexIndex c : corners)
      used[c - *least] = 1;
    for (std::size_t k = 0; k < range; ++k) {
      if (used[k]) distinct.push_back(static_cast<VertexIndex>(*least + k));
    }
    return distinct;
  }
  distinct.assign(corners.begin(), corners.end());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  return distinct;
}

}  // namespace

ScratchVector<VertexIndex> without_repeats(std::span<const VertexIndex> corners) {
  ScratchVector<VertexIndex> kept;
  kept.reserve(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k) {
    if (corners[k] != corners[k == 0 ? corners.size() - 1 : k - 1]) kept.push_back(corners[k]);
  }
  return kept;
}

PolygonWalk walk_of(std::span<const VertexIndex> corners) {
  PolygonWalk walk;
  walk.corners = corners.size();
  if (corners.empty()) return walk;
  walk.vertices = distinct_ascending(corners);
  ScratchVector<std::uint32_t> local(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k)
    local[k] = *local_number(walk, corners[k]);
  ScratchVector<ChainUse> uses(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k)
    uses[k] = {local[k], local[k + 1 == corners.size() ? 0 : k + 1]};
  walk.edges = chain_of(uses, walk.vertices.size());
  return walk;
}

std::optional<std::uint32_t> local_number(const PolygonWalk& walk, VertexIndex v) {
  if (walk.vertices.empty()) return std::nullopt;
  // Corners numbered in one run: the local number is an offset.
  const VertexIndex front = walk.vertices.front();
  if (walk.vertices.back() - front + 1 == walk.vertices.size()) {
    if (v < front || v > walk.vertices.back()) return std::nullopt;
    return static_cast<std::uint32_t>(v - front);
  }
  const auto found = std::lower_bound(walk.vertices.begin(), walk.vertices.end(), v);
  if (found == walk.vertices.end() || *found != v) return std::nullopt;
  return static_cast<std::uint32_t>(found - walk.vertices.begin());
}

ScratchVector<ChainEdge> chain_of(std::span<const ChainUse> uses, std::size_t vertex_count) {
  // A counting sort by the lower end, then each lower end's few uses by the higher end:
  // linear in the uses and the vertices.
  ScratchVector<std::uint32_t> offset(vertex_count + 1, 0);
  for (const ChainUse& use : uses)
    ++offset[std::min(use.from, use.to) + 1];
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  struct Other {
    std::uint32_t high;
    std::int32_t way;
  };
  ScratchVector<Other> others(uses.size());
  {
    ScratchVector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (const ChainUse& use : uses) {
      const bool forward = use.from < use.to;
      others[fill[forward ? use.from : use.to]++] = {forward ? use.to : use.from, forward ? 1 : -1};
    }
  }
  ScratchVector<ChainEdge> chain;
  chain.reserve(uses.size());
  for (std::uint32_t low = 0; low < vertex_count; ++low) {
    const auto first = others.begin() + offset[low];
    const auto last = others.begin() + offset[low + 1];
    std::sort(first, last, [](const Other& a, const Other& b) { return a.high < b.high; });
    for (auto it = first; it != last;) {
      std::int32_t net = 0;
      const std::uint32_t high = it->high;
      for (; it != last && it->high == high; ++it)
        net += it->way;
      chain.push_back({low, high, net});
    }
  }
  return chain;
}

ScratchVector<std::uint32_t> sweep_order(const PolygonWalk& walk, std::span<const Point3> vertices,
                                         const Projection& plane) {
  // The coordinates beside the numbers, so that the sort reads memory in order.
  struct Keyed {
    double u;
    double v;
    std::uint32_t local;
  };
  ScratchVector<Keyed> keyed(walk.vertices.size());
  for (std::uint32_t k = 0; k < keyed.size(); ++k) {
    const Point3& p = vertices[walk.vertices[k]];
    keyed[k] = {plane.u(p), plane.v(p), k};
  }
  std::sort(keyed.begin(), keyed.end(),
            [](const Keyed& a, const Keyed& b) { return a.u < b.u || (a.u == b.u && a.v < b.v); });
  ScratchVector<std::uint32_t> order(keyed.size());
  std::transform(keyed.begin(), keyed.end(), order.begin(), [](const Keyed& k) { return k.local; });
  return order;
}

}  // namespace exactgeo::mesh::internal
