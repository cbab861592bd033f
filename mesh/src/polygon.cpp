#include "polygon.hpp"

#include <algorithm>
#include <cmath>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/weld.hpp"
#include "polygon_triangulation.hpp"

namespace exactgeo::mesh::internal {

using io::InputError;

std::optional<std::string> zero_based_index_problem(std::int64_t index,
                                                    std::uint64_t vertex_count) {
  if (index >= 0 && static_cast<std::uint64_t>(index) < vertex_count) return std::nullopt;
  std::string what = "vertex index ";
  what.append(std::to_string(index));
  what.append(" is out of range: ");
  if (vertex_count == 0) {
    what.append("the file has no vertices");
  } else {
    what.append("valid: 0..");
    what.append(std::to_string(vertex_count - 1));
  }
  return what;
}

std::optional<std::string> FileFaces::add(std::span<const VertexIndex> corners, std::size_t line,
                                          LoadedMesh& out) {
  const std::size_t n = corners.size();
  auto& faces = out.mesh.faces;
  if (n < 3) {
    std::string why = "a face needs at least 3 corners, this one has ";
    why.append(std::to_string(n));
    return why;
  }
  if (n == 3) {
    faces.push_back(make_triangle(corners[0], corners[1], corners[2]));
  } else if (n == 4) {
    faces.push_back(make_quad(corners[0], corners[1], corners[2], corners[3]));
  } else {
    polygons_.push_back({faces.size(), line, corners_.size(), corners_.size() + n});
    corners_.insert(corners_.end(), corners.begin(), corners.end());
    faces.emplace_back();  // its place, filled by finish()
  }
  return std::nullopt;
}

namespace {

bool finite_corners(std::span<const VertexIndex> corners, const std::vector<Point3>& vertices) {
  return std::all_of(corners.begin(), corners.end(), [&](VertexIndex c) {
    const Point3& p = vertices[c];
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  });
}

std::string why_refused(std::size_t corners) {
  std::string why = "a face of ";
  why.append(std::to_string(corners));
  why.append(
      " corners whose edges cross or touch, in every projection onto a coordinate plane, has "
      "no surface to take: --split-polygons (split_polygons=True in Python) makes it the fan "
      "of triangles from its first corner");
  return why;
}

/// "3 faces (first: 5, 9, 12)": the faces a note is about.
std::string faces_named(const std::vector<std::size_t>& faces, const FileNumbering& numbering) {
  std::string s = std::to_string(faces.size());
  s.append(faces.size() == 1 ? " face (" : " faces (first: ");
  for (std::size_t k = 0; k < std::min<std::size_t>(faces.size(), 5); ++k) {
    if (k > 0) s.append(", ");
    s.append(numbering.face(faces[k]));
  }
  if (faces.size() > 5) s.append(", ...");
  s.append(")");
  return s;
}

}  // namespace

void FileFaces::finish(LoadedMesh& out, const std::string& source, const LoadOptions& options) {
  if (options.weld) weld(out);
  if (!polygons_.empty()) {
    std::vector<Face>& faces = out.mesh.faces;
    std::vector<Face> split;
    std::vector<std::size_t> file_faces;
    split.reserve(faces.size() + corners_.size());
    file_faces.reserve(split.capacity());
    std::vector<std::size_t> non_planar;  // file faces
    std::vector<std::size_t> fans;
    auto polygon = polygons_.begin();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (polygon == polygons_.end() || polygon->face != f) {
        split.push_back(faces[f]);
        file_faces.push_back(f);
        continue;
      }
      const std::span<const VertexIndex> corners(corners_.data() + polygon->begin,
                                                 polygon->end - polygon->begin);
      if (!finite_corners(corners, out.mesh.vertices)) {
        // No projection to split in: the fan keeps the face for the mesh checks, which
        // refuse non-finite coordinates, to name.
        append_fan(corners, split);
        file_faces.resize(split.size(), f);
        ++polygon;
        continue;
      }
      const PolygonForm form = triangulate_polygon(corners, out.mesh.vertices, split);
      if (form == PolygonForm::non_planar) non_planar.push_back(f);
      if (form == PolygonForm::self_crossing) {
        if (!options.split_polygons) {
          const std::string what =
              "face " + out.numbering.face(f) + ": " + why_refused(corners.size());
          if (polygon->line == 0) throw InputError(source + ": " + what);
          throw InputError(source, polygon->line, what);
        }
        append_fan(corners, split);
        fans.push_back(f);
      }
      file_faces.resize(split.size(), f);
      ++polygon;
    }
    out.split_polygons += polygons_.size();
    faces = std::move(split);
    // The notes name the file's faces, before file_faces maps the mesh's to them.
    if (!non_planar.empty()) {
      out.notes.push_back(
          source + ": " + faces_named(non_planar, out.numbering) +
          " of more than four corners not in one plane: split into triangles over the "
          "polygon's projection onto a coordinate plane, a surface with the polygon's edges "
          "that does not fold over itself" +
          out.numbering.faces_said());
    }
    if (!fans.empty()) {
      out.notes.push_back(source + ": " + faces_named(fans, out.numbering) +
                          " of more than four corners whose edges cross: made fans of "
                          "triangles from the first corner (--split-polygons)" +
                          out.numbering.faces_said());
    }
    out.numbering.file_faces = std::move(file_faces);
    corners_.clear();
    polygons_.clear();
  }
  require_faces(out, source);
}

void FileFaces::weld(LoadedMesh& out) {
  const std::size_t before = out.mesh.vertices.size();
  const std::vector<VertexIndex> new_index = merge_equal_positions(out.mesh.vertices);
  if (new_index.empty()) return;
  out.welded_vertices = before - out.mesh.vertices.size();
  const auto renumber = [&](VertexIndex& c) {
    if (c != kNoVertex) c = new_index[c];
  };
  for (Face& face : out.mesh.faces)
    std::for_each(face.corners.begin(), face.corners.end(), renumber);
  std::for_each(corners_.begin(), corners_.end(), renumber);
}

void require_faces(const LoadedMesh& loaded, const std::string& source) {
  if (loaded.mesh.faces.empty()) {
    std::string what = source;
    what.append(": the mesh has no faces");
    if (const std::size_t n = loaded.mesh.vertices.size(); n > 0) {
      what.append(": ").append(std::to_string(n)).append(n == 1 ? " vertex" : " vertices");
      what.append(" only, a point cloud (or lines), not a surface");
    }
    throw InputError(what);
  }
}

}  // namespace exactgeo::mesh::internal
