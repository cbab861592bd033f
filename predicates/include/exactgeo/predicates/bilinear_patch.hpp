#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/point.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo {

/// The bilinear patch p(u, v) = (1-u)(1-v) p00 + u(1-v) p10 + u v p11 + (1-u) v p01 over
/// (u, v) in [0, 1]^2. Its boundary is the closed polygon p00 -> p10 -> p11 -> p01. A
/// triangle (a, b, c) is the degenerate patch {a, b, c, c}.
struct BilinearPatch {
  Point3 p00;
  Point3 p10;
  Point3 p11;
  Point3 p01;
};

/// The order in which the ray tests read a patch's corners: p_ij at index i + 2j, that is
/// x0 = p00, x1 = p10, x2 = p01, x3 = p11 (boundary x0 -> x1 -> x3 -> x2). Patches are
/// given in boundary order everywhere else; every reordering goes through here.
template <class T>
constexpr std::array<T, 4> tensor_order(const T& p00, const T& p10, const T& p11, const T& p01) {
  return {p00, p10, p01, p11};
}

/// The affine span of a patch's corners: a solid (skew, with its volume sign), a plane
/// (with three corners that span it) or a line. What the ray tests need to know about a
/// patch independently of any ray, found once per patch (crossing_parity.hpp prepares it
/// for a set of faces).
struct PatchSpan {
  enum class Kind : std::uint8_t {
    skew,       ///< corners not coplanar
    planar,     ///< coplanar, not collinear
    collinear,  ///< all corners on one line (a segment or a point)
  };
  Kind kind = Kind::collinear;
  /// skew: the sign of orient3d(x0, x1, x2, x3), corners in tensor order.
  Sign volume = Sign::zero;
  /// planar: three corners (tensor-order indices) that are not collinear.
  std::array<std::uint8_t, 3> plane_triple{};
};

/// The exact shape of a patch.
enum class PatchShape : std::uint8_t {
  skew,               ///< corners not coplanar: a piece of hyperbolic paraboloid
  convex,             ///< planar, boundary a strictly convex quadrilateral
  concave,            ///< planar, simple boundary with one reflex corner ("dart")
  butterfly,          ///< planar, self-intersecting boundary ("hourglass", "bow tie")
  degenerate_planar,  ///< planar, but a boundary corner has zero turn (repeated or
                      ///< collinear consecutive corners, e.g. a triangle)
  segment,            ///< all corners collinear, not all equal
  point,              ///< all corners equal
};
std::string_view to_string(PatchShape shape) noexcept;

PatchShape classify_patch(const BilinearPatch& patch) noexcept;

/// Crossing parity of the ray {origin + s * direction : s > 0} with the patch, counting
/// the solutions (u, v) in [0,1]^2 of p(u, v) = origin + s direction (a flat patch that
/// folds over itself covers some points twice: they count twice).
enum class RayPatch : std::uint8_t {
  even,
  odd,
  origin_on_patch,  ///< origin = p(u, v) for some (u, v) in [0, 1]^2
  degenerate,       ///< no transversal count along this ray: it meets the patch boundary,
                    ///< or lies in the plane of a flat patch and meets the corners' hull.
                    ///< Ask again with another direction.
};
std::string_view to_string(RayPatch r) noexcept;

/// Exact (Brochu, Edwards, Bridson 2012, Algorithm 1, with every flat shape handled).
/// Preconditions: finite coordinates, direction != 0.
RayPatch ray_patch_parity(const Point3& origin, const Vector3& direction,
                          const BilinearPatch& patch,
                          Arithmetic arithmetic = Arithmetic::exact) noexcept;

/// The crossings of the same ray counted by orientation. The patch is oriented by its
/// corner order: its normal n(u, v) = dp/du x dp/dv points to the side from which the
/// boundary p00 -> p10 -> p11 -> p01 turns counter-clockwise (the side a triangle (a, b, c)
/// faces when given as the patch {a, b, c, c}). A crossing counts +1 where the ray passes
/// to the side n points to (n . direction > 0), -1 the other way, and a tangential
/// contact or a crossing through a flat patch's fold counts 0.
struct RayPatchCrossings {
  RayPatch parity = RayPatch::even;  ///< as ray_patch_parity answers
  /// even: zero; odd: the signed count, +1 or -1 (it is always -1, 0 or +1, so "odd" is
  /// "nonzero"); origin_on_patch, degenerate: zero, there is no count.
  Sign signed_count = Sign::zero;
};

/// Exact, with the stages and the degenerate answers of ray_patch_parity, whose answer is
/// this one's `parity`. The signed count of a ray from a point through a closed, oriented
/// surface is the point's winding number with respect to it (crossing_parity.hpp).
RayPatchCrossings ray_patch_crossings(const Point3& origin, const Vector3& direction,
                                      const BilinearPatch& patch,
                                      Arithmetic arithmetic = Arithmetic::exact) noexcept;

/// Sign of the patch's implicit function phi at x (phi = g012 g132 - g013 g032 with
/// g_pqr(x) = orient3d(x_p, x_q, x_r, x), corners in tensor order): zero on the
/// patch's quadric; for a skew patch and x inside the corners' tetrahedron, negative on the
/// side of the triangles (p00, p10, p01), (p10, p11, p01), positive on the other side.
Sign patch_side(const BilinearPatch& patch, const Point3& x,
                Arithmetic arithmetic = Arithmetic::exact) noexcept;

}  // namespace exactgeo
