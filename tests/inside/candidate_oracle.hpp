#pragma once

// What the candidate finders' tests share (candidates_test.cpp for Embree,
// tree_candidates_test.cpp for the box tree): meshes with dyadic coordinates, and the
// exact oracle, every face whose corners' convex hull the exact ray touches (the hull
// contains the patch, so this is stronger than "every face the predicate says the ray
// crosses or touches").

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside::candidate_oracle {

using mesh::Face;
using mesh::make_quad;
using mesh::make_triangle;
using mesh::Mesh;

/// A closed torus of nu x nv quads with dyadic coordinates (at most about 24 significant
/// bits), every vertex moved by random dyadic noise so most quads are skew; the first
/// `flat_rings` rings are left planar (flat faces, rays in their planes).
inline Mesh bumpy_torus(std::mt19937_64& rng, int nu, int nv, int scale_exponent, double offset) {
  std::uniform_int_distribution<int> noise(-64, 64);
  Mesh mesh;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      Point3 p{(2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b)};
      for (double& c : p) {
        c = std::ldexp(std::round(std::ldexp(c, 12)) + (i == 0 ? 0 : noise(rng)), -12);
        c = std::ldexp(c, scale_exponent) + offset;
      }
      mesh.vertices.push_back(p);
    }
  }
  const auto index = [&](int i, int j) {
    return static_cast<VertexIndex>(((i + nu) % nu) * nv + (j + nv) % nv);
  };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      if ((i + j) % 7 == 3) {  // some triangles too
        mesh.faces.push_back(make_triangle(index(i, j), index(i + 1, j), index(i + 1, j + 1)));
        mesh.faces.push_back(make_triangle(index(i, j), index(i + 1, j + 1), index(i, j + 1)));
      } else {
        mesh.faces.push_back(
            make_quad(index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)));
      }
    }
  }
  return mesh;
}

/// Whether the exact ray touches the convex hull of the face's corners: some face of the
/// corners' tetrahedron (or the triangle itself) is met (classify_ray_triangle is exact,
/// and reports rays meeting degenerate triangles as `coplanar`, never as a miss).
inline bool touches_hull(const Mesh& mesh, const Face& face, const Point3& origin,
                         const Vector3& d) {
  const auto& v = mesh.vertices;
  const auto& c = face.corners;
  if (face.is_triangle()) {
    return classify_ray_triangle(origin, d, v[c[0]], v[c[1]], v[c[2]]).kind != RayTriangle::miss;
  }
  constexpr int kTetrahedron[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {1, 2, 3}};
  for (const auto& t : kTetrahedron) {
    if (classify_ray_triangle(origin, d, v[c[t[0]]], v[c[t[1]]], v[c[t[2]]]).kind !=
        RayTriangle::miss) {
      return true;
    }
  }
  return false;
}

/// Asserts that the candidates `finder` proposes for (origin, direction k) are sorted,
/// without repeats, and include every face of the oracle (all_faces) whose corners' hull
/// the exact ray touches. Returns how many faces were touched.
template <class Finder>
std::size_t expect_complete(const Mesh& mesh, const Finder& finder, const Point3& origin,
                            std::size_t k) {
  std::vector<FaceIndex> candidates;
  finder.find(origin, k, candidates);
  EXPECT_TRUE(std::is_sorted(candidates.begin(), candidates.end()));
  EXPECT_EQ(std::adjacent_find(candidates.begin(), candidates.end()), candidates.end());
  std::vector<FaceIndex> every_face;
  internal::all_faces(mesh, every_face);
  const Vector3 d = ray_direction(k);
  std::size_t touched = 0;
  for (const FaceIndex f : every_face) {
    if (!touches_hull(mesh, mesh.faces[f], origin, d)) continue;
    ++touched;
    const bool proposed = std::binary_search(candidates.begin(), candidates.end(), f);
    EXPECT_TRUE(proposed) << "face " << f << " missed; origin " << std::hexfloat << origin[0] << " "
                          << origin[1] << " " << origin[2] << std::defaultfloat << ", direction "
                          << k;
  }
  return touched;
}

/// The mapped coordinates of split_box below: the box's half-extent 1/2 + 3 2^-25, which
/// lies halfway between two floats (and rounds up, away from the centre), and grid lines
/// at +-(1/4 + 3 2^-26) (also ties) and 0.
inline constexpr double kTieHalfExtent = 0.5 + 3 * 0x1p-25;
inline constexpr std::array<double, 5> kTieLines{-kTieHalfExtent, -(0.25 + 3 * 0x1p-26), 0.0,
                                                 0.25 + 3 * 0x1p-26, kTieHalfExtent};

/// An axis-aligned box, each face a 4 x 4 grid of quads on its plane, its coordinates
/// kTieLines scaled by 2^k and moved by `centre`: axis-parallel faces whose coordinates
/// map into the float frame exactly halfway between two floats.
inline Mesh split_box(int k, double centre) {
  const auto at = [&](double x) { return std::ldexp(x, k) + centre; };
  const double h = kTieHalfExtent;
  const auto& lines = kTieLines;
  Mesh mesh;
  const auto vertex = [&](const Point3& p) {
    mesh.vertices.push_back({at(p[0]), at(p[1]), at(p[2])});
    return static_cast<VertexIndex>(mesh.vertices.size() - 1);
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {-h, h}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        for (std::size_t j = 0; j + 1 < lines.size(); ++j) {
          std::array<VertexIndex, 4> c;
          const std::array<std::pair<std::size_t, std::size_t>, 4> corners{
              {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
          for (std::size_t m = 0; m < 4; ++m) {
            Point3 p;
            p[axis] = side;
            p[u] = lines[corners[m].first];
            p[v] = lines[corners[m].second];
            c[m] = vertex(p);
          }
          mesh.faces.push_back(make_quad(c[0], c[1], c[2], c[3]));
        }
      }
    }
  }
  return mesh;
}

/// The scales the finders are tested at: 2^0, 2^+-1000, and coordinates moved off centre
/// (so that the float frame's origin is not 0).
struct Magnitude {
  int exponent;
  double offset;
};

inline auto magnitudes() {
  return ::testing::Values(Magnitude{0, 0.0}, Magnitude{1000, 0.0}, Magnitude{-1000, 0.0},
                           Magnitude{0, 0x1p30}, Magnitude{-40, -0x1p-10});
}

inline std::string magnitude_name(const ::testing::TestParamInfo<Magnitude>& info) {
  const Magnitude& m = info.param;
  std::string name = m.exponent < 0 ? "scale_2m" : "scale_2p";
  name.append(std::to_string(std::abs(m.exponent)));
  if (m.offset != 0) name.append("_offset");
  return name;
}

/// The padding at its edge: on split_box (at 2^0, 2^+-1000 and off centre), origins on its
/// faces, edges and corners, which the nearest float moves off the box by the full
/// rounding, outward on half of them; every face the exact ray touches must still be
/// proposed by the finder make_finder(mesh) builds.
template <class MakeFinder>
void expect_complete_from_split_box(std::mt19937_64& rng, const MakeFinder& make_finder) {
  const double h = kTieHalfExtent;
  const auto& lines = kTieLines;
  for (const auto& [k, centre] :
       {std::pair{0, 0.0}, std::pair{1000, 0.0}, std::pair{-1000, 0.0}, std::pair{0, 3.0}}) {
    SCOPED_TRACE(k);
    const auto at = [&](double x) { return std::ldexp(x, k) + centre; };
    const Mesh mesh = split_box(k, centre);
    const auto finder = make_finder(mesh);
    std::uniform_int_distribution<std::size_t> line(0, lines.size() - 1);
    std::uniform_int_distribution<int> odd(0, (1 << 20) - 1);
    std::uniform_int_distribution<std::size_t> direction(0, 40);
    std::size_t touched = 0;
    // 400 origins at full effort (tests/support/seed.hpp), at least one cycle of the axes,
    // sides and kinds of the other coordinates (12).
    const std::size_t trials = testing::scaled_trials(400, 12);
    for (int trial = 0; trial < static_cast<int>(trials); ++trial) {
      // On a face: its coordinate +-h; the others on grid lines (edges and corners) or
      // odd multiples of 2^-26 (ties too, inside a grid cell).
      Point3 p;
      const int axis = trial % 3;
      p[axis] = trial % 2 ? h : -h;
      for (const int other : {(axis + 1) % 3, (axis + 2) % 3}) {
        p[other] = trial % 4 < 2 ? lines[line(rng)] : (2.0 * odd(rng) + 1) * 0x1p-26 - 0.5 * h;
      }
      touched += expect_complete(mesh, finder, {at(p[0]), at(p[1]), at(p[2])}, direction(rng));
    }
    EXPECT_GE(touched, trials);  // every origin lies on at least one face
  }
}

}  // namespace exactgeo::inside::candidate_oracle
