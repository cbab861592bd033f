// Embree's candidates against the exact truth: for every ray, every face whose corners'
// convex hull the exact ray touches must be proposed (the hull contains the patch, so this
// is stronger than "every face the predicate says the ray crosses or touches"). Rays are
// random, and grazing: through mesh vertices, through edge points, along the planes of
// flat faces, from points on faces, at magnitudes from 2^-1000 to 2^1000.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using mesh::Face;
using mesh::make_quad;
using mesh::make_triangle;
using mesh::Mesh;

/// A closed torus of nu x nv quads with dyadic coordinates (at most about 24 significant
/// bits), every vertex moved by random dyadic noise so most quads are skew; the first
/// `flat_rings` rings are left planar (flat faces, rays in their planes).
Mesh bumpy_torus(std::mt19937_64& rng, int nu, int nv, int scale_exponent, double offset) {
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
bool touches_hull(const Mesh& mesh, const Face& face, const Point3& origin, const Vector3& d) {
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

/// Asserts that the candidates for (origin, direction k) include every touched face.
/// Returns how many faces were touched.
std::size_t expect_complete(const Mesh& mesh, const internal::EmbreeCandidates& embree,
                            const Point3& origin, std::size_t k) {
  std::vector<FaceIndex> candidates;
  embree.find(origin, k, candidates);
  EXPECT_TRUE(std::is_sorted(candidates.begin(), candidates.end()));
  const Vector3 d = ray_direction(k);
  std::size_t touched = 0;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!touches_hull(mesh, mesh.faces[f], origin, d)) continue;
    ++touched;
    const bool proposed = std::binary_search(candidates.begin(), candidates.end(), f);
    EXPECT_TRUE(proposed) << "face " << f << " missed; origin " << std::hexfloat << origin[0] << " "
                          << origin[1] << " " << origin[2] << std::defaultfloat << ", direction "
                          << k;
  }
  return touched;
}

struct Magnitude {
  int exponent;
  double offset;
};

class EmbreeCandidatesTest : public ::testing::TestWithParam<Magnitude> {};

TEST_P(EmbreeCandidatesTest, IncludeEveryFaceTheExactRayTouches) {
  auto rng = testing::seeded_engine("inside.candidates");
  const Magnitude m = GetParam();
  const Mesh mesh = bumpy_torus(rng, 24, 12, m.exponent, m.offset);
  const internal::EmbreeCandidates embree(mesh, *internal::corner_box(mesh));
  const auto at = [&](double x) { return std::ldexp(x, m.exponent) + m.offset; };
  std::uniform_real_distribution<double> box(-3.2, 3.2);
  std::uniform_int_distribution<std::size_t> direction(0, 40);
  std::uniform_int_distribution<std::size_t> vertex(0, mesh.vertices.size() - 1);
  std::uniform_int_distribution<std::size_t> face(0, mesh.faces.size() - 1);
  std::uniform_int_distribution<int> step(1, 64);
  // An origin on the line through `target` along direction k, a dyadic distance before
  // it: the ray passes exactly through the target (when the subtraction is exact, which
  // it is for these dyadic coordinates at every tested magnitude).
  const auto before = [&](const Point3& target, std::size_t k) {
    const Vector3 d = ray_direction(k);
    const double s = std::ldexp(step(rng), m.exponent - 8);
    return Point3{target[0] - s * d[0], target[1] - s * d[1], target[2] - s * d[2]};
  };

  // Extreme magnitudes send the exact predicates to GMP (products leave the double
  // range), about 100 times slower: fewer rays there.
  const int trials = std::abs(m.exponent) > 100 ? 24 : 400;
  std::size_t touched = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const std::size_t k = direction(rng);
    // Random origins in the box.
    touched +=
        expect_complete(mesh, embree, Point3{at(box(rng)), at(box(rng)), at(box(rng) / 2)}, k);
    // Rays through a vertex, and origins at a vertex.
    const Point3& v = mesh.vertices[vertex(rng)];
    touched += expect_complete(mesh, embree, before(v, k), k);
    touched += expect_complete(mesh, embree, v, k);
    // Rays through the midpoint of a face's edge, and origins there.
    const Face& f = mesh.faces[face(rng)];
    const Point3& a = mesh.vertices[f.corners[0]];
    const Point3& b = mesh.vertices[f.corners[1]];
    const Point3 mid{a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2};
    touched += expect_complete(mesh, embree, before(mid, k), k);
    touched += expect_complete(mesh, embree, mid, k);
  }
  // The test is only meaningful if rays touch faces.
  EXPECT_GT(touched, 10u * static_cast<std::size_t>(trials));
}

INSTANTIATE_TEST_SUITE_P(Magnitudes, EmbreeCandidatesTest,
                         ::testing::Values(Magnitude{0, 0.0}, Magnitude{1000, 0.0},
                                           Magnitude{-1000, 0.0}, Magnitude{0, 0x1p30},
                                           Magnitude{-40, -0x1p-10}),
                         [](const ::testing::TestParamInfo<Magnitude>& param_info) {
                           const Magnitude& m = param_info.param;
                           std::string name = m.exponent < 0 ? "scale_2m" : "scale_2p";
                           name.append(std::to_string(std::abs(m.exponent)));
                           if (m.offset != 0) name.append("_offset");
                           return name;
                         });

/// The padding at its edge: an axis-aligned box, its faces split in a grid, whose face
/// and grid coordinates map into the float frame exactly halfway between two floats, so
/// that the nearest float (ties to even) moves an origin on them off the box by the full
/// rounding, 2^-25 in frame units (for |x| in [1/2, 1)), outward on half of them. Origins
/// on the faces, edges and corners then sit on or beyond a float box's face, and Embree's
/// slab arithmetic decides the rest: every face the exact ray touches must still be
/// proposed. (With kPad at 2^-25 or below, or 0, this test finds misses.)
TEST(EmbreeCandidates, OriginsOnAxisAlignedFacesWhoseCoordinatesAreNotFloats) {
  auto rng = testing::seeded_engine("inside.candidates.ties");
  // Mapped coordinates: the box's half-extent 1/2 + 3 2^-25 (between two floats, rounds
  // up, away from the centre), grid lines at +-(1/4 + 3 2^-26) (also ties) and 0.
  const double h = 0.5 + 3 * 0x1p-25;
  const std::array<double, 5> lines{-h, -(0.25 + 3 * 0x1p-26), 0.0, 0.25 + 3 * 0x1p-26, h};
  for (const auto& [k, centre] :
       {std::pair{0, 0.0}, std::pair{1000, 0.0}, std::pair{-1000, 0.0}, std::pair{0, 3.0}}) {
    SCOPED_TRACE(k);
    const auto at = [&](double x) { return std::ldexp(x, k) + centre; };
    // Each face a 4 x 4 grid of quads on its plane.
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
    const internal::EmbreeCandidates embree(mesh, *internal::corner_box(mesh));
    std::uniform_int_distribution<std::size_t> line(0, lines.size() - 1);
    std::uniform_int_distribution<int> odd(0, (1 << 20) - 1);
    std::uniform_int_distribution<std::size_t> direction(0, 40);
    std::size_t touched = 0;
    for (int trial = 0; trial < 400; ++trial) {
      // On a face: its coordinate +-h; the others on grid lines (edges and corners) or
      // odd multiples of 2^-26 (ties too, inside a grid cell).
      Point3 p;
      const int axis = trial % 3;
      p[axis] = trial % 2 ? h : -h;
      for (const int other : {(axis + 1) % 3, (axis + 2) % 3}) {
        p[other] = trial % 4 < 2 ? lines[line(rng)] : (2.0 * odd(rng) + 1) * 0x1p-26 - 0.5 * h;
      }
      touched += expect_complete(mesh, embree, {at(p[0]), at(p[1]), at(p[2])}, direction(rng));
    }
    EXPECT_GE(touched, 400u);  // every origin lies on at least one face
  }
}

}  // namespace
}  // namespace exactgeo::inside
