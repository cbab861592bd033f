// The certified space cells of an open surface (internal/open_space_cells.hpp): a cell
// labels its points where w over the whole cell lies on one side of the rule's levels.
// Every label a cell gives is checked against the classifier without cells (each point
// by its own ray and certified term) and, for a sample, against the definition,
// w = (1/4 pi) sum of the faces' solid angles in 512-bit MPFR
// (support/solid_angle_oracle.hpp), which shares no code with the library. Meshes with 12
// to 10,000 boundary edges (Spot with faces cut, a sphere with holes of every size, once
// and three times over, an open box, a ribbon), points anywhere in the box, next to rims,
// in and near the cells that carry a label, and in the plane of a flat hole (w = 1/2
// exactly: no cell may label those), at 2^0 and 2^+-1000.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/internal/open_label.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/load.hpp"
#include "open_meshes.hpp"
#include "oracle_label.hpp"
#include "oracle_triangles.hpp"
#include "support/hexfloat.hpp"
#include "support/scale_names.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::open_cells {
namespace {

using mesh::Mesh;
using testing::Triangle;

struct Tally {
  std::size_t points = 0;
  std::size_t by_cells = 0;
  std::size_t by_oracle = 0;
  std::size_t inside_by_cells = 0;
};

/// Points anywhere in the box, next to the rims, and near points a cell labels (moved by
/// 2^-4 to 2^-40 of the box, so into neighbouring cells and onto their shared planes'
/// neighbourhoods): the classifier with cells against the one without, for both rules, and
/// the first `oracle_points` that a cell labels against the definition. The counts of
/// points anywhere and near the rims scale with the effort (tests/support/seed.hpp), at
/// least one of each 30 offsets near the rims.
void expect_cells_right(const Mesh& mesh, std::mt19937_64& rng, int full_anywhere,
                        int full_near_rims, int oracle_points, Tally& tally) {
  const int anywhere = static_cast<int>(testing::scaled_trials(full_anywhere, 30));
  const int near_rims = static_cast<int>(testing::scaled_trials(full_near_rims, 30));
  const std::vector<Triangle> triangles = testing::triangles_of(mesh);
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    const Classifier cells(mesh, {.rule = rule});
    const Classifier rays(mesh, {.space_cells = false, .rule = rule});
    ASSERT_TRUE(cells.open());
    ASSERT_FALSE(rays.space_cell_label(mesh.vertices[0]).has_value());
    const std::span<const BoundaryEdge> rim = cells.boundary();
    Point3 lower = mesh.vertices[mesh.faces[0].corners[0]], upper = lower;
    for (const mesh::Face& f : mesh.faces) {
      for (std::size_t c = 0; c < f.size(); ++c) {
        for (int i = 0; i < 3; ++i) {
          lower[i] = std::min(lower[i], mesh.vertices[f.corners[c]][i]);
          upper[i] = std::max(upper[i], mesh.vertices[f.corners[c]][i]);
        }
      }
    }
    const double extent = std::max({upper[0] - lower[0], upper[1] - lower[1], upper[2] - lower[2]});
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Point3> points;
    for (int n = 0; n < anywhere; ++n) {
      Point3 p;
      for (int i = 0; i < 3; ++i)
        p[i] = std::clamp(lower[i] + unit(rng) * (upper[i] - lower[i]), lower[i], upper[i]);
      points.push_back(p);
    }
    for (int n = 0; n < near_rims; ++n) {
      const BoundaryEdge& e =
          rim[std::uniform_int_distribution<std::size_t>(0, rim.size() - 1)(rng)];
      const double offset = extent * std::ldexp(1.0, -3 - n % 30);
      Point3 p;
      for (int i = 0; i < 3; ++i) {
        p[i] = std::clamp(0.5 * mesh.vertices[e.from][i] + 0.5 * mesh.vertices[e.to][i] +
                              offset * (2 * unit(rng) - 1),
                          lower[i], upper[i]);
      }
      points.push_back(p);
    }
    int oracle_left = oracle_points;
    for (std::size_t n = 0; n < points.size(); ++n) {
      const Point3 p = points[n];
      const std::optional<Location> by_cell = cells.space_cell_label(p);
      const Location got = cells.classify(p);
      ASSERT_EQ(to_string(got), to_string(rays.classify(p)))
          << "point " << testing::hex(p) << ", rule " << to_string(rule);
      ++tally.points;
      if (!by_cell) continue;
      ASSERT_EQ(to_string(*by_cell), to_string(got)) << testing::hex(p);
      ++tally.by_cells;
      tally.inside_by_cells += got == Location::inside;
      // Its neighbourhood: in the same cell or the next ones.
      if (n < static_cast<std::size_t>(anywhere)) {
        for (int k = 4; k <= 40; k += 12) {
          Point3 q;
          for (int i = 0; i < 3; ++i)
            q[i] =
                std::clamp(p[i] + std::ldexp(extent, -k) * (2 * unit(rng) - 1), lower[i], upper[i]);
          points.push_back(q);
        }
      }
      if (oracle_left > 0) {
        --oracle_left;
        const auto want = testing::label_from_oracle(
            rule, testing::generalized_winding_oracle(p, triangles, 0.5));
        if (!want) continue;
        ASSERT_EQ(to_string(*by_cell), to_string(*want))
            << "point " << testing::hex(p) << ", rule " << to_string(rule);
        ++tally.by_oracle;
      }
    }
  }
}

class OpenSpaceCellsAtScale : public ::testing::TestWithParam<int> {};

TEST_P(OpenSpaceCellsAtScale, SpotWithFacesCut) {
  const int scale = GetParam();
  auto rng = testing::seeded_engine("inside.open_cells.spot." + std::to_string(scale));
  const Mesh spot = testing::triangulated(
      mesh::load_mesh(std::string(EXACTGEO_TEST_DATA_DIR) + "/meshes/spot/spot_quadrangulated.obj")
          .mesh);
  Tally tally;
  for (const std::size_t cut : {3u, 30u, 300u}) {
    if (scale != 0 && cut == 300) continue;
    SCOPED_TRACE("faces cut: " + std::to_string(cut));
    Mesh mesh = spot;
    std::shuffle(mesh.faces.begin(), mesh.faces.end(), rng);
    mesh.faces.resize(mesh.faces.size() - cut);
    expect_cells_right(testing::scaled(mesh, scale), rng, 1500, 300, 6, tally);
    ASSERT_FALSE(HasFatalFailure());
  }
  // The cells answer for many points, both ways, and the oracle saw some of them.
  EXPECT_GT(tally.by_cells, tally.points / 4);
  EXPECT_GT(tally.inside_by_cells, tally.by_cells / 20);
  EXPECT_GT(tally.by_cells - tally.inside_by_cells, tally.by_cells / 4);
  EXPECT_GT(tally.by_oracle, 12u);
}

TEST_P(OpenSpaceCellsAtScale, ASphereWithHolesOfEverySize) {
  const int scale = GetParam();
  auto rng = testing::seeded_engine("inside.open_cells.sphere." + std::to_string(scale));
  Tally tally;
  const Mesh mesh = testing::scaled(testing::holed_sphere(rng, 24, 48), scale);
  expect_cells_right(mesh, rng, 3000, 500, 10, tally);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(tally.by_cells, tally.points / 4);
  EXPECT_GT(tally.inside_by_cells, tally.by_cells / 10);
  EXPECT_GT(tally.by_oracle, 10u);
}

TEST_P(OpenSpaceCellsAtScale, ASphereWithHolesThreeTimesOver) {
  // Every face three times: the rims' multiplicity 3, w three times the sphere's (up to
  // 3/2 beside a hole), the cap's loops each three times over; the cells must label as the
  // rays do, and as the definition does.
  const int scale = GetParam();
  auto rng = testing::seeded_engine("inside.open_cells.sphere_thrice." + std::to_string(scale));
  Tally tally;
  Mesh mesh = testing::scaled(testing::holed_sphere(rng, 16, 32), scale);
  const std::vector<mesh::Face> once = mesh.faces;
  for (int copy = 1; copy < 3; ++copy)
    mesh.faces.insert(mesh.faces.end(), once.begin(), once.end());
  expect_cells_right(mesh, rng, 1500, 300, 10, tally);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(tally.by_cells, tally.points / 5);
  EXPECT_GT(tally.inside_by_cells, 0u);  // both ways (the share varies with the holes)
  EXPECT_GT(tally.by_oracle, 10u);
}

TEST_P(OpenSpaceCellsAtScale, AFlatHoleIsNeverLabelled) {
  // The box without its top, of 8 x 8 quads a side: w = 1/2 exactly in the plane of the
  // hole, so the cells just below it (no face reaches them, w above 1/2 at their centres)
  // hold points no cell may label. Points on the plane, and below it by 2^-1 to 2^-40 of
  // the side, against the rays.
  const int k = GetParam();
  auto rng = testing::seeded_engine("inside.open_cells.flat_hole." + std::to_string(k));
  const double side = std::ldexp(1.0, k);
  const Mesh mesh = testing::triangulated(testing::open_box_of_quads(8, k));
  Tally tally;
  expect_cells_right(mesh, rng, 1500, 200, 8, tally);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(tally.by_cells, tally.points / 4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    const Classifier cells(mesh, {.rule = rule});
    const Classifier rays(mesh, {.space_cells = false, .rule = rule});
    std::size_t labelled_below = 0;
    for (int n = 0; n < 120; ++n) {
      const double x = side * (0.05 + 0.9 * unit(rng)), y = side * (0.05 + 0.9 * unit(rng));
      const Point3 on{x, y, side};
      EXPECT_FALSE(cells.space_cell_label(on).has_value()) << testing::hex(on);
      EXPECT_EQ(cells.classify(on), Location::undecided) << testing::hex(on);
      const Point3 below{x, y, side - std::ldexp(side, -1 - n % 40)};
      labelled_below += cells.space_cell_label(below).has_value();
      EXPECT_EQ(cells.classify(below), rays.classify(below)) << testing::hex(below);
    }
    EXPECT_GT(labelled_below, 5u);
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, OpenSpaceCellsAtScale, ::testing::Values(0, 1000, -1000),
                         exactgeo::testing::scale_name);

TEST(OpenSpaceCells, ARibbonWithTenThousandRimEdges) {
  auto rng = testing::seeded_engine("inside.open_cells.ribbon");
  Tally tally;
  expect_cells_right(testing::ribbon(5000), rng, 2000, 400, 6, tally);
  ASSERT_FALSE(HasFatalFailure());
  // (Rims near most of the box: the build stops early, and the cells answer for fewer.)
  EXPECT_GT(tally.by_cells, 100u);
}

}  // namespace
}  // namespace exactgeo::inside::open_cells
