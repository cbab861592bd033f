#pragma once

// Exact minimum-separation oracle for linearly moving primitives, written from the
// definition with GMP rationals and elementary real algebra only (no code of the library
// under test; the query types are the only shared part). Slow on purpose: clarity over
// speed (a few milliseconds per query).
//
// ---------------------------------------------------------------------------------------
// Question
//
// Every point moves linearly, x(t) = (1 - t) x_t0 + t x_t1 for t in [0, 1], so every
// coordinate is a polynomial of degree <= 1 in t with rational coefficients (a double is a
// dyadic rational). For a separation delta >= 0 (delta^2 taken exactly), the oracle
// decides whether
//
//   S = { t in [0, 1] : dist(t) <= delta }
//
// is nonempty, where dist(t) is the Euclidean distance between the point v(t) and the
// closed triangle conv{f0(t), f1(t), f2(t)} (vertex-face), or between the closed segments
// conv{ea0(t), ea1(t)} and conv{eb0(t), eb1(t)} (edge-edge). Degenerate primitives are
// sets like any other: a zero-area triangle is a segment or a point, a zero-length edge is
// a point. dist is continuous in t, so S is closed and, when nonempty, has a minimum: the
// earliest time, also returned.
//
// ---------------------------------------------------------------------------------------
// Features
//
// Both distances are minima of a convex quadratic over a polytope of parameters:
//   vertex-face: |v - (f0 + b1 (f1 - f0) + b2 (f2 - f0))|^2 over b1, b2 >= 0, b1 + b2 <= 1;
//   edge-edge:   |(ea0 + s da) - (eb0 + u db)|^2 over (s, u) in [0, 1]^2,
// with da = ea1 - ea0, db = eb1 - eb0. A continuous function on a compact set attains its
// minimum; take a minimizer in the relative interior of a face F of the parameter polytope
// (a vertex, an edge, or the whole polytope) with F of least dimension. If the affine map
// from parameters to points (or point differences) is not injective on F (a zero-length
// edge, a zero-area triangle, parallel edges), the quadratic is constant along a line
// through the minimizer, and that line leaves F through its relative boundary at another
// minimizer, in a face of lower dimension: impossible. So the map is injective on F (the
// image of F is a nondegenerate point, segment, triangle or parallelogram), the gradient
// along F vanishes at the minimizer, and the minimizing point is the orthogonal
// projection onto the affine hull of F's image, lying in that image. This gives the
// features below: each feature's conjunction, at a fixed t, says "this face's image is
// nondegenerate, the orthogonal projection falls in its closure, and the squared distance
// to the affine hull is <= delta^2". Every feature that holds exhibits a point pair at
// distance <= delta (so dist <= delta), and the feature of F above holds whenever
// dist <= delta.
// Hence, for every t:  dist(t) <= delta  <=>  the conjunction of some feature holds at t.
//
// Point p against a segment [a, b] (e = b - a, w = p - a). If e.e > 0 the projection
// parameter is s = (w.e) / (e.e), in [0, 1] iff w.e >= 0 and e.e - w.e >= 0, and the
// squared distance to the line is |w|^2 - (w.e)^2 / (e.e) = |w x e|^2 / (e.e). Multiplying
// by e.e > 0:
//   point-edge:   w.e >= 0,  e.e - w.e >= 0,  e.e > 0,  |w|^2 (e.e) - (w.e)^2 - delta^2 (e.e) <= 0.
// Point p against a point q:
//   point-point:  |p - q|^2 - delta^2 <= 0.
//
// Vertex-face (7 features): v against each corner fi (3 point-point), v against each edge
// [f0, f1], [f1, f2], [f2, f0] (3 point-edge), and the face: with n = (f1 - f0) x (f2 - f0),
// n.n > 0 (nonzero area). The projection p of v onto the plane differs from v by a
// multiple of n, and (fj - fi) x n is orthogonal to n, so n.((fj - fi) x (p - fi)) =
// n.((fj - fi) x (v - fi)) = (n.n) * (barycentric coordinate of p opposite that edge). So
// p is in the closed triangle iff
//   n.((f1 - f0) x (v - f0)) >= 0,  n.((f2 - f1) x (v - f1)) >= 0,  n.((f0 - f2) x (v - f2)) >= 0,
// and the squared distance to the plane is (n.(v - f0))^2 / (n.n):
//   point-face:   n.n > 0, the three signs above, (n.(v - f0))^2 - delta^2 (n.n) <= 0.
// A zero-area triangle is the union of its three edges (its longest edge, or a point), so
// the point-point and point-edge features cover it.
//
// Edge-edge (9 features): each endpoint of one edge against each endpoint of the other (4
// point-point), each endpoint against the other segment (4 point-edge), and the interiors:
// with r = eb0 - ea0 and w = da x db, w.w > 0 (edges not parallel, both of positive
// length). The stationary point of |s da - u db - r|^2 solves
//   s (da.da) - u (da.db) = r.da,   s (da.db) - u (db.db) = r.db,
// whose determinant is -(w.w). Cramer's rule and the identity
// (a x b).(c x d) = (a.c)(b.d) - (a.d)(b.c) give
//   s = ((r x db).w) / (w.w),   u = ((r x da).w) / (w.w).
// The difference s da - u db - r there is orthogonal to da and db, so parallel to w, and
// its length is |r.w| / |w|:
//   interior:     w.w > 0,  (r x db).w >= 0,  w.w - (r x db).w >= 0,  (r x da).w >= 0,
//                 w.w - (r x da).w >= 0,  (w.r)^2 - delta^2 (w.w) <= 0.
// For parallel or zero-length edges the parameter square maps onto a segment or a point,
// which is the image of the square's boundary (each fibre of a rank <= 1 affine map is a
// line or the whole plane, and meets the square in a segment whose ends are on the
// boundary): the point-point and point-edge features cover it.
//
// ---------------------------------------------------------------------------------------
// Deciding in t
//
// Every condition above is a sign condition (>= 0, > 0, <= 0) on a polynomial in t with
// rational coefficients (degree <= 6). Let Z be the set of real roots in [0, 1] of all
// nonzero condition polynomials of all features (isolated with Sturm sequences on
// squarefree parts, by bisection, with equal roots of different polynomials merged). The
// points 0, 1 and Z cut [0, 1] into finitely many points and open intervals on each of
// which every polynomial has a constant sign, so every feature's conjunction is constant
// on each of these cells. The samples are 0, 1, the roots, and one rational point strictly
// inside each open interval. A sign at a rational sample is an evaluation; at an
// algebraic root alpha (the only root of a squarefree P in an isolating interval
// (lo, hi) whose ends are not roots of P), Q(alpha) = 0 iff gcd(P, Q) has a root in
// (lo, hi), and otherwise the interval is bisected until Q has no root in [lo, hi], when
// sign Q(alpha) = sign Q(lo). An identically zero polynomial has sign 0 everywhere.
//
// Earliest time: the samples are scanned in increasing order and the first one at which
// some feature holds is min S. Indeed, min S is in S, so some feature holds there; if
// min S were inside an open cell, that feature would hold on the whole cell, which
// contains smaller times, so min S is 0, 1 or a root, i.e. a sample. Every sample found
// satisfying is in S (the evaluation is exact), so no earlier sample satisfies. (An
// interval sample can therefore never come first; the implementation checks this.)
//
// The earliest time is reported exactly when it is rational and found as such: 0, 1, a
// bisection midpoint, the root of a squarefree part of degree 1, or the rational with the
// smallest denominator in the final isolating interval when it is a root. The last finds
// every rational root p/q with q < 2^40: two rationals with denominators <= q differ by
// at least 1/q^2 > 2^-80, so the interval holds no other one. Otherwise the time is
// reported as an open isolating interval of width <= 2^-80.

#include <gmpxx.h>

#include "exactgeo/ccd/queries.hpp"

namespace exactgeo::testing {

struct MinSeparationAnswer {
  /// Some t in [0, 1] has distance <= delta.
  bool within = false;
  /// When within: earliest_lo <= min S <= earliest_hi, and no element of S is below
  /// earliest_lo. Equal when the earliest time is known exactly (then it is that time);
  /// otherwise earliest_lo < min S < earliest_hi with earliest_hi - earliest_lo <= 2^-80.
  /// Both 0 when not within.
  mpq_class earliest_lo;
  mpq_class earliest_hi;
};

/// Whether the point v(t) comes within delta of the closed triangle (f0(t), f1(t), f2(t))
/// for some t in [0, 1], and the earliest such t. Throws std::invalid_argument for a
/// non-finite coordinate, or a delta that is negative, NaN or infinite.
MinSeparationAnswer min_separation_oracle(const ccd::VertexFaceQuery& q, double delta);

/// Whether the closed segments [ea0(t), ea1(t)] and [eb0(t), eb1(t)] come within delta of
/// each other for some t in [0, 1], and the earliest such t. Throws std::invalid_argument
/// as above.
MinSeparationAnswer min_separation_oracle(const ccd::EdgeEdgeQuery& q, double delta);

}  // namespace exactgeo::testing
