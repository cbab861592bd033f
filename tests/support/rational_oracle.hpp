#pragma once

// Exact oracles for the predicates, written independently of the library: GMP rationals
// and elementary algebra only. They share nothing with the library but the public types
// (Point3, Sign, RayTriangleHit, BilinearPatch, RayPatch, PatchShape), and reproduce the
// semantics documented on those types. They are slow on purpose: clarity over speed.
//
// Every function requires finite coordinates and throws std::invalid_argument otherwise
// (and for a zero ray direction).

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::testing {

/// Sign of det[b - a, c - a, d - a], evaluated in rationals.
Sign orient3d_oracle(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// How the ray {origin + s direction : s >= 0} meets the closed triangle (a, b, c), with
/// the semantics of RayTriangle / RayTriangleHit:
///  - if the line of the ray crosses the triangle's plane at a single point (n . d != 0
///    with n = (b - a) x (c - a)), that point's parameter s and barycentric coordinates
///    decide: s < 0 or point outside -> miss; s = 0 and point in the closed triangle ->
///    origin_on; s > 0 -> interior, edge (one barycentric coordinate zero: 0 = ab,
///    1 = bc, 2 = ca) or vertex (two zero: 0 = a, 1 = b, 2 = c), with turn = sign(n . d);
///  - otherwise (ray parallel to the plane, or zero-area triangle): origin_on if the
///    origin lies in the convex hull of a, b, c, else coplanar if the ray meets that hull,
///    else miss. feature = 0 and turn = zero in these cases.
RayTriangleHit ray_triangle_oracle(const Point3& origin, const Vector3& direction, const Point3& a,
                                   const Point3& b, const Point3& c);

/// Classification of the ray {origin + s direction : s > 0} against a bilinear patch,
/// decided in this order:
///  1. origin_on_patch: origin = p(u, v) for some (u, v) in [0, 1]^2;
///  2. degenerate: the ray meets one of the four closed boundary segments p00 -> p10 ->
///     p11 -> p01 -> p00;
///  3. degenerate: the corners, the origin and origin + direction lie in one plane and
///     the ray (s > 0) meets the convex hull of the four corners;
///  4. odd / even: parity of the number of solutions (u, v, s) in (0, 1)^2 x (0, inf) of
///     p(u, v) = origin + s direction, counted with multiplicity (a tangential contact, or
///     a crossing through the fold of a flat patch that covers itself twice, counts 2).
RayPatch ray_patch_oracle(const Point3& origin, const Vector3& direction,
                          const BilinearPatch& patch);

/// The count behind step 4 of ray_patch_oracle: the number of solutions (u, v, s) in
/// (0, 1)^2 x (0, inf) of p(u, v) = origin + s direction, with multiplicity (0, 1 or 2).
/// Throws std::invalid_argument when ray_patch_oracle does not answer even or odd (the
/// count is then undefined or infinite).
int ray_patch_crossings_oracle(const Point3& origin, const Vector3& direction,
                               const BilinearPatch& patch);

/// ray_patch_oracle's answer with the crossings of step 4 also counted by orientation:
/// each solution (u, v, s) counts the sign of n(u, v) . direction, n = dp/du x dp/dv (a
/// double solution has n . d = 0 and counts 0). signed_count is that sum for even and
/// odd, zero otherwise. The definition allows any integer; a sum outside -1..1, which
/// RayPatchCrossings cannot hold (the library claims it never happens), throws
/// std::domain_error.
RayPatchCrossings ray_patch_signed_crossings_oracle(const Point3& origin, const Vector3& direction,
                                                    const BilinearPatch& patch);

/// Whether x = p(u, v) for some (u, v) in the closed square [0, 1]^2. Exact for every
/// shape, including flat patches folding over themselves, whose image is not the region
/// bounded by the boundary polygon.
bool point_on_patch_oracle(const Point3& x, const BilinearPatch& patch);

/// The shape of a patch as documented on PatchShape: rank of the corner differences
/// (point, segment, planar, skew); for planar patches, a zero turn at a boundary corner
/// gives degenerate_planar, two crossing opposite edges give butterfly, four equal turns
/// give convex, and the remaining case (three turns one way, one the other) is concave.
PatchShape patch_shape_oracle(const BilinearPatch& patch);

/// For a skew patch, the side of its quadric on which x lies, with the convention of
/// patch_side: zero on the quadric, negative on the side of the diagonal p10 - p01 (the
/// side of the triangles (p00, p10, p01), (p10, p11, p01)) inside the corners'
/// tetrahedron. For a skew patch the quadric's equation is unique up to a constant
/// factor, so this fixes the sign everywhere. Throws std::invalid_argument for a flat
/// patch (coplanar corners), where the sign depends on the chosen polynomial.
Sign patch_side_oracle(const BilinearPatch& patch, const Point3& x);

}  // namespace exactgeo::testing
