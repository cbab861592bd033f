// The unit frame (internal/unit_frame.hpp): the exact rays of a mesh far from magnitude 1
// run on the mesh and the point multiplied by one power of two, where that is exact. The
// labels must be those of the same mesh and points at magnitude 1 (an exact power of two
// apart, where the frame is off), at 2^+-1000, at 1e300 (rounded there, then brought
// down exactly), near DBL_MAX (a box wider than DBL_MAX) and subnormal; where a point or
// the mesh does not map exactly, the rays run as given and the labels are still exact.

#include "exactgeo/inside/internal/unit_frame.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/load.hpp"
#include "inside/scaled_cube.hpp"
#include "support/hexahedron.hpp"
#include "support/seed.hpp"

namespace exactgeo::inside {
namespace {

using internal::UnitFrame;
using mesh::Mesh;
using testing::hex;

const std::string kMeshes = EXACTGEO_TEST_DATA_DIR "/meshes/";

/// Every coordinate times `factor` (rounded when factor is no power of two).
Mesh times(Mesh mesh, double factor) {
  for (Point3& v : mesh.vertices) {
    for (double& x : v)
      x *= factor;
  }
  return mesh;
}

std::vector<Point3> times(std::vector<Point3> points, double factor) {
  for (Point3& p : points) {
    for (double& x : p)
      x *= factor;
  }
  return points;
}

/// x 2^k, when that is exact.
std::optional<double> exactly_scaled(double x, int k) {
  const double y = std::ldexp(x, k);
  if (std::ldexp(y, -k) != x) return std::nullopt;
  return y;
}

std::optional<Point3> exactly_scaled(const Point3& p, int k) {
  Point3 q;
  for (int i = 0; i < 3; ++i) {
    const std::optional<double> x = exactly_scaled(p[i], k);
    if (!x) return std::nullopt;
    q[i] = *x;
  }
  return q;
}

/// The mesh times 2^k, which must be exact.
Mesh exactly_scaled(Mesh mesh, int k) {
  for (Point3& v : mesh.vertices) {
    const std::optional<Point3> w = exactly_scaled(v, k);
    EXPECT_TRUE(w) << "2^" << k << " is not exact at " << hex(v);
    if (w) v = *w;
  }
  return mesh;
}

/// Coordinates rounded to multiples of 2^-bits (so that 2^-1060 keeps them).
Mesh on_grid(Mesh mesh, int bits) {
  for (Point3& v : mesh.vertices) {
    for (double& x : v)
      x = std::ldexp(std::round(std::ldexp(x, bits)), -bits);
  }
  return mesh;
}

/// Random points of the box (grown by 5%), every vertex, edge midpoints, patch centres
/// and those centres one ulp off along each axis: points on faces, edges and corners, and
/// points as close to them as doubles get.
std::vector<Point3> probes(const Mesh& mesh, std::mt19937_64& rng, std::size_t random) {
  const mesh::Box box = *internal::corner_box(mesh);
  std::vector<Point3> points;
  std::uniform_real_distribution<double> unit(-0.05, 1.05);
  for (std::size_t n = 0; n < random; ++n) {
    Point3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = box.lower[i] / 2 + box.upper[i] / 2 +
             (unit(rng) - 0.5) * (box.upper[i] / 2 - box.lower[i] / 2) * 2;
    points.push_back(p);
  }
  for (const Point3& v : mesh.vertices)
    points.push_back(v);
  for (std::size_t f = 0; f < mesh.faces.size(); f += 7) {
    const mesh::Face& face = mesh.faces[f];
    const Point3& a = mesh.vertices[face.corner(0)];
    const Point3& b = mesh.vertices[face.corner(1)];
    points.push_back({a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2});
    Point3 centre{};
    for (std::size_t k = 0; k < face.size(); ++k) {
      for (int i = 0; i < 3; ++i)
        centre[i] += mesh.vertices[face.corner(k)][i] / static_cast<double>(face.size());
    }
    points.push_back(centre);
    for (int i = 0; i < 3; ++i) {
      for (const double toward : {-INFINITY, INFINITY}) {
        Point3 moved = centre;
        moved[i] = std::nextafter(moved[i], toward);
        points.push_back(moved);
      }
    }
  }
  return points;
}

std::vector<Location> labels(const Classifier& c, const std::vector<Point3>& points) {
  std::vector<Location> out(points.size());
  classify_batch(c, points, out, Arithmetic::exact, 2);
  return out;
}

/// `unit` (a mesh at magnitude 1: the frame is off) and its copy multiplied by 2^k, with
/// the frame on: the copy's labels of the points that 2^k maps exactly, with Embree and
/// cells, and with every face a candidate and no cells, must be unit's.
void expect_same_labels(const std::string& name, const Mesh& unit,
                        const std::vector<Point3>& points, int k) {
  SCOPED_TRACE(name);
  const Mesh far = exactly_scaled(unit, k);
  EXPECT_FALSE(UnitFrame(unit, *internal::corner_box(unit)).on());
  EXPECT_TRUE(UnitFrame(far, *internal::corner_box(far)).on());
  std::vector<Point3> unit_points;
  std::vector<Point3> far_points;
  for (const Point3& p : points) {
    if (const std::optional<Point3> q = exactly_scaled(p, k)) {
      unit_points.push_back(p);
      far_points.push_back(*q);
    }
  }
  EXPECT_GT(far_points.size(), points.size() * 9 / 10);
  const std::vector<Location> expected = labels(Classifier(unit), unit_points);
  const std::vector<Location> got = labels(Classifier(far), far_points);
  std::size_t by_location[3] = {};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ++by_location[static_cast<int>(expected[i])];
    ASSERT_EQ(got[i], expected[i]) << "point " << i << ": " << hex(far_points[i]);
  }
  EXPECT_GT(by_location[static_cast<int>(Location::inside)], 0u);
  EXPECT_GT(by_location[static_cast<int>(Location::outside)], 0u);
  EXPECT_GT(by_location[static_cast<int>(Location::boundary)], 0u);
  const Classifier brute(far, {.candidates = CandidateSearch::brute_force,
                               .allow_non_manifold = false,
                               .space_cells = false});
  for (std::size_t i = 0; i < far_points.size(); i += 5)
    ASSERT_EQ(brute.classify(far_points[i]), expected[i]) << "point " << i << " (brute force)";
}

TEST(UnitFrame, OffInsideTheWindowOnOutsideIt) {
  for (const int k : {-64, 0, 63}) {
    const Mesh cube = testing::scaled_cube(k, false);  // extent 2^k
    EXPECT_FALSE(UnitFrame(cube, *internal::corner_box(cube)).on()) << k;
  }
  for (const int k : {-1074, -1060, -65, 65, 1000, 1023}) {
    SCOPED_TRACE(k);
    const Mesh cube = testing::scaled_cube(k, false);
    const UnitFrame frame(cube, *internal::corner_box(cube));
    ASSERT_TRUE(frame.on());
    // Extent 2^k in [2^(e-1), 2^e): multiplied by 2^-(k+1), the corners are 0 and 1/2.
    EXPECT_EQ(frame.exponent(), -(k + 1));
    EXPECT_EQ(frame.vertices()[7], (Point3{0.5, 0.5, 0.5}));
    EXPECT_EQ(*frame.map({std::ldexp(1.0, k), 0.0, -0.0}), (Point3{0.5, 0.0, -0.0}));
  }
}

TEST(UnitFrame, MapsOnlyExactly) {
  const Mesh cube = testing::scaled_cube(1000, false);
  const UnitFrame frame(cube, *internal::corner_box(cube));
  ASSERT_TRUE(frame.on());
  // 2^-1001 takes 2^-21 to the smallest normal; below it bits go, and far below all.
  EXPECT_EQ(*frame.map({0x1p-21, 3 * 0x1p-21, 1.0}), (Point3{0x1p-1022, 3 * 0x1p-1022, 0x1p-1001}));
  EXPECT_EQ(*frame.map({0x1p-73, 0.0, 0.0}), (Point3{0x1p-1074, 0.0, 0.0}));
  EXPECT_FALSE(frame.map({3 * 0x1p-74, 0.0, 0.0}));  // 1.5 2^-1074
  EXPECT_FALSE(frame.map({1.0, 0x1p-100, 1.0}));
  EXPECT_FALSE(frame.map({1.0, 1.0, -DBL_TRUE_MIN}));
  // Up: a subnormal mesh's frame multiplies by 2^1060; DBL_MAX cannot follow.
  const Mesh tiny = testing::scaled_cube(-1060, false);
  const UnitFrame up(tiny, *internal::corner_box(tiny));
  ASSERT_TRUE(up.on());
  EXPECT_EQ(*up.map({DBL_TRUE_MIN, 0x1p-1000, 0.0}), (Point3{0x1p-15, 0x1p59, 0.0}));
  EXPECT_FALSE(up.map({DBL_TRUE_MIN, DBL_MAX, 0.0}));
}

TEST(UnitFrame, OffWhenAFaceCornerDoesNotMap) {
  // The cube [0, 2^1000]^3 with a second box [c, 2^-20]^3 inside it, c = 2^-30 + 2^-80:
  // 2^-1001 would take c to 2^-1031 + 2^-1081, below the subnormals' last bit, so the frame
  // is off; a copy of the small box's corners that no face uses leaves it on.
  const double c = 0x1p-30 + 0x1p-80;
  Mesh mesh = testing::scaled_cube(1000, true);
  for (const Point3& u : testing::unit_cube_corners())
    mesh.vertices.push_back(
        {u[0] > 0 ? 0x1p-20 : c, u[1] > 0 ? 0x1p-20 : c, u[2] > 0 ? 0x1p-20 : c});
  EXPECT_TRUE(UnitFrame(mesh, *internal::corner_box(mesh)).on());
  for (const auto& f : testing::kHexahedronFaces)
    mesh.faces.push_back(mesh::make_quad(8 + f[0], 8 + f[1], 8 + f[2], 8 + f[3]));
  EXPECT_FALSE(UnitFrame(mesh, *internal::corner_box(mesh)).on());
  // The exact labels (nonzero: 2 in the small box). 2^-30 maps exactly and lies just
  // outside the small box: against the small box rounded by the frame it would lie on it.
  const Classifier classifier(mesh);
  EXPECT_EQ(classifier.classify({0x1p-25, 0x1p-25, 0x1p-25}), Location::inside);
  EXPECT_EQ(classifier.classify({c, 0x1p-25, 0x1p-25}), Location::boundary);
  EXPECT_EQ(classifier.classify({0x1p-30, 0x1p-25, 0x1p-25}), Location::inside);
  EXPECT_EQ(classifier.classify({0x1p-25, 0x1p-25, 0x1p-30}), Location::inside);
  EXPECT_EQ(classifier.classify({0x1p999, 0.0, 0x1p999}), Location::boundary);
  EXPECT_EQ(classifier.classify({0x1p999, 0x1p999, 0x1p1000}), Location::boundary);
  EXPECT_EQ(classifier.classify({0x1p999, 0x1p999, std::nextafter(0x1p1000, 0.0)}),
            Location::inside);
}

TEST(UnitFrame, PointsThatDoNotMapCastRaysAsGiven) {
  // The cube [0, 2^1000]^3 (frame on): points with coordinates far below 2^-21 do not map,
  // and their rays run against the cube as given. Its truth is known exactly.
  for (const bool triangles : {false, true}) {
    const Mesh cube = testing::scaled_cube(1000, triangles);
    const Classifier classifier(cube);
    const Classifier brute(cube, {.candidates = CandidateSearch::brute_force,
                                  .allow_non_manifold = false,
                                  .space_cells = false});
    const double small[] = {0.0, DBL_TRUE_MIN, 0x1p-100, 3 * 0x1p-74, 0x1p500, 0x1p999};
    for (const double x : small) {
      for (const double y : small) {
        for (const double z : {0x1p-60, 0x1p999, 0x1p1000, 0x1.0000000000001p1000}) {
          const Point3 p{x, y, z};
          EXPECT_EQ(classifier.classify(p), testing::cube_truth(p, 1000)) << hex(p);
          EXPECT_EQ(brute.classify(p), testing::cube_truth(p, 1000)) << hex(p);
        }
      }
    }
  }
}

TEST(UnitFrame, SpotFarFromMagnitudeOneLabelsAsAtOne) {
  // Spot's coordinates on a grid of 2^-40 (it has some near 2^-61, which 2^-1000 would
  // round), |x| < 1.05.
  const Mesh spot = on_grid(mesh::load_mesh(kMeshes + "spot/spot_quadrangulated.obj").mesh, 40);
  auto rng = testing::seeded_engine("inside.unit_frame.spot");
  // The random probes scale with the effort (tests/support/seed.hpp); the vertices, edge
  // midpoints and patch centres are all kept.
  const std::size_t random = testing::scaled_trials(3000);
  const std::vector<Point3> points = probes(spot, rng, random);
  expect_same_labels("2^1000", spot, points, 1000);
  expect_same_labels("2^-1000", spot, points, -1000);
  // Near DBL_MAX: Spot with z halved (exactly: |coordinates| < 0.96) at 2^1024, a box wider
  // than DBL_MAX along y (-0.74 to 0.95); the points that overflow there are left out.
  {
    Mesh flatter = spot;
    for (Point3& v : flatter.vertices)
      v[2] /= 2;
    const mesh::Box box = *internal::corner_box(exactly_scaled(flatter, 1024));
    EXPECT_FALSE(std::isfinite(box.upper[1] - box.lower[1]));
    expect_same_labels("2^1024", flatter, probes(flatter, rng, random), 1024);
  }
  // 1e300: the mesh and the points rounded there, against their exact copies at 2^-997
  // (extent about 1: the frame off).
  {
    const Mesh far = times(spot, 1e300);
    std::vector<Point3> far_points = times(points, 1e300);
    std::vector<Point3> unit_points;
    for (const Point3& p : far_points) {
      if (const std::optional<Point3> q = exactly_scaled(p, -997)) unit_points.push_back(*q);
    }
    expect_same_labels("1e300", exactly_scaled(far, -997), unit_points, 997);
  }
  // Subnormal: Spot on a grid of 2^-12 at 2^-1060, grid points 2^-1072 apart; the probes
  // rounded to 2^-14 (on faces or not, as they fall).
  {
    const Mesh grid = on_grid(spot, 12);
    std::vector<Point3> grid_points = probes(grid, rng, random);
    for (Point3& p : grid_points) {
      for (double& x : p)
        x = std::ldexp(std::round(std::ldexp(x, 14)), -14);
    }
    expect_same_labels("2^-1060", grid, grid_points, -1060);
  }
}

}  // namespace
}  // namespace exactgeo::inside
