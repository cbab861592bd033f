#include "cli/info_command.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <optional>
#include <ostream>
#include <sstream>

#include "cli/info_report.hpp"
#include "cli/marked_ply.hpp"
#include "cli/mesh_load_options.hpp"
#include "cli/mesh_marks.hpp"
#include "cli/output_file.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/self_intersection.hpp"

namespace exactgeo::cli {

using mesh::load_mesh;
using mesh::LoadedMesh;
using mesh::MeshCheck;

ExitCode run_info(const InfoOptions& options, std::ostream& out, std::ostream& err) {
  LoadedMesh loaded;
  try {
    loaded = load_mesh(options.mesh, options.load);
  } catch (const std::exception& e) {  // InputError, or a failure inside a reader
    err << "exactgeo info: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  for (const std::string& note : loaded.notes)
    err << "exactgeo info: warning: " << note << "\n";
  // The marked file is reserved before the work, so an unwritable path fails at once.
  std::optional<OutputFile> mark_file;
  try {
    if (!options.mark.empty()) mark_file.emplace(options.mark);
  } catch (const OutputFileError& e) {
    err << "exactgeo info: --mark: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  const MeshCheck check = mesh::check_mesh(loaded.mesh);
  // What `inside` says of the mesh by its default rule.
  InfoFindings findings{
      loaded,
      check,
      inside::rule_problem(check, inside::rule_for(check, std::nullopt), false, loaded),
      {},
      {}};
  if (!findings.problem) {
    findings.problem = inside::face_soup_problem(loaded, std::nullopt, inside::kCommandLineNames);
  }
  if (check.geometry_checkable()) findings.self = mesh::find_self_intersections(loaded.mesh);
  if (mark_file) {
    findings.marks = info_marks(loaded.mesh, check, findings.self);
    try {
      mark_file->commit(marked_ply(*findings.marks));
    } catch (const OutputFileError& e) {
      err << "exactgeo info: --mark: " << e.what() << "\n";
      return ExitCode::input_error;
    }
  }
  std::ostringstream text;
  if (options.json) {
    write_info_json(text, options.mesh, findings, options.mark);
  } else {
    write_info_table(text, options.mesh, findings, options.mark);
  }
  out << text.str();
  out.flush();
  return ExitCode::success;
}

CLI::App& add_info_command(CLI::App& app, InfoOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "info",
      "Report what a mesh file holds: vertices, faces (quads, triangles), bounding box, "
      "closed or not (boundary edges), non-manifold edges, orientation, degenerate faces and "
      "non-planar quads (both decided exactly), components, pairs of faces that intersect "
      "(exact: their interiors share a point; touching is not intersecting, nor are "
      "coplanar faces facing opposite ways, as where two solids meet face to face), and "
      "whether `exactgeo inside` can use it. Exit code 0 whenever the file loads.");
  sub->add_option("mesh", options.mesh,
                  "mesh file (OBJ, OFF, PLY, STL exactly; others via assimp), or - for "
                  "standard input (with --format)")
      ->required();
  add_mesh_format_option(*sub, options.load.format);
  add_weld_flag(*sub, options.load.weld, " first (for face soups; STL is always welded)");
  add_split_polygons_flag(*sub, options.load.split_polygons, " instead of refusing the file");
  sub->add_flag("--json", options.json, "print one JSON object instead of the table");
  sub->add_option("--mark", options.mark,
                  "also write the mesh as a PLY file with a colour per face: intersecting, "
                  "degenerate, on a non-manifold or boundary edge, non-planar quad (the "
                  "legend is in the file's comments and in the report)")
      ->type_name("OUT.ply");
  return *sub;
}

}  // namespace exactgeo::cli
