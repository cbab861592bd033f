#include "cli/ccd_mesh_frames.hpp"

#include <algorithm>
#include <exception>
#include <utility>

#include "cli/plural.hpp"
#include "exactgeo/mesh/load.hpp"

namespace exactgeo::cli {

using mesh::LoadedMesh;

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
           ": ccd-mesh reads OBJ, OFF, PLY and STL files only (other formats come through "
           "assimp, which rounds coordinates to float and welds vertices)";
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
std::optional<std::string> connectivity_problem(const FrameFiles& files, const mesh::Mesh& mesh0,
                                                const mesh::Mesh& mesh1) {
  const std::string& frame0 = files.paths[0];
  const std::string& frame1 = files.paths[1];
  if (mesh0.vertices.size() != mesh1.vertices.size()) {
    return "the frames differ: " + frame0 + " has " +
           plural(mesh0.vertices.size(), "vertex", "vertices") + ", " + frame1 + " has " +
           std::to_string(mesh1.vertices.size());
  }
  const std::size_t common = std::min(mesh0.faces.size(), mesh1.faces.size());
  for (std::size_t f = 0; f < common; ++f) {
    if (mesh0.faces[f] != mesh1.faces[f]) {
      return "the frames differ in connectivity: face " + std::to_string(f) + " is " +
             corners_text(mesh0.faces[f]) + " in " + frame0 + " and " +
             corners_text(mesh1.faces[f]) + " in " + frame1;
    }
  }
  if (mesh0.faces.size() != mesh1.faces.size()) {
    return "the frames differ: " + frame0 + " has " + plural(mesh0.faces.size(), "face", "faces") +
           ", " + frame1 + " has " + std::to_string(mesh1.faces.size());
  }
  return std::nullopt;
}

/// The faces of more than four corners split in the second frame as in the first: the
/// reader splits each frame by its own geometry, and a step needs one set of triangles.
/// (Both frames number their faces alike when their polygons are the same; otherwise
/// connectivity_problem names the first difference.)
void split_as_the_first_frame(const LoadedMesh& first, LoadedMesh& second) {
  const std::vector<std::size_t>& file_faces = first.numbering.file_faces;
  if (file_faces.empty() || file_faces != second.numbering.file_faces) return;
  for (std::size_t f = 0; f < file_faces.size(); ++f) {
    const bool polygon = (f > 0 && file_faces[f - 1] == file_faces[f]) ||
                         (f + 1 < file_faces.size() && file_faces[f + 1] == file_faces[f]);
    if (polygon) second.mesh.faces[f] = first.mesh.faces[f];
  }
}

}  // namespace

std::optional<std::array<LoadedMesh, 2>> load_frames(const FrameFiles& files,
                                                     std::string& problem) {
  if (files.paths[0] == "-" && files.paths[1] == "-") {
    problem = "the two frames cannot both come from standard input";
    return std::nullopt;
  }
  const mesh::LoadOptions load{
      .weld = false, .split_polygons = files.split_polygons, .format = files.format};
  std::array<LoadedMesh, 2> frames;
  for (std::size_t k = 0; k < 2; ++k) {
    try {
      frames[k] = mesh::load_mesh(files.paths[k], load);
    } catch (const std::exception& e) {  // InputError, or a failure inside a reader
      problem = e.what();
      return std::nullopt;
    }
    if (auto why =
            frame_problem(mesh::mesh_source_name(files.paths[k]), frames[k], files.split_quads)) {
      problem = std::move(*why);
      return std::nullopt;
    }
  }
  split_as_the_first_frame(frames[0], frames[1]);
  if (auto why = connectivity_problem(files, frames[0].mesh, frames[1].mesh)) {
    problem = std::move(*why);
    return std::nullopt;
  }
  return frames;
}

}  // namespace exactgeo::cli
