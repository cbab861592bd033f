// `exactgeo ccd-mesh` end to end (run_ccd_mesh: loading, checks, the JSON report) against
// exhaustive pairwise CCD written here: random moving meshes go to OBJ files, and the
// pairs the command prints must be exactly the non-adjacent pairs that vertex_face_ccd /
// edge_edge_ccd report.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "apps/marked_ply_text.hpp"
#include "cli/ccd_mesh_command.hpp"
#include "cli/peak_memory.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/mesh/load.hpp"
#include "support/generators.hpp"
#include "support/scratch_dir.hpp"
#include "support/seed.hpp"

namespace exactgeo::cli {
namespace {

namespace fs = std::filesystem;
using Corners = std::array<std::size_t, 3>;
using Pair = std::vector<std::size_t>;  // [v, f] or [a0, a1, b0, b1]

struct Frames {
  std::vector<Point3> t0, t1;
  std::vector<Corners> faces;
};

/// An n x n grid of unit quads in z = 0, split into triangles; every vertex moves by up to
/// 1.5 in each coordinate, so the sheet crumples through itself.
Frames crumpling_sheet(int n, testing::Rng& rng) {
  Frames f;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const Point3 p{double(i), double(j), 0.0};
      const Point3 d = testing::random_point(rng, 1.5);
      f.t0.push_back(p);
      f.t1.push_back({p[0] + d[0], p[1] + d[1], p[2] + d[2]});
    }
  }
  const auto at = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      f.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      f.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return f;
}

/// OBJ vertex lines that read back exactly.
void write_vertices(std::ostream& out, const std::vector<Point3>& vertices) {
  char line[128];
  for (const Point3& p : vertices) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    out << line;
  }
}

void write_obj(const fs::path& path, const std::vector<Point3>& vertices,
               const std::vector<Corners>& faces) {
  std::ofstream out(path);
  write_vertices(out, vertices);
  for (const Corners& c : faces)
    out << "f " << c[0] + 1 << ' ' << c[1] + 1 << ' ' << c[2] + 1 << '\n';
}

/// The same sheet with each pair of triangles (a, b, c), (a, c, d) written as the quad
/// (a, b, c, d): --split-quads must give the triangles back.
void write_quad_obj(const fs::path& path, const std::vector<Point3>& vertices,
                    const std::vector<Corners>& faces) {
  std::ofstream out(path);
  write_vertices(out, vertices);
  for (std::size_t f = 0; f + 1 < faces.size(); f += 2) {
    const Corners &a = faces[f], &b = faces[f + 1];
    out << "f " << a[0] + 1 << ' ' << a[1] + 1 << ' ' << a[2] + 1 << ' ' << b[2] + 1 << '\n';
  }
}

/// Writes both frames into `dir` with `write` (write_obj or write_quad_obj) and returns
/// options that name them, on two threads.
template <class Write>
CcdMeshOptions frames_in(const fs::path& dir, const Frames& frames, Write write) {
  write(dir / "t0.obj", frames.t0, frames.faces);
  write(dir / "t1.obj", frames.t1, frames.faces);
  CcdMeshOptions options;
  options.frame0 = (dir / "t0.obj").string();
  options.frame1 = (dir / "t1.obj").string();
  options.threads = 2;
  return options;
}

/// The integer arrays of `key` in a JSON report: "key": [[1, 2], [3, 4]].
std::vector<Pair> pairs_in(const std::string& json, const std::string& key) {
  std::vector<Pair> pairs;
  std::size_t at = json.find("\"" + key + "\": [");
  if (at == std::string::npos) return {{}};  // missing: fails every comparison
  at = json.find('[', at);
  if (json.compare(at, 2, "[]") == 0) return pairs;
  const std::size_t end = json.find("]]", at);
  if (end == std::string::npos) return {{}};  // malformed: fails every comparison
  std::istringstream in(json.substr(at + 1, end + 1 - (at + 1)));
  char c = 0;
  while (in >> c && c == '[') {
    Pair p;
    std::size_t value = 0;
    while (in >> value) {
      p.push_back(value);
      in >> c;
      if (c == ']') break;
    }
    pairs.push_back(p);
    in >> c;  // ',' or the end
  }
  return pairs;
}

/// Every non-adjacent pair through the per-pair CCD, in the report's canonical order.
std::pair<std::vector<Pair>, std::vector<Pair>> exhaustive(const Frames& f, ccd::Method method) {
  std::vector<Pair> vertex_face, edge_edge;
  ccd::Options options;
  options.method = method;
  for (std::size_t v = 0; v < f.t0.size(); ++v) {
    for (std::size_t i = 0; i < f.faces.size(); ++i) {
      const Corners& c = f.faces[i];
      if (v == c[0] || v == c[1] || v == c[2]) continue;
      const ccd::VertexFaceQuery q{f.t0[v], f.t0[c[0]], f.t0[c[1]], f.t0[c[2]],
                                   f.t1[v], f.t1[c[0]], f.t1[c[1]], f.t1[c[2]]};
      if (ccd::vertex_face_ccd(q, options).collision) vertex_face.push_back({v, i});
    }
  }
  std::vector<std::array<std::size_t, 2>> edges;
  for (const Corners& c : f.faces) {
    for (int k = 0; k < 3; ++k)
      edges.push_back({std::min(c[k], c[(k + 1) % 3]), std::max(c[k], c[(k + 1) % 3])});
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto &a = edges[i], &b = edges[j];
      if (a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1]) continue;
      const ccd::EdgeEdgeQuery q{f.t0[a[0]], f.t0[a[1]], f.t0[b[0]], f.t0[b[1]],
                                 f.t1[a[0]], f.t1[a[1]], f.t1[b[0]], f.t1[b[1]]};
      if (ccd::edge_edge_ccd(q, options).collision) edge_edge.push_back({a[0], a[1], b[0], b[1]});
    }
  }
  std::sort(vertex_face.begin(), vertex_face.end());
  return {vertex_face, edge_edge};
}

TEST(CcdMeshCommand, MatchesExhaustivePairwiseCcdOnRandomMovingMeshes) {
  auto rng = testing::seeded_engine("CcdMeshCommand.random");
  const testing::ScratchDir dir("exactgeo_ccd_mesh");
  for (const int n : {4, 7, 10}) {
    const Frames frames = crumpling_sheet(n, rng);
    CcdMeshOptions options = frames_in(dir.path, frames, write_obj);
    for (const ccd::Method method : {ccd::Method::exact, ccd::Method::parity}) {
      options.method = method;
      options.json = true;
      std::ostringstream out, err;
      ASSERT_EQ(run_ccd_mesh(options, out, err), ExitCode::success) << err.str();
      const auto [vertex_face, edge_edge] = exhaustive(frames, method);
      const std::string what = "n = " + std::to_string(n) + ", " +
                               std::string(ccd::to_string(method)) + ": " + out.str();
      EXPECT_FALSE(vertex_face.empty() && edge_edge.empty()) << "the sheet should collide";
      EXPECT_EQ(pairs_in(out.str(), "vertex_face"), vertex_face) << what;
      EXPECT_EQ(pairs_in(out.str(), "edge_edge"), edge_edge) << what;
    }
  }
}

TEST(CcdMeshCommand, JsonStatesThePeakMemory) {
  // The process's peak resident memory: a number, at least what the step's frames hold.
  auto rng = testing::seeded_engine("CcdMeshCommand.peak-memory");
  const testing::ScratchDir dir("exactgeo_ccd_mesh_memory");
  const Frames frames = crumpling_sheet(10, rng);
  CcdMeshOptions options = frames_in(dir.path, frames, write_obj);
  options.json = true;
  std::ostringstream out, err;
  ASSERT_EQ(run_ccd_mesh(options, out, err), ExitCode::success) << err.str();
  const std::string json = out.str();
  const std::size_t at = json.find("\"peak_memory_bytes\": ");
  ASSERT_NE(at, std::string::npos) << json;
  const std::size_t bytes = std::stoull(json.substr(at + 21));
  EXPECT_GE(bytes, 2 * sizeof(Point3) * frames.t0.size()) << json;
  EXPECT_GE(peak_resident_bytes().value_or(0), bytes);  // it only grows
}

// --mark colours frame 0: exactly the faces and vertices of colliding vertex-face pairs,
// exactly the edges of colliding edge-edge pairs (and their other vertices), as the
// exhaustive pairwise CCD finds them.
TEST(CcdMeshCommand, MarkColoursExactlyTheCollidingElements) {
  auto rng = testing::seeded_engine("CcdMeshCommand.mark");
  const testing::ScratchDir dir("exactgeo_ccd_mesh_mark");
  const Frames frames = crumpling_sheet(6, rng);
  CcdMeshOptions options = frames_in(dir.path, frames, write_obj);
  options.mark = (dir.path / "marked.ply").string();
  std::ostringstream out, err;
  ASSERT_EQ(run_ccd_mesh(options, out, err), ExitCode::success) << err.str();
  std::ifstream file(options.mark);
  const auto ply = testing::read_marked_ply(
      std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>()));
  ASSERT_TRUE(ply.complete);
  ASSERT_EQ(ply.faces.size(), frames.faces.size());
  ASSERT_EQ(ply.vertex_colours.size(), frames.t0.size());

  const auto [vertex_face, edge_edge] = exhaustive(frames, ccd::Method::exact);
  ASSERT_FALSE(vertex_face.empty());
  ASSERT_FALSE(edge_edge.empty());
  const Rgb grey = ply.face_colours[0] == ply.face_colours[1] ? ply.face_colours[0] : Rgb{};
  std::vector<bool> face_hit(frames.faces.size()), vertex_hit(frames.t0.size());
  for (const Pair& p : vertex_face) {
    vertex_hit[p[0]] = true;
    face_hit[p[1]] = true;
  }
  std::set<std::array<std::size_t, 2>> edges;
  for (const Pair& p : edge_edge) {
    edges.insert({p[0], p[1]});
    edges.insert({p[2], p[3]});
  }
  // The colours, as the legend in the report names them.
  const auto colour_named = [&](const std::string& meaning) {
    for (const std::string& line : ply.legend) {
      if (line.find(meaning) == std::string::npos) continue;
      std::istringstream words(line.substr(line.find(' ', 8) + 1));
      return testing::read_rgb(words);
    }
    ADD_FAILURE() << "no legend for " << meaning;
    return grey;
  };
  const Rgb hit_face = colour_named("the face of a colliding vertex-face pair");
  const Rgb quiet_face = colour_named("face 200 200 200");
  const Rgb hit_vertex = colour_named("the vertex of a colliding vertex-face pair");
  const Rgb edge_end = colour_named("an end of a colliding edge");
  const Rgb quiet_vertex = colour_named("vertex 120 120 120");
  EXPECT_NE(hit_face, quiet_face);
  for (std::size_t f = 0; f < frames.faces.size(); ++f)
    EXPECT_EQ(ply.face_colours[f], face_hit[f] ? hit_face : quiet_face) << "face " << f;
  std::set<std::size_t> edge_ends;
  for (const auto& e : edges)
    edge_ends.insert(e.begin(), e.end());
  for (std::size_t v = 0; v < frames.t0.size(); ++v) {
    const Rgb expected = vertex_hit[v] ? hit_vertex : edge_ends.count(v) ? edge_end : quiet_vertex;
    EXPECT_EQ(ply.vertex_colours[v], expected) << "vertex " << v;
  }
  const std::set<std::array<std::size_t, 2>> marked_edges(ply.edges.begin(), ply.edges.end());
  EXPECT_EQ(marked_edges, edges);
  EXPECT_EQ(ply.edges.size(), edges.size());  // each once
}

TEST(CcdMeshCommand, SplitQuadsGivesTheTrianglesOfTheStatedDiagonal) {
  auto rng = testing::seeded_engine("CcdMeshCommand.split-quads");
  const testing::ScratchDir dir("exactgeo_ccd_mesh_quads");
  const Frames frames = crumpling_sheet(6, rng);
  CcdMeshOptions options = frames_in(dir.path, frames, write_quad_obj);
  options.json = true;
  std::ostringstream refused_out, refused_err;
  EXPECT_EQ(run_ccd_mesh(options, refused_out, refused_err), ExitCode::input_error);
  EXPECT_TRUE(refused_out.str().empty());
  EXPECT_NE(refused_err.str().find("--split-quads"), std::string::npos) << refused_err.str();

  options.split_quads = true;
  std::ostringstream out, err;
  ASSERT_EQ(run_ccd_mesh(options, out, err), ExitCode::success) << err.str();
  const auto [vertex_face, edge_edge] = exhaustive(frames, ccd::Method::exact);
  EXPECT_FALSE(vertex_face.empty() && edge_edge.empty()) << "the sheet should collide";
  EXPECT_EQ(pairs_in(out.str(), "vertex_face"), vertex_face) << out.str();
  EXPECT_EQ(pairs_in(out.str(), "edge_edge"), edge_edge) << out.str();
}

TEST(CcdMeshCommand, APolygonIsSplitAsInTheFirstFrame) {
  // A pentagon, convex in the first frame; in the second its corner 0 has moved inwards
  // (reflex), so its own ear clipping would cut other triangles.
  const testing::ScratchDir dir("exactgeo_ccd_mesh_polygon");
  const fs::path first = dir.path / "first.obj";
  const fs::path second = dir.path / "second.obj";
  std::ofstream(first) << "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 2 5 0\nv 0 4 0\nf 1 2 3 4 5\n";
  std::ofstream(second) << "v 2 3 1\nv 4 0 1\nv 4 4 1\nv 2 5 1\nv 0 4 1\nf 1 2 3 4 5\n";
  const mesh::LoadedMesh own = mesh::load_mesh(second.string());
  const mesh::LoadedMesh as_first = mesh::load_mesh(first.string());
  ASSERT_NE(own.mesh.faces, as_first.mesh.faces);  // the case this test is about
  CcdMeshOptions options;
  options.frame0 = first.string();
  options.frame1 = second.string();
  options.json = true;
  std::ostringstream out, err;
  EXPECT_EQ(run_ccd_mesh(options, out, err), ExitCode::success) << err.str();
  EXPECT_NE(out.str().find("\"candidates\": "), std::string::npos) << out.str();
}

}  // namespace
}  // namespace exactgeo::cli
