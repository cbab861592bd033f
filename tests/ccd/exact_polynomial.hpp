#pragma once

// Exact polynomials in time for the CCD certificate tests: GMP rational coefficients, the
// moving points of a query as affine polynomials, Sturm sequences to decide whether a
// polynomial has a root in a closed interval, and random paths of midpoint splits.
// Written for clarity, not speed.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "exactgeo/predicates/point.hpp"
#include "support/generators.hpp"

namespace exactgeo::ccd::testing_polynomials {

/// A polynomial in t with rational coefficients, lowest degree first.
using Polynomial = std::vector<mpq_class>;

inline Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  Polynomial r(a.size() + b.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j)
      r[i + j] += a[i] * b[j];
  }
  return r;
}

inline Polynomial operator+(Polynomial a, const Polynomial& b) {
  if (a.size() < b.size()) a.resize(b.size(), mpq_class(0));
  for (std::size_t i = 0; i < b.size(); ++i)
    a[i] += b[i];
  return a;
}

inline Polynomial operator-(const Polynomial& a) {
  Polynomial r = a;
  for (mpq_class& c : r)
    c = -c;
  return r;
}

inline void trim(Polynomial& p) {
  while (!p.empty() && p.back() == 0)
    p.pop_back();
}

inline mpq_class evaluate(const Polynomial& p, const mpq_class& t) {
  mpq_class value = 0;
  for (std::size_t i = p.size(); i-- > 0;)
    value = value * t + p[i];
  return value;
}

/// The remainder of a divided by b (b nonzero, trimmed).
inline Polynomial remainder(Polynomial a, const Polynomial& b) {
  trim(a);
  while (a.size() >= b.size() && !a.empty()) {
    const mpq_class factor = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i)
      a[shift + i] -= factor * b[i];
    trim(a);
  }
  return a;
}

/// Whether the nonzero polynomial p has a root in the closed interval [a, b] (Sturm).
inline bool has_root_in(Polynomial p, const mpq_class& a, const mpq_class& b) {
  trim(p);
  if (evaluate(p, a) == 0 || evaluate(p, b) == 0) return true;
  std::vector<Polynomial> sequence{p};
  Polynomial derivative;
  for (std::size_t i = 1; i < p.size(); ++i)
    derivative.push_back(p[i] * static_cast<long>(i));
  trim(derivative);
  if (!derivative.empty()) sequence.push_back(derivative);
  while (sequence.size() >= 2 && !sequence.back().empty()) {
    Polynomial next = -remainder(sequence[sequence.size() - 2], sequence.back());
    trim(next);
    if (next.empty()) break;
    sequence.push_back(next);
  }
  auto variations = [&](const mpq_class& t) {
    int count = 0;
    int previous = 0;
    for (const Polynomial& q : sequence) {
      const int s = sgn(evaluate(q, t));
      if (s == 0) continue;
      if (previous != 0 && s != previous) ++count;
      previous = s;
    }
    return count;
  };
  return variations(a) - variations(b) > 0;
}

/// A point's coordinate along the step, (1 - t) x0 + t x1, as a polynomial.
inline Polynomial moving(double x0, double x1) {
  return {mpq_class(x0), mpq_class(x1) - mpq_class(x0)};
}

using MovingVector = std::array<Polynomial, 3>;

inline MovingVector difference(const Point3& to_t0, const Point3& to_t1, const Point3& from_t0,
                               const Point3& from_t1) {
  MovingVector r;
  for (int k = 0; k < 3; ++k)
    r[k] = moving(to_t0[k], to_t1[k]) + -moving(from_t0[k], from_t1[k]);
  return r;
}

inline Polynomial det3(const MovingVector& a, const MovingVector& b, const MovingVector& c) {
  return a[0] * (b[1] * c[2] + -(b[2] * c[1])) + a[1] * (b[2] * c[0] + -(b[0] * c[2])) +
         a[2] * (b[0] * c[1] + -(b[1] * c[0]));
}

inline MovingVector cross(const MovingVector& a, const MovingVector& b) {
  return {a[1] * b[2] + -(a[2] * b[1]), a[2] * b[0] + -(a[0] * b[2]), a[0] * b[1] + -(a[1] * b[0])};
}

inline Polynomial dot(const MovingVector& a, const MovingVector& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Whether p is nonzero with the given sign throughout the closed interval [a, b].
inline bool of_sign_throughout(const Polynomial& p, int sign, const mpq_class& a,
                               const mpq_class& b) {
  Polynomial q = p;
  trim(q);
  return !q.empty() && !has_root_in(q, a, b) && sgn(evaluate(q, a)) == sign;
}

/// The Bernstein coefficients of p (degree at most n) on [a, b]: those of q(x) = p(a + (b -
/// a) x) on [0, 1], b_k = sum_{j <= k} C(k, j) / C(n, j) q_j.
inline std::vector<mpq_class> bernstein_on(Polynomial p, int n, const mpq_class& a,
                                           const mpq_class& b) {
  p.resize(static_cast<std::size_t>(n) + 1, mpq_class(0));
  // q(x) = p(a + h x): Taylor shift by a (repeated synthetic division), then scale by h^j.
  Polynomial q = p;
  for (int i = 0; i < n; ++i) {
    for (int j = n - 1; j >= i; --j)
      q[static_cast<std::size_t>(j)] += a * q[static_cast<std::size_t>(j) + 1];
  }
  mpq_class power = 1;
  for (int j = 0; j <= n; ++j) {
    q[static_cast<std::size_t>(j)] *= power;
    power *= b - a;
  }
  auto choose = [](int m, int k) {
    mpq_class c = 1;
    for (int i = 0; i < k; ++i)
      c = c * (m - i) / (i + 1);
    return c;
  };
  std::vector<mpq_class> coefficients(static_cast<std::size_t>(n) + 1, mpq_class(0));
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= k; ++j)
      coefficients[static_cast<std::size_t>(k)] +=
          choose(k, j) / choose(n, j) * q[static_cast<std::size_t>(j)];
  }
  return coefficients;
}

/// Walks one random path of midpoint splits, from the whole step [0, 1] down to a depth
/// drawn from [0, max_depth]: calls visit(coefficients, start, end) on every piece of it
/// (the step included), split(coefficients) giving the halves' coefficients. Stops at a
/// fatal test failure.
template <class Coefficients, class Split, class Visit>
void walk_random_split_path(testing::Rng& rng, int max_depth, Coefficients c, Split split,
                            Visit visit) {
  mpq_class start = 0;
  mpq_class end = 1;
  const int depth = testing::uniform_int(rng, 0, max_depth);
  for (int d = 0;; ++d) {
    visit(c, start, end);
    if (::testing::Test::HasFatalFailure() || d == depth) return;
    const auto [left, right] = split(c);
    const mpq_class middle = (start + end) / 2;
    if (testing::uniform_int(rng, 0, 1) == 0) {
      c = left;
      end = middle;
    } else {
      c = right;
      start = middle;
    }
  }
}

/// The largest |computed - scale * exact| / threshold over the Bernstein coefficients of
/// every piece along one random split path: the error bound a certificate rests on,
/// measured. `exact` are the polynomials (degree at most `degree`); computed(c, i) gives
/// the certificate's coefficients of polynomial i on the piece whose coefficients are c.
template <class Coefficients, class Split, class Computed>
double worst_coefficient_error(testing::Rng& rng, int max_depth, const Coefficients& whole_step,
                               Split split, const std::vector<Polynomial>& exact, int degree,
                               int scale, double threshold, Computed computed) {
  double worst = 0.0;
  walk_random_split_path(rng, max_depth, whole_step, split,
                         [&](const Coefficients& c, const mpq_class& start, const mpq_class& end) {
                           for (std::size_t i = 0; i < exact.size(); ++i) {
                             const std::vector<mpq_class> b =
                                 bernstein_on(exact[i], degree, start, end);
                             const auto& ci = computed(c, i);
                             for (std::size_t k = 0; k < b.size(); ++k) {
                               const mpq_class error = abs(mpq_class(ci[k]) - scale * b[k]);
                               worst = std::max(worst, mpq_class(error / threshold).get_d());
                             }
                           }
                         });
  return worst;
}

}  // namespace exactgeo::ccd::testing_polynomials
