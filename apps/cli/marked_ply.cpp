#include "cli/marked_ply.hpp"

#include "cli/json.hpp"

namespace exactgeo::cli {

namespace {

void append_colour(std::string& text, Rgb c) {
  text.append(" ").append(std::to_string(c.red));
  text.append(" ").append(std::to_string(c.green));
  text.append(" ").append(std::to_string(c.blue));
}

void append_header(std::string& text, const MarkedMesh& marked) {
  text.append("ply\nformat ascii 1.0\ncomment made by exactgeo --mark\n");
  for (const LegendEntry& entry : marked.legend) {
    text.append("comment legend ").append(entry.element);
    append_colour(text, entry.colour);
    text.append(" ").append(hex_colour(entry.colour)).append(": ").append(entry.meaning);
    text.append(" (").append(std::to_string(entry.count)).append(")\n");
  }
  text.append("element vertex ").append(std::to_string(marked.vertices.size())).append("\n");
  text.append("property double x\nproperty double y\nproperty double z\n");
  if (!marked.vertex_colours.empty()) {
    text.append("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  }
  text.append("element face ").append(std::to_string(marked.faces.size())).append("\n");
  text.append("property list uchar int vertex_indices\n");
  text.append("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  if (!marked.edges.empty()) {
    text.append("element edge ").append(std::to_string(marked.edges.size())).append("\n");
    text.append("property int vertex1\nproperty int vertex2\n");
    text.append("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  }
  text.append("end_header\n");
}

}  // namespace

std::string legend_json(const MarkedMesh& marked, const std::string& path) {
  std::string text = "{\"file\": " + json_string(path) + ", \"legend\": [";
  for (std::size_t i = 0; i < marked.legend.size(); ++i) {
    const LegendEntry& entry = marked.legend[i];
    text.append(i > 0 ? ", " : "").append("{\"element\": ").append(json_string(entry.element));
    text.append(", \"colour\": ").append(json_string(hex_colour(entry.colour)));
    text.append(", \"meaning\": ").append(json_string(entry.meaning));
    text.append(", \"count\": ").append(std::to_string(entry.count)).append("}");
  }
  return text.append("]}");
}

std::string legend_text(const MarkedMesh& marked, const std::string& path) {
  std::string text = "marked in " + path + ":\n";
  for (const LegendEntry& entry : marked.legend) {
    text.append("  ").append(hex_colour(entry.colour)).append("  ").append(entry.element);
    text.append(": ").append(entry.meaning).append(": ").append(std::to_string(entry.count));
    text.append("\n");
  }
  return text;
}

std::string marked_ply(const MarkedMesh& marked) {
  std::string text;
  append_header(text, marked);
  for (std::size_t v = 0; v < marked.vertices.size(); ++v) {
    const Point3& p = marked.vertices[v];
    text.append(shortest(p[0])).append(" ").append(shortest(p[1]));
    text.append(" ").append(shortest(p[2]));
    if (!marked.vertex_colours.empty()) append_colour(text, marked.vertex_colours[v]);
    text.append("\n");
  }
  for (std::size_t f = 0; f < marked.faces.size(); ++f) {
    const mesh::Face& face = marked.faces[f];
    text.append(std::to_string(face.size()));
    for (std::size_t k = 0; k < face.size(); ++k)
      text.append(" ").append(std::to_string(face.corners[k]));
    append_colour(text, marked.face_colours[f]);
    text.append("\n");
  }
  for (const ColouredEdge& edge : marked.edges) {
    text.append(std::to_string(edge.vertices[0])).append(" ");
    text.append(std::to_string(edge.vertices[1]));
    append_colour(text, edge.colour);
    text.append("\n");
  }
  return text;
}

}  // namespace exactgeo::cli
