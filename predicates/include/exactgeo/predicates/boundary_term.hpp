#pragma once

// The generalized winding number of an open surface: an exact integer plus a term over its
// boundary only, the term enclosed with certified bounds.
//
// Faces F oriented by their corner order have, at a point p off them, the generalized
// winding number w(p) = (1/4 pi) sum_f Omega_f(p), Omega_f the signed solid angle of f seen
// from p (positive from the side its corners turn clockwise, so that w = 1 inside a closed
// surface whose faces are counter-clockwise seen from outside). On a closed oriented
// surface w is the integer signed crossing count of any ray (crossing_parity.hpp). An open
// surface has a boundary: the oriented edges used more often in one direction than in the
// other, each `multiplicity` times net, as the faces run them.
//
// The antipodal decomposition. Take the ray p + s r (s >= 0) and close F with the cone K
// swept by its boundary away from the ray: K = {b - s r : b on the boundary, s >= 0},
// oriented so that its boundary cancels F's. F + K is closed (its one end is the point at
// infinity in direction -r, which the ray leaves behind), and the ray meets K only if it
// meets the boundary (p + s r = b - s' r puts b on the ray). So when the ray meets no
// boundary edge, w_{F+K}(p) is its signed crossing count with F, S_r(p), and
// w_F = S_r - w_K. The strip of K over a boundary edge a -> b, seen from p, covers the
// spherical triangle of the directions to b, a and -r, which is what the planar triangle
// (b, a, p - r) covers; hence
//
//     w(p) = S_r(p) + (1/4 pi) sum_{a -> b} m_ab Omega(p; a, b, p - r).
//
// The same holds for bilinear patches: their edges are straight segments, and S_r counts
// crossings with the patches themselves. Each triangle's solid angle (Van Oosterom and
// Strackee, IEEE Trans. Biomed. Eng. 30(2), 1983), with A = a - p, B = b - p, C = c - p, is
//
//     Omega = 2 atan2(det[A, B, C], |A||B||C| + (A.B)|C| + (A.C)|B| + (B.C)|A|),
//
// in (-2 pi, 2 pi): the half angle theta = atan2(N, D) lies in (-pi, pi). Its one branch
// cut, N = 0 with D < 0, is where p lies on the strip of K over the edge: where the ray
// meets the edge.
//
// Certified. A filter first (plain doubles and an a priori error bound,
// src/boundary_term_filter.cpp). Then each stage encloses every operation's exact
// result: doubles rounded outward
// (one ulp past the correctly rounded result, which IEEE 754 arithmetic and sqrt
// guarantee holds the exact one), then MPFR intervals of more and more bits (every
// operation, atan2 and pi included, correctly rounded down and up). The half angle's range
// over the box N x D is taken at the box's corners: the box lies in a half plane whose
// angles run continuously, where the extreme angles of a convex set are at its corners.
// Where the box straddles the branch cut, the exact sign of N (an exact predicate) says
// which side p is on; where it holds the origin (p within rounding of the edge's line),
// the stage cannot decide. The double stage's atan2 is the C library's, whose error the
// stage bounds by 2^-40 radians: 2048 ulps of pi (whose ulp is 2^-51), where every libm
// in use is within a few (glibc's atan2 comes from the IBM Accurate Mathematical Library,
// designed to round correctly).

#include <array>
#include <cstdint>
#include <span>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo {

/// A boundary edge, oriented as the faces run it, counted `multiplicity` times (the
/// number of uses one way minus the other, positive).
struct BoundaryEdge {
  VertexIndex from = 0;
  VertexIndex to = 0;
  std::int32_t multiplicity = 1;
};

/// Bounds certain to hold a real number.
struct Enclosure {
  double lower = 0.0;
  double upper = 0.0;

  /// A double between the bounds, the one the command line and Python report as the value.
  double midpoint() const noexcept { return lower + (upper - lower) / 2; }
};

enum class BoundaryTermKind : std::uint8_t {
  enclosed,       ///< `turns` holds the term
  ray_on_edge,    ///< the ray meets a boundary edge: no decomposition along it
  point_on_edge,  ///< the point lies on a boundary edge (a closed segment)
  undecided,      ///< this precision cannot enclose it (the point is too near an edge's line)
};

/// How an enclosed number compares with a level: certainly below, certainly above, or
/// the enclosure holds the level.
enum class Versus : std::uint8_t { below, above, unsure };

struct BoundaryTerm {
  BoundaryTermKind kind = BoundaryTermKind::undecided;
  /// enclosed: bounds on (1/4 pi) sum m Omega(p; a, b, p - r), in turns, rounded outward
  /// to doubles (to report; decisions near a level take `versus`, made at full precision).
  Enclosure turns;
  /// enclosed: the term against the two levels asked for, compared at the stage's
  /// precision.
  std::array<Versus, 2> versus{Versus::unsure, Versus::unsure};
};

/// The precisions the certified term is tried at, in bits: doubles (53: the filter, then
/// outward-rounded intervals), then MPFR.
inline constexpr unsigned kBoundaryTermPrecisions[] = {53, 128, 512, 2048};

/// The boundary term of the generalized winding number of `point` along the ray in
/// direction `ray`, certified, at `precision_bits` (53: doubles; more: MPFR), compared with
/// `levels` (for a label by w >= 1/2 with S crossings along the ray: 1/2 - S).
/// Preconditions: finite coordinates, ray != 0, edges index into vertices.
BoundaryTerm boundary_term(const Point3& point, const Vector3& ray,
                           std::span<const Point3> vertices, std::span<const BoundaryEdge> edges,
                           unsigned precision_bits, std::array<double, 2> levels = {0.0, 0.0});

/// The same in plain doubles, no bound: the non-exact baseline.
double boundary_term_double(const Point3& point, const Vector3& ray,
                            std::span<const Point3> vertices, std::span<const BoundaryEdge> edges);

}  // namespace exactgeo
