#include "cli/info_report.hpp"

#include <iomanip>
#include <ostream>
#include <string_view>

#include "cli/json.hpp"
#include "cli/plural.hpp"
#include "exactgeo/mesh/load.hpp"

namespace exactgeo::cli {

using mesh::LoadedMesh;
using mesh::MeshCheck;

namespace {

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

std::string self_intersection_text(const InfoFindings& f) {
  if (!f.self) return "not checked (a corner index out of range or a non-finite coordinate)";
  return mesh::self_intersection_problem(*f.self, f.loaded.numbering).value_or("none");
}

}  // namespace

void write_info_json(std::ostream& out, const std::string& file, const InfoFindings& f,
                     const std::string& mark_path) {
  const LoadedMesh& loaded = f.loaded;
  const MeshCheck& c = f.check;
  out << "{\"file\": " << json_string(file) << ", \"format\": " << json_string(loaded.format)
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
      << ", \"unbalanced_edges\": " << c.unbalanced_edges.count
      << ", \"degenerate_faces\": " << c.degenerate_faces.count
      << ", \"zero_area_faces\": " << c.zero_area_faces.count
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
  if (f.marks) out << ", \"mark\": " << legend_json(*f.marks, mark_path);
  out << "}\n";
}

void write_info_table(std::ostream& out, const std::string& file, const InfoFindings& f,
                      const std::string& mark_path) {
  const LoadedMesh& loaded = f.loaded;
  const MeshCheck& c = f.check;
  auto row = [&out](std::string_view label, const std::string& value) {
    out << std::left << std::setw(20) << label << value << "\n";
  };
  row("file", mesh::mesh_source_name(file));
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
  row("winding numbers",
      c.unbalanced_edges.count == 0
          ? std::string("defined (every edge used as often in each direction)")
          : "not defined: " + plural(c.unbalanced_edges.count, "edge is", "edges are") +
                " used more often in one direction than in the other");
  row("degenerate faces", std::to_string(c.degenerate_faces.count) + " (" +
                              std::to_string(c.zero_area_faces.count) + " of zero area)");
  row("non-planar quads", std::to_string(c.non_planar_quads.count));
  row("unreferenced", std::to_string(c.unreferenced_vertices) + " vertices");
  row("components", std::to_string(c.components));
  row("self-intersection", self_intersection_text(f));
  std::string usable = f.problem ? "no: " + *f.problem : "yes";
  if (!f.problem && !c.closed() && c.unbalanced_edges.count > 0) {
    usable += ", as an open surface (" + plural(c.unbalanced_edges.count, "edge", "edges") +
              " run more often one way than the other): labelled by its generalized winding "
              "number";
  }
  if (const auto zero_area = mesh::zero_area_note(c.zero_area_faces, f.loaded.numbering);
      zero_area && !f.problem) {
    usable += "; " + *zero_area;
  }
  out << "usable for `exactgeo inside`: " << usable << "\n";
  if (f.marks) out << legend_text(*f.marks, mark_path);
}

}  // namespace exactgeo::cli
