// Faces of more than four corners. A planar simple polygon (concave, with corners inside
// straight edges, with a hole written through a bridge) becomes triangles that cover it
// exactly: checked against exact rational oracles that know nothing of the reader (every
// triangle turns as the polygon does, their areas add up to the polygon's, and at random
// points the number of triangles covering the point is the polygon's winding number
// there), for polygons in three different planes and at 2^0, 2^+-1000 and subnormal
// scales. A polygon off its plane by one coordinate step is split over its projection,
// with a note; a self-crossing one is refused, naming the file's face, or made a fan on
// request; every message names faces as the file numbers them.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "support/polygon_oracle.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

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
  std::snprintf(buffer, sizeof buffer, "%.17g", x);  // 17 digits: the double back exactly
  return buffer;
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

/// The certificate that `triangles` tile the polygon (in its own (x, y) coordinates):
/// each turns as the polygon does, strictly; their areas add up; at random points
/// (dyadic, off every edge) the triangles covering the point number the polygon's
/// winding number there.
void expect_tiles(const Polygon2& polygon,
                  const std::vector<std::array<std::uint32_t, 3>>& triangles, std::mt19937_64& rng,
                  const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(triangles.size(), polygon.cycle.size() - 2);
  for (const auto& t : triangles) {
    ASSERT_EQ(testing::orientation_oracle(polygon.points[t[0]], polygon.points[t[1]],
                                          polygon.points[t[2]]),
              Sign::positive);  // the generators' polygons turn counter-clockwise
  }
  ASSERT_TRUE(testing::areas_add_up(polygon, triangles));
  Point2 lower = polygon.points[0];
  Point2 upper = lower;
  for (const Point2& q : polygon.points) {
    for (int k = 0; k < 2; ++k) {
      lower[k] = std::min(lower[k], q[k]);
      upper[k] = std::max(upper[k], q[k]);
    }
  }
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  int inside = 0;
  for (int sample = 0; sample < 400; ++sample) {
    Point2 q;
    for (int k = 0; k < 2; ++k)  // 2^-12 steps: exact sums with the integers
      q[k] =
          lower[k] + std::ldexp(std::floor(std::ldexp(unit(rng), 12) * (upper[k] - lower[k])), -12);
    const std::optional<int> winding = testing::winding_number_oracle(polygon, q);
    if (!winding) continue;
    int covering = 0;
    bool on_a_side = false;
    for (const auto& t : triangles) {
      const Point2 &a = polygon.points[t[0]], &b = polygon.points[t[1]], &c = polygon.points[t[2]];
      const Sign s0 = testing::orientation_oracle(a, b, q);
      const Sign s1 = testing::orientation_oracle(b, c, q);
      const Sign s2 = testing::orientation_oracle(c, a, q);
      on_a_side = on_a_side || s0 == Sign::zero || s1 == Sign::zero || s2 == Sign::zero;
      covering += s0 == Sign::positive && s1 == Sign::positive && s2 == Sign::positive;
    }
    if (on_a_side) continue;
    ASSERT_EQ(covering, *winding) << "at (" << q[0] << ", " << q[1] << ")";
    ++checked;
    inside += covering;
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(inside, 0);
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

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "(no error)";
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

}  // namespace
}  // namespace exactgeo::mesh
