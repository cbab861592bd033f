#pragma once

// Where to put the separation δ in a minimum-separation test: near the query's smallest
// distance over the step, sampled in plain doubles (only to place δ; an exact oracle
// decides), and around it.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/common/internal/closest_direction.hpp"
#include "exactgeo/ccd/queries.hpp"
#include "support/generators.hpp"

namespace exactgeo::ccd {

/// The smallest distance over the step, estimated in plain doubles from samples (only to
/// place δ near it: the oracle decides): at each sampled time, the length of the point of
/// the slice of corner differences (a triangle or a parallelogram) closest to the origin,
/// as closest_direction finds it.
template <class Query>
inline double sampled_distance(Query q, int samples) {
  const std::array<Point3*, 8> p = points(q);
  constexpr std::size_t H = std::is_same_v<Query, VertexFaceQuery> ? 3 : 4;
  constexpr std::array<std::array<int, 2>, H> pairs = [] {
    if constexpr (H == 3) {
      return std::array<std::array<int, 2>, 3>{{{0, 1}, {0, 2}, {0, 3}}};
    } else {
      return std::array<std::array<int, 2>, 4>{{{0, 2}, {0, 3}, {1, 3}, {1, 2}}};
    }
  }();
  double best = INFINITY;
  for (int i = 0; i <= samples; ++i) {
    const double t = static_cast<double>(i) / samples;
    auto at = [&](int k, int axis) {
      return (*p[k])[axis] + t * ((*p[k + 4])[axis] - (*p[k])[axis]);
    };
    std::array<Vector3, H> slice;
    for (std::size_t c = 0; c < H; ++c) {
      for (int axis = 0; axis < 3; ++axis)
        slice[c][axis] = at(pairs[c][0], axis) - at(pairs[c][1], axis);
    }
    const Vector3 closest = internal::closest_direction(slice);
    best = std::min(best, std::sqrt(closest[0] * closest[0] + closest[1] * closest[1] +
                                    closest[2] * closest[2]));
  }
  return best;
}

/// δ values near the query's smallest distance and around it, and some spread ones.
template <class Query>
inline std::vector<double> deltas_for(const Query& q, testing::Rng& rng) {
  const double d = sampled_distance(q, 64);
  std::vector<double> out{std::nextafter(d, 0.0), d, std::nextafter(d, INFINITY)};
  if (std::isfinite(d) && d > 0.0) {
    out.push_back(d * testing::uniform(rng, 0.5, 1.0));
    out.push_back(d * testing::uniform(rng, 1.0, 1.5));
  }
  out.push_back(testing::uniform(rng, 0.0, 1.0));
  out.erase(std::remove_if(out.begin(), out.end(),
                           [](double x) { return !(x > 0.0) || !std::isfinite(x); }),
            out.end());
  return out;
}

}  // namespace exactgeo::ccd
