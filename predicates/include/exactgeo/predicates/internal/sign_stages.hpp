#pragma once

// The three stages that decide the sign of a formula on Offset inputs:
//
//   filtered_sign   semi-static filter: evaluate in double, compare with a bound derived at
//                   compile time (roundoff.hpp); answers or says "don't know" (nullopt).
//   expansion_sign  exact, with stack-allocated floating-point expansions, after an exact
//                   power-of-two rescaling if the inputs' exponents demand one
//                   (exponent_range.hpp); "don't know" only when no rescaling makes
//                   expansion arithmetic safe or a narrowing does not fit.
//   rational_sign   exact with GMP rationals; always answers.
//
// A formula descriptor names the polynomial (formulas.hpp), its number of input vectors,
// its total degree, which coordinates it reads (cross2 ignores one), and optionally a
// custom expansion evaluation.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

#include "exactgeo/predicates/internal/expansion.hpp"
#include "exactgeo/predicates/internal/exponent_range.hpp"
#include "exactgeo/predicates/internal/formulas.hpp"
#include "exactgeo/predicates/internal/offset.hpp"
#include "exactgeo/predicates/internal/rational.hpp"
#include "exactgeo/predicates/internal/roundoff.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::internal {

/// How the filter normalises its inputs. The bound is epsilon * prod_g m_g^deg_g with m_g
/// the largest |input| of group g; any grouping in which the formula is homogeneous is
/// sound. By axis suits formulas on points (orient3d: one max per coordinate, as in FPG);
/// by vector suits formulas with a direction whose scale is unrelated to the points'.
enum class Grouping { by_axis, by_vector };

template <class Formula, Grouping grouping>
constexpr int kGroupCount = grouping == Grouping::by_axis ? 3 : Formula::kVectors;

template <class T, std::size_t N>
using VectorArray = std::array<Vec3<T>, N>;

// --- formula descriptors ----------------------------------------------------------------

/// Default: every coordinate of every input vector is read.
struct ReadsAllCoordinates {
  static constexpr bool reads(int /*axis*/, int /*parameter*/) { return true; }
};

struct Det3Formula : ReadsAllCoordinates {
  static constexpr int kVectors = 3;
  static constexpr int kDegree = 3;
  template <class T>
  static constexpr auto evaluate(const VectorArray<T, 3>& v, int /*unused*/) {
    return det3(v[0], v[1], v[2]);
  }
};

/// cross2(axis, a, b): the parameter is the dropped axis.
struct Cross2Formula {
  static constexpr int kVectors = 2;
  static constexpr int kDegree = 2;
  static constexpr bool reads(int axis, int dropped_axis) { return axis != dropped_axis; }
  template <class T>
  static constexpr auto evaluate(const VectorArray<T, 2>& v, int axis) {
    return cross2(axis, v[0], v[1]);
  }
};

struct Dot3Formula : ReadsAllCoordinates {
  static constexpr int kVectors = 2;
  static constexpr int kDegree = 2;
  template <class T>
  static constexpr auto evaluate(const VectorArray<T, 2>& v, int /*unused*/) {
    return dot3(v[0], v[1]);
  }
};

struct PhiFormula : ReadsAllCoordinates {
  static constexpr int kVectors = 4;
  static constexpr int kDegree = 6;
  template <class T>
  static constexpr auto evaluate(const VectorArray<T, 4>& v, int /*unused*/) {
    return bilinear_phi(v[0], v[1], v[2], v[3]);
  }

  /// The four determinants are exact expansions of up to 192 components; compressed they
  /// are a handful of components for any input the exponent check lets through, so they
  /// are narrowed to 16 before the products (which would otherwise need 2*192*192).
  template <int C>
  static std::optional<Sign> expansion_sign(const VectorArray<Expansion<C>, 4>& v, int) noexcept {
    constexpr int kNarrow = 16;
    auto narrowed = [](auto&& e) { return e.compress().template narrow<kNarrow>(); };
    const auto g012 = narrowed(det3(v[0], v[1], v[2]));
    const auto g132 = narrowed(det3(v[1], v[3], v[2]));
    const auto g013 = narrowed(det3(v[0], v[1], v[3]));
    const auto g032 = narrowed(det3(v[0], v[3], v[2]));
    if (!g012 || !g132 || !g013 || !g032) return std::nullopt;
    return ((*g012) * (*g132) - (*g013) * (*g032)).sign();
  }
};

// --- stage 1: semi-static filter ------------------------------------------------------

template <class Formula, Grouping grouping>
inline constexpr auto kFilterConstant = [] {
  constexpr int groups = kGroupCount<Formula, grouping>;
  using R = Roundoff<groups>;
  VectorArray<R, Formula::kVectors> inputs{};
  for (int v = 0; v < Formula::kVectors; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      inputs[v][axis] =
          R::input(grouping == Grouping::by_axis ? axis : v, R::InputError::one_rounding);
    }
  }
  return derive_filter(Formula::evaluate(inputs, 0));
}();

/// x^k for a compile-time k.
template <int k>
constexpr double power(double x) noexcept {
  if constexpr (k == 0) {
    return 1.0;
  } else {
    return x * power<k - 1>(x);
  }
}

/// The filter's test: every group maximum within the guard, and |value| above the
/// certified error bound. Written with folds over the groups and non-short-circuit `&` so
/// that the hot path has no loop and a single, predictable branch.
template <const auto& constant, std::size_t G>
inline bool filter_certifies(double value, const std::array<double, G>& maxima) noexcept {
  return [&]<std::size_t... g>(std::index_sequence<g...>) {
    const int in_guard = ((static_cast<int>(maxima[g] >= constant.guard_low) &
                           static_cast<int>(maxima[g] <= constant.guard_high)) &
                          ...);
    const double bound = (constant.epsilon * ... * power<constant.degree[g]>(maxima[g]));
    return (in_guard & static_cast<int>(std::fabs(value) > bound)) != 0;
  }
  (std::make_index_sequence<G>{});
}

/// A group whose inputs are all exactly zero makes every term vanish (every group appears
/// in every term: derive_filter checks it).
template <std::size_t G>
inline bool some_group_is_zero(const std::array<double, G>& maxima) noexcept {
  for (const double m : maxima) {
    if (m == 0.0) return true;
  }
  return false;
}

/// max(a, b) for non-NaN operands, in the form compilers turn into one maxsd.
inline double larger(double a, double b) noexcept {
  return a < b ? b : a;
}

template <std::size_t N>
inline VectorArray<double, N> rounded(const Offsets<N>& in) noexcept {
  VectorArray<double, N> out;
  for (std::size_t v = 0; v < N; ++v)
    out[v] = in[v].rounded();
  return out;
}

/// Per group, the largest |input|. Each maximum starts from an input, not from 0: a
/// comparison with a known constant would compile to a data-dependent branch.
template <Grouping grouping, std::size_t N>
inline auto group_maxima(const VectorArray<double, N>& x) noexcept {
  if constexpr (grouping == Grouping::by_axis) {
    std::array<double, 3> m;
    for (int axis = 0; axis < 3; ++axis) {
      m[axis] = std::fabs(x[0][axis]);
      for (std::size_t v = 1; v < N; ++v)
        m[axis] = larger(m[axis], std::fabs(x[v][axis]));
    }
    return m;
  } else {
    std::array<double, N> m;
    for (std::size_t v = 0; v < N; ++v) {
      m[v] = larger(larger(std::fabs(x[v][0]), std::fabs(x[v][1])), std::fabs(x[v][2]));
    }
    return m;
  }
}

/// The filter's approximation of the formula: rounded inputs, with the coordinates the
/// formula ignores set to zero so that they do not inflate the maxima.
template <class Formula, std::size_t N>
inline VectorArray<double, N> filter_inputs(const Offsets<N>& in, int parameter) noexcept {
  VectorArray<double, N> x = rounded(in);
  for (int axis = 0; axis < 3; ++axis) {
    if (Formula::reads(axis, parameter)) continue;
    for (std::size_t v = 0; v < N; ++v)
      x[v][axis] = 0.0;
  }
  return x;
}

/// Stage 1 on its own: the certified sign, Sign::zero for a vanishing group, or nullopt.
template <class Formula, Grouping grouping, std::size_t N>
inline std::optional<Sign> filtered_sign(const Offsets<N>& in, int parameter) noexcept {
  static_assert(N == Formula::kVectors);
  const VectorArray<double, N> x = filter_inputs<Formula>(in, parameter);
  const double value = Formula::evaluate(x, parameter);
  const auto maxima = group_maxima<grouping>(x);
  if (filter_certifies<kFilterConstant<Formula, grouping>>(value, maxima)) return sign_of(value);
  if (some_group_is_zero(maxima)) return Sign::zero;
  return std::nullopt;
}

// --- stage 2: expansions ----------------------------------------------------------------

// The exact stages are kept out of line and marked cold: inlined, their kilobytes of
// stack-allocated expansions would make every call pay for a frame (and stack probes) that
// the filter almost never needs.
template <class Formula, std::size_t N>
[[gnu::noinline, gnu::cold]] std::optional<Sign> expansion_sign(const Offsets<N> in,
                                                                int parameter) noexcept {
  ExponentRange range;
  for (const Offset& o : in) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!Formula::reads(axis, parameter)) continue;
      range.include(o.head(axis));
      range.include(o.tail(axis));
    }
  }
  const std::optional<int> scaling = range.exact_scaling(Formula::kDegree);
  if (!scaling) return std::nullopt;
  // Exact differences; when none of them needed a second component (dyadic grids, inputs
  // already relative to one another) the whole evaluation runs on one-component inputs,
  // with every product four times smaller.
  VectorArray<Expansion<2>, N> e;
  bool all_single = true;
  for (std::size_t v = 0; v < N; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!Formula::reads(axis, parameter)) continue;  // left zero
      const double head = in[v].head(axis);
      const double tail = in[v].tail(axis);
      e[v][axis] = *scaling == 0 ? Expansion<2>::difference(head, tail)
                                 : Expansion<2>::difference(std::ldexp(head, *scaling),
                                                            std::ldexp(tail, *scaling));
      all_single &= e[v][axis].size() <= 1;
    }
  }
  auto evaluate = [parameter](const auto& inputs) -> std::optional<Sign> {
    if constexpr (requires { Formula::expansion_sign(inputs, parameter); }) {
      return Formula::expansion_sign(inputs, parameter);
    } else {
      return Formula::evaluate(inputs, parameter).sign();
    }
  };
  if (all_single) {
    VectorArray<Expansion<1>, N> single;
    for (std::size_t v = 0; v < N; ++v) {
      for (int axis = 0; axis < 3; ++axis)
        single[v][axis] = *e[v][axis].template narrow<1>();
    }
    return evaluate(single);
  }
  return evaluate(e);
}

// --- stage 3: rationals -----------------------------------------------------------------

template <std::size_t N>
VectorArray<Rational, N> rational_vectors(const Offsets<N>& in) {
  VectorArray<Rational, N> q;
  for (std::size_t v = 0; v < N; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      q[v][axis] = Rational(in[v].head(axis)) - Rational(in[v].tail(axis));
    }
  }
  return q;
}

template <class Formula, std::size_t N>
[[gnu::noinline, gnu::cold]] Sign rational_sign(const Offsets<N> in, int parameter) noexcept {
  return Formula::evaluate(rational_vectors(in), parameter).sign();
}

}  // namespace exactgeo::internal
