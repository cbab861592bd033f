#pragma once

// Continuous collision detection queries: primitives moving linearly from t = 0 to t = 1.
// Field names follow the public CCD benchmark files (Wang et al., ACM TOG 2021): _t0 is
// the position at the start of the step, _t1 at its end.

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::ccd {

/// A vertex v against a triangle (f0, f1, f2).
struct VertexFaceQuery {
  Point3 v_t0, f0_t0, f1_t0, f2_t0;
  Point3 v_t1, f0_t1, f1_t1, f2_t1;
};

/// Edge a = (ea0, ea1) against edge b = (eb0, eb1).
struct EdgeEdgeQuery {
  Point3 ea0_t0, ea1_t0, eb0_t0, eb1_t0;
  Point3 ea0_t1, ea1_t1, eb0_t1, eb1_t1;
};

}  // namespace exactgeo::ccd
