// The outside anchor for `exactgeo inside`: CGAL's Side_of_triangle_mesh (exact predicates,
// AABB tree) on the same mesh with every quad split into two triangles along its c0-c2
// diagonal, on the same points, one thread. Built only for the benchmark, when Debian's
// libcgal-dev is installed; never shipped.
//
// Usage: cgal_inside_anchor MESH POINTS [LABELS_OUT]
// Prints one JSON object: triangles, points, inside, outside, boundary, build_seconds,
// seconds. LABELS_OUT, if given, receives one word per point (to compare with exactgeo).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <chrono>
#include <fstream>
#include <iostream>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/io/numbers.hpp"
#include "exactgeo/mesh/load.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: cgal_inside_anchor MESH POINTS [LABELS_OUT]\n";
    return 2;
  }
  try {
    const exactgeo::mesh::Mesh mesh = exactgeo::mesh::load_mesh(argv[1]).mesh;
    std::ifstream points_file(argv[2]);
    exactgeo::io::RecordReader reader(points_file, argv[2]);
    std::vector<Kernel::Point_3> points;
    while (const auto record = reader.next()) {
      points.emplace_back((*record).at(0), (*record).at(1), (*record).at(2));
    }

    SurfaceMesh sm;
    std::vector<SurfaceMesh::Vertex_index> vertex;
    for (const auto& p : mesh.vertices)
      vertex.push_back(sm.add_vertex({p[0], p[1], p[2]}));
    std::size_t refused = 0;
    for (const auto& f : mesh.faces) {
      const auto& c = f.corners;
      const auto add = [&](std::size_t a, std::size_t b, std::size_t d) {
        if (sm.add_face(vertex[c[a]], vertex[c[b]], vertex[c[d]]) == SurfaceMesh::null_face())
          ++refused;
      };
      add(0, 1, 2);
      if (!f.is_triangle()) add(0, 2, 3);
    }
    if (refused != 0) {
      std::cerr << "cgal_inside_anchor: CGAL refused " << refused << " triangles\n";
      return 2;
    }

    const Clock::time_point build_start = Clock::now();
    const CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel> side(sm);
    const double build_seconds = seconds_since(build_start);

    std::vector<CGAL::Bounded_side> sides(points.size());
    const Clock::time_point start = Clock::now();
    for (std::size_t i = 0; i < points.size(); ++i)
      sides[i] = side(points[i]);
    const double seconds = seconds_since(start);

    std::array<std::size_t, 3> count{};  // inside, outside, boundary
    std::ofstream labels;
    if (argc > 3) labels.open(argv[3]);
    for (const CGAL::Bounded_side s : sides) {
      const int k = s == CGAL::ON_BOUNDED_SIDE ? 0 : s == CGAL::ON_UNBOUNDED_SIDE ? 1 : 2;
      ++count[static_cast<std::size_t>(k)];
      if (labels.is_open()) labels << (k == 0 ? "inside\n" : k == 1 ? "outside\n" : "boundary\n");
    }
    std::cout << "{\"triangles\": " << sm.number_of_faces() << ", \"points\": " << points.size()
              << ", \"inside\": " << count[0] << ", \"outside\": " << count[1]
              << ", \"boundary\": " << count[2] << ", \"build_seconds\": " << build_seconds
              << ", \"seconds\": " << seconds << "}\n";
  } catch (const std::exception& e) {
    std::cerr << "cgal_inside_anchor: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
