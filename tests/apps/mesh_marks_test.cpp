// The `--mark` pictures: the PLY file keeps every coordinate and face exactly and reads
// back with its colours; `exactgeo info --mark` colours each face by its first finding,
// checked against findings computed here (every pair of faces through face_contact, not
// the broad phase); files that cannot be written leave nothing behind.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "apps/marked_ply_text.hpp"
#include "cli/info_command.hpp"
#include "cli/marked_ply.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "support/hexahedron.hpp"
#include "support/scratch_dir.hpp"

namespace exactgeo::cli {
namespace {

namespace fs = std::filesystem;
using mesh::Face;
using mesh::make_quad;
using mesh::make_triangle;
using mesh::Mesh;
using testing::read_marked_ply;

TEST(MarkedPly, KeepsEveryCoordinateAndFaceExactlyAndEveryColour) {
  Mesh m;
  m.vertices = {{1.0 / 3.0, -0.0, 1e-300},
                {std::ldexp(1.0, 1000), std::numeric_limits<double>::denorm_min(), 0.1},
                {-2.5, std::nextafter(1.0, 2.0), 7.0},
                {0, 0, 1}};
  m.faces = {make_triangle(0, 1, 2), make_quad(0, 1, 2, 3)};
  MarkedMesh marked{m.vertices, m.faces, {{1, 2, 3}, {250, 0, 255}}, {}, {}, {}};
  marked.vertex_colours = {{9, 8, 7}, {0, 0, 0}, {255, 255, 255}, {4, 5, 6}};
  marked.edges = {{{0, 3}, {10, 20, 30}}};
  marked.legend = {{"face", "first kind", {1, 2, 3}, 1}, {"edge", "an edge", {10, 20, 30}, 1}};
  const std::string text = marked_ply(marked);

  const mesh::LoadedMesh back = mesh::read_ply(text, "marked.ply", {});
  ASSERT_EQ(back.mesh.vertices.size(), m.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    for (std::size_t k = 0; k < 3; ++k) {  // bit for bit, the sign of -0 included
      EXPECT_EQ(std::signbit(back.mesh.vertices[v][k]), std::signbit(m.vertices[v][k]));
      EXPECT_EQ(back.mesh.vertices[v][k], m.vertices[v][k]) << v << " " << k;
    }
  }
  EXPECT_EQ(back.mesh.faces, m.faces);

  const auto ply = read_marked_ply(text);
  EXPECT_TRUE(ply.complete) << text;
  EXPECT_EQ(ply.face_colours, marked.face_colours);
  EXPECT_EQ(ply.vertex_colours, marked.vertex_colours);
  ASSERT_EQ(ply.edges.size(), 1u);
  EXPECT_EQ(ply.edges[0], (std::array<std::size_t, 2>{0, 3}));
  EXPECT_EQ(ply.edge_colours[0], (Rgb{10, 20, 30}));
  EXPECT_EQ(ply.legend, (std::vector<std::string>{"legend face 1 2 3 #010203: first kind (1)",
                                                  "legend edge 10 20 30 #0a141e: an edge (1)"}));
}

/// Appends the axis-aligned box [lower, upper] as six outward-facing quads (corner c at
/// lower or upper by the bits of c, as support/hexahedron.hpp numbers them).
void add_box(Mesh& m, const Point3& lower, const Point3& upper) {
  const auto first = static_cast<VertexIndex>(m.vertices.size());
  for (std::size_t c = 0; c < 8; ++c) {
    m.vertices.push_back({(c & 1) ? upper[0] : lower[0], (c & 2) ? upper[1] : lower[1],
                          (c & 4) ? upper[2] : lower[2]});
  }
  for (const auto& q : testing::kHexahedronFaces)
    m.faces.push_back(make_quad(first + q[0], first + q[1], first + q[2], first + q[3]));
}

void write_obj(const fs::path& path, const Mesh& m) {
  std::ofstream out(path);
  out.precision(17);
  for (const Point3& p : m.vertices)
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const Face& f : m.faces) {
    out << 'f';
    for (std::size_t k = 0; k < f.size(); ++k)
      out << ' ' << f.corners[k] + 1;
    out << '\n';
  }
}

class MarkCommand : public ::testing::Test {
 protected:
  const testing::ScratchDir scratch_{"exactgeo_marks"};
  const fs::path& dir_ = scratch_.path;
};

TEST_F(MarkCommand, InfoColoursEachFaceByItsFirstFinding) {
  // Two crossing boxes, an open box (one face missing) with a skew quad hanging off it
  // and a fin on an edge, a closed box with one corner moved (three skew quads) and a
  // degenerate triangle: every category of the legend but "undecided".
  Mesh m;
  add_box(m, {0, 0, 0}, {1, 1, 1});
  add_box(m, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5});
  add_box(m, {3, 0, 0}, {4, 1, 1});
  m.faces.pop_back();
  m.vertices.push_back({5, 0, 0.25});
  m.vertices.push_back({5, 1, 0});
  const auto n = static_cast<VertexIndex>(m.vertices.size());
  m.faces.push_back(make_quad(17, 19, n - 1, n - 2));  // skew: off the box's x = 4 side
  m.faces.push_back(make_triangle(0, 1, 1));           // degenerate
  m.vertices.push_back({3.5, -1, 0.5});
  m.faces.push_back(make_triangle(16, 17, n));  // a fin below the open box: edge 16-17 thrice
  add_box(m, {6, 0, 0}, {7, 1, 1});
  m.vertices.back() = {7.25, 1.125, 1.5};
  write_obj(dir_ / "planted.obj", m);

  InfoOptions options;
  options.mesh = (dir_ / "planted.obj").string();
  options.mark = (dir_ / "marked.ply").string();
  std::ostringstream out, err;
  ASSERT_EQ(run_info(options, out, err), ExitCode::success) << err.str();
  std::ifstream file(options.mark);
  const std::string text((std::istreambuf_iterator<char>(file)), {});
  const auto ply = read_marked_ply(text);
  ASSERT_TRUE(ply.complete);
  ASSERT_EQ(ply.face_colours.size(), m.faces.size());

  // The colour of each meaning, from the legend: "legend face R G B #hex: meaning (count)".
  std::map<std::string, Rgb> colour_of;
  std::map<std::string, std::size_t> count_of;
  for (const std::string& line : ply.legend) {
    std::istringstream words(line.substr(std::string("legend face ").size()));
    const Rgb colour = testing::read_rgb(words);
    const std::size_t colon = line.find(": ");
    const std::size_t open = line.rfind(" (");
    const std::string meaning = line.substr(colon + 2, open - colon - 2);
    colour_of[meaning.substr(0, 12)] = colour;  // its first words tell it
    count_of[meaning.substr(0, 12)] = std::stoul(line.substr(open + 2));
    EXPECT_NE(out.str().find(meaning), std::string::npos) << "the report shows the legend";
  }
  ASSERT_EQ(colour_of.size(), 7u) << text.substr(0, 1000);

  // The findings, independently: every pair through face_contact, the edges counted here.
  const std::size_t faces = m.faces.size();
  std::vector<bool> intersecting(faces), undecided(faces), boundary(faces), fin(faces);
  for (std::size_t a = 0; a < faces; ++a) {
    for (std::size_t b = a + 1; b < faces; ++b) {
      const mesh::FaceContact c = mesh::face_contact(m, a, b);
      if (c == mesh::FaceContact::intersecting) intersecting[a] = intersecting[b] = true;
      if (c == mesh::FaceContact::undecided) undecided[a] = undecided[b] = true;
    }
  }
  for (std::size_t f = 0; f < faces; ++f) {
    for (std::size_t i = 0; i < m.faces[f].size(); ++i) {
      const VertexIndex u = m.faces[f].corner(i), v = m.faces[f].corner(i + 1);
      if (u == v) continue;
      std::size_t uses = 0;
      for (const Face& g : m.faces)
        for (std::size_t j = 0; j < g.size(); ++j)
          uses += (g.corner(j) == u && g.corner(j + 1) == v) ||
                  (g.corner(j) == v && g.corner(j + 1) == u);
      boundary[f] = boundary[f] || uses == 1;
      fin[f] = fin[f] || uses > 2;
    }
  }
  const mesh::MeshCheck check = mesh::check_mesh(m);
  std::map<std::string, std::size_t> expected_counts;
  for (std::size_t f = 0; f < faces; ++f) {
    const std::string kind = intersecting[f]                     ? "intersects another"
                             : undecided[f]                      ? "intersection undecided"
                             : check.face_findings[f].degenerate ? "degenerate (repeated"
                             : fin[f]                            ? "on a non-manifold"
                             : boundary[f]                       ? "on a boundary"
                             : check.face_findings[f].non_planar ? "non-planar quad"
                                                                 : "none of these";
    const std::string key = kind.substr(0, 12);
    ASSERT_TRUE(colour_of.count(key)) << kind;
    EXPECT_EQ(ply.face_colours[f], colour_of[key]) << "face " << f << ": " << kind;
    ++expected_counts[key];
  }
  for (const auto& [key, count] : count_of)
    EXPECT_EQ(count, expected_counts[key]) << key;
  // Every category but "undecided" is planted here.
  for (const char* planted : {"intersects", "degenerate", "on", "non-planar", "none"}) {
    std::size_t seen = 0;
    for (const auto& [key, count] : expected_counts)
      seen += key.rfind(planted, 0) == 0 ? count : 0;
    EXPECT_GT(seen, 0u) << planted;
  }
  EXPECT_NE(out.str().find("pairs of faces intersect"), std::string::npos) << out.str();
}

TEST_F(MarkCommand, AnUnwritableMarkFailsFirstAndLeavesNothing) {
  Mesh m;
  add_box(m, {0, 0, 0}, {1, 1, 1});
  write_obj(dir_ / "box.obj", m);
  InfoOptions options;
  options.mesh = (dir_ / "box.obj").string();
  options.mark = (dir_ / "no" / "such" / "dir.ply").string();
  std::ostringstream out, err;
  EXPECT_EQ(run_info(options, out, err), ExitCode::input_error);
  EXPECT_EQ(out.str(), "");
  EXPECT_NE(err.str().find("exactgeo info: --mark: cannot write '" + options.mark + "'"),
            std::string::npos)
      << err.str();
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace exactgeo::cli
