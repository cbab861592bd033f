#include "polygon.hpp"

#include "exactgeo/io/input_error.hpp"

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

std::optional<std::string> add_polygon(std::span<const VertexIndex> corners, bool split_polygons,
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
  } else if (split_polygons) {
    for (std::size_t i = 1; i + 1 < n; ++i) {
      faces.push_back(make_triangle(corners[0], corners[i], corners[i + 1]));
    }
    ++out.split_polygons;
  } else {
    std::string why = "a face with ";
    why.append(std::to_string(n));
    why.append(
        " corners: only triangles and quads are supported (--split-polygons splits larger "
        "polygons into triangle fans)");
    return why;
  }
  return std::nullopt;
}

void require_faces(const LoadedMesh& loaded, const std::string& source) {
  if (loaded.mesh.faces.empty()) {
    std::string what = source;
    what.append(": the mesh has no faces");
    throw InputError(what);
  }
}

}  // namespace exactgeo::mesh::internal
