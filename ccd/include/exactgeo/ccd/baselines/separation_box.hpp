#pragma once

// The minimum-separation baseline: the per-axis box test in plain doubles, as Tight
// Inclusion's minimum-separation mode decides it (Wang et al., "A Large-Scale Benchmark and
// an Inclusion-Based Algorithm for Continuous Collision Detection", ACM TOG 2021).
//
// The difference map F(t, u, v) between a point of one primitive and a point of the other
// (vertex - face point at barycentric (u, v); edge a at u - edge b at v) is affine in each
// parameter, so over a box of parameters its values lie in the box of its values at the
// box's eight corners. The test asks whether F meets the cube [-δ, δ]^3 for some
// parameters of the domain ([0, 1]^3; for the face, u + v <= 1): it splits the longest
// side of a parameter box while its corners' box meets the cube, and answers yes when the
// corners' box lies inside the cube, when a box is narrower than `tolerance` in every
// parameter and still meets it, or when more than `max_boxes` boxes were looked at.
//
// It is conservative by design, not exact: the cube holds points up to sqrt(3) δ away
// (a Euclidean distance in (δ, sqrt(3) δ] is reported), the tolerance adds about its own
// width times the primitives' speed, and plain doubles round. It exists to be measured
// against Options::min_separation (ccd.hpp), which decides the Euclidean question exactly.

#include <cstddef>

#include "exactgeo/ccd/queries.hpp"

namespace exactgeo::ccd {

struct SeparationBoxBaselineOptions {
  double tolerance = 1e-6;         ///< the parameter width at which a box meeting the cube is a yes
  std::size_t max_boxes = 100000;  ///< past this many boxes the answer is yes
};

/// Whether the primitives may come within δ in every coordinate at once during the step.
bool vertex_face_separation_box_baseline(const VertexFaceQuery& query, double delta,
                                         const SeparationBoxBaselineOptions& options = {}) noexcept;
bool edge_edge_separation_box_baseline(const EdgeEdgeQuery& query, double delta,
                                       const SeparationBoxBaselineOptions& options = {}) noexcept;

}  // namespace exactgeo::ccd
