#include "mesh_cloth_model.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace exactgeo::cloth {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 load(std::span<const double> x, std::size_t v) {
  return {x[3 * v], x[3 * v + 1], x[3 * v + 2]};
}

void store(std::span<double> x, std::size_t v, const Vec3& p) {
  x[3 * v] = p[0];
  x[3 * v + 1] = p[1];
  x[3 * v + 2] = p[2];
}

double material_distance(std::span<const std::array<double, 2>> material, std::size_t a,
                         std::size_t b) {
  return std::hypot(material[b][0] - material[a][0], material[b][1] - material[a][1]);
}

/// p turned by `angle` about the vertical axis through `centre` (as place_obstacle turns).
Vec3 turned(const Vec3& p, const std::array<double, 3>& centre, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double x = p[0] - centre[0], z = p[2] - centre[2];
  return {centre[0] + (c * x + s * z), p[1], centre[2] + (-s * x + c * z)};
}

}  // namespace

MeshClothModel::MeshClothModel(const Scene& scene, const MeshClothParameters& parameters)
    : parameters_(parameters), ball_(scene.ball) {
  set_topology(scene.faces, scene.cloth_faces, scene.material);
}

void MeshClothModel::set_topology(std::span<const ccd::Triangle> faces, std::size_t sheet_faces,
                                  std::span<const std::array<double, 2>> material) {
  // Every sheet edge with the corner opposite it in each of its triangles.
  std::vector<std::tuple<ccd::VertexIndex, ccd::VertexIndex, ccd::VertexIndex>> sides;
  inverse_mass_.assign(material.size(), 0.0);
  std::vector<double> mass(material.size(), 0.0);
  for (std::size_t f = 0; f < sheet_faces; ++f) {
    const ccd::Triangle& t = faces[f];
    for (int k = 0; k < 3; ++k) {
      const ccd::VertexIndex a = t[k], b = t[(k + 1) % 3];
      sides.emplace_back(std::min(a, b), std::max(a, b), t[(k + 2) % 3]);
    }
    const auto& p = material[t[0]];
    const auto& q = material[t[1]];
    const auto& r = material[t[2]];
    const double area =
        0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    for (const ccd::VertexIndex v : t)
      mass[v] += area / 3.0;
  }
  for (std::size_t v = 0; v < mass.size(); ++v) {
    if (mass[v] > 0.0) inverse_mass_[v] = 1.0 / mass[v];
  }
  std::sort(sides.begin(), sides.end());
  constraints_.clear();
  for (std::size_t i = 0; i < sides.size();) {
    const auto [a, b, c] = sides[i];
    constraints_.push_back({a, b, material_distance(material, a, b), false});
    std::size_t j = i + 1;
    while (j < sides.size() && std::get<0>(sides[j]) == a && std::get<1>(sides[j]) == b)
      ++j;
    if (j == i + 2) {
      const ccd::VertexIndex d = std::get<2>(sides[i + 1]);
      constraints_.push_back({c, d, material_distance(material, c, d), true});
    }
    i = j;
  }
}

void MeshClothModel::keep_off_obstacles(std::span<const double> x0, std::span<double> x1,
                                        std::size_t v, double ball_turn) const {
  const double margin = parameters_.contact_margin;
  const double keep = 1.0 - parameters_.friction;
  Vec3 p = load(x1, v);
  const Vec3 start = load(x0, v);
  if (p[1] < margin) {  // the ground, at rest
    p = {start[0] + keep * (p[0] - start[0]), margin, start[2] + keep * (p[2] - start[2])};
  }
  if (ball_) {
    const SpinningBall& b = *ball_;
    const auto outside = [&](const Vec3& q) {
      const Vec3 d{q[0] - b.centre[0], q[1] - b.centre[1], q[2] - b.centre[2]};
      const double r = std::hypot(d[0], d[1], d[2]);
      const double s = r > 0.0 ? (b.radius + margin) / r : 1.0;
      return Vec3{b.centre[0] + s * d[0], b.centre[1] + s * d[1], b.centre[2] + s * d[2]};
    };
    const double r = std::hypot(p[0] - b.centre[0], p[1] - b.centre[1], p[2] - b.centre[2]);
    if (r < b.radius + margin) {
      // Friction against the surface, which carries the start point along by the turn.
      const Vec3 carried = turned(start, b.centre, ball_turn);
      p = outside({carried[0] + keep * (p[0] - carried[0]), carried[1] + keep * (p[1] - carried[1]),
                   carried[2] + keep * (p[2] - carried[2])});
    }
  }
  store(x1, v, p);
}

void MeshClothModel::predict(std::span<const double> x0, std::span<double> velocity,
                             std::span<double> x1, double dt, double ball_turn) const {
  const std::size_t n = inverse_mass_.size();
  const double keep = 1.0 - parameters_.air_damping;
  for (std::size_t v = 0; v < n; ++v) {
    velocity[3 * v + 1] -= dt * parameters_.gravity;
    for (std::size_t k = 0; k < 3; ++k) {
      velocity[3 * v + k] *= keep;
      x1[3 * v + k] = x0[3 * v + k] + dt * velocity[3 * v + k];
    }
  }
  project(x0, x1, inverse_mass_, ball_turn);
  for (std::size_t i = 0; i < 3 * n; ++i)
    velocity[i] = (x1[i] - x0[i]) / dt;
}

void MeshClothModel::relax(std::span<const double> x0, std::span<double> velocity,
                           std::span<double> x1, std::span<const unsigned char> pinned, double dt,
                           double ball_turn) const {
  std::vector<double> inverse_mass = inverse_mass_;
  for (std::size_t v = 0; v < inverse_mass.size(); ++v) {
    if (pinned[v] != 0) inverse_mass[v] = 0.0;
  }
  project(x0, x1, inverse_mass, ball_turn);
  for (std::size_t v = 0; v < inverse_mass.size(); ++v) {
    if (pinned[v] != 0) continue;
    for (std::size_t k = 0; k < 3; ++k)
      velocity[3 * v + k] = (x1[3 * v + k] - x0[3 * v + k]) / dt;
  }
}

void MeshClothModel::project(std::span<const double> x0, std::span<double> x1,
                             std::span<const double> inverse_mass, double ball_turn) const {
  for (int iteration = 0; iteration < parameters_.iterations; ++iteration) {
    for (const Constraint& c : constraints_) {
      const double wa = inverse_mass[c.a], wb = inverse_mass[c.b];
      const Vec3 pa = load(x1, c.a), pb = load(x1, c.b);
      const Vec3 d{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
      const double len = std::hypot(d[0], d[1], d[2]);
      if (len == 0.0 || wa + wb == 0.0) continue;
      const double error = len - c.rest;
      const double stiffness = c.bending     ? parameters_.bending_stiffness
                               : error > 0.0 ? parameters_.stretch_stiffness
                                             : parameters_.compress_stiffness;
      const double step = stiffness * error / (len * (wa + wb));
      for (std::size_t k = 0; k < 3; ++k) {
        x1[3 * c.a + k] += wa * step * d[k];
        x1[3 * c.b + k] -= wb * step * d[k];
      }
    }
    for (std::size_t v = 0; v < inverse_mass.size(); ++v) {
      if (inverse_mass[v] > 0.0) keep_off_obstacles(x0, x1, v, ball_turn);
    }
  }
}

}  // namespace exactgeo::cloth
