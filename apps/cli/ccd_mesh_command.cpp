#include "cli/ccd_mesh_command.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <exception>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/ccd_mesh_frames.hpp"
#include "cli/ccd_mesh_report.hpp"
#include "cli/ccd_method_option.hpp"
#include "cli/json.hpp"
#include "cli/marked_ply.hpp"
#include "cli/mesh_load_options.hpp"
#include "cli/mesh_marks.hpp"
#include "cli/number_option.hpp"
#include "cli/output_file.hpp"
#include "cli/peak_memory.hpp"
#include "cli/threads_option.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::cli {

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

  std::string problem;
  const auto frames = load_frames({.paths = {options.frame0, options.frame1},
                                   .format = options.format,
                                   .split_polygons = options.split_polygons,
                                   .split_quads = options.split_quads},
                                  problem);
  if (!frames) return fail(problem);
  for (const mesh::LoadedMesh& frame : *frames) {
    for (const std::string& note : frame.notes)
      err << "exactgeo ccd-mesh: warning: " << note << "\n";
  }
  const mesh::Mesh& mesh0 = (*frames)[0].mesh;
  const mesh::Mesh& mesh1 = (*frames)[1].mesh;

  std::optional<ccd::MeshCcd> mesh_ccd;
  try {
    mesh_ccd.emplace(mesh0.vertices.size(), mesh::triangle_surface_of(mesh0).triangles);
  } catch (const std::invalid_argument& e) {
    return fail(options.frame0 + ": " + e.what());
  }

  const std::vector<double> positions0 = ccd::flat_positions(mesh0.vertices);
  const std::vector<double> positions1 = ccd::flat_positions(mesh1.vertices);
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
    write_ccd_mesh_json(text, options.method, options.time_of_impact, result, marks, options.mark,
                        peak_resident_bytes());
  } else {
    write_ccd_mesh_report(text, options.method, options.time_of_impact, *mesh_ccd, result, marks,
                          options.mark);
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
  add_number_option(
      *sub, "--toi-width",
      [&options](double width) -> std::optional<std::string> {
        if (!(width > 0.0)) return "expected a positive number";
        options.time_of_impact = true;
        options.time_of_impact_width = width;
        return std::nullopt;
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
                          " instead of refusing the files (every polygon is split as in the "
                          "first frame)");
  sub->add_flag(
      "--json", options.json,
      "print one JSON object (pairs, candidate counts, time of impact, seconds, peak memory) "
      "instead of the report");
  return *sub;
}

}  // namespace exactgeo::cli
