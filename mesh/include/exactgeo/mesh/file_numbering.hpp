#pragma once

// How a file numbers the vertices and faces of the Mesh read from it, so that messages
// name them as the file does: OBJ counts from 1, OFF and PLY (and exactgeo's Mesh) from
// 0, and a polygon split into triangles gives each of them the polygon's number.

#include <cstddef>
#include <string>
#include <vector>

namespace exactgeo::mesh {

struct FileNumbering {
  std::size_t first = 0;  ///< the number of the first vertex and face: 1 in OBJ, else 0
  /// The file's face (counted from 0) of each Mesh face, when some polygon was split;
  /// empty when Mesh face f is the file's face f.
  std::vector<std::size_t> file_faces{};

  std::string vertex(std::size_t v) const { return std::to_string(v + first); }
  std::string face(std::size_t f) const {
    return std::to_string((file_faces.empty() ? f : file_faces[f]) + first);
  }

  /// What a message naming faces adds: " (faces numbered from 1, as in the file)".
  std::string faces_said() const { return said("faces"); }
  /// The same for a message naming vertices and faces.
  std::string vertices_and_faces_said() const { return said("vertices and faces"); }

 private:
  std::string said(const char* what) const {
    std::string s = " (";
    s.append(what);
    s.append(first == 1 ? " numbered from 1, as in the file" : " numbered from 0");
    if (!file_faces.empty()) s.append("; the triangles of a split polygon by its number");
    s.append(")");
    return s;
  }
};

}  // namespace exactgeo::mesh
