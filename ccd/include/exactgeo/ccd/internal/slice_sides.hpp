#pragma once

// Which side of its time slice's edges the origin lies on, as polynomials in time.
//
// A time slice is a convex polygon P_0 .. P_{H-1} (vertex-face: the triangle c0, c1, c2;
// edge-edge: the parallelogram c00, c10, c11, c01), with normal N = (P_1 - P_0) x
// (P_{H-1} - P_0). For each edge, s_i = (P_i x P_{i+1}) . N. When the origin lies in the
// slice's plane (the coplanarity cubic p vanishes, coplanarity.hpp) and N != 0, it is on
// the closed polygon iff every s_i >= 0, and strictly inside iff every s_i > 0. So, on a
// piece of the step:
//
//  * some s_i < 0 throughout: the origin is never on the slice, the piece holds no root
//    (where N = 0, s_i = 0: never certified negative);
//  * every s_i > 0 throughout and p of opposite signs at the piece's two ends: at the time
//    t* in between where p = 0, the origin is strictly inside the slice, so F has a root.
//
// The second proves a collision without corners or parity: a pass through the face, which
// root parity cannot see (two roots), settled by polynomials alone.
//
// Each corner moves affinely, so P_i x P_j and N are quadratics and s_i a quartic in t.
// In Bernstein form over the step, with W_a and N_b the quadratics' coefficients
// (W_0 = A_i x A_j, W_1 = (A_i x B_j + B_i x A_j) / 2, W_2 = B_i x B_j; A at t0, B at t1),
// the quartic's coefficients times 6 are
//   6 W0.N0,  3 (W0.N1 + W1.N0),  W0.N2 + 4 W1.N1 + W2.N0,  3 (W1.N2 + W2.N1),  6 W2.N2.
// All of it is computed with running error bounds (bounded.hpp); de Casteljau gives the
// coefficients on halves. All five strictly of one sign prove that sign throughout.

#include <array>
#include <cstddef>
#include <utility>

#include "exactgeo/ccd/internal/bounded.hpp"
#include "exactgeo/predicates/internal/offset.hpp"

namespace exactgeo::ccd::internal {

/// The side quartics of a step with C corners (6: vertex-face, 8: edge-edge), on a piece.
template <std::size_t C>
class SliceSides {
 public:
  static constexpr std::size_t H = C / 2;
  using Quartic = std::array<Bounded, 5>;
  using Coefficients = std::array<Quartic, H>;

  /// The quartics over the whole step, from the step's corners (rounded differences).
  static Coefficients of(const exactgeo::internal::Offsets<C>& corners) noexcept {
    // Polygon order of the slice's corners (boundary_image.hpp numbering).
    constexpr std::array<std::size_t, H> kAround = [] {
      if constexpr (H == 3) {
        return std::array<std::size_t, 3>{0, 1, 2};
      } else {
        return std::array<std::size_t, 4>{0, 2, 3, 1};
      }
    }();
    std::array<Vector, H> start;
    std::array<Vector, H> end;
    for (std::size_t k = 0; k < H; ++k) {
      start[k] = rounded(corners[kAround[k]]);
      end[k] = rounded(corners[H + kAround[k]]);
    }
    const Quadratic normal =
        cross_quadratic(difference(start[1], start[0]), difference(end[1], end[0]),
                        difference(start[H - 1], start[0]), difference(end[H - 1], end[0]));
    Coefficients sides;
    for (std::size_t i = 0; i < H; ++i) {
      const std::size_t j = (i + 1) % H;
      const Quadratic w = cross_quadratic(start[i], end[i], start[j], end[j]);
      sides[i] = dot_quartic(w, normal);
    }
    return sides;
  }

  /// The coefficients on the two halves of a piece.
  static std::pair<Coefficients, Coefficients> split(const Coefficients& c) noexcept {
    std::pair<Coefficients, Coefficients> halves;
    for (std::size_t i = 0; i < H; ++i) {
      Quartic b = c[i];
      // de Casteljau at 1/2: the left half takes the first entry of each level, the
      // right half the last.
      for (int level = 0; level <= 4; ++level) {
        halves.first[i][level] = b[0];
        halves.second[i][4 - level] = b[4 - level];
        for (int k = 0; k < 4 - level; ++k)
          b[k] = midpoint(b[k], b[k + 1]);
      }
    }
    return halves;
  }

  /// Some edge's quartic is certainly negative on the whole piece: no root there.
  static bool origin_outside(const Coefficients& c) noexcept {
    for (const Quartic& q : c) {
      if (all_of_sign(q, Sign::negative)) return true;
    }
    return false;
  }

  /// Every edge's quartic is certainly positive on the whole piece.
  static bool origin_inside(const Coefficients& c) noexcept {
    for (const Quartic& q : c) {
      if (!all_of_sign(q, Sign::positive)) return false;
    }
    return true;
  }

 private:
  using Vector = std::array<Bounded, 3>;
  using Quadratic = std::array<Vector, 3>;  // Bernstein coefficients of a vector quadratic

  static Vector rounded(const exactgeo::internal::Offset& o) noexcept {
    const auto r = o.rounded();
    return {Bounded::rounded(r[0]), Bounded::rounded(r[1]), Bounded::rounded(r[2])};
  }

  static Vector difference(const Vector& a, const Vector& b) noexcept {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  }

  static Vector cross(const Vector& a, const Vector& b) noexcept {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }

  static Bounded dot(const Vector& a, const Vector& b) noexcept {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  /// x(t) x y(t) for x, y affine (x_a at the piece's start, x_b at its end).
  static Quadratic cross_quadratic(const Vector& x_a, const Vector& x_b, const Vector& y_a,
                                   const Vector& y_b) noexcept {
    const Vector mixed_1 = cross(x_a, y_b);
    const Vector mixed_2 = cross(x_b, y_a);
    Vector middle;
    for (int k = 0; k < 3; ++k)
      middle[k] = midpoint(mixed_1[k], mixed_2[k]);
    return {cross(x_a, y_a), middle, cross(x_b, y_b)};
  }

  /// w(t) . n(t) for two vector quadratics, times 6.
  static Quartic dot_quartic(const Quadratic& w, const Quadratic& n) noexcept {
    return {6.0 * dot(w[0], n[0]), 3.0 * (dot(w[0], n[1]) + dot(w[1], n[0])),
            dot(w[0], n[2]) + 4.0 * dot(w[1], n[1]) + dot(w[2], n[0]),
            3.0 * (dot(w[1], n[2]) + dot(w[2], n[1])), 6.0 * dot(w[2], n[2])};
  }

  static bool all_of_sign(const Quartic& q, Sign s) noexcept {
    for (const Bounded& b : q) {
      if (b.certified_sign() != s) return false;
    }
    return true;
  }
};

}  // namespace exactgeo::ccd::internal
