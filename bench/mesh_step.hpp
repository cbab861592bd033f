#pragma once

// The mesh-level CCD steps of the benchmarks (ccd_mesh_bench, broad_phase_peers): a mesh
// file whose vertices move by a seeded uniform random motion, or two mesh files, the
// command line's FRAME0 and FRAME1. Quads are split into two triangles.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::ccd::bench {

/// One step: positions at t0 and t1 (3 doubles per vertex) and the triangles.
struct MeshStep {
  std::vector<double> t0, t1;
  std::vector<Triangle> faces;
};

/// The mean length of the triangles' edges at t0 (shared edges counted once per triangle).
double mean_edge_length(const MeshStep& mesh_step);

/// mesh_step.t1 = mesh_step.t0 moved by `amplitude` mean edge lengths at most in each
/// coordinate (uniform, seeded); the fraction `standing` of vertices lowest on the widest axis stands.
void random_motion(MeshStep& mesh_step, double amplitude, double standing, std::uint64_t seed);

/// The first step: FRAME0 moved by random_motion, or FRAME0 to FRAME1 when two paths are
/// given (then nullopt when their vertex counts differ). Loading errors are thrown as
/// mesh::load_mesh throws them.
std::optional<MeshStep> load_step(const std::vector<std::string>& paths, double motion,
                                  double standing, std::uint64_t seed);

/// A following step: from step.t1 on by a new random motion with `seed`.
MeshStep moved_on(const MeshStep& step, double motion, double standing, std::uint64_t seed);

}  // namespace exactgeo::ccd::bench
