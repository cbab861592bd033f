#include "exactgeo/predicates/boundary_term.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "boundary_term_filter.hpp"
#include "double_interval.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "mpfr_interval.hpp"

// The derivation, the branch cut and why corners bound the angle: boundary_term.hpp.

namespace exactgeo {
namespace {

using internal::DoubleInterval;
using internal::kAtan2Error;
using internal::MpfrInterval;
using kernel::Offset;

// ---- What each interval type does its own way ------------------------------------------

/// How one stage builds and reads its numbers.
struct DoubleStage {
  using Number = DoubleInterval;
  Number exact(double x) const noexcept { return Number::exact(x); }
  Number difference(double a, double b) const noexcept { return Number::difference(a, b); }
  Number two_pi() const noexcept {
    // M_PI is pi rounded down (pi = 0x1.921fb54442d18469...p+1); doubling is exact.
    constexpr double pi_below = 0x1.921fb54442d18p+1;
    return {2 * pi_below, 2 * DoubleInterval::up(pi_below)};
  }
  /// Each vector scaled by a power of two so that its largest bound is in [1, 2): solid
  /// angles depend only on the vectors' directions, and the products below then neither
  /// overflow nor lose their relative accuracy to underflow. A scaling that rounds (a
  /// component pushed below 2^-1022) widens its bounds.
  void normalize(std::array<Number, 3>& v) const noexcept {
    double largest = 0.0;
    for (const Number& x : v)
      largest = std::max({largest, std::abs(x.lo), std::abs(x.hi)});
    if (largest == 0.0 || !std::isfinite(largest)) return;
    const int shift = -std::ilogb(largest);
    for (Number& x : v) {
      for (double* bound : {&x.lo, &x.hi}) {
        const double scaled = std::ldexp(*bound, shift);
        if (std::ldexp(scaled, -shift) == *bound) {
          *bound = scaled;
        } else {
          *bound = bound == &x.lo ? DoubleInterval::down(scaled) : DoubleInterval::up(scaled);
        }
      }
    }
  }
  bool usable(const Number& x) const noexcept { return x.finite(); }
  int lower_sign(const Number& x) const noexcept { return (x.lo > 0) - (x.lo < 0); }
  int upper_sign(const Number& x) const noexcept { return (x.hi > 0) - (x.hi < 0); }
  /// The lower (upper) bound replaced by a zero of sign `zero_sign`.
  Number with_lower_zero(Number x, int zero_sign) const noexcept {
    x.lo = std::copysign(0.0, zero_sign);
    return x;
  }
  Number with_upper_zero(Number x, int zero_sign) const noexcept {
    x.hi = std::copysign(0.0, zero_sign);
    return x;
  }
  /// The angles of the box y x x, from its corners.
  Number corner_angles(const Number& y, const Number& x) const noexcept {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double yy : {y.lo, y.hi}) {
      for (const double xx : {x.lo, x.hi}) {
        const double angle = std::atan2(yy, xx);
        lo = std::min(lo, angle);
        hi = std::max(hi, angle);
      }
    }
    return {DoubleInterval::down(lo - kAtan2Error), DoubleInterval::up(hi + kAtan2Error)};
  }
  Enclosure enclosure(const Number& x) const noexcept { return {x.lo, x.hi}; }
  Versus versus(const Number& x, double level) const noexcept {
    return x.hi < level ? Versus::below : x.lo > level ? Versus::above : Versus::unsure;
  }
};

struct MpfrStage {
  using Number = MpfrInterval;
  mpfr_prec_t precision;

  Number exact(double x) const { return Number::exact(x, precision); }
  Number difference(double a, double b) const { return Number::difference(a, b, precision); }
  Number two_pi() const { return Number::two_pi(precision); }
  void normalize(std::array<Number, 3>&) const noexcept {}  // no overflow to fear
  bool usable(const Number&) const noexcept { return true; }
  int lower_sign(const Number& x) const noexcept { return mpfr_sgn(x.lo()); }
  int upper_sign(const Number& x) const noexcept { return mpfr_sgn(x.hi()); }
  Number with_lower_zero(Number x, int zero_sign) const {
    mpfr_set_zero(x.lo(), zero_sign);
    return x;
  }
  Number with_upper_zero(Number x, int zero_sign) const {
    mpfr_set_zero(x.hi(), zero_sign);
    return x;
  }
  /// The same with two atan2 evaluations (the costly operation here) instead of eight:
  /// the corners of least and greatest angle are found first by exact comparisons (the
  /// box lies within a half plane, where angle(c) < angle(m) exactly when the cross
  /// product c x m is positive; products of two numbers are exact at twice the precision).
  Number corner_angles(const Number& y, const Number& x) const {
    struct Corner {
      const __mpfr_struct* y;
      const __mpfr_struct* x;
    };
    const Corner corners[4] = {
        {y.lo(), x.lo()}, {y.lo(), x.hi()}, {y.hi(), x.lo()}, {y.hi(), x.hi()}};
    mpfr_t left, right;
    mpfr_init2(left, 2 * precision);
    mpfr_init2(right, 2 * precision);
    // angle(c) < angle(m): c.x m.y - c.y m.x > 0.
    const auto before = [&](const Corner& c, const Corner& m) {
      mpfr_mul(left, c.x, m.y, MPFR_RNDN);   // exact
      mpfr_mul(right, c.y, m.x, MPFR_RNDN);  // exact
      return mpfr_greater_p(left, right) != 0;
    };
    Corner least = corners[0], greatest = corners[0];
    for (const Corner& c : corners) {
      if (before(c, least)) least = c;
      if (before(greatest, c)) greatest = c;
    }
    mpfr_clear(left);
    mpfr_clear(right);
    Number angles(precision);
    mpfr_atan2(angles.lo(), least.y, least.x, MPFR_RNDD);
    mpfr_atan2(angles.hi(), greatest.y, greatest.x, MPFR_RNDU);
    return angles;
  }
  Enclosure enclosure(const Number& x) const {
    return {mpfr_get_d(x.lo(), MPFR_RNDD), mpfr_get_d(x.hi(), MPFR_RNDU)};
  }
  Versus versus(const Number& x, double level) const {
    return mpfr_cmp_d(x.hi(), level) < 0   ? Versus::below
           : mpfr_cmp_d(x.lo(), level) > 0 ? Versus::above
                                           : Versus::unsure;
  }
};

// ---- The algorithm, once for every stage ------------------------------------------------

template <class N>
N dot(const std::array<N, 3>& a, const std::array<N, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class N>
N det3(const std::array<N, 3>& a, const std::array<N, 3>& b, const std::array<N, 3>& c) {
  const std::array<N, 3> b_cross_c{b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2],
                                   b[0] * c[1] - b[1] * c[0]};
  return dot(a, b_cross_c);
}

/// Is the point on the closed segment [a, b]? Exact: A = a - p and B = b - p parallel
/// (A x B = 0) and not pointing the same way (A.B <= 0).
bool on_segment(const Point3& p, const Point3& a, const Point3& b) noexcept {
  const kernel::ExactSigns signs;
  const Offset pa = Offset::between(p, a), pb = Offset::between(p, b);
  for (int axis = 0; axis < 3; ++axis) {
    if (signs.cross2(axis, pa, pb) != Sign::zero) return false;
  }
  return signs.dot3(pa, pb) != Sign::positive;
}

/// Does x lie on the open ray from p away from `apex` (the direction -apex)? Exact: X = x - p
/// parallel to the apex direction (X x apex = 0) and pointing against it (X.apex < 0).
bool on_ray(const Point3& p, const Vector3& apex, const Point3& x) noexcept {
  const kernel::ExactSigns signs;
  const Offset px = Offset::between(p, x), direction = Offset::vector(apex);
  for (int axis = 0; axis < 3; ++axis) {
    if (signs.cross2(axis, px, direction) != Sign::zero) return false;
  }
  return signs.dot3(px, direction) == Sign::negative;
}

/// The half angle atan2(num, den) over the box num x den, or why there is none.
template <class Stage>
std::optional<typename Stage::Number> half_angle(const Stage& stage,
                                                 const typename Stage::Number& num,
                                                 const typename Stage::Number& den, const Point3& p,
                                                 const Point3& a, const Point3& b,
                                                 const Vector3& apex, BoundaryTermKind& why) {
  const bool num_positive = stage.lower_sign(num) > 0, num_negative = stage.upper_sign(num) < 0;
  // In an open half plane (upper, lower, right) the angles run continuously.
  if (num_positive || num_negative || stage.lower_sign(den) > 0) {
    return stage.corner_angles(num, den);
  }
  if (stage.upper_sign(den) < 0) {
    // The box straddles the branch cut: the exact sign of num = det[a - p, b - p, apex]
    // says on which side of it the point is.
    const Sign side = kernel::ExactSigns{}.det3_by_vector(
        Offset::between(p, a), Offset::between(p, b), Offset::vector(apex));
    if (side == Sign::zero) {
      why = BoundaryTermKind::ray_on_edge;
      return std::nullopt;
    }
    return side == Sign::positive ? stage.corner_angles(stage.with_lower_zero(num, +1), den)
                                  : stage.corner_angles(stage.with_upper_zero(num, -1), den);
  }
  // The box holds the origin. Exactly 0/0 is a degenerate ray or point, never a lack of
  // precision: with unit vectors a', b', c' (c' = apex's), num = 0 makes them coplanar and
  // den = 0 makes |a' + b' + c'| = 1 (den / (|A||B||C|) = (|a' + b' + c'|^2 - 1) / 2); of the
  // unit vectors c' = s - a' - b' (s a unit vector), the only ones are -a' and -b' (the
  // unit circles about 0 and a' + b' meet at a' and b'). So two of them are opposite: the
  // point lies inside the edge (a' = -b', or on an end), or an end lies on the ray (a' or
  // b' = -c'), which then meets the edge: cast the next one, as when it crosses the edge.
  // Any other origin in the box is rounding, which a finer stage removes.
  if (on_segment(p, a, b)) {
    why = BoundaryTermKind::point_on_edge;
  } else if (on_ray(p, apex, a) || on_ray(p, apex, b)) {
    why = BoundaryTermKind::ray_on_edge;
  } else {
    why = BoundaryTermKind::undecided;
  }
  return std::nullopt;
}

template <class Stage>
BoundaryTerm term_at(const Stage& stage, const Point3& p, const Vector3& apex,
                     std::span<const Point3> vertices, std::span<const BoundaryEdge> edges,
                     std::array<double, 2> levels) {
  using Number = typename Stage::Number;
  const auto vector = [&](const Point3& head) {
    std::array<Number, 3> v{stage.difference(head[0], p[0]), stage.difference(head[1], p[1]),
                            stage.difference(head[2], p[2])};
    stage.normalize(v);
    return v;
  };
  std::array<Number, 3> d{stage.exact(apex[0]), stage.exact(apex[1]), stage.exact(apex[2])};
  stage.normalize(d);
  const Number length_d = sqrt(dot(d, d));
  Number total = stage.exact(0.0);
  for (const BoundaryEdge& edge : edges) {
    const Point3& a = vertices[edge.from];
    const Point3& b = vertices[edge.to];
    const std::array<Number, 3> va = vector(a), vb = vector(b);
    const Number num = det3(va, vb, d);
    const Number length_a = sqrt(dot(va, va)), length_b = sqrt(dot(vb, vb));
    const Number den = length_a * length_b * length_d + dot(va, vb) * length_d +
                       dot(va, d) * length_b + dot(vb, d) * length_a;
    if (!stage.usable(num) || !stage.usable(den)) return {BoundaryTermKind::undecided, {}};
    BoundaryTermKind why = BoundaryTermKind::undecided;
    const std::optional<Number> theta = half_angle(stage, num, den, p, a, b, apex, why);
    if (!theta) return {why, {}};
    total = total + *theta * stage.exact(edge.multiplicity);
  }
  // Omega / 4 pi = 2 theta / 4 pi = theta / 2 pi.
  const Number turns = total / stage.two_pi();
  if (!stage.usable(turns)) return {BoundaryTermKind::undecided, {}};
  return {BoundaryTermKind::enclosed,
          stage.enclosure(turns),
          {stage.versus(turns, levels[0]), stage.versus(turns, levels[1])}};
}

/// MPFR keeps caches per thread (pi, and the table of mpfr_atan), which only
/// mpfr_free_cache frees: a thread that ran the MPFR stage frees its own when it ends (the
/// batch functions' worker threads end with each call), or they leak, a few hundred bytes
/// a thread (LeakSanitizer reported them from classify_batch). Where MPFR was built without
/// thread-local caches, they are shared and left alone.
struct MpfrThreadCaches {
  MpfrThreadCaches() = default;
  MpfrThreadCaches(const MpfrThreadCaches&) = delete;
  MpfrThreadCaches& operator=(const MpfrThreadCaches&) = delete;
  ~MpfrThreadCaches() {
    if (mpfr_buildopt_tls_p() != 0) mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
  }
};

}  // namespace

BoundaryTerm boundary_term(const Point3& point, const Vector3& ray,
                           std::span<const Point3> vertices, std::span<const BoundaryEdge> edges,
                           unsigned precision_bits, std::array<double, 2> levels) {
  const Vector3 apex{-ray[0], -ray[1], -ray[2]};  // the cone's vertex at infinity
  if (precision_bits <= 53) {
    if (auto filtered = internal::filtered_boundary_term(point, apex, vertices, edges, levels)) {
      return *filtered;
    }
    return term_at(DoubleStage{}, point, apex, vertices, edges, levels);
  }
  thread_local MpfrThreadCaches caches;  // freed when this thread ends
  static_cast<void>(caches);
  return term_at(MpfrStage{static_cast<mpfr_prec_t>(precision_bits)}, point, apex, vertices, edges,
                 levels);
}

double boundary_term_double(const Point3& point, const Vector3& ray,
                            std::span<const Point3> vertices, std::span<const BoundaryEdge> edges) {
  const auto minus = [](const Point3& x, const Point3& y) {
    return Vector3{x[0] - y[0], x[1] - y[1], x[2] - y[2]};
  };
  const auto dot3 = [](const Vector3& x, const Vector3& y) {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  };
  const Vector3 d{-ray[0], -ray[1], -ray[2]};
  const double ld = std::sqrt(dot3(d, d));
  double total = 0.0;
  for (const BoundaryEdge& edge : edges) {
    const Vector3 a = minus(vertices[edge.from], point), b = minus(vertices[edge.to], point);
    const Vector3 bxd{b[1] * d[2] - b[2] * d[1], b[2] * d[0] - b[0] * d[2],
                      b[0] * d[1] - b[1] * d[0]};
    const double la = std::sqrt(dot3(a, a)), lb = std::sqrt(dot3(b, b));
    const double den = la * lb * ld + dot3(a, b) * ld + dot3(a, d) * lb + dot3(b, d) * la;
    total += edge.multiplicity * std::atan2(dot3(a, bxd), den);
  }
  return total / (2 * std::numbers::pi);
}

}  // namespace exactgeo
