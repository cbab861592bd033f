// The exact grid (boxes/exact_grid.hpp): the pairs of groups whose exact boxes meet,
// exactly those and each once, against brute force over all pairs; random groups on a
// coarse lattice (many boxes that only touch) at 2^0 and 2^+-1000, degenerate sets (every
// point at one place, a flat set, groups far apart, coordinates near the largest double),
// and grids from one cell to many, the few groups over the same points as the many or over
// points of their own. A grid axis's cell never decreases along the axis.

#include "exactgeo/boxes/exact_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "support/seed.hpp"

namespace exactgeo::boxes {
namespace {

using MetPairs = std::map<std::pair<std::size_t, std::size_t>, int>;  // pair -> times found

template <std::size_t NA, std::size_t NB>
MetPairs met_by_brute_force(std::span<const Point3> points,
                            std::span<const std::array<VertexIndex, NA>> a,
                            std::span<const std::array<VertexIndex, NB>> b) {
  MetPairs pairs;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (exact_box_of<NA>(points, a[i]).meets(exact_box_of<NB>(points, b[j]))) pairs[{i, j}] = 1;
    }
  }
  return pairs;
}

template <std::size_t NA, std::size_t NB>
MetPairs met_by_grid(std::span<const Point3> points, std::span<const std::array<VertexIndex, NA>> a,
                     std::span<const std::array<VertexIndex, NB>> b, GridScratch& scratch,
                     double cells_per_group) {
  MetPairs pairs;
  overlapping_groups_by_grid<NA, NB>(
      points, a, b,
      [&](std::size_t i, std::size_t j) {
        ++pairs[{i, j}];
      },
      scratch, cells_per_group);
  return pairs;
}

/// Groups of 4 and of 3 over `points`.
struct FewAndMany {
  std::vector<std::array<VertexIndex, 4>> few;
  std::vector<std::array<VertexIndex, 3>> many;
};

/// Groups of points near one another (a point of `points` and others a few steps of
/// `step` from it along each axis, appended to `points`), as a pass's regions and a
/// surface's triangles are (none along `still_axis`, if below 3), and of any points of
/// `points` (the first `spread` of the many).
FewAndMany random_few_and_many(std::mt19937_64& rng, std::vector<Point3>& points, std::size_t few,
                               std::size_t many, double step, int still_axis = 3,
                               std::size_t spread = 5) {
  const std::size_t given = points.size();
  std::uniform_int_distribution<VertexIndex> any(0, static_cast<VertexIndex>(given - 1));
  std::uniform_int_distribution<int> steps(-2, 2);
  const auto near = [&](VertexIndex v) {
    Point3 p = points[v];
    for (int k = 0; k < 3; ++k)
      p[k] += k == still_axis ? 0.0 : steps(rng) * step;
    points.push_back(p);
    return static_cast<VertexIndex>(points.size() - 1);
  };
  FewAndMany g;
  g.few.resize(few);
  g.many.resize(many);
  for (auto& group : g.few) {
    group[0] = any(rng);
    for (std::size_t k = 1; k < 4; ++k)
      group[k] = near(group[0]);
  }
  for (std::size_t j = 0; j < many; ++j) {
    auto& group = g.many[j];
    group[0] = any(rng);
    for (std::size_t k = 1; k < 3; ++k)
      group[k] = j < spread ? any(rng) : near(group[0]);
  }
  return g;
}

/// The same with the few groups over points of their own (the overload with two sets of
/// points): group i's corners copied to points 4i to 4i + 3, in reverse order, so that
/// reading them from the many's points instead gives other boxes.
MetPairs met_by_grid_with_own_points(std::span<const Point3> points, const FewAndMany& g,
                                     GridScratch& scratch, double cells_per_group) {
  std::vector<Point3> own(4 * g.few.size());
  std::vector<std::array<VertexIndex, 4>> few(g.few.size());
  for (std::size_t i = 0; i < g.few.size(); ++i) {
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t at = 4 * i + (3 - k);
      own[at] = points[g.few[i][k]];
      few[i][k] = static_cast<VertexIndex>(at);
    }
  }
  MetPairs pairs;
  overlapping_groups_by_grid<4, 3>(
      own, std::span<const std::array<VertexIndex, 4>>(few), points,
      std::span<const std::array<VertexIndex, 3>>(g.many),
      [&](std::size_t i, std::size_t j) {
        ++pairs[{i, j}];
      },
      scratch, cells_per_group);
  return pairs;
}

void expect_exactly_the_meeting_pairs(std::span<const Point3> points, const FewAndMany& g,
                                      const std::string& what) {
  const MetPairs expected = met_by_brute_force<4, 3>(
      points, std::span(g.few), std::span<const std::array<VertexIndex, 3>>(g.many));
  GridScratch scratch;  // reused from one grid to the next, as a pass's caller does
  for (const double cells_per_group : {0.01, 2.0, 50.0, 1e6}) {
    const MetPairs found =
        met_by_grid<4, 3>(points, std::span(g.few), std::span(g.many), scratch, cells_per_group);
    EXPECT_EQ(found, expected) << what << ", " << cells_per_group << " cells per group";
    EXPECT_EQ(met_by_grid_with_own_points(points, g, scratch, cells_per_group), expected)
        << what << ", " << cells_per_group << " cells per group, the few's own points";
  }
}

TEST(ExactGrid, FindsExactlyThePairsWhoseExactBoxesMeetEachOnce) {
  std::mt19937_64 rng = testing::seeded_engine("ExactGrid.brute_force");
  for (const int e : {0, 1000, -1000}) {
    const double s = std::ldexp(1.0, e);
    for (int round = 0; round < 20; ++round) {
      // A lattice of 2^-3 steps, so that many boxes touch exactly; a random offset and
      // spread, flat along an axis now and then.
      std::uniform_int_distribution<int> lattice(0, 8 + 8 * (round % 8));
      const int flat_axis = round % 4;  // 3: none
      std::vector<Point3> points(200);
      for (Point3& p : points) {
        for (int k = 0; k < 3; ++k)
          p[k] = k == flat_axis ? 0.75 * s : s * (lattice(rng) / 8.0 - 3.0);
      }
      const FewAndMany g = random_few_and_many(rng, points, 1 + round * 5, 150, s / 8.0, flat_axis);
      expect_exactly_the_meeting_pairs(
          points, g, "2^" + std::to_string(e) + " round " + std::to_string(round));
    }
  }
}

TEST(ExactGrid, DegenerateSets) {
  std::mt19937_64 rng = testing::seeded_engine("ExactGrid.degenerate");
  const double big = std::numeric_limits<double>::max();
  // Every point at one place: every pair meets.
  {
    std::vector<Point3> points(30, Point3{1.5, -2.0, 0.0});
    const FewAndMany g = random_few_and_many(rng, points, 7, 40, 0.0);
    expect_exactly_the_meeting_pairs(points, g, "one place");
  }
  // Near the largest doubles: spans and volumes overflow.
  {
    std::vector<Point3> points(120);
    std::uniform_int_distribution<int> pick(0, 4);
    const std::array<double, 5> values{-big, -0.5 * big, 0.0, 0.5 * big, big};
    for (Point3& p : points) {
      for (double& x : p)
        x = values[static_cast<std::size_t>(pick(rng))];
    }
    const FewAndMany g = random_few_and_many(rng, points, 20, 100, 0.25 * big);
    expect_exactly_the_meeting_pairs(points, g, "huge");
  }
  // The smallest subnormals beside zero: spans and volumes underflow.
  {
    std::vector<Point3> points(120);
    std::uniform_int_distribution<int> pick(-3, 3);
    const double tiny = std::numeric_limits<double>::denorm_min();
    for (Point3& p : points) {
      for (double& x : p)
        x = pick(rng) * tiny;
    }
    const FewAndMany g = random_few_and_many(rng, points, 20, 100, tiny);
    expect_exactly_the_meeting_pairs(points, g, "tiny");
  }
  // Two clusters far apart, the few groups in one of them and across.
  {
    std::vector<Point3> points(100);
    std::uniform_real_distribution<double> near(0.0, 1.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double shift = i % 2 == 0 ? 0.0 : 1e200;
      points[i] = {shift + near(rng), near(rng), -shift + near(rng)};
    }
    const FewAndMany g = random_few_and_many(rng, points, 10, 80, 0.125);
    expect_exactly_the_meeting_pairs(points, g, "two clusters");
  }
}

TEST(ExactGrid, AnAxisCellNeverDecreases) {
  std::mt19937_64 rng = testing::seeded_engine("ExactGrid.monotone");
  const double big = std::numeric_limits<double>::max();
  const std::array<std::pair<double, double>, 6> spans{{{0.0, 1.0},
                                                        {-3.0, 1e-300},
                                                        {-big, big},
                                                        {1.0, 1.0},
                                                        {-0x1p-1070, 0x1p-1070},
                                                        {0x1p+1000, 0x1.8p+1000}}};
  for (const auto& [lower, upper] : spans) {
    for (const std::uint32_t count : {1u, 2u, 7u, 1024u}) {
      const GridAxis axis(lower, upper, count);
      std::vector<double> xs{-big,
                             big,
                             lower,
                             upper,
                             0.0,
                             -0.0,
                             std::nextafter(lower, -big),
                             std::nextafter(upper, big)};
      std::uniform_real_distribution<double> unit(-2.0, 2.0);
      for (int i = 0; i < 200; ++i) {
        const double t = unit(rng);
        xs.push_back(lower + t * (upper - lower));
        xs.push_back(std::ldexp(unit(rng), std::uniform_int_distribution<int>(-1074, 1023)(rng)));
      }
      std::erase_if(xs, [](double x) { return !std::isfinite(x); });
      std::sort(xs.begin(), xs.end());
      for (std::size_t i = 1; i < xs.size(); ++i) {
        EXPECT_LE(axis.cell(xs[i - 1]), axis.cell(xs[i]))
            << lower << " " << upper << " " << count << ": " << xs[i - 1] << " " << xs[i];
      }
      for (const double x : xs)
        EXPECT_LT(axis.cell(x), std::max(count, 1u));
    }
  }
}

}  // namespace
}  // namespace exactgeo::boxes
