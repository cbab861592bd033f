#pragma once

// Open surfaces for the open-surface tests: a mesh scaled by a power of two, a ribbon
// with long rims, a sphere with holes of every size, a sheet with hundreds of holes and
// long slits, and a box without its top.

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>
#include <random>

#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::testing {

using mesh::Mesh;

/// The mesh times 2^k (exact, away from the ends of the double range).
inline Mesh scaled(Mesh mesh, int k) {
  for (Point3& v : mesh.vertices) {
    for (double& x : v)
      x = std::ldexp(x, k);
  }
  return mesh;
}

/// A ribbon of n quads (2n triangles) wound twice around the unit sphere from pole to
/// pole, about 0.1 wide: its two rims have n edges each.
inline Mesh ribbon(std::size_t n) {
  Mesh mesh;
  for (std::size_t i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n);
    const double polar = 0.2 + 2.7 * t, around = 4 * std::numbers::pi * t;
    for (const double r : {0.95, 1.05}) {
      mesh.vertices.push_back({r * std::sin(polar) * std::cos(around),
                               r * std::sin(polar) * std::sin(around),
                               r * std::cos(polar) + 0.05 * (r - 1) * 20});
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto a = static_cast<VertexIndex>(2 * i);
    mesh.faces.push_back(mesh::make_triangle(a, a + 2, a + 1));
    mesh.faces.push_back(mesh::make_triangle(a + 1, a + 2, a + 3));
  }
  return mesh;
}

/// A latitude-longitude sphere of triangles (rings from polar angle 0.1 to pi - 0.1, so
/// two small holes at the poles) with caps and random faces cut out: holes of every size.
inline Mesh holed_sphere(std::mt19937_64& rng, std::size_t rings, std::size_t sectors) {
  Mesh mesh;
  for (std::size_t i = 0; i <= rings; ++i) {
    const double polar =
        0.1 + (std::numbers::pi - 0.2) * static_cast<double>(i) / static_cast<double>(rings);
    for (std::size_t j = 0; j < sectors; ++j) {
      const double around =
          2 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(sectors);
      mesh.vertices.push_back({std::sin(polar) * std::cos(around),
                               std::sin(polar) * std::sin(around), std::cos(polar)});
    }
  }
  std::uniform_int_distribution<std::size_t> coin(0, 40);
  const auto at = [&](std::size_t i, std::size_t j) {
    return static_cast<VertexIndex>(i * sectors + j % sectors);
  };
  for (std::size_t i = 0; i < rings; ++i) {
    for (std::size_t j = 0; j < sectors; ++j) {
      // A window of 6 x 8 quads on one side, and one face in 41 elsewhere.
      const bool window = i >= rings / 3 && i < rings / 3 + 6 && j < 8;
      if (window) continue;
      if (coin(rng) != 0)
        mesh.faces.push_back(mesh::make_triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1)));
      if (coin(rng) != 0)
        mesh.faces.push_back(mesh::make_triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1)));
    }
  }
  return mesh;
}

/// A wavy sheet of 2 n^2 triangles over the unit square with many holes: each triangle
/// cut out with probability 1 / `one_in` (hundreds of small holes, some merged), and
/// slits, every fourth row of cells from the third, cut along all but two cells at each
/// end (long rims: about 4 n edges each).
inline Mesh perforated_sheet(std::mt19937_64& rng, std::size_t n, std::size_t one_in) {
  Mesh mesh;
  for (std::size_t j = 0; j <= n; ++j) {
    for (std::size_t i = 0; i <= n; ++i) {
      const double x = static_cast<double>(i) / static_cast<double>(n);
      const double y = static_cast<double>(j) / static_cast<double>(n);
      mesh.vertices.push_back({x, y, 0.15 * std::sin(3 * x) * std::cos(2 * y) + 0.05 * x * y});
    }
  }
  const auto at = [&](std::size_t i, std::size_t j) {
    return static_cast<VertexIndex>(j * (n + 1) + i);
  };
  std::uniform_int_distribution<std::size_t> coin(0, one_in - 1);
  for (std::size_t j = 0; j < n; ++j) {
    const bool slit_row = j % 4 == 2 && j + 2 < n;
    for (std::size_t i = 0; i < n; ++i) {
      if (slit_row && i >= 2 && i + 2 < n) continue;
      if (coin(rng) != 0)
        mesh.faces.push_back(mesh::make_triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1)));
      if (coin(rng) != 0)
        mesh.faces.push_back(mesh::make_triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1)));
    }
  }
  return mesh;
}

/// The box [0, 2^k]^3 without its top face z = 2^k, every other face split into n x n
/// quads, counter-clockwise seen from outside: a rim of 4n edges.
inline Mesh open_box_of_quads(int n, int k) {
  Mesh mesh;
  std::map<std::array<double, 3>, VertexIndex> index;
  const auto vertex = [&](const Point3& p) {
    const auto [it, added] = index.try_emplace(p, static_cast<VertexIndex>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(p);
    return it->second;
  };
  const double side = std::ldexp(1.0, k);
  struct Face {
    Point3 origin;
    int u, v;  // axes, u x v the outward normal
  };
  const std::array<Face, 5> faces{{{{0, 0, 0}, 1, 0},
                                   {{0, 0, 0}, 2, 1},
                                   {{side, 0, 0}, 1, 2},
                                   {{0, 0, 0}, 0, 2},
                                   {{0, side, 0}, 2, 0}}};
  for (const Face& f : faces) {
    const auto at = [&](int i, int j) {
      Point3 p = f.origin;
      p[f.u] += side * i / n;
      p[f.v] += side * j / n;
      return vertex(p);
    };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j)
        mesh.faces.push_back(
            mesh::make_quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)));
    }
  }
  return mesh;
}

}  // namespace exactgeo::testing
