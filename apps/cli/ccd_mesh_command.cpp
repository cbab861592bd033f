#include "cli/ccd_mesh_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "cli/ccd_method_option.hpp"
#include "cli/json.hpp"
#include "cli/marked_ply.hpp"
#include "cli/mesh_load_options.hpp"
#include "cli/mesh_marks.hpp"
#include "cli/number_option.hpp"
#include "cli/output_file.hpp"
#include "cli/plural.hpp"
#include "cli/threads_option.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/load.hpp"

namespace exactgeo::cli {

using io::InputError;
using mesh::load_mesh;
using mesh::LoadedMesh;
using mesh::LoadOptions;

namespace {

/// "[a, b, c]" (or four corners for a quad).
std::string corners_text(const mesh::Face& face) {
  std::string s = "[";
  for (std::size_t k = 0; k < face.size(); ++k) {
    if (k > 0) s.append(", ");
    s.append(std::to_string(face.corners[k]));
  }
  s.append("]");
  return s;
}

/// Why `loaded` cannot be a frame: coordinates rounded by assimp, or quads (unless they are
/// split).
std::optional<std::string> frame_problem(const std::string& path, const LoadedMesh& loaded,
                                         bool split_quads) {
  if (loaded.coordinates_via_float) {
    return path +
           ": ccd-mesh reads OBJ, OFF and PLY files only (other formats come through assimp, "
           "which rounds coordinates to float and welds vertices)";
  }
  const std::vector<mesh::Face>& faces = loaded.mesh.faces;
  const auto first_quad = std::find_if(faces.begin(), faces.end(),
                                       [](const mesh::Face& f) { return !f.is_triangle(); });
  if (first_quad == faces.end() || split_quads) return std::nullopt;
  const auto quads = static_cast<std::size_t>(
      std::count_if(first_quad, faces.end(), [](const mesh::Face& f) { return !f.is_triangle(); }));
  return "triangle meshes are needed: " + path + " has " + plural(quads, "quad", "quads") +
         " (first: face " + std::to_string(first_quad - faces.begin()) +
         "); --split-quads splits each along its diagonal c0-c2";
}

/// Where the frames stop holding the same mesh: vertex count, then the first differing
/// face, then face count.
std::optional<std::string> connectivity_problem(const CcdMeshOptions& options,
                                                const mesh::Mesh& mesh0, const mesh::Mesh& mesh1) {
  if (mesh0.vertices.size() != mesh1.vertices.size()) {
    return "the frames differ: " + options.frame0 + " has " +
           plural(mesh0.vertices.size(), "vertex", "vertices") + ", " + options.frame1 + " has " +
           std::to_string(mesh1.vertices.size());
  }
  const std::size_t common = std::min(mesh0.faces.size(), mesh1.faces.size());
  for (std::size_t f = 0; f < common; ++f) {
    if (mesh0.faces[f] != mesh1.faces[f]) {
      return "the frames differ in connectivity: face " + std::to_string(f) + " is " +
             corners_text(mesh0.faces[f]) + " in " + options.frame0 + " and " +
             corners_text(mesh1.faces[f]) + " in " + options.frame1;
    }
  }
  if (mesh0.faces.size() != mesh1.faces.size()) {
    return "the frames differ: " + options.frame0 + " has " +
           plural(mesh0.faces.size(), "face", "faces") + ", " + options.frame1 + " has " +
           std::to_string(mesh1.faces.size());
  }
  return std::nullopt;
}

/// The faces as triangles, in face order; a quad (c0, c1, c2, c3) becomes (c0, c1, c2) and
/// (c0, c2, c3).
std::vector<ccd::Triangle> triangles_of(const mesh::Mesh& mesh) {
  std::vector<ccd::Triangle> triangles;
  triangles.reserve(mesh.faces.size());
  for (const mesh::Face& f : mesh.faces) {
    const auto& c = f.corners;
    triangles.push_back({c[0], c[1], c[2]});
    if (!f.is_triangle()) triangles.push_back({c[0], c[2], c[3]});
  }
  return triangles;
}

/// x, y, z of vertex 0, then of vertex 1, ... (StepPositions' layout).
std::vector<double> flat_positions(const std::vector<Point3>& vertices) {
  std::vector<double> flat;
  flat.reserve(3 * vertices.size());
  for (const Point3& p : vertices)
    flat.insert(flat.end(), p.begin(), p.end());
  return flat;
}

std::string interval_text(const ccd::TimeInterval& t) {
  return "[" + shortest(t.start) + ", " + shortest(t.end) + "]";
}

void write_json(std::string& text, const CcdMeshOptions& options, const ccd::MeshCcdResult& result,
                const std::optional<MarkedMesh>& marks) {
  text.append("{\"method\": ").append(json_string(ccd::to_string(options.method)));
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
  if (options.time_of_impact) {
    text.append(", \"time_of_impact\": ")
        .append(result.time_of_impact ? interval_text(*result.time_of_impact) : "null");
  }
  text.append(", \"seconds\": ")
      .append(shortest(result.broad_phase_seconds + result.narrow_phase_seconds));
  text.append(", \"broad_phase_seconds\": ").append(shortest(result.broad_phase_seconds));
  text.append(", \"narrow_phase_seconds\": ").append(shortest(result.narrow_phase_seconds));
  if (marks) text.append(", \"mark\": ").append(legend_json(*marks, options.mark));
  text.append("}\n");
}

void write_report(std::string& text, const CcdMeshOptions& options, const ccd::MeshCcd& mesh,
                  const ccd::MeshCcdResult& result, const std::optional<MarkedMesh>& marks) {
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
  row("method", std::string(ccd::to_string(options.method)));
  row("vertex-face pairs", std::to_string(result.vertex_face.size()));
  row("edge-edge pairs", std::to_string(result.edge_edge.size()));
  row("candidates", std::to_string(result.candidates()) + " (" +
                        std::to_string(result.vertex_face_candidates) + " vertex-face, " +
                        std::to_string(result.edge_edge_candidates) + " edge-edge)");
  if (options.time_of_impact) {
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
  if (marks) text.append(legend_text(*marks, options.mark));
}

}  // namespace

ExitCode run_ccd_mesh(const CcdMeshOptions& options, std::ostream& out, std::ostream& err) {
  const auto fail = [&err](const std::string& message) {
    err << "exactgeo ccd-mesh: " << message << "\n";
    return ExitCode::input_error;
  };
  if (options.time_of_impact && options.method != ccd::Method::exact) {
    return fail("--toi needs --method exact (parity only says whether a pair collides)");
  }
  double min_separation = 0.0;
  if (options.min_separation) {
    std::string error;
    const auto delta = parse_min_separation(*options.min_separation, error);
    if (!delta) return fail("--min-separation must be a finite number >= 0: " + error);
    if (*delta > 0.0 && options.method != ccd::Method::exact) {
      return fail("--min-separation needs --method exact");
    }
    min_separation = *delta;
  }

  // The marked file is reserved before the work, so an unwritable path fails at once.
  std::optional<OutputFile> mark_file;
  try {
    if (!options.mark.empty()) mark_file.emplace(options.mark);
  } catch (const OutputFileError& e) {
    return fail("--mark: " + std::string(e.what()));
  }

  // No welding: it could merge vertices in one frame and not in the other.
  const LoadOptions load{
      .weld = false, .split_polygons = options.split_polygons, .format = options.format};
  if (options.frame0 == "-" && options.frame1 == "-") {
    return fail("the two frames cannot both come from standard input");
  }
  std::array<LoadedMesh, 2> frames;
  const std::array<const std::string*, 2> paths{&options.frame0, &options.frame1};
  for (std::size_t k = 0; k < 2; ++k) {
    try {
      frames[k] = load_mesh(*paths[k], load);
    } catch (const std::exception& e) {  // InputError, or a failure inside a reader
      return fail(e.what());
    }
    if (const auto problem =
            frame_problem(mesh::mesh_source_name(*paths[k]), frames[k], options.split_quads)) {
      return fail(*problem);
    }
  }
  const mesh::Mesh& mesh0 = frames[0].mesh;
  const mesh::Mesh& mesh1 = frames[1].mesh;
  if (const auto problem = connectivity_problem(options, mesh0, mesh1)) return fail(*problem);

  std::optional<ccd::MeshCcd> mesh_ccd;
  try {
    mesh_ccd.emplace(mesh0.vertices.size(), triangles_of(mesh0));
  } catch (const std::invalid_argument& e) {
    return fail(options.frame0 + ": " + e.what());
  }

  const std::vector<double> positions0 = flat_positions(mesh0.vertices);
  const std::vector<double> positions1 = flat_positions(mesh1.vertices);
  ccd::MeshCcdOptions ccd_options;
  ccd_options.method = options.method;
  if (options.time_of_impact) ccd_options.time_of_impact_width = options.time_of_impact_width;
  ccd_options.threads = options.threads;
  ccd_options.min_separation = min_separation;
  ccd::MeshCcdResult result;
  try {
    result = mesh_ccd->step({positions0, positions1}, ccd_options);
  } catch (const std::exception& e) {
    // The loaders refuse non-finite numbers and the frames were checked above, so this
    // is threads or memory running out.
    return fail("cannot run the step: " + std::string(e.what()));
  }

  std::optional<MarkedMesh> marks;
  std::vector<mesh::Face> triangles;
  if (mark_file) {
    for (const ccd::Triangle& t : mesh_ccd->faces())
      triangles.push_back(mesh::make_triangle(t[0], t[1], t[2]));
    marks = collision_marks(mesh0.vertices, triangles, result);
    try {
      mark_file->commit(marked_ply(*marks));
    } catch (const OutputFileError& e) {
      return fail("--mark: " + std::string(e.what()));
    }
  }
  std::string text;
  if (options.json) {
    write_json(text, options, result, marks);
  } else {
    write_report(text, options, *mesh_ccd, result, marks);
  }
  out << text << std::flush;
  return ExitCode::success;
}

CLI::App& add_ccd_mesh_command(CLI::App& app, CcdMeshOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "ccd-mesh",
      "Continuous collision detection on a triangle mesh over one time step. FRAME0 and "
      "FRAME1 hold the same mesh (the same vertex count and the same faces) at the start and "
      "at the end of the step; each vertex moves on the straight line between. Prints every "
      "colliding vertex-face pair (vertex-face V F) and edge-edge pair (edge-edge A0 A1 B0 B1, "
      "each edge with its smaller vertex first), skipping pairs that share a vertex, after the "
      "broad-phase candidate count and the time per phase. Indices are 0-based. Exit code 0 "
      "whether or not anything collides.");
  sub->add_option("frame0", options.frame0,
                  "the mesh at the start of the step (OBJ, OFF or PLY, read exactly); - for "
                  "standard input (with --format)")
      ->required();
  sub->add_option("frame1", options.frame1,
                  "the mesh at the end of the step: the same faces, other positions")
      ->required();
  add_mesh_format_option(*sub, options.format);
  sub->add_option("--mark", options.mark,
                  "also write frame 0 as a PLY file (the triangles the step ran on) with the "
                  "colliding vertices, edges and faces coloured (the legend is in the file's "
                  "comments and in the report)")
      ->type_name("OUT.ply");
  add_ccd_method_option(*sub, options.method, {ccd::Method::exact, ccd::Method::parity},
                        "exact (default: every root, exactly) or parity (the 2012 root parity "
                        "algorithm: misses pairs that touch an even number of times)");
  sub->add_flag("--toi", options.time_of_impact,
                "exact only: also report the earliest time of impact as an interval [start, "
                "end] within the step [0, 1] (no collision before start, one by end) of width "
                "at most 1e-6, or as none");
  sub->add_option_function<double>(
      "--toi-width",
      [&options](double width) {
        if (!(width > 0.0) || !std::isfinite(width)) {
          throw CLI::ValidationError("--toi-width",
                                     "expected a positive number, got " + shortest(width));
        }
        options.time_of_impact = true;
        options.time_of_impact_width = width;
      },
      "the widest time-of-impact interval (implies --toi; default 1e-6)");
  sub->add_option("--min-separation", options.min_separation,
                  "exact only: also report pairs whose Euclidean distance drops to at most "
                  "this during the step (default 0: contact)");
  add_threads_option(*sub, options.threads);
  sub->add_flag("--split-quads", options.split_quads,
                "accept quads: each quad c0 c1 c2 c3 becomes the triangles c0 c1 c2 and c0 c2 c3 "
                "(its diagonal c0-c2), in place, so face indices in the output count triangles "
                "in file order");
  add_split_polygons_flag(*sub, options.split_polygons,
                          " (the same split in both frames) instead of refusing the files");
  sub->add_flag("--json", options.json,
                "print one JSON object (pairs, candidate counts, time of impact, seconds) "
                "instead of the report");
  return *sub;
}

}  // namespace exactgeo::cli
