#include "pass_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "exactgeo/boxes/point_groups.hpp"
#include "region_points.hpp"

namespace exactgeo::remesh::internal {

namespace {

/// go_ahead when every footprint asks for boxes (a pass of collapses): in order, each
/// operation's region boxes against those of the operations already going ahead, first
/// through the box around all of an operation's regions (two region boxes overlap only
/// inside both operations' boxes), with the same float boxes as the box tree's (each
/// corner's rounded outward, united). It costs the operations times those going ahead,
/// where the tree's walk costs every pair of overlapping regions proposed: a remesher
/// proposes thousands of collapses in a pass and applies tens.
std::vector<bool> go_ahead_by_boxes(std::span<const Footprint> operations,
                                    std::span<const std::array<RegionCorner, 4>> regions,
                                    std::span<const std::size_t> first_region,
                                    std::span<const Point3> points) {
  // The float boxes of the regions' corners only, in the scale of all the points (the
  // surface's vertices and the regions' new points, as boxes::point_boxes would take it):
  // the same boxes as the box tree's, without a box for every vertex of the surface.
  std::vector<boxes::FloatBox> region_box(regions.size());
  if (!regions.empty()) {
    double largest = 0.0;
    const auto take = [&](const Point3& p) {
      for (const double x : p)
        largest = std::max(largest, std::fabs(x));
    };
    for (const Point3& p : points)
      take(p);
    for (const auto& region : regions) {
      for (const RegionCorner& c : region)
        if (c.vertex == kNoVertex) take(c.point);
    }
    const boxes::Scale scale(largest);
    std::vector<boxes::FloatBox> vertex_box(points.size());  // each vertex's, once
    std::vector<bool> boxed(points.size(), false);
    const auto corner_box = [&](const RegionCorner& c) {
      if (c.vertex == kNoVertex) return boxes::point_box(c.point, scale);
      if (!boxed[c.vertex]) {
        vertex_box[c.vertex] = boxes::point_box(points[c.vertex], scale);
        boxed[c.vertex] = true;
      }
      return vertex_box[c.vertex];
    };
    for (std::size_t r = 0; r < regions.size(); ++r) {
      region_box[r] = corner_box(regions[r][0]);
      for (std::size_t k = 1; k < 4; ++k)
        region_box[r] = boxes::united(region_box[r], corner_box(regions[r][k]));
    }
  }
  std::vector<bool> ahead(operations.size(), false);
  std::vector<bool> taken(points.size(), false);  // a vertex of an operation going ahead
  std::vector<std::size_t> going;                 // the operations going ahead
  std::vector<boxes::FloatBox> going_box;         // and the box around each one's regions
  for (std::size_t i = 0; i < operations.size(); ++i) {
    const std::vector<VertexIndex>& vertices = operations[i].vertices;
    if (std::any_of(vertices.begin(), vertices.end(), [&](VertexIndex v) { return taken[v]; }))
      continue;
    const std::size_t begin = first_region[i], end = first_region[i + 1];
    bool apart = true;
    if (begin < end) {
      boxes::FloatBox all = region_box[begin];
      for (std::size_t r = begin + 1; r < end; ++r)
        all = boxes::united(all, region_box[r]);
      for (std::size_t g = 0; g < going.size() && apart; ++g) {
        if (!boxes::overlap(all, going_box[g])) continue;
        const std::size_t j = going[g];
        for (std::size_t r = begin; r < end && apart; ++r) {
          for (std::size_t q = first_region[j]; q < first_region[j + 1] && apart; ++q)
            apart = !boxes::overlap(region_box[r], region_box[q]);
        }
      }
      if (apart) {
        going.push_back(i);
        going_box.push_back(all);
      }
    }
    if (!apart) continue;
    ahead[i] = true;
    for (const VertexIndex v : vertices)
      taken[v] = true;
  }
  return ahead;
}

}  // namespace

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
  std::vector<std::size_t> first_region(operations.size() + 1, 0);
  for (std::size_t i = 0; i < operations.size(); ++i)
    first_region[i + 1] = first_region[i] + operations[i].regions.size();
  if (std::all_of(operations.begin(), operations.end(),
                  [](const Footprint& f) { return f.by_boxes; })) {
    return go_ahead_by_boxes(operations, regions, first_region, points);
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
