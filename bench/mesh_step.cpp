#include "mesh_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "exactgeo/mesh/load.hpp"

namespace exactgeo::ccd::bench {

double mean_edge_length(const MeshStep& mesh_step) {
  double sum = 0.0;
  for (const Triangle& f : mesh_step.faces) {
    for (int i = 0; i < 3; ++i) {
      double d2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double d = mesh_step.t0[3 * f[i] + k] - mesh_step.t0[3 * f[(i + 1) % 3] + k];
        d2 += d * d;
      }
      sum += std::sqrt(d2);
    }
  }
  return sum / (3.0 * static_cast<double>(mesh_step.faces.size()));
}

void random_motion(MeshStep& mesh_step, double amplitude, double standing, std::uint64_t seed) {
  const std::size_t n = mesh_step.t0.size() / 3;
  int axis = 0;
  std::array<double, 3> extent{};
  for (int k = 0; k < 3; ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t v = 0; v < n; ++v) {
      lo = std::min(lo, mesh_step.t0[3 * v + k]);
      hi = std::max(hi, mesh_step.t0[3 * v + k]);
    }
    extent[k] = hi - lo;
    if (extent[k] > extent[axis]) axis = k;
  }
  std::vector<double> heights(n);
  for (std::size_t v = 0; v < n; ++v)
    heights[v] = mesh_step.t0[3 * v + axis];
  std::vector<double> sorted = heights;
  std::sort(sorted.begin(), sorted.end());
  const double cut =
      standing > 0
          ? sorted[std::min(n - 1, static_cast<std::size_t>(standing * static_cast<double>(n)))]
          : -INFINITY;
  std::mt19937_64 rng(seed);
  const double step = amplitude * mean_edge_length(mesh_step);
  std::uniform_real_distribution<double> d(-step, step);
  mesh_step.t1 = mesh_step.t0;
  for (std::size_t v = 0; v < n; ++v) {
    if (heights[v] < cut) continue;
    for (int k = 0; k < 3; ++k)
      mesh_step.t1[3 * v + k] += d(rng);
  }
}

std::optional<MeshStep> load_step(const std::vector<std::string>& paths, double motion,
                                  double standing, std::uint64_t seed) {
  MeshStep mesh_step;
  const auto first = mesh::load_mesh(paths[0]);
  mesh_step.t0 = flat_positions(first.mesh.vertices);
  mesh_step.faces = mesh::triangle_surface_of(first.mesh).triangles;
  if (paths.size() == 2) {
    mesh_step.t1 = flat_positions(mesh::load_mesh(paths[1]).mesh.vertices);
    if (mesh_step.t1.size() != mesh_step.t0.size()) return std::nullopt;
  } else {
    random_motion(mesh_step, motion, standing, seed);
  }
  return mesh_step;
}

MeshStep moved_on(const MeshStep& step, double motion, double standing, std::uint64_t seed) {
  MeshStep following = step;
  following.t0 = step.t1;
  random_motion(following, motion, standing, seed);
  return following;
}

}  // namespace exactgeo::ccd::bench
