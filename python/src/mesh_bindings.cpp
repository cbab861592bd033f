// exactgeo.Mesh and exactgeo.load_mesh.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "mesh_object.hpp"

namespace exactgeo::python {

namespace {

using mesh::Face;
using mesh::kNoVertex;

/// Checks one face's corner count (3 or 4; the indices were checked) and makes the face.
Face face_from(const VertexIndex* corners, std::size_t count, std::size_t row) {
  if (count != 3 && count != 4) {
    throw py::value_error("faces[" + std::to_string(row) + "] has " + std::to_string(count) +
                          " corners; a face is a triangle (3) or a quad (4)");
  }
  Face face;
  std::copy_n(corners, count, face.corners.begin());
  return face;
}

/// Faces from an (m, 3) or (m, 4) integer array, or from a sequence of 3- and 4-sequences.
std::vector<Face> faces_from(const py::object& faces, std::size_t vertex_count) {
  const IndexRange range = vertex_range(vertex_count);
  std::vector<Face> result;
  if (py::isinstance<py::array>(faces)) {
    const py::array_t<VertexIndex> array = vertex_indices(faces, "faces", {3, 4}, range);
    const auto width = static_cast<std::size_t>(array.shape(1));
    result.reserve(static_cast<std::size_t>(array.shape(0)));
    for (std::size_t row = 0; row < static_cast<std::size_t>(array.shape(0)); ++row)
      result.push_back(face_from(array.data() + row * width, width, row));
    return result;
  }
  if (!py::isinstance<py::sequence>(faces) || py::isinstance<py::str>(faces)) {
    throw py::value_error("faces must be an (m, 3) or (m, 4) integer array or a list of faces");
  }
  std::size_t row = 0;
  for (const py::handle face : faces) {
    VertexIndex corners[4] = {};
    std::size_t count = 0;  // all of them, though only the first four are kept
    try {
      for (const py::handle corner : face) {
        const VertexIndex index = corner_index(corner, {"faces", row}, range);
        if (count < 4) corners[count] = index;
        ++count;
      }
    } catch (const py::error_already_set&) {
      throw py::value_error("faces[" + std::to_string(row) + "] is not a sequence of indices");
    }
    result.push_back(face_from(corners, count, row));
    ++row;
  }
  return result;
}

MeshObject mesh_from_arrays(const py::object& vertices_in, const py::object& faces) {
  const Doubles vertices = coordinates(vertices_in, "vertices", {-1, 3});
  MeshObject object;
  object.loaded.format = "arrays";
  const std::span<const Point3> points = points_of(vertices);
  object.loaded.mesh.vertices.assign(points.begin(), points.end());
  object.loaded.mesh.faces = faces_from(faces, points.size());
  return object;
}

MeshObject load(const std::filesystem::path& path, bool weld, bool split_polygons,
                const std::optional<std::string>& format) {
  require_openable(path);
  MeshObject object;
  object.file = path.string();
  {
    py::gil_scoped_release release;
    object.loaded = mesh::load_mesh(
        path.string(),
        {.weld = weld, .split_polygons = split_polygons, .format = format.value_or("")});
  }
  for (const std::string& note : object.loaded.notes)
    warn(note);
  return object;
}

py::array_t<double> vertices_of(const MeshObject& object) {
  const auto& vertices = object.loaded.mesh.vertices;
  py::array_t<double> array({static_cast<py::ssize_t>(vertices.size()), py::ssize_t{3}});
  std::copy_n(vertices.data()->data(), 3 * vertices.size(), array.mutable_data());
  return array;
}

/// (m, 3) when every face is a triangle, else (m, 4) with -1 as the fourth corner of
/// triangles.
py::array_t<std::int64_t> faces_of(const MeshObject& object) {
  const auto& faces = object.loaded.mesh.faces;
  const bool all_triangles =
      std::all_of(faces.begin(), faces.end(), [](const Face& f) { return f.is_triangle(); });
  const std::size_t width = all_triangles ? 3 : 4;
  py::array_t<std::int64_t> array(
      {static_cast<py::ssize_t>(faces.size()), static_cast<py::ssize_t>(width)});
  std::int64_t* out = array.mutable_data();
  for (const Face& face : faces) {
    for (std::size_t k = 0; k < width; ++k)
      *out++ = face.corners[k] == kNoVertex ? -1 : static_cast<std::int64_t>(face.corners[k]);
  }
  return array;
}

py::list point_list(const Point3& p) {
  py::list list;
  for (const double x : p)
    list.append(x);
  return list;
}

/// The keys and values of `exactgeo info --json` (tests compare the two).
py::dict info_of(const MeshObject& object) {
  mesh::MeshCheck c;
  std::optional<std::string> problem;
  std::optional<mesh::SelfIntersections> self;
  {
    py::gil_scoped_release release;
    c = mesh::check_mesh(object.loaded.mesh);
    problem = inside::rule_problem(c, inside::rule_for(c, std::nullopt), false, object.loaded);
    if (c.geometry_checkable()) self = mesh::find_self_intersections(object.loaded.mesh);
  }
  const mesh::LoadedMesh& loaded = object.loaded;
  py::dict info;
  info["file"] = object.file ? py::object(py::str(*object.file)) : py::none();
  info["format"] = loaded.format;
  info["coordinates_via_float"] = loaded.coordinates_via_float;
  info["vertices"] = c.vertices;
  info["welded_vertices"] = loaded.welded_vertices;
  info["split_polygons"] = loaded.split_polygons;
  info["faces"] = c.faces;
  info["quads"] = c.quads;
  info["triangles"] = c.triangles;
  if (c.bounding_box) {
    py::dict box;
    box["lower"] = point_list(c.bounding_box->lower);
    box["upper"] = point_list(c.bounding_box->upper);
    info["bounding_box"] = box;
  } else {
    info["bounding_box"] = py::none();
  }
  info["closed"] = c.closed();
  info["boundary_edges"] = c.boundary_edges.count;
  info["manifold"] = c.manifold();
  info["non_manifold_edges"] = c.non_manifold_edges.count;
  info["consistently_oriented"] =
      c.consistently_oriented ? py::object(py::bool_(*c.consistently_oriented)) : py::none();
  info["unbalanced_edges"] = c.unbalanced_edges.count;
  info["degenerate_faces"] = c.degenerate_faces.count;
  info["zero_area_faces"] = c.zero_area_faces.count;
  info["non_planar_quads"] = c.non_planar_quads.count;
  info["unreferenced_vertices"] = c.unreferenced_vertices;
  info["components"] = c.components;
  info["intersecting_face_pairs"] =
      self ? py::object(py::int_(self->intersecting.size())) : py::none();
  info["undecided_face_pairs"] = self ? py::object(py::int_(self->undecided.size())) : py::none();
  info["problem"] = problem ? py::object(py::str(*problem)) : py::none();
  return info;
}

std::string repr_of(const MeshObject& object) {
  const auto& faces = object.loaded.mesh.faces;
  const auto triangles = static_cast<std::size_t>(
      std::count_if(faces.begin(), faces.end(), [](const Face& f) { return f.is_triangle(); }));
  return "<exactgeo.Mesh: " + std::to_string(object.loaded.mesh.vertices.size()) + " vertices, " +
         std::to_string(faces.size() - triangles) + " quads, " + std::to_string(triangles) +
         " triangles" + (object.file ? ", from " + *object.file : std::string()) + ">";
}

}  // namespace

void bind_mesh(py::module_& module) {
  py::class_<MeshObject>(module, "Mesh", R"doc(A surface mesh of quads and triangles.

A quad is the bilinear patch through its four corners in boundary order (no diagonal is
ever chosen); coordinates are kept exactly as given.)doc")
      .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("faces"),
           R"doc(A mesh from arrays.

vertices: (n, 3) coordinates, finite and each exactly a double (other dtypes are
    converted exactly or refused: see docs/python.md).
faces: an (m, 3) or (m, 4) integer array of 0-based vertex indices, or a list whose
    items are triangles (3 indices) and quads (4 indices), mixed; ints, never floats.

Raises ValueError naming the row of a wrong face (an index out of range or not an
integer, a wrong corner count) or of a vertex that is not finite or not exactly a
double.)doc")
      .def_property_readonly("vertices", &vertices_of, "(n, 3) float64 copy of the coordinates")
      .def_property_readonly("faces", &faces_of,
                             "(m, 3) int64 when every face is a triangle, else (m, 4) with -1 "
                             "as the fourth corner of triangles")
      .def_property_readonly("vertex_count",
                             [](const MeshObject& m) { return m.loaded.mesh.vertices.size(); })
      .def_property_readonly("face_count",
                             [](const MeshObject& m) { return m.loaded.mesh.faces.size(); })
      .def_property_readonly(
          "format", [](const MeshObject& m) { return m.loaded.format; },
          "the file format read (\"obj\", \"ply binary little endian\", ...), or \"arrays\"")
      .def("info", &info_of, R"doc(What `exactgeo info --json` reports, as a dict.

Counts of vertices, faces, quads and triangles; the bounding box; closed, manifold,
consistently oriented; degenerate faces and non-planar quads (both decided exactly);
components; pairs of faces that intersect and pairs the check could not decide (exact,
touching is not intersecting; None when a coordinate is not finite); and "problem": why
exactgeo.Classifier would refuse the mesh, or None.)doc")
      .def("__repr__", &repr_of);

  module.def("load_mesh", &load, py::arg("path"), py::kw_only(), py::arg("weld") = false,
             py::arg("split_polygons") = false, py::arg("format") = py::none(),
             R"doc(Reads a mesh file, keeping coordinates exact.

OBJ, OFF, PLY (ASCII and binary, float and double) and STL (ASCII and binary) are read by
exactgeo's own readers: decimal numbers correctly rounded, binary values bit for bit. STL,
a triangle soup, is always welded. Other formats (glTF, 3DS, ...) go through assimp, whose
coordinates are 32-bit floats (info()["coordinates_via_float"]).

weld: merge vertices with exactly equal coordinates (face soups).
split_polygons: make a face of more than four corners whose edges cross (which has no
    surface to split into) the fan of triangles from its first corner, instead of
    refusing the file. Other polygons are always split into triangles, exactly: a planar
    one into triangles covering exactly it, a non-planar one over its projection (with
    a warning).
format: "obj", "off", "ply", "stl" or a format assimp reads ("glb", ...), for a file whose
    name has no extension or a misleading one; None: the extension decides.

Raises OSError when the file cannot be opened, ValueError with the file and line (or
face) for malformed content.)doc");
}

}  // namespace exactgeo::python
