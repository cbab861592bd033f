#pragma once

// Whether the convex hulls of two small point sets meet, decided in GMP rationals as a
// linear program: a common point is x = sum l_i e_i = sum m_j r_j with l, m >= 0 and
// sum l = sum m = 1. The oracle for the swept regions (swept_region_test.cpp,
// pass_schedule_test.cpp); it shares no code with the library, which decides by signs of
// orientations (swept_region.cpp), nor with the support oracles' clipping.
//
// The program is solved by brute force over its basic solutions: a feasible program whose
// feasible set is bounded (here: weights of two simplices) has a basic feasible solution,
// one whose nonzero weights belong to linearly independent columns, and a linear
// objective takes its maximum there. So every subset of columns is tried: Gauss-Jordan
// elimination in rationals, kept when the columns are independent, the system consistent
// and the solution non-negative. Slow on purpose (up to 2^8 small eliminations).

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <span>
#include <vector>

#include "exactgeo/predicates/point.hpp"

namespace exactgeo::testing {

/// Whether the closed hulls of `e` and `r` have a common point at which some point of `e`
/// not flagged in `shared` (bit i for e[i]) has positive weight. With `shared` 0: whether
/// the hulls meet. For points e affinely independent (a point, a segment, a triangle) and
/// `shared` flagging those of its corners that are also corners of r: whether they meet
/// outside the hull of the shared corners (a point of hull(e) has one set of weights,
/// and it lies in the shared corners' hull exactly when the others' weights are 0).
inline bool hulls_meet_beyond(std::span<const Point3> e, unsigned shared,
                              std::span<const Point3> r) {
  // A box test first (exact on doubles): hulls in boxes apart are apart.
  for (int k = 0; k < 3; ++k) {
    const auto [e_lo, e_hi] = std::minmax_element(
        e.begin(), e.end(), [k](const Point3& p, const Point3& q) { return p[k] < q[k]; });
    const auto [r_lo, r_hi] = std::minmax_element(
        r.begin(), r.end(), [k](const Point3& p, const Point3& q) { return p[k] < q[k]; });
    if ((*e_hi)[k] < (*r_lo)[k] || (*r_hi)[k] < (*e_lo)[k]) return false;
  }
  // Columns: (p, 1, 0) for e's points, (-p, 0, 1) for r's; right-hand side (0, 0, 0, 1, 1).
  constexpr std::size_t kRows = 5;
  const std::size_t n = e.size() + r.size();
  std::vector<std::array<mpq_class, kRows>> columns(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool of_e = i < e.size();
    const Point3& p = of_e ? e[i] : r[i - e.size()];
    for (int k = 0; k < 3; ++k)
      columns[i][k] = of_e ? mpq_class(p[k]) : mpq_class(-p[k]);
    columns[i][3] = of_e ? 1 : 0;
    columns[i][4] = of_e ? 0 : 1;
  }
  std::vector<std::size_t> chosen;
  std::vector<std::vector<mpq_class>> m(kRows);
  for (unsigned subset = 1; subset < (1u << n); ++subset) {
    const auto k = static_cast<std::size_t>(std::popcount(subset));
    if (k > kRows) continue;  // more columns than rows: dependent
    chosen.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (subset & (1u << i)) chosen.push_back(i);
    }
    for (std::size_t row = 0; row < kRows; ++row) {
      m[row].assign(k + 1, 0);
      for (std::size_t c = 0; c < k; ++c)
        m[row][c] = columns[chosen[c]][row];
      m[row][k] = row < 3 ? 0 : 1;
    }
    // Gauss-Jordan: a pivot in every chosen column, or the columns are dependent.
    bool independent = true;
    for (std::size_t c = 0; c < k && independent; ++c) {
      std::size_t pivot = c;
      while (pivot < kRows && m[pivot][c] == 0)
        ++pivot;
      if (pivot == kRows) {
        independent = false;
        break;
      }
      std::swap(m[pivot], m[c]);
      const mpq_class lead = m[c][c];
      for (mpq_class& x : m[c])
        x /= lead;
      for (std::size_t row = 0; row < kRows; ++row) {
        if (row == c || m[row][c] == 0) continue;
        const mpq_class factor = m[row][c];
        for (std::size_t col = c; col <= k; ++col)
          m[row][col] -= factor * m[c][col];
      }
    }
    if (!independent) continue;
    bool consistent = true;
    for (std::size_t row = k; row < kRows; ++row)
      consistent = consistent && m[row][k] == 0;
    if (!consistent) continue;
    bool non_negative = true;
    mpq_class objective = 0;
    for (std::size_t c = 0; c < k; ++c) {
      non_negative = non_negative && m[c][k] >= 0;
      const std::size_t i = chosen[c];
      if (i < e.size() && !(shared & (1u << i))) objective += m[c][k];
    }
    if (non_negative && objective > 0) return true;
  }
  return false;
}

/// Whether the closed hulls of the two point sets meet.
inline bool hulls_meet(std::span<const Point3> a, std::span<const Point3> b) {
  return hulls_meet_beyond(a, 0, b);
}

}  // namespace exactgeo::testing
