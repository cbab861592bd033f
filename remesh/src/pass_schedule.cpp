#include "pass_schedule.hpp"

#include <algorithm>
#include <utility>

#include "exactgeo/boxes/point_groups.hpp"
#include "region_points.hpp"

namespace exactgeo::remesh::internal {

BoxSchedule::Box BoxSchedule::box_of(const std::array<RegionCorner, 4>& region) noexcept {
  Box box{region[0].point, region[0].point};
  for (std::size_t k = 1; k < 4; ++k)
    box = united(box, Box{region[k].point, region[k].point});
  return box;
}

BoxSchedule::Box BoxSchedule::united(Box a, const Box& b) noexcept {
  for (int i = 0; i < 3; ++i) {
    a.lower[i] = std::min(a.lower[i], b.lower[i]);
    a.upper[i] = std::max(a.upper[i], b.upper[i]);
  }
  return a;
}

bool BoxSchedule::overlap(const Box& a, const Box& b) noexcept {
  for (int i = 0; i < 3; ++i) {
    if (a.upper[i] < b.lower[i] || b.upper[i] < a.lower[i]) return false;
  }
  return true;
}

bool BoxSchedule::take(const Footprint& operation) {
  const std::vector<VertexIndex>& vertices = operation.vertices;
  if (std::any_of(vertices.begin(), vertices.end(), [&](VertexIndex v) { return taken_[v] != 0; }))
    return false;
  own_.clear();
  for (const auto& region : operation.regions)
    own_.push_back(box_of(region));
  if (!own_.empty()) {
    Box all = own_[0];
    for (const Box& b : own_)
      all = united(all, b);
    for (std::size_t g = 0; g < going_.size(); ++g) {
      if (!overlap(all, going_[g])) continue;
      for (const Box& mine : own_) {
        for (std::size_t q = first_[g]; q < first_[g + 1]; ++q)
          if (overlap(mine, region_[q])) return false;
      }
    }
    going_.push_back(all);
    region_.insert(region_.end(), own_.begin(), own_.end());
    first_.push_back(region_.size());
  }
  for (const VertexIndex v : vertices)
    taken_[v] = 1;
  return true;
}

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
  // The regions whose boxes meet each region's.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (!regions.empty()) {
    CornerPoints boxed;  // the corners only: the regions are a few of the surface
    boxed.assign(points.size(), regions);
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
        if (regions_meet(regions[r], regions[other])) {
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
