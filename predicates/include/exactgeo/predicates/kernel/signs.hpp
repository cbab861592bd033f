#pragma once

// Sign policies: the one interface through which the geometric algorithms (ray-triangle,
// ray-patch and crossing parity here; CCD and mesh's face contacts above) ask for the sign
// of a polynomial. Writing the algorithms against a policy gives, from one source,
//
//   ExactSigns     filter -> expansions -> rationals: the product (optionally counting
//                  which stage decided, into a caller-owned StageCounts);
//   DoubleSigns    the plain double evaluation of the same formulas, no filter and no
//                  fallback: the non-exact baseline users compare against;
//   RationalSigns  rationals only: the slow reference.
//
// Policies are small value types without global state; they are safe to copy and to use
// from many threads (a StageCounts must not be shared between threads).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "exactgeo/predicates/arithmetic.hpp"
#include "exactgeo/predicates/kernel/exact_stages.hpp"
#include "exactgeo/predicates/kernel/filter.hpp"

namespace exactgeo::kernel {

/// How many signs each stage decided.
struct StageCounts {
  std::uint64_t filter = 0;
  std::uint64_t expansion = 0;
  std::uint64_t rational = 0;

  std::uint64_t total() const noexcept { return filter + expansion + rational; }
};

/// The named predicates every policy offers, in terms of the policy's generic sign().
template <class Policy>
class NamedSigns {
 public:
  /// sign of det[a, b, c]; filter normalised per axis (inputs are points' offsets).
  Sign det3_by_axis(const Offset& a, const Offset& b, const Offset& c) const noexcept {
    return self().template sign<Det3Formula, Grouping::by_axis>(Offsets<3>{a, b, c});
  }
  /// sign of det[a, b, c]; filter normalised per vector (one of them is a direction).
  Sign det3_by_vector(const Offset& a, const Offset& b, const Offset& c) const noexcept {
    return self().template sign<Det3Formula, Grouping::by_vector>(Offsets<3>{a, b, c});
  }
  /// sign of (a x b)[axis].
  Sign cross2(int axis, const Offset& a, const Offset& b) const noexcept {
    return self().template sign<Cross2Formula, Grouping::by_vector>(Offsets<2>{a, b}, axis);
  }
  Sign dot3(const Offset& a, const Offset& b) const noexcept {
    return self().template sign<Dot3Formula, Grouping::by_vector>(Offsets<2>{a, b});
  }
  /// orient3d(x0, x1, x2, x3) for a_i = x_i - o.
  Sign tetrahedron_volume(const Offsets<4>& a) const noexcept {
    return self().template sign<TetrahedronVolumeFormula, Grouping::by_axis>(a);
  }
  /// The same, given a cheap exact test that proves the volume zero (false: no proof). The
  /// exact policy consults it only where its filter cannot decide, so a volume that is
  /// clearly nonzero never pays for it; the others consult it first.
  template <class ZeroProof>
  Sign tetrahedron_volume(const Offsets<4>& a, ZeroProof proves_zero) const noexcept {
    return self().template sign_unless_zero<TetrahedronVolumeFormula, Grouping::by_axis>(
        a, proves_zero);
  }

  /// A sign with a cheap exact proof of zero, consulted first (policies with a filter
  /// override this to consult it only where the filter cannot decide).
  template <class Formula, Grouping grouping, std::size_t N, class ZeroProof>
  Sign sign_unless_zero(const Offsets<N>& in, ZeroProof proves_zero) const noexcept {
    return proves_zero() ? Sign::zero : self().template sign<Formula, grouping>(in);
  }
  /// ((x1 - x0) x (x2 - x0))[axis] for a_i = x_i - o.
  Sign triangle_normal(int axis, const Offset& a0, const Offset& a1,
                       const Offset& a2) const noexcept {
    return self().template sign<TriangleNormalFormula, Grouping::by_projected_axis>(
        Offsets<3>{a0, a1, a2}, axis);
  }
  /// sign of the bilinear patch's implicit function at the origin (formulas.hpp).
  Sign phi(const Offsets<4>& a) const noexcept {
    return self().template sign<PhiFormula, Grouping::by_axis>(a);
  }

 private:
  const Policy& self() const noexcept { return static_cast<const Policy&>(*this); }
};

/// Where the filter's bound did not certify: the rest of stage 1 (a vanishing group), then
/// stages 2 and 3, expansions and rationals. Out of line, so that their stack of
/// expansions never enlarges the hot path's frame (not cold: exact_stages.hpp says why). The inputs
/// are views (a few pointers), passed by value.
template <class Formula, Grouping grouping, std::size_t N>
[[gnu::noinline]] Sign sign_after_filter(const Offsets<N> in, int parameter,
                                         StageCounts* counts) noexcept {
  if (vanishing_group<Formula, grouping>(in, parameter)) {
    if (counts) ++counts->filter;
    return Sign::zero;
  }
  if (const std::optional<Sign> s = expansion_sign<Formula>(in, parameter)) {
    if (counts) ++counts->expansion;
    return *s;
  }
  if (counts) ++counts->rational;
  return rational_sign<Formula>(in, parameter);
}

/// A bound on a formula's rounding error fixed once for a set of inputs (a static filter,
/// StaticDet3Signs), which ExactSigns::sign tries before its per-sign filter.
struct StaticBound {
  double value;
};
/// No static bound: the per-sign filter comes first.
struct NoStaticBound {};
/// No cheap proof of zero: nothing between the filter and sign_after_filter.
struct NoZeroProof {
  constexpr bool operator()() const noexcept { return false; }
};

class ExactSigns : public NamedSigns<ExactSigns> {
 public:
  explicit ExactSigns(StageCounts* counts = nullptr) noexcept : counts_(counts) {}

  /// Every exact sign, in the one place where its stages are written: the first that
  /// decides answers, and is counted under its name (StageCounts).
  ///
  ///   1. filter     a static bound first where the caller has one (`ahead`), then the
  ///                 formula in double certified by its own bound (filter.hpp); where
  ///                 neither certifies, the caller's cheap proof of zero (`proves_zero`),
  ///                 then a group of inputs that vanishes;
  ///   2. expansion  exact floating-point expansions (expansion_sign, exact_stages.hpp);
  ///   3. rational   dyadic rationals (rational_sign), which always answer.
  ///
  /// The hot path is the first compare, inline with one predictable branch. What follows a
  /// static bound that does not certify runs out of line (sign_behind_static_bound: this
  /// same sequence without it), so that the one compare stays small enough to inline; what
  /// follows the filter runs out of line too (sign_after_filter), so that the exact stages'
  /// stack never enlarges the hot path's frame.
  template <class Formula, Grouping grouping, std::size_t N, class Ahead = NoStaticBound,
            class ZeroProof = NoZeroProof>
  Sign sign(const Offsets<N>& in, int parameter = 0, Ahead ahead = {},
            ZeroProof proves_zero = {}) const noexcept {
    static_assert(std::is_same_v<Ahead, StaticBound> || std::is_same_v<Ahead, NoStaticBound>);
    if constexpr (std::is_same_v<Ahead, StaticBound>) {
      const double value = Formula::evaluate(rounded(in), parameter);
      if (std::fabs(value) > ahead.value) [[likely]] {
        count_filter();
        return sign_of(value);
      }
      return sign_behind_static_bound<Formula, grouping>(in, parameter, proves_zero);
    } else {
      if (const auto f = internal::evaluate_filter<Formula, grouping>(in, parameter); f.certified)
          [[likely]] {
        count_filter();
        return sign_of(f.value);
      }
      if (proves_zero()) {
        count_filter();
        return Sign::zero;
      }
      return sign_after_filter<Formula, grouping>(in, parameter, counts_);
    }
  }

  /// sign() with a cheap exact proof of zero, consulted only where the filter cannot
  /// decide, so a volume that is clearly nonzero never pays for it.
  template <class Formula, Grouping grouping, std::size_t N, class ZeroProof>
  Sign sign_unless_zero(const Offsets<N>& in, ZeroProof proves_zero) const noexcept {
    return sign<Formula, grouping>(in, 0, NoStaticBound{}, proves_zero);
  }

  /// Records one sign decided by a filter.
  void count_filter() const noexcept {
    if (counts_) ++counts_->filter;
  }

  /// Exact numbers for the few rare-path computations done outside sign() (the folded
  /// flat patch test).
  template <std::size_t N>
  static VectorArray<Rational, N> numbers(const Offsets<N>& in) {
    return rational_vectors(in);
  }

 private:
  /// The per-sign filter and the exact stages, where a static bound did not certify.
  template <class Formula, Grouping grouping, std::size_t N, class ZeroProof>
  [[gnu::noinline]] Sign sign_behind_static_bound(const Offsets<N>& in, int parameter,
                                                  ZeroProof proves_zero) const noexcept {
    return sign<Formula, grouping>(in, parameter, NoStaticBound{}, proves_zero);
  }

  StageCounts* counts_;
};

/// Error bounds for det3 signs whose inputs are all among a known set of vectors, fixed
/// once for the set (a static filter) instead of measured per sign.
struct Det3Bounds {
  double by_axis = INFINITY;    ///< det3_by_axis of three of the vectors
  double by_vector = INFINITY;  ///< det3_by_vector of the vectors and at most one direction
};

/// The bounds for `vectors` and `direction`. The filter's analysis (roundoff.hpp) holds for
/// any upper bounds m_g on the magnitudes of each group's inputs that lie within its guard,
/// not only for the measured maxima: here m_g is the largest |coordinate| of all the vectors
/// on axis g (by axis), or, by vector, A for a vector and max(A, |direction|) for the third
/// factor (A: the largest coordinate of all the vectors), which bounds every product of
/// three group maxima with at most one direction. Unusable (out of the guard): infinite.
template <std::size_t N>
Det3Bounds det3_bounds(const Offsets<N>& vectors, const Vector3& direction) noexcept {
  Vec3<double> axis_max{};
  for (const Offset& o : vectors) {
    const Vec3<double> r = o.rounded();
    for (int a = 0; a < 3; ++a)
      axis_max[a] = std::max(axis_max[a], std::fabs(r[a]));
  }
  const double largest = std::max({axis_max[0], axis_max[1], axis_max[2]});
  const double third = std::max(
      {largest, std::fabs(direction[0]), std::fabs(direction[1]), std::fabs(direction[2])});
  constexpr auto& by_axis = kFilterConstant<Det3Formula, Grouping::by_axis>;
  constexpr auto& by_vector = kFilterConstant<Det3Formula, Grouping::by_vector>;
  auto in_guard = [](const auto& constant, double m) {
    return m >= constant.guard_low && m <= constant.guard_high;
  };
  Det3Bounds b;
  if (in_guard(by_axis, axis_max[0]) && in_guard(by_axis, axis_max[1]) &&
      in_guard(by_axis, axis_max[2])) {
    b.by_axis = by_axis.epsilon * axis_max[0] * axis_max[1] * axis_max[2];
  }
  if (in_guard(by_vector, largest) && in_guard(by_vector, third)) {
    b.by_vector = by_vector.epsilon * largest * largest * third;
  }
  return b;
}

/// ExactSigns behind a static filter for det3 signs (Det3Bounds): the one compare that
/// replaces the per-sign maxima where the bound certifies, the full exact policy
/// elsewhere (ExactSigns::sign with the bound ahead of its stages). Only for signs whose
/// inputs are among the vectors the bounds were made for.
class StaticDet3Signs : public NamedSigns<StaticDet3Signs> {
 public:
  StaticDet3Signs(const ExactSigns& exact, const Det3Bounds& bounds) noexcept
      : exact_(exact), bounds_(bounds) {}

  template <class Formula, Grouping grouping, std::size_t N>
  Sign sign(const Offsets<N>& in, int parameter = 0) const noexcept {
    if constexpr (std::is_same_v<Formula, Det3Formula> && grouping != Grouping::by_projected_axis) {
      const double bound = grouping == Grouping::by_axis ? bounds_.by_axis : bounds_.by_vector;
      return exact_.sign<Formula, grouping>(in, parameter, StaticBound{bound});
    } else {
      return exact_.sign<Formula, grouping>(in, parameter);
    }
  }

  template <class Formula, Grouping grouping, std::size_t N, class ZeroProof>
  Sign sign_unless_zero(const Offsets<N>& in, ZeroProof proves_zero) const noexcept {
    return exact_.sign_unless_zero<Formula, grouping>(in, proves_zero);
  }

  template <std::size_t N>
  static VectorArray<Rational, N> numbers(const Offsets<N>& in) {
    return ExactSigns::numbers(in);
  }

 private:
  ExactSigns exact_;
  Det3Bounds bounds_;
};

/// The policy for signs among `vectors` and `direction`: the static filter in front of the
/// exact policy; any other policy unchanged.
template <class Signs, std::size_t N>
auto with_static_filter(const Signs& signs, const Offsets<N>& vectors,
                        const Vector3& direction) noexcept {
  if constexpr (std::is_same_v<Signs, ExactSigns>) {
    return StaticDet3Signs(signs, det3_bounds(vectors, direction));
  } else {
    return signs;
  }
}

class DoubleSigns : public NamedSigns<DoubleSigns> {
 public:
  template <class Formula, Grouping grouping, std::size_t N>
  Sign sign(const Offsets<N>& in, int parameter = 0) const noexcept {
    return sign_of(Formula::evaluate(rounded(in), parameter));
  }

  template <std::size_t N>
  static VectorArray<double, N> numbers(const Offsets<N>& in) noexcept {
    return rounded(in);
  }
};

class RationalSigns : public NamedSigns<RationalSigns> {
 public:
  template <class Formula, Grouping grouping, std::size_t N>
  Sign sign(const Offsets<N>& in, int parameter = 0) const noexcept {
    return rational_sign<Formula>(in, parameter);
  }

  template <std::size_t N>
  static VectorArray<Rational, N> numbers(const Offsets<N>& in) {
    return rational_vectors(in);
  }
};

/// Calls f with the policy that implements `arithmetic`.
template <class F>
decltype(auto) with_signs(Arithmetic arithmetic, F&& f) {
  switch (arithmetic) {
    case Arithmetic::plain_double:
      return std::forward<F>(f)(DoubleSigns{});
    case Arithmetic::rational:
      return std::forward<F>(f)(RationalSigns{});
    case Arithmetic::exact:
      break;
  }
  return std::forward<F>(f)(ExactSigns{});
}

/// The exact sign of one coordinate of an offset: fl(head - tail) has the sign of
/// head - tail under round-to-nearest, and is zero only when they are equal.
inline Sign coordinate_sign(const Offset& v, int axis) noexcept {
  return sign_of(v.head(axis) - v.tail(axis));
}

}  // namespace exactgeo::kernel
