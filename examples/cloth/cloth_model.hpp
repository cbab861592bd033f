#pragma once

// The sheet's dynamics: a mass-spring model (structural, shear and bending springs between
// the grid's vertices) stepped explicitly, then a few Gauss-Seidel passes of position-based
// stretch limiting. Every vertex has the same mass. Deterministic: the same input gives the
// same bits (fixed loop order, no threads).
//
// Stiffness and damping are per-step numbers (k dt^2 / m and c dt / m), so the explicit
// step stays stable at every resolution and time step: the stiffest mode of the grid has
// omega^2 dt^2 <= 4 (structural + shear + bending) = 1.6, below symplectic Euler's limit 4.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "scene.hpp"

namespace exactgeo::cloth {

struct ClothParameters {
  double gravity = 9.81;         ///< m/s^2, along -y
  double structural = 0.25;      ///< k dt^2 / m of springs to the 4 grid neighbours
  double shear = 0.1;            ///< ... to the 4 diagonal neighbours
  double bending = 0.05;         ///< ... to the vertices two steps away along x and z
  double spring_damping = 0.05;  ///< c dt / m along each spring
  double air_damping = 0.002;    ///< fraction of the velocity lost per step
  double max_stretch = 0.1;      ///< structural and shear springs: at most 10% longer
  int stretch_iterations = 4;
};

class ClothModel {
 public:
  explicit ClothModel(const Scene& scene, const ClothParameters& parameters = {});

  /// Predicts the end of a step of length dt for the whole mesh: the sheet's velocities
  /// get the spring and gravity accelerations, x1 = x0 + dt * v, stretch is limited in
  /// x1, and v becomes (x1 - x0) / dt. The obstacle's x1 is a copy of its x0 (exactly
  /// standing). velocity holds 3 values per sheet vertex; x0 and x1 3 per mesh vertex.
  void predict(std::span<const double> x0, std::span<double> velocity, std::span<double> x1,
               double dt) const;

  std::size_t spring_count() const noexcept { return springs_.size(); }

 private:
  struct Spring {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    double rest = 0.0;
    double stiffness = 0.0;  ///< k dt^2 / m
    bool limits_stretch = false;
  };

  void add_spring(const Scene& scene, std::uint32_t a, std::uint32_t b, double stiffness,
                  bool limits_stretch);

  ClothParameters parameters_;
  std::size_t cloth_vertices_ = 0;
  std::vector<Spring> springs_;
  mutable std::vector<double> acceleration_;  // scratch, 3 per sheet vertex
};

}  // namespace exactgeo::cloth
