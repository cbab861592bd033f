#pragma once

// Stage 1 of every sign: the semi-static filter. Evaluate the formula in double on the
// rounded inputs and compare with epsilon * prod_g m_g^deg_g, where epsilon is derived at
// compile time from the formula itself (roundoff.hpp) and m_g are the largest inputs of
// each group, measured at run time. Answers, or leaves the sign undecided (std::nullopt).

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

#include "exactgeo/predicates/kernel/formula_descriptors.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"
#include "exactgeo/predicates/kernel/roundoff.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::kernel {

/// How the filter normalises its inputs. The bound is epsilon * prod_g m_g^deg_g with m_g
/// the largest |input| of group g; any grouping in which the formula is homogeneous is
/// sound. By axis suits formulas on points (orient3d: one max per coordinate, as in FPG);
/// by vector suits formulas with a direction whose scale is unrelated to the points';
/// by projected axis is "by axis" for 2D formulas that drop the axis given as their
/// parameter (two groups: the axes parameter + 1 and parameter + 2, mod 3).
enum class Grouping { by_axis, by_vector, by_projected_axis };

template <class Formula, Grouping grouping>
constexpr int kGroupCount = grouping == Grouping::by_axis             ? 3
                            : grouping == Grouping::by_projected_axis ? 2
                                                                      : Formula::kVectors;

/// The group of coordinate `axis` of input vector `vector` (for by_projected_axis, with
/// the dropped axis given; it belongs to no group and is reported as group 0, unread).
template <Grouping grouping>
constexpr int group_of(int vector, int axis, int dropped_axis) {
  switch (grouping) {
    case Grouping::by_axis:
      return axis;
    case Grouping::by_vector:
      return vector;
    case Grouping::by_projected_axis:
      return axis == dropped_axis ? 0 : (axis - dropped_axis + 2) % 3;
  }
  return 0;
}

template <class Formula, Grouping grouping>
inline constexpr auto kFilterConstant = [] {
  constexpr int groups = kGroupCount<Formula, grouping>;
  using R = Roundoff<groups>;
  VectorArray<R, Formula::kVectors> inputs{};
  for (int v = 0; v < Formula::kVectors; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      // The analysis does not depend on the parameter: evaluate with parameter 0.
      inputs[v][axis] = R::input(group_of<grouping>(v, axis, 0), R::InputError::one_rounding);
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
inline auto group_maxima(const VectorArray<double, N>& x, int parameter) noexcept {
  if constexpr (grouping == Grouping::by_projected_axis) {
    const int i = (parameter + 1) % 3;
    const int j = (parameter + 2) % 3;
    std::array<double, 2> m{std::fabs(x[0][i]), std::fabs(x[0][j])};
    for (std::size_t v = 1; v < N; ++v) {
      m[0] = larger(m[0], std::fabs(x[v][i]));
      m[1] = larger(m[1], std::fabs(x[v][j]));
    }
    return m;
  } else if constexpr (grouping == Grouping::by_axis) {
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

namespace internal {

/// The filter's evaluation: the formula's double value and whether the bound certifies its
/// sign. This is not a second way to say "undecided" (the stage's answer is filtered_sign's
/// std::optional): it is the hot path of every exact sign, kept a plain struct because GCC 12
/// compiles the policies' single branch on it far better than on the optional
/// (docs/predicates.md, "Measurements").
struct FilterEvaluation {
  double value;
  bool certified;
};

template <class Formula, Grouping grouping, std::size_t N>
inline FilterEvaluation evaluate_filter(const Offsets<N>& in, int parameter) noexcept {
  static_assert(N == Formula::kVectors);
  const VectorArray<double, N> x = filter_inputs<Formula>(in, parameter);
  const double value = Formula::evaluate(x, parameter);
  return {value, filter_certifies<kFilterConstant<Formula, grouping>>(
                     value, group_maxima<grouping>(x, parameter))};
}

}  // namespace internal

/// Some group of inputs is exactly zero, so every term and the formula vanish. Asked only
/// after the bound failed to certify (a zero maximum always fails the guard).
template <class Formula, Grouping grouping, std::size_t N>
inline bool vanishing_group(const Offsets<N>& in, int parameter) noexcept {
  return some_group_is_zero(
      group_maxima<grouping>(filter_inputs<Formula>(in, parameter), parameter));
}

/// Stage 1 of every exact sign: the formula in double on the rounded inputs, its sign
/// certified by the bound; Sign::zero where a group of inputs vanishes; else undecided.
template <class Formula, Grouping grouping, std::size_t N>
inline std::optional<Sign> filtered_sign(const Offsets<N>& in, int parameter) noexcept {
  if (const auto f = internal::evaluate_filter<Formula, grouping>(in, parameter); f.certified) {
    return sign_of(f.value);
  }
  if (vanishing_group<Formula, grouping>(in, parameter)) return Sign::zero;
  return std::nullopt;
}

}  // namespace exactgeo::kernel
