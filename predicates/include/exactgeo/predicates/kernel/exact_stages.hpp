#pragma once

// Stages 2 and 3 of every sign, both exact:
//
//   expansion_sign  stack-allocated floating-point expansions, after an exact power-of-two
//                   rescaling if the inputs' exponents demand one (exponent_range.hpp);
//                   undecided (nullopt) only when no rescaling makes expansion arithmetic safe or
//                   a narrowing does not fit;
//   rational_sign   exact rationals (dyadic: GMP integers times powers of two, dyadic.hpp);
//                   always answers.

#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>

#include "exactgeo/predicates/kernel/dyadic.hpp"
#include "exactgeo/predicates/kernel/expansion.hpp"
#include "exactgeo/predicates/kernel/exponent_range.hpp"
#include "exactgeo/predicates/kernel/formula_descriptors.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"
#include "exactgeo/predicates/kernel/rational.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::kernel {

/// The most components per coordinate of an exact-vector input the expansion stage takes.
inline constexpr int kLongExactVector = 4;

/// Whether Formula's exact value on K-component inputs fits in 16 KB of stack: true for
/// det3, cross2, dot3 and the triangle normal on four-component inputs (det3: six triple
/// products of at most 2 * (2 * 4 * 4) * 4 = 256 components, 1,536 in all); not for the
/// tetrahedron volume, whose differences double the inputs first, nor for phi (both
/// narrow their intermediate values instead, formula_descriptors.hpp).
template <class Formula, std::size_t N, int K>
inline constexpr bool kFitsOnStack =
    sizeof(decltype(Formula::evaluate(std::declval<VectorArray<Expansion<K>, N>>(), 0))) <=
    16 * 1024;

// The exact stages are kept out of line, so that their kilobytes of stack-allocated
// expansions are not part of the frame of every (filtered) sign. The expansion stage is
// not marked cold: on exactly degenerate inputs (the public handcrafted CCD set) it runs
// for most signs, and compiled for size, as cold code is, it costs instructions there
// (docs/predicates.md, "Measurements"). Rationals stay cold.
template <class Formula, std::size_t N>
[[gnu::noinline]] std::optional<Sign> expansion_sign(const Offsets<N> in, int parameter) noexcept {
  // Exact-vector inputs (exact_vector.hpp) are sums of up to eight components. Where every
  // coordinate read has at most two, it is an input like head - tail (two components, the
  // same exponent conditions, which bound each component) and is evaluated here; up to
  // four, as four-component inputs where the formula's value then fits (kFitsOnStack) or
  // the formula narrows its intermediate values itself (its own expansion_sign); longer
  // ones are left to rationals.
  bool exact_vectors = false;
  int longest = 0;  // components of the longest exact-vector coordinate read
  ExponentRange range;
  for (const Offset& o : in) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!Formula::reads(axis, parameter)) continue;
      if (o.is_exact_vector()) {
        const auto& c = o.exact_vector().exact[axis];
        if (c.size() > kLongExactVector) return std::nullopt;
        longest = std::max(longest, c.size());
        for (int i = 0; i < c.size(); ++i)
          range.include(c.data()[i]);
        exact_vectors = true;
      } else {
        range.include(o.head(axis));
        range.include(o.tail(axis));
      }
    }
  }
  constexpr bool kTakesLong = kFitsOnStack<Formula, N, kLongExactVector> ||
                              requires(const VectorArray<Expansion<kLongExactVector>, N>& v) {
    Formula::expansion_sign(v, parameter);
  };
  if (longest > 2 && !kTakesLong) return std::nullopt;
  const std::optional<int> scaling = range.exact_scaling(Formula::kDegree);
  if (!scaling || (exact_vectors && *scaling != 0)) return std::nullopt;
  // The exact inputs with capacity K: exact-vector coordinates as they are (at most K
  // components, checked above), the others as exact differences head - tail.
  const auto exact_inputs = [&]<int K>() {
    VectorArray<Expansion<K>, N> e;
    for (std::size_t v = 0; v < N; ++v) {
      for (int axis = 0; axis < 3; ++axis) {
        if (!Formula::reads(axis, parameter)) continue;  // left zero
        if (in[v].is_exact_vector()) {
          e[v][axis] = *in[v].exact_vector().exact[axis].template narrow<K>();
          continue;
        }
        const double head = in[v].head(axis);
        const double tail = in[v].tail(axis);
        e[v][axis] = *(*scaling == 0 ? Expansion<2>::difference(head, tail)
                                     : Expansion<2>::difference(std::ldexp(head, *scaling),
                                                                std::ldexp(tail, *scaling)))
                          .template narrow<K>();
      }
    }
    return e;
  };
  auto evaluate = [parameter](const auto& inputs) -> std::optional<Sign> {
    if constexpr (requires { Formula::expansion_sign(inputs, parameter); }) {
      return Formula::expansion_sign(inputs, parameter);
    } else {
      return Formula::evaluate(inputs, parameter).sign();
    }
  };
  if constexpr (kTakesLong) {
    if (longest > 2) return evaluate(exact_inputs.template operator()<kLongExactVector>());
  }
  // When no input needed a second component (dyadic grids, inputs already relative to one
  // another) the whole evaluation runs on one-component inputs, with every product four
  // times smaller.
  const VectorArray<Expansion<2>, N> e = exact_inputs.template operator()<2>();
  VectorArray<Expansion<1>, N> single;
  for (std::size_t v = 0; v < N; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      const std::optional<Expansion<1>> one = e[v][axis].template narrow<1>();
      if (!one) return evaluate(e);
      single[v][axis] = *one;
    }
  }
  return evaluate(single);
}

/// The exact value of one coordinate of an input, as a rational.
inline Rational rational_coordinate(const Offset& o, int axis) {
  if (o.is_exact_vector()) {
    const auto& e = o.exact_vector().exact[axis];
    Rational sum;
    for (int i = 0; i < e.size(); ++i)
      sum = sum + Rational(e.data()[i]);
    return sum;
  }
  return Rational(o.head(axis)) - Rational(o.tail(axis));
}

template <std::size_t N>
VectorArray<Rational, N> rational_vectors(const Offsets<N>& in) {
  VectorArray<Rational, N> q;
  for (std::size_t v = 0; v < N; ++v) {
    for (int axis = 0; axis < 3; ++axis)
      q[v][axis] = rational_coordinate(in[v], axis);
  }
  return q;
}

/// The exact value of one coordinate of an input, as a dyadic rational.
inline Dyadic dyadic_coordinate(const Offset& o, int axis) {
  if (o.is_exact_vector()) {
    const auto& e = o.exact_vector().exact[axis];
    return Dyadic::sum_of(e.data(), e.size());
  }
  const double difference[2] = {o.head(axis), -o.tail(axis)};
  return Dyadic::sum_of(difference, 2);
}

template <class Formula, std::size_t N>
[[gnu::noinline, gnu::cold]] Sign rational_sign(const Offsets<N> in, int parameter) noexcept {
  VectorArray<Dyadic, N> q;
  for (std::size_t v = 0; v < N; ++v) {
    for (int axis = 0; axis < 3; ++axis) {
      if (Formula::reads(axis, parameter)) q[v][axis] = dyadic_coordinate(in[v], axis);
    }
  }
  return Formula::evaluate(q, parameter).sign();
}

}  // namespace exactgeo::kernel
