#include "cli/mesh_marks.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace exactgeo::cli {

namespace {

constexpr Rgb kUnmarked{200, 200, 200};  // light grey (ccd-mesh: no collision)
constexpr Rgb kUnmarkedVertex{120, 120, 120};
constexpr Rgb kRed{230, 25, 75};
constexpr Rgb kMagenta{240, 50, 230};
constexpr Rgb kPurple{145, 30, 180};
constexpr Rgb kOrange{245, 130, 48};
constexpr Rgb kBlue{0, 130, 200};
constexpr Rgb kPaleBlue{185, 210, 235};  // quiet: every quad of a smooth mesh is one
constexpr Rgb kPlain{235, 235, 235};

/// Every face gets the colour of the first category it belongs to; the legend counts
/// the faces shown in each colour.
struct FaceCategory {
  const char* meaning;
  Rgb colour;
};

}  // namespace

MarkedMesh info_marks(const mesh::Mesh& mesh, const mesh::MeshCheck& check,
                      const std::optional<mesh::SelfIntersections>& self) {
  enum Category : std::size_t {
    intersecting,
    undecided,
    degenerate,
    non_manifold,
    boundary,
    non_planar,
    unmarked,
    kCategories
  };
  constexpr std::array<FaceCategory, kCategories> kFaceCategories{{
      {"intersects another face", kRed},
      {"intersection undecided (a contact the edge method cannot see past)", kMagenta},
      {"degenerate (repeated corner or zero area)", kPurple},
      {"on a non-manifold edge (used by three or more faces)", kOrange},
      {"on a boundary edge (used by one face)", kBlue},
      {"non-planar quad (a bilinear patch, not a defect)", kPaleBlue},
      {"none of these", kPlain},
  }};

  std::vector<std::array<bool, kCategories>> in(mesh.faces.size());
  if (self) {
    for (const auto& pair : self->intersecting)
      in[pair.first][intersecting] = in[pair.second][intersecting] = true;
    for (const auto& pair : self->undecided)
      in[pair.first][undecided] = in[pair.second][undecided] = true;
  }
  MarkedMesh marked{mesh.vertices, mesh.faces, {}, {}, {}, {}};
  std::array<std::size_t, kCategories> counts{};
  marked.face_colours.reserve(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const mesh::FaceFindings& found = check.face_findings[f];
    in[f][degenerate] = found.degenerate;
    in[f][non_manifold] = found.non_manifold_edge;
    in[f][boundary] = found.boundary_edge;
    in[f][non_planar] = found.non_planar;
    in[f][unmarked] = true;
    std::size_t category = 0;
    while (!in[f][category])
      ++category;
    ++counts[category];
    marked.face_colours.push_back(kFaceCategories[category].colour);
  }
  for (std::size_t c = 0; c < kCategories; ++c) {
    marked.legend.push_back(
        {"face", kFaceCategories[c].meaning, kFaceCategories[c].colour, counts[c]});
  }
  return marked;
}

MarkedMesh collision_marks(std::span<const Point3> vertices, std::span<const mesh::Face> triangles,
                           const ccd::MeshCcdResult& result) {
  MarkedMesh marked{vertices, triangles, {}, {}, {}, {}};
  marked.face_colours.assign(triangles.size(), kUnmarked);
  marked.vertex_colours.assign(vertices.size(), kUnmarkedVertex);
  std::size_t faces = 0;
  std::size_t face_vertices = 0;
  std::size_t edge_vertices = 0;
  for (const ccd::VertexFacePair& pair : result.vertex_face) {
    faces += marked.face_colours[pair.face] == kUnmarked ? 1 : 0;
    face_vertices += marked.vertex_colours[pair.vertex] == kUnmarkedVertex ? 1 : 0;
    marked.face_colours[pair.face] = kRed;
    marked.vertex_colours[pair.vertex] = kOrange;
  }
  std::vector<ccd::Edge> edges;
  for (const ccd::EdgeEdgePair& pair : result.edge_edge) {
    edges.push_back(pair.a);
    edges.push_back(pair.b);
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const ccd::Edge& edge : edges) {
    marked.edges.push_back({{edge[0], edge[1]}, kBlue});
    for (const VertexIndex v : edge) {
      if (marked.vertex_colours[v] != kUnmarkedVertex) continue;
      marked.vertex_colours[v] = kBlue;
      ++edge_vertices;
    }
  }
  marked.legend = {
      {"face", "the face of a colliding vertex-face pair", kRed, faces},
      {"face", "no collision", kUnmarked, triangles.size() - faces},
      {"vertex", "the vertex of a colliding vertex-face pair", kOrange, face_vertices},
      {"edge", "an edge of a colliding edge-edge pair", kBlue, edges.size()},
      {"vertex", "an end of a colliding edge (and in no colliding vertex-face pair)", kBlue,
       edge_vertices},
      {"vertex", "no collision", kUnmarkedVertex, vertices.size() - face_vertices - edge_vertices},
  };
  return marked;
}

}  // namespace exactgeo::cli
