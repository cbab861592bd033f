// How a file numbers a mesh's vertices and faces (file_numbering.hpp): from 0 or from 1,
// a split polygon's triangles by the polygon's number, and the words a message adds to say
// so, as the header documents them; and the numbering the readers give: OBJ counts from 1,
// OFF from 0, and a pentagon's three triangles bear its number in either.

#include "exactgeo/mesh/file_numbering.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"

namespace exactgeo::mesh {
namespace {

TEST(FileNumbering, FromZeroFromOneAndSplitPolygons) {
  const FileNumbering mesh_order;
  EXPECT_EQ(mesh_order.vertex(3), "3");
  EXPECT_EQ(mesh_order.face(0), "0");
  EXPECT_EQ(mesh_order.faces_said(), " (faces numbered from 0)");
  EXPECT_EQ(mesh_order.vertices_and_faces_said(), " (vertices and faces numbered from 0)");

  const FileNumbering obj{1, {}};
  EXPECT_EQ(obj.vertex(0), "1");
  EXPECT_EQ(obj.face(41), "42");
  EXPECT_EQ(obj.faces_said(), " (faces numbered from 1, as in the file)");
  EXPECT_EQ(obj.vertices_and_faces_said(), " (vertices and faces numbered from 1, as in the file)");

  // Mesh faces 1, 2 and 3 are the triangles of the file's face 1.
  const FileNumbering split{1, {0, 1, 1, 1, 2}};
  EXPECT_EQ(split.face(0), "1");
  EXPECT_EQ(split.face(3), "2");
  EXPECT_EQ(split.face(4), "3");
  EXPECT_EQ(split.vertex(4), "5");  // vertices are never split
  EXPECT_EQ(split.faces_said(),
            " (faces numbered from 1, as in the file; the triangles of a split polygon by its "
            "number)");
}

TEST(FileNumbering, TheReadersNumberAsTheirFiles) {
  // A triangle, a flat pentagon (three triangles) and a quad.
  const std::string vertices = "0 0 0\n2 0 0\n3 1 0\n1 2 0\n-1 1 0\n";
  std::string obj;
  for (std::size_t at = 0; at < vertices.size();) {
    const std::size_t end = vertices.find('\n', at);
    obj.append("v ").append(vertices, at, end + 1 - at);
    at = end + 1;
  }
  obj.append("f 1 2 3\nf 1 2 3 4 5\nf 1 2 3 4\n");
  const LoadedMesh from_obj = read_obj(obj, "n.obj", {});
  const LoadedMesh from_off =
      read_off("OFF\n5 3 0\n" + vertices + "3 0 1 2\n5 0 1 2 3 4\n4 0 1 2 3\n", "n.off", {});
  ASSERT_EQ(from_obj.mesh.faces.size(), 5u);
  ASSERT_EQ(from_off.mesh.faces.size(), 5u);
  EXPECT_EQ(from_obj.numbering.first, 1u);
  EXPECT_EQ(from_off.numbering.first, 0u);
  for (const LoadedMesh* m : {&from_obj, &from_off}) {
    EXPECT_EQ(m->numbering.file_faces, (std::vector<std::size_t>{0, 1, 1, 1, 2}));
    EXPECT_TRUE(m->mesh.faces[4] == make_quad(0, 1, 2, 3));
  }
  EXPECT_EQ(from_obj.numbering.face(4), "3");  // the quad is OBJ's third face
  EXPECT_EQ(from_off.numbering.face(4), "2");  // and OFF's face 2
  EXPECT_EQ(from_obj.numbering.face(2), "2");  // a triangle of the pentagon
}

}  // namespace
}  // namespace exactgeo::mesh
