// Faces of more than four corners, as the readers take them (polygon.hpp). A planar simple
// polygon (concave, with corners inside straight edges, with a hole written through a
// bridge) becomes triangles that cover it exactly: checked against exact rational oracles
// that know nothing of the reader (every triangle turns as the polygon does, their areas
// add up to the polygon's, and at random points the number of triangles covering the point
// is the polygon's winding number there), for polygons in three different planes and at
// 2^0, 2^+-1000 and subnormal scales. Large polygons of every family (convex, star-shaped,
// with corners inside straight edges, comb-shaped, with many holes through bridges), from
// 10 to 10^5 corners, are checked the same way. A polygon off its plane by one coordinate
// step is split over its projection, with a note; a self-crossing one is refused, naming
// the file's face, or made a fan on request; every message names faces as the file numbers
// them; every reader splits. And FileFaces directly: faces kept or split in place, the
// file's face numbers, zero-based indices checked, a file without faces refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "../../mesh/src/polygon.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "mesh/mesh_io.hpp"
#include "mesh/polygon_tiling.hpp"
#include "support/polygon_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

using test_io::mesh_io;  // the readers' fixture and PLY writer (mesh_io.hpp)
using test_io::put;
using test_io::to_ply;
using test_polygons::expect_tiles;

using testing::keyhole_polygon;
using testing::Point2;
using testing::Polygon2;
using testing::random_star_polygon;

/// Where a polygon of the (x, y) plane goes in space: exact for the integer coordinates
/// of the generators (below 2^22) times a power of two.
using Embedding = std::function<Point3(double x, double y)>;

std::vector<std::pair<std::string, Embedding>> embeddings(double s) {
  return {
      {"z = 0",
       [s](double x, double y) {
         return Point3{s * x, s * y, 0.0};
       }},
      {"x = 0, mirrored",
       [s](double x, double y) {
         return Point3{0.0, s * y, s * x};
       }},
      {"z = x + y",
       [s](double x, double y) {
         return Point3{s * x, s * y, s * (x + y)};
       }},
  };
}

std::string number(double x) {
  char buffer[40];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;  // shortest, exact
  return std::string(buffer, end);
}

/// The polygon as an OFF file of one face, its points mapped by `embed`.
std::string polygon_off(const Polygon2& polygon, const Embedding& embed) {
  std::string off = "OFF\n";
  off.append(std::to_string(polygon.points.size())).append(" 1 0\n");
  for (const Point2& q : polygon.points) {
    const Point3 p = embed(q[0], q[1]);
    off.append(number(p[0])).append(" ").append(number(p[1])).append(" ");
    off.append(number(p[2])).append("\n");
  }
  off.append(std::to_string(polygon.cycle.size()));
  for (const std::uint32_t c : polygon.cycle)
    off.append(" ").append(std::to_string(c));
  return off.append("\n");
}

std::vector<std::array<std::uint32_t, 3>> triangles_of(const Mesh& mesh) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (const Face& f : mesh.faces) {
    EXPECT_TRUE(f.is_triangle());
    triangles.push_back({f.corners[0], f.corners[1], f.corners[2]});
  }
  return triangles;
}

TEST(Polygons, PlanarPolygonsBecomeTrianglesThatTileThem) {
  std::mt19937_64 rng =
      testing::seeded_engine("Polygons.PlanarPolygonsBecomeTrianglesThatTileThem");
  std::uniform_int_distribution<int> corners(5, 40);
  std::vector<std::pair<std::string, Polygon2>> polygons = {
      {"keyhole", keyhole_polygon(false)}, {"keyhole, L-shaped hole", keyhole_polygon(true)}};
  for (int k = 0; k < 12; ++k) {
    polygons.emplace_back("star " + std::to_string(k),
                          random_star_polygon(rng, corners(rng), k % 2 == 1));
  }
  for (const double scale :
       {1.0, std::ldexp(1.0, 1000), std::ldexp(1.0, -1000), std::ldexp(1.0, -1060)}) {
    for (const auto& [plane, embed] : embeddings(scale)) {
      for (const auto& [name, polygon] : polygons) {
        const std::string what = name + " in " + plane + " at scale " + number(scale);
        const LoadedMesh loaded = read_off(polygon_off(polygon, embed), "p.off", {});
        EXPECT_EQ(loaded.split_polygons, 1u) << what;
        EXPECT_TRUE(loaded.notes.empty()) << what << ": " << loaded.notes.front();
        // Every triangle bears the file's face number 0.
        EXPECT_EQ(loaded.numbering.file_faces,
                  std::vector<std::size_t>(loaded.mesh.faces.size(), 0))
            << what;
        expect_tiles(polygon, triangles_of(loaded.mesh), rng, what);
        // The mesh checks see faces of non-zero area, none repeating a corner, and an open
        // surface whose boundary is the polygon's (the bridge's two walks cancel).
        const MeshCheck check = check_mesh(loaded.mesh);
        EXPECT_EQ(check.degenerate_faces.count, 0u) << what;
        EXPECT_EQ(check.unbalanced_edges.count,
                  polygon.cycle.size() - (name.starts_with("keyhole") ? 2 : 0))
            << what;
      }
    }
  }
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// The polygons of one family, of about `corners` corners.
struct Family {
  std::string name;
  std::function<Polygon2(std::mt19937_64&, int corners)> make;
};

std::vector<Family> families() {
  return {
      {"convex", [](std::mt19937_64& rng, int n) { return testing::convex_polygon(rng, n); }},
      {"star", [](std::mt19937_64& rng, int n) { return testing::star_polygon(rng, n, false); }},
      {"star with corners inside edges",
       [](std::mt19937_64& rng, int n) { return testing::star_polygon(rng, n, true); }},
      {"comb", [](std::mt19937_64& rng, int n) { return testing::comb_polygon(rng, n / 4); }},
      {"star with holes",
       [](std::mt19937_64& rng, int n) { return testing::holed_star_polygon(rng, n); }},
  };
}

/// Scale factors that put the polygon's coordinates near 2^0, 2^1000 (the largest below
/// it), 2^-1000 and among the subnormals (every one below 2^-1022), all exactly: the
/// embeddings' coordinates are integers below 2^bits, bits at most 52.
std::vector<std::pair<std::string, double>> scales_for(const Polygon2& polygon) {
  double largest = 0;
  for (const Point2& q : polygon.points)
    largest = std::max(largest, std::abs(q[0]) + std::abs(q[1]));
  int bits = 0;
  std::frexp(largest, &bits);  // largest < 2^bits
  return {{"2^0", 1.0},
          {"2^1000", std::ldexp(1.0, 1000 - bits)},
          {"2^-1000", std::ldexp(1.0, -1000)},
          {"subnormal", std::ldexp(1.0, -1022 - bits)}};
}

/// The number of pairs of corners the cycle joins more often one way than the other: its
/// boundary edges, a bridge walked both ways not among them.
std::size_t boundary_edges(const Polygon2& polygon) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> net;
  const std::size_t n = polygon.cycle.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t a = polygon.cycle[k];
    const std::uint32_t b = polygon.cycle[(k + 1) % n];
    net[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
  }
  return static_cast<std::size_t>(
      std::count_if(net.begin(), net.end(), [](const auto& entry) { return entry.second != 0; }));
}

TEST(Polygons, LargePolygonsOfEveryFamilyBecomeTrianglesThatTileThem) {
  std::mt19937_64 rng =
      testing::seeded_engine("Polygons.LargePolygonsOfEveryFamilyBecomeTrianglesThatTileThem");
  for (const int size : {10, 100, 1000, 10000, 100000}) {
    for (const auto& [family, make] : families()) {
      const Polygon2 polygon = make(rng, size);
      const auto scales = scales_for(polygon);
      // Every plane and scale up to 1000 corners; above, one (the seed picks).
      std::vector<std::pair<std::size_t, std::size_t>> cases;
      for (std::size_t e = 0; e < 3; ++e) {
        for (std::size_t k = 0; k < scales.size(); ++k)
          cases.emplace_back(e, k);
      }
      std::shuffle(cases.begin(), cases.end(), rng);
      cases.resize(size <= 1000 ? cases.size() : 1);
      for (const auto& [e, k] : cases) {
        const auto [plane, embed] = embeddings(scales[k].second)[e];
        const std::string what = family + " of " + std::to_string(polygon.cycle.size()) +
                                 " corners in " + plane + " at scale " + scales[k].first;
        const LoadedMesh loaded = read_off(polygon_off(polygon, embed), "p.off", {});
        EXPECT_EQ(loaded.split_polygons, 1u) << what;
        EXPECT_TRUE(loaded.notes.empty()) << what << ": " << loaded.notes.front();
        EXPECT_EQ(loaded.numbering.file_faces,
                  std::vector<std::size_t>(loaded.mesh.faces.size(), 0))
            << what;
        // Each sample point costs a pass over the edges and the triangles: fewer for the
        // largest polygons.
        expect_tiles(polygon, triangles_of(loaded.mesh), rng, what, size <= 1000 ? 400 : 40);
        if (size <= 1000) {
          const MeshCheck check = check_mesh(loaded.mesh);
          EXPECT_EQ(check.degenerate_faces.count, 0u) << what;
          EXPECT_EQ(check.unbalanced_edges.count, boundary_edges(polygon)) << what;
        }
      }
    }
  }
}

/// The polygon whose first four points are the corners of a square, counter-clockwise,
/// with every edge of its cycle from one of them to the next cut into `pieces` edges by
/// new points (appended): the same region, with many corners when `pieces` is large.
/// Coordinates are multiplied by `pieces`, so that the cuts fall on integers.
Polygon2 with_square_sides_cut(const Polygon2& polygon, int pieces) {
  Polygon2 cut;
  for (const Point2& q : polygon.points)
    cut.points.push_back({q[0] * pieces, q[1] * pieces});
  const std::size_t n = polygon.cycle.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t a = polygon.cycle[k];
    const std::uint32_t b = polygon.cycle[(k + 1) % n];
    cut.cycle.push_back(a);
    if (a >= 4 || b != (a + 1) % 4) continue;
    for (int t = 1; t < pieces; ++t) {
      const Point2& p = cut.points[a];
      const Point2& q = cut.points[b];
      cut.points.push_back({p[0] + (q[0] - p[0]) / pieces * t, p[1] + (q[1] - p[1]) / pieces * t});
      cut.cycle.push_back(static_cast<std::uint32_t>(cut.points.size() - 1));
    }
  }
  return cut;
}

TEST(Polygons, AHoleTouchingTheOutsideAtACornerIsSplit) {
  // The square [0, 8]^2 less the triangle (0, 0), (2, 4), (4, 2), walked from corner 0
  // around the outside, then around the hole back to corner 0: the hole touches the
  // outside there. With few corners ear clipping splits it; with many, the sweep
  // triangulation declines a corner walked four ways, and ear clipping splits it, each
  // certified like any other.
  const Polygon2 notched{{{0, 0}, {8, 0}, {8, 8}, {0, 8}, {4, 2}, {2, 4}}, {0, 1, 2, 3, 0, 5, 4}};
  std::mt19937_64 rng = testing::seeded_engine("Polygons.AHoleTouchingTheOutsideAtACornerIsSplit");
  for (const int pieces : {1, 8}) {
    const Polygon2 polygon = with_square_sides_cut(notched, pieces);
    for (const auto& [plane, embed] : embeddings(1.0)) {
      const LoadedMesh loaded = read_off(polygon_off(polygon, embed), "notch.off", {});
      EXPECT_TRUE(loaded.notes.empty()) << plane;
      expect_tiles(polygon, triangles_of(loaded.mesh), rng,
                   "notch of " + std::to_string(polygon.cycle.size()) + " corners in " + plane);
    }
  }
}

TEST(Polygons, LoopsThatTouchOrOverlapAreRefused) {
  // The square [0, 8]^2 (corners 0 to 3) and points inside it and beside it; each
  // polygon as written and with the square's sides cut into 8 edges each (more corners
  // than ear clipping is used for: the sweeps).
  const std::vector<Point2> points = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {4, 2},  {2, 4},
                                      {3, 3}, {3, 5}, {5, 5}, {5, 3}, {16, 8}, {8, 16}};
  const std::vector<Point2> two_holes = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {5, 5}, {5, 6},
                                         {6, 6}, {6, 5}, {3, 5}, {2, 5}, {2, 6}, {3, 6}};
  const std::vector<std::pair<std::string, Polygon2>> refused = {
      // An inner loop turning as the outer one, joined at corner 0: wound around twice.
      {"nested", {points, {0, 1, 2, 3, 0, 4, 5}}},
      // Two loops joined at corner 2 (a figure eight): tiled only by n - 4 triangles.
      {"figure eight", {points, {0, 1, 2, 10, 11, 2, 3}}},
      // A keyhole whose bridge runs through the hole (and its corner (3, 3)).
      {"bridge across the hole", {points, {0, 1, 2, 3, 0, 8, 9, 6, 7, 8}}},
      // Two holes whose bridges cross each other.
      {"bridges that cross", {two_holes, {0, 1, 8, 9, 10, 11, 8, 1, 2, 3, 0, 4, 5, 6, 7, 4}}},
  };
  const std::vector<std::pair<std::string, Polygon2>> split = {
      // The same corners as a keyhole with its bridge beside the hole.
      {"keyhole", {points, {0, 1, 2, 3, 0, 6, 7, 8, 9, 6}}},
      // The two holes with bridges that do not cross.
      {"two holes", {two_holes, {0, 1, 2, 3, 10, 11, 8, 9, 10, 3, 0, 4, 5, 6, 7, 4}}},
  };
  std::mt19937_64 rng = testing::seeded_engine("Polygons.LoopsThatTouchOrOverlapAreRefused");
  for (const int pieces : {1, 8}) {
    for (const auto& [name, written] : refused) {
      const Polygon2 polygon = with_square_sides_cut(written, pieces);
      const std::string error = error_of(
          [&] { (void)read_off(polygon_off(polygon, embeddings(1.0)[0].second), "t.off", {}); });
      EXPECT_NE(error.find("face 0: a face of " + std::to_string(polygon.cycle.size()) +
                           " corners whose edges cross"),
                std::string::npos)
          << name << ": " << error;
    }
    for (const auto& [name, written] : split) {
      const Polygon2 polygon = with_square_sides_cut(written, pieces);
      const LoadedMesh loaded =
          read_off(polygon_off(polygon, embeddings(1.0)[0].second), "t.off", {});
      expect_tiles(polygon, triangles_of(loaded.mesh), rng,
                   name + " of " + std::to_string(polygon.cycle.size()) + " corners");
    }
  }
}

TEST(Polygons, ALargeSelfCrossingPolygonIsRefused) {
  // A convex polygon of 10^5 corners with two neighbours swapped: the edges into and out
  // of the pair are the crossing diagonals of a convex quadrilateral. The sweep refuses
  // each projection before any triangle is made (ear clipping would take minutes).
  std::mt19937_64 rng = testing::seeded_engine("Polygons.ALargeSelfCrossingPolygonIsRefused");
  Polygon2 polygon = testing::convex_polygon(rng, 100000);
  std::swap(polygon.cycle[500], polygon.cycle[501]);
  const std::string error = error_of(
      [&] { (void)read_off(polygon_off(polygon, embeddings(1.0)[0].second), "big.off", {}); });
  EXPECT_NE(error.find("big.off:100003: face 0: a face of 100000 corners whose edges cross"),
            std::string::npos)
      << error.substr(0, 200);
}

TEST(Polygons, RepeatedCornersAndLinesAreHandled) {
  // A corner written twice in a row is an edge of zero length: dropped.
  const Polygon2 square{{{0, 0}, {4, 0}, {4, 4}, {2, 4}, {0, 4}}, {0, 1, 2, 3, 4}};
  const std::string twice = "OFF\n5 1 0\n0 0 0\n4 0 0\n4 4 0\n2 4 0\n0 4 0\n6 0 1 1 2 3 4\n";
  const LoadedMesh loaded = read_off(twice, "twice.off", {});
  std::mt19937_64 rng = testing::seeded_engine("Polygons.RepeatedCornersAndLinesAreHandled");
  expect_tiles(square, triangles_of(loaded.mesh), rng, "a corner written twice");
  // Every corner on one line: zero-area triangles, which the checks find and
  // classification drops.
  const LoadedMesh line =
      read_off("OFF\n5 1 0\n0 0 0\n1 1 1\n2 2 2\n3 3 3\n4 4 4\n5 0 1 2 3 4\n", "line.off", {});
  EXPECT_EQ(line.mesh.faces.size(), 3u);
  EXPECT_EQ(check_mesh(line.mesh).zero_area_faces.count, 3u);
}

TEST(Polygons, OffThePlaneByOneStepIsSplitOverItsProjectionWithANote) {
  std::mt19937_64 rng =
      testing::seeded_engine("Polygons.OffThePlaneByOneStepIsSplitOverItsProjection");
  for (const double scale : {1.0, std::ldexp(1.0, 1000), std::ldexp(1.0, -1000)}) {
    for (int k = 0; k < 6; ++k) {
      const Polygon2 polygon = random_star_polygon(rng, 12, k % 2 == 1);
      // z = 0 but one corner one step of the coordinates' size up: the normal stays
      // nearest z, so the triangles' (x, y) projections tile the polygon.
      const std::size_t lifted = static_cast<std::size_t>(k) % polygon.points.size();
      const Embedding embed = [&](double x, double y) {
        const bool is_lifted = x == polygon.points[lifted][0] && y == polygon.points[lifted][1];
        return Point3{scale * x, scale * y, is_lifted ? scale : 0.0};
      };
      const LoadedMesh loaded = read_off(polygon_off(polygon, embed), "bent.off", {});
      ASSERT_EQ(loaded.notes.size(), 1u);
      EXPECT_NE(
          loaded.notes[0].find("bent.off: 1 face (0) of more than four corners not in one plane"),
          std::string::npos)
          << loaded.notes[0];
      expect_tiles(polygon, triangles_of(loaded.mesh), rng, "one corner lifted");
    }
  }
}

TEST(Polygons, SelfCrossingPolygonsAreRefusedOrMadeFansOnRequest) {
  // A pentagram: its edges cross in its plane, and every other projection is a line.
  const std::string pentagram =
      "v 0 10 0\nv 6 -8 0\nv -10 3 0\nv 10 3 0\nv -6 -8 0\nf 1 2 3\nf 1 2 3 4 5\n";
  const std::string error = error_of([&] { (void)read_obj(pentagram, "star.obj", {}); });
  for (const char* part : {"star.obj:7: face 2: a face of 5 corners whose edges cross",
                           "--split-polygons", "first corner"}) {
    EXPECT_NE(error.find(part), std::string::npos) << error;
  }
  const LoadedMesh fan = read_obj(pentagram, "star.obj", {.split_polygons = true});
  EXPECT_EQ(fan.mesh.faces.size(), 4u);
  EXPECT_EQ(fan.mesh.faces[1], make_triangle(0, 1, 2));
  EXPECT_EQ(fan.mesh.faces[3], make_triangle(0, 3, 4));
  ASSERT_EQ(fan.notes.size(), 1u);
  EXPECT_NE(fan.notes[0].find("star.obj: 1 face (2) of more than four corners whose edges cross: "
                              "made fans of triangles from the first corner"),
            std::string::npos)
      << fan.notes[0];
  EXPECT_EQ(fan.numbering.file_faces, (std::vector<std::size_t>{0, 1, 1, 1}));
}

TEST(Polygons, EarsThatOverlapAreCaught) {
  // Its edges cross, yet every ear clipping finds is a good ear locally: the triangles
  // (1, 2, 3), (0, 1, 3), (0, 3, 4) all turn alike, and the first two overlap. Only the
  // certificate (no two triangles overlap) refuses it.
  const std::string crossing = "OFF\n5 1 0\n0 0 0\n20 17 0\n0 12 0\n6 13 0\n0 16 0\n5 0 1 2 3 4\n";
  EXPECT_NE(error_of([&] { (void)read_off(crossing, "c.off", {}); }).find("c.off:8: face 0:"),
            std::string::npos);
}

TEST(Polygons, MessagesNameTheFilesFaces) {
  // Face 1 (OBJ numbers from 1) is a pentagon, three triangles in the mesh; face 2 is a
  // triangle written as a quad, which classification refuses: named 2, not 4.
  const std::string obj =
      "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 3 0\nv -1 1 0\nv 0 0 5\n"
      "f 1 2 3 4 5\nf 1 2 6 6\nf 2 3 6\n";
  const LoadedMesh loaded = read_obj(obj, "m.obj", {});
  ASSERT_EQ(loaded.mesh.faces.size(), 5u);
  EXPECT_EQ(loaded.numbering.file_faces, (std::vector<std::size_t>{0, 0, 0, 1, 2}));
  const MeshCheck check = check_mesh(loaded.mesh);
  const std::string problem = closed_surface_problem(check, loaded).value_or("");
  EXPECT_NE(problem.find("1 face repeats a corner (first: 2)"), std::string::npos) << problem;
  EXPECT_NE(problem.find("numbered from 1, as in the file; the triangles of a split polygon by "
                         "its number"),
            std::string::npos)
      << problem;
  // Without the polygon, nothing about split polygons is said.
  const LoadedMesh plain = read_obj("v 0 0 0\nv 2 0 0\nv 0 0 5\nf 1 2 3 3\n", "q.obj", {});
  const std::string plain_problem =
      closed_surface_problem(check_mesh(plain.mesh), plain).value_or("");
  EXPECT_NE(plain_problem.find("(first: 1)"), std::string::npos) << plain_problem;
  EXPECT_EQ(plain_problem.find("split polygon"), std::string::npos) << plain_problem;
}

// ---------------------------------------------------------------------------------------
// In every reader

TEST_F(mesh_io, PolygonsAreSplitInEveryReader) {
  // A convex pentagon and a concave hexagon, flat: triangles, no option needed. (Their
  // tiling is checked against exact oracles above.)
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n";
  const LoadedMesh pentagon = load("p.obj", obj);
  EXPECT_EQ(pentagon.split_polygons, 1u);
  EXPECT_EQ(pentagon.mesh.faces.size(), 3u);

  const std::string off = "OFF\n5 2 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n3 0 1 2\n5 0 1 2 3 4\n";
  const LoadedMesh two = load("p.off", off);
  EXPECT_EQ(two.mesh.faces.size(), 4u);
  EXPECT_EQ(two.numbering.file_faces, (std::vector<std::size_t>{0, 1, 1, 1}));
  // The pentagram's edges cross: refused at its line, with the way out.
  const std::string star = "OFF\n5 1 0\n0 10 0\n6 -8 0\n-10 3 0\n10 3 0\n-6 -8 0\n5 0 1 2 3 4\n";
  EXPECT_MESSAGE_HAS(load_error("s.off", star), "s.off:8: face 0:", "cross", "--split-polygons");

  Mesh mesh;
  // An L: corner 1 is its inner corner; seen from corner 0, the end of an arm, the
  // other arm is hidden behind it.
  mesh.vertices = {{4, 1, 0}, {1, 1, 0}, {1, 4, 0}, {0, 4, 0}, {0, 0, 0}, {4, 0, 0}};
  mesh.faces = {make_triangle(0, 1, 5)};
  std::string ply = to_ply(mesh, {"binary_little_endian"});
  // Turn the triangle into the hexagon 0 1 2 3 4 5: count byte 6, then three more indices.
  const std::size_t face_at = ply.size() - (1 + 3 * 4 + 2);
  ply[face_at] = 6;
  std::string extra;
  for (const std::int32_t i : {2, 3, 4})
    put(extra, i, false);
  ply.insert(face_at + 1 + 2 * 4, extra);  // after corners 0 1: 0 1 2 3 4 5
  const LoadedMesh hex = load("h.ply", ply);
  EXPECT_EQ(hex.split_polygons, 1u);
  EXPECT_EQ(hex.mesh.faces.size(), 4u);
  // Not the fan from corner 0, whose first two triangles lie outside the L.
  for (const Face& f : hex.mesh.faces) {
    EXPECT_FALSE(f == make_triangle(0, 1, 2) || f == make_triangle(0, 2, 3));
  }
  // A binary file has no lines: the face is named alone.
  std::string crossed = ply;
  std::swap(crossed[face_at + 1 + 2 * 4], crossed[face_at + 1 + 4 * 4]);  // 0 1 4 3 2 5
  EXPECT_MESSAGE_HAS(load_error("x.ply", crossed), "x.ply: face 0:", "cross", "--split-polygons");
}

// ---------------------------------------------------------------------------------------
// The readers' faces, directly (polygon.hpp)

TEST(Polygons, FileFacesKeepTrianglesAndQuadsAndSplitTheRestInPlace) {
  LoadedMesh out;
  out.mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}};
  internal::FileFaces faces;
  const std::vector<VertexIndex> two{0, 1};
  EXPECT_EQ(faces.add(two, 1, out), "a face needs at least 3 corners, this one has 2");
  const std::vector<VertexIndex> triangle{0, 1, 2}, pentagon{0, 1, 2, 3, 4}, quad{0, 1, 2, 3};
  EXPECT_EQ(faces.add(triangle, 2, out), std::nullopt);
  EXPECT_EQ(faces.add(pentagon, 3, out), std::nullopt);
  EXPECT_EQ(faces.add(quad, 4, out), std::nullopt);
  faces.finish(out, "f.off", {});
  // The pentagon's three triangles where it stood, between the triangle and the quad.
  ASSERT_EQ(out.mesh.faces.size(), 5u);
  EXPECT_TRUE(out.mesh.faces[0] == make_triangle(0, 1, 2));
  EXPECT_TRUE(out.mesh.faces[4] == make_quad(0, 1, 2, 3));
  EXPECT_EQ(out.split_polygons, 1u);
  EXPECT_EQ(out.numbering.file_faces, (std::vector<std::size_t>{0, 1, 1, 1, 2}));
  Polygon2 polygon;
  for (const Point3& v : out.mesh.vertices)
    polygon.points.push_back({v[0], v[1]});
  polygon.cycle = {0, 1, 2, 3, 4};
  std::vector<std::array<std::uint32_t, 3>> split;
  for (std::size_t f = 1; f < 4; ++f) {
    const Face& t = out.mesh.faces[f];
    split.push_back({t.corners[0], t.corners[1], t.corners[2]});
  }
  auto rng = testing::seeded_engine("Polygons.FileFaces");
  expect_tiles(polygon, split, rng, "the pentagon");
}

TEST(Polygons, ZeroBasedIndicesAndFilesWithoutFaces) {
  EXPECT_EQ(internal::zero_based_index_problem(0, 3), std::nullopt);
  EXPECT_EQ(internal::zero_based_index_problem(2, 3), std::nullopt);
  EXPECT_EQ(internal::zero_based_index_problem(3, 3),
            "vertex index 3 is out of range: valid: 0..2");
  EXPECT_EQ(internal::zero_based_index_problem(-1, 3),
            "vertex index -1 is out of range: valid: 0..2");
  EXPECT_EQ(internal::zero_based_index_problem(0, 0),
            "vertex index 0 is out of range: the file has no vertices");
  LoadedMesh none;
  EXPECT_EQ(error_of([&] { internal::require_faces(none, "n.off"); }),
            "n.off: the mesh has no faces");
  none.mesh.vertices = {{0, 0, 0}};
  EXPECT_EQ(error_of([&] { internal::require_faces(none, "n.off"); }),
            "n.off: the mesh has no faces: 1 vertex only, a point cloud (or lines), not a surface");
}

}  // namespace
}  // namespace exactgeo::mesh
