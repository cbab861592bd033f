#pragma once

// A mesh with colours, as an ASCII PLY file that any mesh viewer opens (MeshLab,
// Blender, ParaView): the vertices with their exact coordinates (`property double`,
// shortest decimals that read back to the same doubles), every face with a colour, and
// optionally colours per vertex and coloured edges. The legend (which colour means what,
// and how many there are) is in the header's comments, so the file explains itself.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cli/colour.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::cli {

/// What a colour means: "intersects another face", and how many elements have it.
struct LegendEntry {
  std::string element;  ///< "face", "vertex" or "edge"
  std::string meaning;
  Rgb colour;
  std::size_t count = 0;
};

struct ColouredEdge {
  std::array<VertexIndex, 2> vertices{};
  Rgb colour;
};

struct MarkedMesh {
  std::span<const Point3> vertices;
  std::span<const mesh::Face> faces;
  std::vector<Rgb> face_colours;    ///< one per face
  std::vector<Rgb> vertex_colours;  ///< empty, or one per vertex
  std::vector<ColouredEdge> edges;  ///< written as PLY `edge` elements
  std::vector<LegendEntry> legend;
};

/// The legend as a JSON object: {"file": PATH, "legend": [{"element", "colour" ("#rrggbb"),
/// "meaning", "count"}, ...]}.
std::string legend_json(const MarkedMesh& marked, const std::string& path);

/// The legend for a report: "marked in PATH:" and a line per colour.
std::string legend_text(const MarkedMesh& marked, const std::string& path);

/// The whole PLY file. Precondition: face_colours has one colour per face, and
/// vertex_colours none or one per vertex.
std::string marked_ply(const MarkedMesh& marked);

}  // namespace exactgeo::cli
