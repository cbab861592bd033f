#include "cli/ccd_mesh_report.hpp"

#include <iomanip>
#include <sstream>
#include <string_view>

#include "cli/json.hpp"
#include "cli/plural.hpp"

namespace exactgeo::cli {

namespace {

/// "[start, end]". (Appended piece by piece: GCC 12 warns, wrongly, about the same text
/// built with operator+ from a literal.)
std::string interval_text(const ccd::TimeInterval& t) {
  std::string text = "[";
  text.append(shortest(t.start)).append(", ").append(shortest(t.end)).append("]");
  return text;
}

}  // namespace

void write_ccd_mesh_json(std::string& text, ccd::Method method, bool time_of_impact,
                         const ccd::MeshCcdResult& result, const std::optional<MarkedMesh>& marks,
                         const std::string& mark_path,
                         std::optional<std::size_t> peak_memory_bytes) {
  text.append("{\"method\": ").append(json_string(ccd::to_string(method)));
  text.append(", \"vertex_face\": [");
  for (std::size_t i = 0; i < result.vertex_face.size(); ++i) {
    const ccd::VertexFacePair& p = result.vertex_face[i];
    text.append(i > 0 ? ", [" : "[").append(std::to_string(p.vertex));
    text.append(", ").append(std::to_string(p.face)).append("]");
  }
  text.append("], \"edge_edge\": [");
  for (std::size_t i = 0; i < result.edge_edge.size(); ++i) {
    const ccd::EdgeEdgePair& p = result.edge_edge[i];
    text.append(i > 0 ? ", [" : "[").append(std::to_string(p.a[0]));
    text.append(", ").append(std::to_string(p.a[1]));
    text.append(", ").append(std::to_string(p.b[0]));
    text.append(", ").append(std::to_string(p.b[1])).append("]");
  }
  text.append("], \"candidates\": ").append(std::to_string(result.candidates()));
  text.append(", \"vertex_face_candidates\": ")
      .append(std::to_string(result.vertex_face_candidates));
  text.append(", \"edge_edge_candidates\": ").append(std::to_string(result.edge_edge_candidates));
  if (time_of_impact) {
    text.append(", \"time_of_impact\": ")
        .append(result.time_of_impact ? interval_text(*result.time_of_impact) : "null");
  }
  text.append(", \"seconds\": ")
      .append(shortest(result.broad_phase_seconds + result.narrow_phase_seconds));
  text.append(", \"broad_phase_seconds\": ").append(shortest(result.broad_phase_seconds));
  text.append(", \"narrow_phase_seconds\": ").append(shortest(result.narrow_phase_seconds));
  text.append(", \"peak_memory_bytes\": ")
      .append(peak_memory_bytes ? std::to_string(*peak_memory_bytes) : "null");
  if (marks) text.append(", \"mark\": ").append(legend_json(*marks, mark_path));
  text.append("}\n");
}

void write_ccd_mesh_report(std::string& text, ccd::Method method, bool time_of_impact,
                           const ccd::MeshCcd& mesh, const ccd::MeshCcdResult& result,
                           const std::optional<MarkedMesh>& marks, const std::string& mark_path) {
  std::ostringstream report;
  auto row = [&report](std::string_view label, const std::string& value) {
    report << std::left << std::setw(20) << label << value << "\n";
  };
  auto seconds = [](double s) {
    std::ostringstream value;
    value << std::fixed << std::setprecision(6) << s << " s";
    return value.str();
  };
  row("mesh", plural(mesh.vertex_count(), "vertex", "vertices") + ", " +
                  plural(mesh.faces().size(), "face", "faces") + ", " +
                  plural(mesh.edges().size(), "edge", "edges"));
  row("method", std::string(ccd::to_string(method)));
  row("vertex-face pairs", std::to_string(result.vertex_face.size()));
  row("edge-edge pairs", std::to_string(result.edge_edge.size()));
  row("candidates", std::to_string(result.candidates()) + " (" +
                        std::to_string(result.vertex_face_candidates) + " vertex-face, " +
                        std::to_string(result.edge_edge_candidates) + " edge-edge)");
  if (time_of_impact) {
    row("time of impact",
        result.time_of_impact ? interval_text(*result.time_of_impact) : std::string("none"));
  }
  row("broad phase", seconds(result.broad_phase_seconds));
  row("narrow phase", seconds(result.narrow_phase_seconds));
  text.append(report.str());
  for (const ccd::VertexFacePair& p : result.vertex_face) {
    text.append("vertex-face ").append(std::to_string(p.vertex));
    text.append(" ").append(std::to_string(p.face)).append("\n");
  }
  for (const ccd::EdgeEdgePair& p : result.edge_edge) {
    text.append("edge-edge ").append(std::to_string(p.a[0]));
    text.append(" ").append(std::to_string(p.a[1]));
    text.append(" ").append(std::to_string(p.b[0]));
    text.append(" ").append(std::to_string(p.b[1])).append("\n");
  }
  if (marks) text.append(legend_text(*marks, mark_path));
}

}  // namespace exactgeo::cli
