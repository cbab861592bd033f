#include "cli/info_command.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>
#include <string_view>

#include "cli/json.hpp"
#include "cli/marked_ply.hpp"
#include "cli/mesh_load_options.hpp"
#include "cli/mesh_marks.hpp"
#include "cli/output_file.hpp"
#include "cli/plural.hpp"
#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/self_intersection.hpp"

namespace exactgeo::cli {

using io::InputError;
using mesh::load_mesh;
using mesh::LoadedMesh;
using mesh::MeshCheck;

namespace {

using mesh::MeshCheck;

/// "[x, y, z]" (the same text is a JSON array).
std::string point_text(const Point3& p) {
  std::string s = "[";
  for (std::size_t k = 0; k < 3; ++k) {
    if (k > 0) s.append(", ");
    s.append(shortest(p[k]));
  }
  s.append("]");
  return s;
}

std::string yes_no(bool b) {
  return b ? "yes" : "no";
}

/// Everything info found, for either form of the report.
struct Findings {
  const LoadedMesh& loaded;
  const MeshCheck& check;
  std::optional<std::string> problem;  ///< why `inside` refuses the mesh
  /// nullopt when the check could not run (a corner out of range, a non-finite coordinate).
  std::optional<mesh::SelfIntersections> self;
  std::optional<MarkedMesh> marks;  ///< with --mark
};

std::string self_intersection_text(const Findings& f) {
  if (!f.self) return "not checked (a corner index out of range or a non-finite coordinate)";
  return mesh::self_intersection_problem(*f.self, f.loaded.first_index()).value_or("none");
}

void write_json(std::ostream& out, const InfoOptions& options, const Findings& f) {
  const LoadedMesh& loaded = f.loaded;
  const MeshCheck& c = f.check;
  out << "{\"file\": " << json_string(options.mesh)
      << ", \"format\": " << json_string(loaded.format)
      << ", \"coordinates_via_float\": " << (loaded.coordinates_via_float ? "true" : "false")
      << ", \"vertices\": " << c.vertices << ", \"welded_vertices\": " << loaded.welded_vertices
      << ", \"split_polygons\": " << loaded.split_polygons << ", \"faces\": " << c.faces
      << ", \"quads\": " << c.quads << ", \"triangles\": " << c.triangles << ", \"bounding_box\": ";
  if (c.bounding_box) {
    out << "{\"lower\": " << point_text(c.bounding_box->lower)
        << ", \"upper\": " << point_text(c.bounding_box->upper) << "}";
  } else {
    out << "null";
  }
  out << ", \"closed\": " << (c.closed() ? "true" : "false")
      << ", \"boundary_edges\": " << c.boundary_edges.count
      << ", \"manifold\": " << (c.manifold() ? "true" : "false")
      << ", \"non_manifold_edges\": " << c.non_manifold_edges.count
      << ", \"consistently_oriented\": "
      << (c.consistently_oriented ? (*c.consistently_oriented ? "true" : "false") : "null")
      << ", \"degenerate_faces\": " << c.degenerate_faces.count
      << ", \"non_planar_quads\": " << c.non_planar_quads.count
      << ", \"unreferenced_vertices\": " << c.unreferenced_vertices
      << ", \"components\": " << c.components;
  if (f.self) {
    out << ", \"intersecting_face_pairs\": " << f.self->intersecting.size()
        << ", \"undecided_face_pairs\": " << f.self->undecided.size();
  } else {
    out << ", \"intersecting_face_pairs\": null, \"undecided_face_pairs\": null";
  }
  out << ", \"problem\": " << (f.problem ? json_string(*f.problem) : std::string("null"));
  if (f.marks) out << ", \"mark\": " << legend_json(*f.marks, options.mark);
  out << "}\n";
}

void write_table(std::ostream& out, const InfoOptions& options, const Findings& f) {
  const LoadedMesh& loaded = f.loaded;
  const MeshCheck& c = f.check;
  auto row = [&out](std::string_view label, const std::string& value) {
    out << std::left << std::setw(20) << label << value << "\n";
  };
  row("file", mesh::mesh_source_name(options.mesh));
  row("format", loaded.format);
  if (loaded.coordinates_via_float) {
    out << "warning: coordinates came through 32-bit floats (assimp): not the file's exact "
           "values\n";
  }

  std::string vertices = std::to_string(c.vertices);
  if (loaded.welded_vertices > 0) {
    vertices.append(" (");
    vertices.append(plural(loaded.welded_vertices, "duplicate", "duplicates"));
    vertices.append(" welded)");
  }
  row("vertices", vertices);

  std::string faces = std::to_string(c.faces);
  faces.append(" (");
  faces.append(plural(c.quads, "quad", "quads"));
  faces.append(", ");
  faces.append(plural(c.triangles, "triangle", "triangles"));
  if (loaded.split_polygons > 0) {
    faces.append("; ");
    faces.append(plural(loaded.split_polygons, "polygon", "polygons"));
    faces.append(" split into triangles");
  }
  faces.append(")");
  row("faces", faces);

  if (c.bounding_box) {
    std::string box = point_text(c.bounding_box->lower);
    box.append(" to ");
    box.append(point_text(c.bounding_box->upper));
    row("bounding box", box);
  } else {
    row("bounding box", "none");
  }

  std::string closed = yes_no(c.closed());
  if (!c.closed()) {
    closed.append(": ");
    closed.append(plural(c.boundary_edges.count, "boundary edge", "boundary edges"));
    // An edge used 3, 5, ... times also leaves the surface open.
    if (const std::size_t odd = c.odd_edges.count - c.boundary_edges.count; odd > 0) {
      closed.append(", ");
      closed.append(plural(odd, "edge", "edges"));
      closed.append(" used by an odd number of faces");
    }
  }
  row("closed", closed);

  std::string manifold = yes_no(c.manifold());
  if (!c.manifold()) {
    manifold.append(": ");
    manifold.append(plural(c.non_manifold_edges.count, "non-manifold edge", "non-manifold edges"));
  }
  row("manifold", manifold);

  row("orientation", !c.consistently_oriented   ? "n/a (not every edge shared by two faces)"
                     : *c.consistently_oriented ? "consistent"
                                                : "inconsistent");
  row("degenerate faces", std::to_string(c.degenerate_faces.count));
  row("non-planar quads", std::to_string(c.non_planar_quads.count));
  row("unreferenced", std::to_string(c.unreferenced_vertices) + " vertices");
  row("components", std::to_string(c.components));
  row("self-intersection", self_intersection_text(f));
  out << "usable for `exactgeo inside`: " << (f.problem ? "no: " + *f.problem : "yes") << "\n";
  if (f.marks) out << legend_text(*f.marks, options.mark);
}

}  // namespace

ExitCode run_info(const InfoOptions& options, std::ostream& out, std::ostream& err) {
  LoadedMesh loaded;
  try {
    loaded = load_mesh(options.mesh, options.load);
  } catch (const std::exception& e) {  // InputError, or a failure inside a reader
    err << "exactgeo info: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  // The marked file is reserved before the work, so an unwritable path fails at once.
  std::optional<OutputFile> mark_file;
  try {
    if (!options.mark.empty()) mark_file.emplace(options.mark);
  } catch (const OutputFileError& e) {
    err << "exactgeo info: --mark: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  const MeshCheck check = mesh::check_mesh(loaded.mesh);
  Findings findings{loaded, check, mesh::closed_surface_problem(check, loaded), {}, {}};
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
    write_json(text, options, findings);
  } else {
    write_table(text, options, findings);
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
                  "mesh file (OBJ, OFF, PLY exactly; others via assimp), or - for standard "
                  "input (with --format)")
      ->required();
  add_mesh_format_option(*sub, options.load.format);
  add_weld_flag(*sub, options.load.weld, " first (for face soups, STL)");
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
