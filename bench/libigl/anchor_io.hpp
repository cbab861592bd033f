#pragma once

// The binary files scripts/inside-peers.py hands to the libigl anchors (little-endian):
// a mesh as int64 vertex and triangle counts, the vertices as float64 triples and the
// triangles as int32 triples; points as an int64 count and float64 triples; the answer as
// one float64 winding number per point. A mesh path not ending in .bin is a mesh file
// (OBJ, OFF, PLY, STL), read by libigl itself as a user of it would
// (scripts/inside-end-to-end.py). Built only by those scripts, against a libigl checkout
// outside this repository (libigl is MPL-2.0 and not packaged for Debian).

#include <igl/read_triangle_mesh.h>
#include <Eigen/Core>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace anchor {

template <class T>
std::vector<T> read_values(std::ifstream& in, std::int64_t count) {
  std::vector<T> values(static_cast<std::size_t>(count));
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(count * sizeof(T)));
  if (!in) throw std::runtime_error("short file");
  return values;
}

inline void read_mesh(const std::string& path, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  if (path.size() < 4 || path.compare(path.size() - 4, 4, ".bin") != 0) {
    if (!igl::read_triangle_mesh(path, V, F)) throw std::runtime_error("cannot read " + path);
    return;
  }
  std::ifstream in(path, std::ios::binary);
  const auto counts = read_values<std::int64_t>(in, 2);
  const auto vertices = read_values<double>(in, 3 * counts[0]);
  const auto triangles = read_values<std::int32_t>(in, 3 * counts[1]);
  V.resize(counts[0], 3);
  F.resize(counts[1], 3);
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      V(i, k) = vertices[static_cast<std::size_t>(3 * i + k)];
  for (Eigen::Index i = 0; i < F.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      F(i, k) = triangles[static_cast<std::size_t>(3 * i + k)];
}

inline Eigen::MatrixXd read_points(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::int64_t count = read_values<std::int64_t>(in, 1)[0];
  const auto coordinates = read_values<double>(in, 3 * count);
  Eigen::MatrixXd Q(count, 3);
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      Q(i, k) = coordinates[static_cast<std::size_t>(3 * i + k)];
  return Q;
}

inline void write_answers(const std::string& path, const Eigen::VectorXd& W) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(W.data()),
            static_cast<std::streamsize>(W.size() * sizeof(double)));
}

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace anchor
