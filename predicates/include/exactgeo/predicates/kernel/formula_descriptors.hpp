#pragma once

// Formula descriptors: what the sign stages need to know about each polynomial of
// formulas.hpp: its number of input vectors, its total degree, which coordinates it reads
// (cross2 ignores one), how to evaluate it, and optionally a custom exact evaluation with
// expansions.

#include <optional>

#include "exactgeo/predicates/kernel/expansion.hpp"
#include "exactgeo/predicates/kernel/formulas.hpp"
#include "exactgeo/predicates/sign.hpp"

namespace exactgeo::kernel {

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

/// The volume sign of four points given relative to an origin (tetrahedron_volume).
struct TetrahedronVolumeFormula : ReadsAllCoordinates {
  static constexpr int kVectors = 4;
  static constexpr int kDegree = 3;
  template <class T>
  static constexpr auto evaluate(const VectorArray<T, 4>& v, int /*unused*/) {
    return tetrahedron_volume(v[0], v[1], v[2], v[3]);
  }

  /// On inputs of more than two components (shorter ones use evaluate) the three
  /// differences are compressed and narrowed to four components before det3 (differences
  /// of nearby points are short), which keeps the value within 1,536 components instead
  /// of 12,288.
  template <int C>
  requires(C > 2) static std::optional<Sign> expansion_sign(const VectorArray<Expansion<C>, 4>& v,
                                                            int) noexcept {
    VectorArray<Expansion<4>, 3> d;
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k < 3; ++k) {
        auto difference = v[i + 1][k] - v[0][k];
        const auto narrowed = difference.compress().template narrow<4>();
        if (!narrowed) return std::nullopt;
        d[i][k] = *narrowed;
      }
    }
    return det3(d[0], d[1], d[2]).sign();
  }
};

/// A normal component of a triangle given relative to an origin; the parameter is the
/// axis, which the formula does not read.
struct TriangleNormalFormula {
  static constexpr int kVectors = 3;
  static constexpr int kDegree = 2;
  static constexpr bool reads(int axis, int normal_axis) { return axis != normal_axis; }
  template <class T>
  static constexpr auto evaluate(const VectorArray<T, 3>& v, int axis) {
    return triangle_normal(axis, v[0], v[1], v[2]);
  }
};

}  // namespace exactgeo::kernel
