#pragma once

// A pass's swept regions as groups of points for the box queries of boxes/point_groups.hpp:
// a region's corners index the surface's vertices, and its new point (a split's, vertex
// kNoVertex) is appended after them.

#include <array>
#include <span>
#include <vector>

#include "exactgeo/remesh/swept_region.hpp"

namespace exactgeo::remesh::internal {

/// `points` starts with the surface's vertices; `groups` holds each region's four corners.
struct RegionPoints {
  std::vector<Point3> points;
  std::vector<std::array<VertexIndex, 4>> groups;

  RegionPoints(std::span<const Point3> vertices,
               std::span<const std::array<RegionCorner, 4>> regions)
      : points(vertices.begin(), vertices.end()), groups(regions.size()) {
    for (std::size_t r = 0; r < regions.size(); ++r) {
      for (std::size_t k = 0; k < 4; ++k) {
        if (regions[r][k].vertex != kNoVertex) {
          groups[r][k] = regions[r][k].vertex;
        } else {
          groups[r][k] = static_cast<VertexIndex>(points.size());
          points.push_back(regions[r][k].point);
        }
      }
    }
  }
};

}  // namespace exactgeo::remesh::internal
