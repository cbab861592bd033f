#include "cloth_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace exactgeo::cloth {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 load(std::span<const double> x, std::uint32_t v) {
  return {x[3 * v], x[3 * v + 1], x[3 * v + 2]};
}

double length(const Vec3& d) {
  return std::hypot(d[0], d[1], d[2]);
}

Vec3 difference(std::span<const double> x, std::uint32_t a, std::uint32_t b) {
  const Vec3 pa = load(x, a);
  const Vec3 pb = load(x, b);
  return {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
}

}  // namespace

ClothModel::ClothModel(const Scene& scene, const ClothParameters& parameters)
    : parameters_(parameters),
      cloth_vertices_(scene.cloth_vertices),
      acceleration_(3 * scene.cloth_vertices) {
  const std::uint32_t n = scene.resolution;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t v = i * n + j;
      if (j + 1 < n) add_spring(scene, v, v + 1, parameters_.structural, true);
      if (i + 1 < n) add_spring(scene, v, v + n, parameters_.structural, true);
      if (i + 1 < n && j + 1 < n) add_spring(scene, v, v + n + 1, parameters_.shear, true);
      if (i + 1 < n && j > 0) add_spring(scene, v, v + n - 1, parameters_.shear, true);
      if (j + 2 < n) add_spring(scene, v, v + 2, parameters_.bending, false);
      if (i + 2 < n) add_spring(scene, v, v + 2 * n, parameters_.bending, false);
    }
  }
}

void ClothModel::add_spring(const Scene& scene, std::uint32_t a, std::uint32_t b, double stiffness,
                            bool limits_stretch) {
  // Rest lengths from the flat grid, not from the (possibly perturbed) start positions.
  const std::uint32_t n = scene.resolution;
  const double di = static_cast<double>(b / n) - static_cast<double>(a / n);
  const double dj = static_cast<double>(b % n) - static_cast<double>(a % n);
  springs_.push_back({a, b, scene.spacing * std::hypot(di, dj), stiffness, limits_stretch});
}

void ClothModel::predict(std::span<const double> x0, std::span<double> velocity,
                         std::span<double> x1, double dt) const {
  const std::size_t nc = cloth_vertices_;
  // Forces, as accelerations (equal masses): gravity, then every spring.
  for (std::size_t v = 0; v < nc; ++v) {
    acceleration_[3 * v] = 0.0;
    acceleration_[3 * v + 1] = -parameters_.gravity;
    acceleration_[3 * v + 2] = 0.0;
  }
  const std::span<const double> v0(velocity);
  for (const Spring& s : springs_) {
    const Vec3 d = difference(x0, s.a, s.b);
    const double len = length(d);
    if (len == 0.0) continue;
    const Vec3 relative = difference(v0, s.a, s.b);
    const double closing = (relative[0] * d[0] + relative[1] * d[1] + relative[2] * d[2]) / len;
    const double magnitude =
        (s.stiffness * (len - s.rest) / dt + parameters_.spring_damping * closing) /
        (dt * len);  // times d: along the unit direction
    for (std::size_t k = 0; k < 3; ++k) {
      acceleration_[3 * s.a + k] += magnitude * d[k];
      acceleration_[3 * s.b + k] -= magnitude * d[k];
    }
  }
  // Symplectic Euler.
  const double keep = 1.0 - parameters_.air_damping;
  for (std::size_t i = 0; i < 3 * nc; ++i) {
    velocity[i] = (velocity[i] + dt * acceleration_[i]) * keep;
    x1[i] = x0[i] + dt * velocity[i];
  }
  std::copy(x0.begin() + static_cast<std::ptrdiff_t>(3 * nc), x0.end(),
            x1.begin() + static_cast<std::ptrdiff_t>(3 * nc));
  // Stretch limiting in the predicted positions: pull both ends of an over-long spring
  // together by half the excess each.
  const double limit = 1.0 + parameters_.max_stretch;
  for (int iteration = 0; iteration < parameters_.stretch_iterations; ++iteration) {
    for (const Spring& s : springs_) {
      if (!s.limits_stretch) continue;
      const Vec3 d = difference(x1, s.a, s.b);
      const double len = length(d);
      const double excess = len - limit * s.rest;
      if (excess <= 0.0) continue;
      const double scale = 0.5 * excess / len;
      for (std::size_t k = 0; k < 3; ++k) {
        x1[3 * s.a + k] += scale * d[k];
        x1[3 * s.b + k] -= scale * d[k];
      }
    }
  }
  for (std::size_t i = 0; i < 3 * nc; ++i)
    velocity[i] = (x1[i] - x0[i]) / dt;
}

}  // namespace exactgeo::cloth
