#pragma once

// CCD queries whose roots are known exactly, worked out by hand, for the tests of the
// pieces of the exact method (time pieces, parity on pieces, the polynomial decision, the
// root search).
//
// The edge-edge ones keep edge a = [(-1, 0, 0), (1, 0, 0)] still and move edge b in the
// plane x = X (X = 0 unless said), its ends b0(t) = (X, y0(t), z0(t)) and
// b1(t) = (X, y1(t), z1(t)) with y0 < 0 < y1 throughout. Line b meets the plane y = 0 at
// height z = N(t) / (y0 - y1) with N = y0 z1 - z0 y1, so b crosses the x-axis exactly when
// N(t) = 0, at x = X: inside edge a (u = 1/2) for X = 0, beside it for X = 2. With y0 =
// -1 + t/2 and y1 = 1 (so that N is a quadratic):
//
//   z0 = -3/16 - t,   z1 = 2t:   N = t^2 - t + 3/16 = (t - 1/4)(t - 3/4): b passes up
//                                through a at t = 1/4 and back down at t = 3/4;
//   z0 = -35/64 - t/2, z1 = 2t:  N = t^2 - 3t/2 + 35/64 = (t - 5/8)(t - 7/8): the same,
//                                late in the step;
//   z0 = -1 - 12t,    z1 = 18t:  N = (3t - 1)^2: b touches a at t = 1/3 and turns back
//                                (a tangential contact, a double root);
//   z0 = -1 - e - 12t, z1 = 18t: N = (3t - 1)^2 + e > 0 for e > 0: b stays below a, a
//                                near miss closest at about t = 1/3.

#include "exactgeo/ccd/queries.hpp"

namespace exactgeo::ccd::known_roots {

/// A vertex falling straight through a still triangle: from height 3 to -7 above the
/// point (1/4, 1/4) of the triangle (0, 0, 0), (1, 0, 0), (0, 1, 0); one root, at t* = 3/10
/// (not dyadic: no split ever lands on it).
inline VertexFaceQuery falling_vertex() {
  return {{0.25, 0.25, 3},  {0, 0, 0}, {1, 0, 0}, {0, 1, 0},
          {0.25, 0.25, -7}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}

/// Edge b in the plane x = `x` with y0 = -1 + t/2, y1 = 1 and the given heights.
inline EdgeEdgeQuery edge_b_moving(double x, double z0_t0, double z0_t1, double z1_t0,
                                   double z1_t1) {
  return {{-1, 0, 0}, {1, 0, 0}, {x, -1, z0_t0},   {x, 1, z1_t0},
          {-1, 0, 0}, {1, 0, 0}, {x, -0.5, z0_t1}, {x, 1, z1_t1}};
}

/// Two roots, t = 1/4 and t = 3/4: b passes through a and back (parity even).
inline EdgeEdgeQuery through_and_back() {
  return edge_b_moving(0, -0.1875, -1.1875, 0, 2);
}

/// Two roots late in the step, t = 5/8 and t = 7/8.
inline EdgeEdgeQuery through_and_back_late() {
  return edge_b_moving(0, -0.546875, -1.046875, 0, 2);
}

/// The same motion beside edge a (x = 2): the lines cross at t = 1/4 and 3/4, the edges
/// never meet.
inline EdgeEdgeQuery through_and_back_beside() {
  return edge_b_moving(2, -0.1875, -1.1875, 0, 2);
}

/// One tangential contact at t = 1/3 (a double root).
inline EdgeEdgeQuery tangent_at_one_third() {
  return edge_b_moving(0, -1, -13, 0, 18);
}

/// The tangential motion lowered by e > 0: a near miss.
inline EdgeEdgeQuery near_miss(double e) {
  return edge_b_moving(0, -1 - e, -13 - e, 0, 18);
}

}  // namespace exactgeo::ccd::known_roots
