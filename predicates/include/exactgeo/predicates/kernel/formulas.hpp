#pragma once

// The polynomials behind every predicate, each written once and evaluated on several
// number types: double (the filter's approximation and the plain-double baseline),
// Roundoff (the filter constant, at compile time), Expansion (exact) and Rational (the
// GMP reference). The expression trees here are exactly the ones the filter analyses,
// so a formula must not be rewritten without re-deriving nothing: the constant follows.

#include <array>
#include <cstddef>

namespace exactgeo::kernel {

template <class T>
using Vec3 = std::array<T, 3>;

template <class T, std::size_t N>
using VectorArray = std::array<Vec3<T>, N>;

/// det[a, b, c] = a . (b x c), expanded along a.
template <class T>
constexpr auto det3(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// Component `axis` of a x b: the 2D cross product of a and b projected onto the
/// coordinate plane orthogonal to `axis`, in the orientation (axis+1, axis+2).
template <class T>
constexpr auto cross2(int axis, const Vec3<T>& a, const Vec3<T>& b) {
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  return a[i] * b[j] - a[j] * b[i];
}

template <class T>
constexpr auto dot3(const Vec3<T>& a, const Vec3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// a - b, coordinate by coordinate.
template <class T>
constexpr auto difference(const Vec3<T>& a, const Vec3<T>& b) {
  using R = decltype(a[0] - b[0]);
  return Vec3<R>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

/// det[a1 - a0, a2 - a0, a3 - a0] = orient3d(x0, x1, x2, x3) for a_i = x_i - o, any o: the
/// volume sign of four points known only relative to some origin.
template <class T>
constexpr auto tetrahedron_volume(const Vec3<T>& a0, const Vec3<T>& a1, const Vec3<T>& a2,
                                  const Vec3<T>& a3) {
  return det3(difference(a1, a0), difference(a2, a0), difference(a3, a0));
}

/// ((a1 - a0) x (a2 - a0))_axis: a component of the normal of the triangle (x0, x1, x2).
template <class T>
constexpr auto triangle_normal(int axis, const Vec3<T>& a0, const Vec3<T>& a1, const Vec3<T>& a2) {
  return cross2(axis, difference(a1, a0), difference(a2, a0));
}

/// The bilinear patch's implicit function at the origin, for corners given relative to
/// the origin (a_i = x_i - o) with x0 = p00, x1 = p10, x2 = p01, x3 = p11:
///   phi = g012 g132 - g013 g032,  g_pqr = orient3d(x_p, x_q, x_r, o) = -det[a_p, a_q, a_r].
/// The two minus signs cancel in each product.
template <class T>
constexpr auto bilinear_phi(const Vec3<T>& a0, const Vec3<T>& a1, const Vec3<T>& a2,
                            const Vec3<T>& a3) {
  return det3(a0, a1, a2) * det3(a1, a3, a2) - det3(a0, a1, a3) * det3(a0, a3, a2);
}

}  // namespace exactgeo::kernel
