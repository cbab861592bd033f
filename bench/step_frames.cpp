#include "step_frames.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "exactgeo/mesh/load.hpp"

namespace exactgeo::ccd::bench {

std::vector<double> flat(const mesh::Mesh& mesh) {
  std::vector<double> xyz;
  xyz.reserve(3 * mesh.vertices.size());
  for (const Point3& p : mesh.vertices)
    xyz.insert(xyz.end(), p.begin(), p.end());
  return xyz;
}

std::vector<Triangle> triangles(const mesh::Mesh& mesh) {
  std::vector<Triangle> faces;
  for (const mesh::Face& f : mesh.faces) {
    faces.push_back({f.corners[0], f.corners[1], f.corners[2]});
    if (!f.is_triangle()) faces.push_back({f.corners[0], f.corners[2], f.corners[3]});
  }
  return faces;
}

double mean_edge_length(const Frames& frames) {
  double sum = 0.0;
  for (const Triangle& f : frames.faces) {
    for (int i = 0; i < 3; ++i) {
      double d2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double d = frames.t0[3 * f[i] + k] - frames.t0[3 * f[(i + 1) % 3] + k];
        d2 += d * d;
      }
      sum += std::sqrt(d2);
    }
  }
  return sum / (3.0 * static_cast<double>(frames.faces.size()));
}

void random_motion(Frames& frames, double amplitude, double standing, std::uint64_t seed) {
  const std::size_t n = frames.t0.size() / 3;
  int axis = 0;
  std::array<double, 3> extent{};
  for (int k = 0; k < 3; ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t v = 0; v < n; ++v) {
      lo = std::min(lo, frames.t0[3 * v + k]);
      hi = std::max(hi, frames.t0[3 * v + k]);
    }
    extent[k] = hi - lo;
    if (extent[k] > extent[axis]) axis = k;
  }
  std::vector<double> heights(n);
  for (std::size_t v = 0; v < n; ++v)
    heights[v] = frames.t0[3 * v + axis];
  std::vector<double> sorted = heights;
  std::sort(sorted.begin(), sorted.end());
  const double cut =
      standing > 0
          ? sorted[std::min(n - 1, static_cast<std::size_t>(standing * static_cast<double>(n)))]
          : -INFINITY;
  std::mt19937_64 rng(seed);
  const double step = amplitude * mean_edge_length(frames);
  std::uniform_real_distribution<double> d(-step, step);
  frames.t1 = frames.t0;
  for (std::size_t v = 0; v < n; ++v) {
    if (heights[v] < cut) continue;
    for (int k = 0; k < 3; ++k)
      frames.t1[3 * v + k] += d(rng);
  }
}

std::optional<Frames> load_frames(const std::vector<std::string>& paths, double motion,
                                  double standing, std::uint64_t seed) {
  Frames frames;
  const auto first = mesh::load_mesh(paths[0]);
  frames.t0 = flat(first.mesh);
  frames.faces = triangles(first.mesh);
  if (paths.size() == 2) {
    frames.t1 = flat(mesh::load_mesh(paths[1]).mesh);
    if (frames.t1.size() != frames.t0.size()) return std::nullopt;
  } else {
    random_motion(frames, motion, standing, seed);
  }
  return frames;
}

Frames moved_on(const Frames& step, double motion, double standing, std::uint64_t seed) {
  Frames following = step;
  following.t0 = step.t1;
  random_motion(following, motion, standing, seed);
  return following;
}

}  // namespace exactgeo::ccd::bench
