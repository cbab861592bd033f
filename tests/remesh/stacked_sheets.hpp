#pragma once

// A stack of bumpy sheets, and the same crumpled by collision-safe random moves: the
// surface the random operation tests work on, where many operations would make two
// sheets meet.

#include <cmath>
#include <random>
#include <vector>

#include "exactgeo/remesh/operations.hpp"

namespace exactgeo::testing {

using remesh::Move;
using remesh::Surface;

/// Bumpy n x n sheets of squares of side 1/4 stacked `spacing` apart, heights in steps
/// of 2^-7 up to 12 steps from the plane; all sheets share one triangulation, so the gap
/// between two is linear on each triangle and smallest at a vertex: more than spacing -
/// 24 / 128 > 0.
inline Surface stack(int sheets, int n, std::mt19937_64& rng, double spacing = 0.25) {
  std::uniform_int_distribution<int> bump(-12, 12);
  Surface s;
  for (int k = 0; k < sheets; ++k) {
    const auto first = static_cast<VertexIndex>(s.vertices.size());
    const auto index = [&](int i, int j) {
      return first + static_cast<VertexIndex>(i + (n + 1) * j);
    };
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i)
        s.vertices.push_back({0.25 * i, 0.25 * j, spacing * k + std::ldexp(bump(rng), -7)});
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        s.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
        s.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
      }
    }
  }
  return s;
}

/// The stack crumpled by rounds of random vertical moves (relocate_vertices refuses the
/// colliding ones), so that the sheets come close where the operations' regions reach.
inline void crumple(Surface& surface, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> step(-28, 28);  // in steps of 2^-7
  for (int round = 0; round < 12; ++round) {
    std::vector<Move> moves;
    for (VertexIndex v = 0; v < surface.vertices.size(); ++v) {
      const Point3& p = surface.vertices[v];
      moves.push_back({v, {p[0], p[1], p[2] + std::ldexp(step(rng), -7)}});
    }
    relocate_vertices(surface, moves);
  }
}

/// The surface with every coordinate times 2^exponent: exact, so no predicate's sign
/// changes (the tests' scales 2^0 and 2^+-1000).
inline Surface times_power_of_two(Surface s, int exponent) {
  for (Point3& p : s.vertices) {
    for (double& x : p)
      x = std::ldexp(x, exponent);
  }
  return s;
}

}  // namespace exactgeo::testing
