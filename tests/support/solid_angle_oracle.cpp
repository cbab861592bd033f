#include "support/solid_angle_oracle.hpp"

#include <mpfr.h>

#include <array>

namespace exactgeo::testing {
namespace {

constexpr mpfr_prec_t kBits = 512;

/// An mpfr_t that frees itself.
struct Real {
  mpfr_t x;
  Real() { mpfr_init2(x, kBits); }
  explicit Real(double v) : Real() { mpfr_set_d(x, v, MPFR_RNDN); }
  Real(const Real&) = delete;
  Real& operator=(const Real&) = delete;
  ~Real() { mpfr_clear(x); }
};

using Vector = std::array<Real, 3>;

void set_difference(Vector& v, const Point3& head, const Point3& tail) {
  for (int i = 0; i < 3; ++i)
    mpfr_sub_d(v[i].x, Real(head[i]).x, tail[i], MPFR_RNDN);
}

void dot(Real& out, const Vector& a, const Vector& b) {
  Real t;
  mpfr_mul(out.x, a[0].x, b[0].x, MPFR_RNDN);
  for (int i = 1; i < 3; ++i) {
    mpfr_mul(t.x, a[i].x, b[i].x, MPFR_RNDN);
    mpfr_add(out.x, out.x, t.x, MPFR_RNDN);
  }
}

void length(Real& out, const Vector& a) {
  dot(out, a, a);
  mpfr_sqrt(out.x, out.x, MPFR_RNDN);
}

/// Adds the half solid angle of the triangle of directions a, b, c (seen from the origin)
/// to `sum`.
void add_half_angle(Real& sum, const Vector& a, const Vector& b, const Vector& c) {
  // det[a, b, c] = a . (b x c)
  Vector bxc;
  Real u, v;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    mpfr_mul(u.x, b[j].x, c[k].x, MPFR_RNDN);
    mpfr_mul(v.x, b[k].x, c[j].x, MPFR_RNDN);
    mpfr_sub(bxc[i].x, u.x, v.x, MPFR_RNDN);
  }
  Real numerator, la, lb, lc, denominator, term;
  dot(numerator, a, bxc);
  length(la, a);
  length(lb, b);
  length(lc, c);
  mpfr_mul(denominator.x, la.x, lb.x, MPFR_RNDN);
  mpfr_mul(denominator.x, denominator.x, lc.x, MPFR_RNDN);
  const auto add_product = [&](const Vector& x, const Vector& y, const Real& z) {
    dot(term, x, y);
    mpfr_mul(term.x, term.x, z.x, MPFR_RNDN);
    mpfr_add(denominator.x, denominator.x, term.x, MPFR_RNDN);
  };
  add_product(a, b, lc);
  add_product(a, c, lb);
  add_product(b, c, la);
  mpfr_atan2(term.x, numerator.x, denominator.x, MPFR_RNDN);
  mpfr_add(sum.x, sum.x, term.x, MPFR_RNDN);
}

/// Adds the half solid angle of the triangle seen from p to `sum`.
void add_half_angle(Real& sum, const Point3& p, const Triangle& t) {
  Vector a, b, c;
  set_difference(a, t[0], p);
  set_difference(b, t[1], p);
  set_difference(c, t[2], p);
  add_half_angle(sum, a, b, c);
}

/// sum / 2 pi + crossings - level, rounded.
double turns_minus(Real& sum, std::int64_t crossings, double level) {
  Real two_pi;
  mpfr_const_pi(two_pi.x, MPFR_RNDN);
  mpfr_mul_2ui(two_pi.x, two_pi.x, 1, MPFR_RNDN);
  mpfr_div(sum.x, sum.x, two_pi.x, MPFR_RNDN);
  mpfr_add_si(sum.x, sum.x, static_cast<long>(crossings), MPFR_RNDN);
  mpfr_sub_d(sum.x, sum.x, level, MPFR_RNDN);
  return mpfr_get_d(sum.x, MPFR_RNDN);
}

}  // namespace

double generalized_winding_oracle(const Point3& p, std::span<const Triangle> triangles,
                                  double level) {
  Real sum(0.0);
  for (const Triangle& t : triangles)
    add_half_angle(sum, p, t);
  // w = sum of Omega / 4 pi = sum of half angles / 2 pi.
  return turns_minus(sum, 0, level);
}

double decomposed_winding_oracle(const Point3& p, const Vector3& ray, std::int64_t crossings,
                                 std::span<const Segment> boundary, double level) {
  Vector c;
  for (int i = 0; i < 3; ++i)
    mpfr_set_d(c[i].x, -ray[i], MPFR_RNDN);
  Real sum(0.0);
  for (const Segment& s : boundary) {
    Vector a, b;
    set_difference(a, s[0], p);
    set_difference(b, s[1], p);
    add_half_angle(sum, a, b, c);
  }
  return turns_minus(sum, crossings, level);
}

}  // namespace exactgeo::testing
