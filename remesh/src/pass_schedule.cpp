#include "pass_schedule.hpp"

#include <algorithm>
#include <utility>

#include "exactgeo/boxes/point_groups.hpp"
#include "region_points.hpp"

namespace exactgeo::remesh::internal {

std::vector<bool> go_ahead(std::span<const Footprint> operations, std::span<const Point3> points) {
  // Every region of the pass, with its operation, and the pairs whose boxes overlap.
  std::vector<std::array<RegionCorner, 4>> regions;
  std::vector<std::size_t> operation_of;
  for (std::size_t i = 0; i < operations.size(); ++i) {
    for (const auto& r : operations[i].regions) {
      regions.push_back(r);
      operation_of.push_back(i);
    }
  }
  // The regions whose boxes meet each region's.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (!regions.empty()) {
    const RegionPoints boxed(points, regions);
    boxes::overlapping_groups<4>(boxed.points, boxed.groups, [&](std::size_t x, std::size_t y) {
      if (operation_of[x] == operation_of[y]) return;
      pairs.emplace_back(x, y);
      pairs.emplace_back(y, x);
    });
  }
  const Buckets near(regions.size(), pairs);
  std::vector<std::size_t> first_region(operations.size() + 1, 0);
  for (std::size_t i = 0; i < operations.size(); ++i)
    first_region[i + 1] = first_region[i] + operations[i].regions.size();

  std::vector<bool> ahead(operations.size(), false);
  std::vector<bool> taken(points.size(), false);  // a vertex of an operation going ahead
  for (std::size_t i = 0; i < operations.size(); ++i) {
    const std::vector<VertexIndex>& vertices = operations[i].vertices;
    if (std::any_of(vertices.begin(), vertices.end(), [&](VertexIndex v) { return taken[v]; }))
      continue;
    bool apart = true;
    for (std::size_t r = first_region[i]; r < first_region[i + 1] && apart; ++r) {
      for (const std::size_t other : near.of(r)) {
        const std::size_t j = operation_of[other];
        if (!ahead[j]) continue;  // later, or waiting
        const bool by_boxes = operations[i].by_boxes || operations[j].by_boxes;
        if (by_boxes || regions_meet(regions[r], regions[other])) {
          apart = false;
          break;
        }
      }
    }
    if (!apart) continue;
    ahead[i] = true;
    for (const VertexIndex v : vertices)
      taken[v] = true;
  }
  return ahead;
}

std::vector<bool> share_no_vertex(std::span<const std::array<VertexIndex, 4>> operations,
                                  std::size_t vertex_count) {
  std::vector<bool> ahead(operations.size(), false);
  std::vector<bool> taken(vertex_count, false);  // a vertex of an operation going ahead
  for (std::size_t i = 0; i < operations.size(); ++i) {
    const auto& vertices = operations[i];
    if (std::any_of(vertices.begin(), vertices.end(),
                    [&](VertexIndex v) { return v != kNoVertex && taken[v]; }))
      continue;
    ahead[i] = true;
    for (const VertexIndex v : vertices)
      if (v != kNoVertex) taken[v] = true;
  }
  return ahead;
}

}  // namespace exactgeo::remesh::internal
