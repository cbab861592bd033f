#pragma once

// The sheets' dynamics on any triangulation (the model the remesher's changing meshes
// need; cloth_model.hpp is the block scene's grid of springs): position-based dynamics.
// Each step, velocities get gravity and air damping, x1 = x0 + dt v is predicted, then a
// few Gauss-Seidel passes project distance constraints onto x1: every edge keeps its rest
// length (stretch fully, compression softly), and the two corners opposite each inner edge
// keep theirs (a weak bending resistance); rest lengths come from the material
// coordinates, masses from the material areas (a third of each triangle's to each
// corner). Projection is stable at any resolution and time step, which an explicit
// spring model is not once edges differ fourfold in length. Then the ground plane and
// the ball, if any, push vertices out to a small margin (with friction against the ball's
// spinning surface), and v = (x1 - x0) / dt. Deterministic: fixed loop order, no threads.
//
// These analytic contacts only keep the sheets off the obstacles' smooth shapes; that the
// step is free of collisions with the obstacles' actual triangles and with the sheets
// themselves is the collision filter's business (collision_filter.hpp).

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "scene.hpp"

namespace exactgeo::cloth {

struct MeshClothParameters {
  double gravity = 9.81;             ///< m/s^2, along -y
  double stretch_stiffness = 1.0;    ///< fraction of an edge's excess length removed per pass
  double compress_stiffness = 0.02;  ///< ... of its shortfall
  double bending_stiffness = 0.02;   ///< ... of the opposite corners' distance error
  int iterations = 8;
  double air_damping = 0.002;     ///< fraction of the velocity lost per step
  double contact_margin = 0.006;  ///< metres kept above the ground and off the ball
  double friction = 0.6;          ///< fraction of the sliding motion lost in a contact
};

class MeshClothModel {
 public:
  MeshClothModel(const Scene& scene, const MeshClothParameters& parameters = {});

  /// Takes the sheets' triangulation: faces [0, sheet_faces) of `faces`, whose corners
  /// are the sheet vertices [0, material.size()).
  void set_topology(std::span<const ccd::Triangle> faces, std::size_t sheet_faces,
                    std::span<const std::array<double, 2>> material);

  /// Predicts the sheets' end of a step of length dt: x1's sheet part and `velocity` (3
  /// values per sheet vertex) are written; x1's obstacle part is left as it is (the caller
  /// places the obstacle). `ball_turn`: the angle the ball turns by over the step (0: none).
  void predict(std::span<const double> x0, std::span<double> velocity, std::span<double> x1,
               double dt, double ball_turn) const;

  /// Projects the constraints again with the `pinned` sheet vertices held where x1 has them
  /// (the ones the collision filter froze at x0), so that the rest of the sheet follows
  /// them instead of leaving them behind; the others' x1 and velocity are rewritten.
  void relax(std::span<const double> x0, std::span<double> velocity, std::span<double> x1,
             std::span<const unsigned char> pinned, double dt, double ball_turn) const;

 private:
  struct Constraint {
    ccd::VertexIndex a = 0;
    ccd::VertexIndex b = 0;
    double rest = 0.0;
    bool bending = false;
  };

  /// Pushes vertex v of x1 out of the ground and the ball, with friction.
  void keep_off_obstacles(std::span<const double> x0, std::span<double> x1, std::size_t v,
                          double ball_turn) const;

  /// The constraint passes on x1, with these inverse masses, then the obstacles' pushes
  /// (of the vertices with a mass).
  void project(std::span<const double> x0, std::span<double> x1,
               std::span<const double> inverse_mass, double ball_turn) const;

  MeshClothParameters parameters_;
  std::optional<SpinningBall> ball_;
  std::vector<Constraint> constraints_;
  std::vector<double> inverse_mass_;  // per sheet vertex
};

}  // namespace exactgeo::cloth
