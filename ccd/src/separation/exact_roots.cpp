#include "exactgeo/ccd/separation/internal/exact_roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "exactgeo/ccd/separation/internal/features.hpp"
#include "exactgeo/ccd/separation/internal/real_roots.hpp"

namespace exactgeo::ccd::internal {

namespace {

RationalPolynomial power_form(const Homogeneous<Rational>& p) {
  return RationalPolynomial::from_homogeneous(
      std::vector<Rational>(p.c.begin(), p.c.begin() + p.degree + 1));
}

/// A feature's polynomials in the power basis of the step's time.
struct ExactFeature {
  RationalPolynomial gap;
  RationalPolynomial weight;
  std::vector<RationalPolynomial> in_feature;

  explicit ExactFeature(const Feature<Rational>& f)
      : gap(power_form(f.gap)), weight(power_form(f.weight)) {
    for (int i = 0; i < f.in_feature_count; ++i)
      in_feature.push_back(power_form(f.in_feature[i]));
  }
};

bool holds_at_end(const Feature<Rational>& f, bool end) {
  auto sign = [end](const Homogeneous<Rational>& p) {
    return (end ? p.at_end() : p.at_start()).sign();
  };
  if (sign(f.gap) == Sign::positive || sign(f.weight) != Sign::positive) return false;
  for (int i = 0; i < f.in_feature_count; ++i) {
    if (sign(f.in_feature[i]) == Sign::negative) return false;
  }
  return true;
}

/// The weight and in-feature conditions at a root of the squarefree `p`.
bool conditions_at_root(const ExactFeature& f, const RationalPolynomial& p,
                        const IsolatedRoot& root) {
  if (sign_at_root(f.weight, p, root) != Sign::positive) return false;
  for (const RationalPolynomial& q : f.in_feature) {
    if (sign_at_root(q, p, root) == Sign::negative) return false;
  }
  return true;
}

bool conditions_at(const ExactFeature& f, const Rational& t) {
  if (f.weight.sign_at(t) != Sign::positive) return false;
  for (const RationalPolynomial& q : f.in_feature) {
    if (q.sign_at(t) == Sign::negative) return false;
  }
  return true;
}

/// A rational strictly between the roots r < s of the squarefree p (either may be an
/// exact sentinel such as 0 or 1).
Rational point_between(IsolatedRoot r, IsolatedRoot s, const RationalPolynomial& p) {
  for (;;) {
    const Rational upper = r.exact ? *r.exact : r.hi;
    const Rational lower = s.exact ? *s.exact : s.lo;
    if (upper < lower) return (upper + lower) / 2;
    if (!r.exact) {
      internal::halve_isolating_interval(p, r);
    } else {
      internal::halve_isolating_interval(p, s);
    }
  }
}

/// A time within δ: a root of the squarefree `p`, or an exact rational (p unused).
struct WithinTime {
  IsolatedRoot root;
  RationalPolynomial p;
};

WithinTime at_rational(const Rational& t) {
  return {{t, t, t}, {}};
}

/// a < b, for two times each isolated against its own polynomial. Equal roots of two
/// polynomials are roots of their gcd, which divides both and so has at most one root in
/// the overlap of the two isolating intervals (whose ends are roots of neither).
bool earlier(WithinTime a, WithinTime b) {
  for (;;) {
    const Rational a_hi = a.root.exact ? *a.root.exact : a.root.hi;
    const Rational b_lo = b.root.exact ? *b.root.exact : b.root.lo;
    if (a_hi < b_lo) return true;
    const Rational a_lo = a.root.exact ? *a.root.exact : a.root.lo;
    const Rational b_hi = b.root.exact ? *b.root.exact : b.root.hi;
    if (b_hi < a_lo) return false;
    if (a.root.exact && b.root.exact) return false;  // equal
    if (a.root.exact) {
      if (b.p.sign_at(*a.root.exact) == Sign::zero) return false;  // b's only root there
    } else if (b.root.exact) {
      if (a.p.sign_at(*b.root.exact) == Sign::zero) return false;
    } else {
      const RationalPolynomial g = gcd(a.p, b.p);
      const Rational lo = std::max(a_lo, b_lo), hi = std::min(a_hi, b_hi);
      if (g.degree() >= 1 && lo < hi && g.sign_at(lo) != g.sign_at(hi)) return false;
    }
    if (!a.root.exact) halve_isolating_interval(a.p, a.root);
    if (!b.root.exact) halve_isolating_interval(b.p, b.root);
  }
}

/// The feature's earliest time in (0, 1) with its conditions, gap aside (it vanishes
/// identically): tested at every root and between every two roots of the product of its
/// polynomials, in time order.
std::optional<WithinTime> earliest_with_conditions(const ExactFeature& f) {
  if (f.weight.is_zero()) return std::nullopt;
  RationalPolynomial product = f.weight;
  for (const RationalPolynomial& q : f.in_feature) {
    if (!q.is_zero()) product = product * q;
  }
  const RationalPolynomial p = squarefree_part(product);
  std::vector<IsolatedRoot> samples{{Rational(0), 0, 0}};
  for (const IsolatedRoot& r : roots_between(p, 0, 1))
    samples.push_back(r);
  samples.push_back({Rational(1), 1, 1});
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
    if (i > 0 && conditions_at_root(f, p, samples[i])) return WithinTime{samples[i], p};
    const Rational between = point_between(samples[i], samples[i + 1], p);
    if (conditions_at(f, between)) return at_rational(between);
  }
  return std::nullopt;
}

/// A rational in (lo, hi) that is not a root of p (one of a few tries: p has few roots).
Rational split_point(const RationalPolynomial& p, const Rational& lo, const Rational& hi) {
  for (int k = 2;; ++k) {
    const Rational m = lo + (hi - lo) / k;
    if (p.sign_at(m) != Sign::zero) return m;
  }
}

/// The gap's roots in (lo, hi) (not roots themselves) with the feature's other conditions:
/// a cluster of roots is settled whole when its Tarski queries agree (none with weight > 0,
/// or one in-feature polynomial negative at every root; or every condition strict at every
/// root), and split otherwise. With `earliest` the first such root, isolated; without,
/// some such root (its interval then need not isolate it).
std::optional<WithinTime> gap_root_in(const ExactFeature& f, const RationalPolynomial& p,
                                      const TarskiQueries& queries, const Rational& lo,
                                      const Rational& hi, bool earliest) {
  const int n = queries.count(lo, hi);
  if (n == 0) return std::nullopt;
  const int weight = queries.query(0, lo, hi);  // the weight is never negative
  if (weight == 0) return std::nullopt;
  bool all_strict = weight == n;
  bool single_holds = weight == 1;
  for (std::size_t i = 0; i < f.in_feature.size(); ++i) {
    const int q = queries.query(i + 1, lo, hi);
    if (q == -n) return std::nullopt;
    all_strict = all_strict && q == n;
    single_holds = single_holds && q >= 0;
  }
  if (n == 1) {
    if (!single_holds) return std::nullopt;
    return WithinTime{{std::nullopt, lo, hi}, p};
  }
  if (all_strict) {
    if (!earliest) return WithinTime{{std::nullopt, lo, hi}, p};
    return WithinTime{roots_between(p, lo, hi).front(), p};
  }
  const Rational m = split_point(p, lo, hi);
  if (auto left = gap_root_in(f, p, queries, lo, m, earliest)) return left;
  return gap_root_in(f, p, queries, m, hi, earliest);
}

/// The feature's earliest root of its gap in (0, 1) with its other conditions.
std::optional<WithinTime> earliest_root(const ExactFeature& f, bool earliest) {
  RationalPolynomial p = squarefree_part(f.gap);
  // Roots at the step's ends are not inside it: divide them out (p is squarefree).
  if (p.sign_at(0) == Sign::zero) p = p / RationalPolynomial({Rational(0), Rational(1)});
  if (p.sign_at(1) == Sign::zero) p = p / RationalPolynomial({Rational(-1), Rational(1)});
  if (p.degree() < 1) return std::nullopt;
  std::vector<RationalPolynomial> conditions{f.weight};
  conditions.insert(conditions.end(), f.in_feature.begin(), f.in_feature.end());
  return gap_root_in(f, p, TarskiQueries(p, conditions), 0, 1, earliest);
}

/// The earliest time within δ (with `earliest` false: some time within δ), or nullopt.
/// Among the candidates, each a time within δ, is the earliest one t*: 0 or 1 if they
/// are within; otherwise t* is attained by the feature holding the closest point, whose
/// conditions hold at t* (its weight positive), so it is that feature's earliest gap root
/// or, when its gap vanishes identically, its earliest sample.
template <class FeaturesOf>
std::optional<WithinTime> exactly_within(const QueryPoints& x, double delta, std::size_t count,
                                         FeaturesOf feature_of, bool earliest) {
  std::array<Moving<Rational>, 4> m;
  for (int k = 0; k < 4; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      m[k][axis] = Homogeneous<Rational>::linear(Rational(x[k][axis]), Rational(x[k + 4][axis]));
    }
  }
  const Rational delta2 = Rational(delta) * Rational(delta);
  std::vector<Feature<Rational>> features;
  for (std::size_t i = 0; i < count; ++i)
    features.push_back(feature_of(i, m, delta2));
  for (const Feature<Rational>& f : features) {
    if (holds_at_end(f, false)) return at_rational(0);
  }
  std::optional<WithinTime> best;
  for (const Feature<Rational>& g : features) {
    const ExactFeature f(g);
    const auto t = f.gap.is_zero() ? earliest_with_conditions(f) : earliest_root(f, earliest);
    if (t && !earliest) return t;
    if (t && (!best || earlier(*t, *best))) best = t;
  }
  if (best) return best;
  for (const Feature<Rational>& f : features) {
    if (holds_at_end(f, true)) return at_rational(1);
  }
  return std::nullopt;
}

/// A bracket of doubles around the time, of width at most `width` where doubles allow:
/// the isolating interval halved until narrow enough, or until its ends would not be
/// doubles; then its ends rounded outward.
/// The doubles around a root's isolating interval: its ends rounded outward.
TimeInterval outward(const IsolatedRoot& r) {
  const Rational lo = r.exact ? *r.exact : r.lo;
  const Rational hi = r.exact ? *r.exact : r.hi;
  const double start = lo.toward_zero();  // truncated toward zero: at most lo (lo >= 0)
  double end = hi.toward_zero();
  if (Rational(end) < hi) end = std::nextafter(end, 2.0);
  return {start, end};
}

/// The root's bracket in doubles, at most `width` wide or one double spacing (no two
/// doubles lie closer): the isolating interval is halved, exactly, until its outward
/// rounding is that narrow. A root that is itself a double is found as one (bisection of
/// an interval whose ends are not dyadic may never land on it).
TimeInterval bracket_of(WithinTime t, double width) {
  TimeInterval b = outward(t.root);
  while (!t.root.exact && b.end - b.start > width && std::nextafter(b.start, 2.0) < b.end) {
    const double between = std::nextafter(b.start, 2.0);
    if (std::nextafter(between, 2.0) == b.end && t.p.sign_at(Rational(between)) == Sign::zero) {
      t.root.exact = Rational(between);
    } else {
      halve_isolating_interval(t.p, t.root);
    }
    b = outward(t.root);
  }
  return b;
}

}  // namespace

ExactSeparation exact_separation(const QueryPoints& x, bool vertex_face, double delta,
                                 std::optional<double> width) {
  const auto t = vertex_face ? exactly_within(
                                   x, delta, kVertexFaceFeatures,
                                   [](std::size_t i, const auto& m, const Rational& d2) {
                                     return vertex_face_feature(i, m, d2);
                                   },
                                   width.has_value())
                             : exactly_within(
                                   x, delta, kEdgeEdgeFeatures,
                                   [](std::size_t i, const auto& m, const Rational& d2) {
                                     return edge_edge_feature(i, m, d2);
                                   },
                                   width.has_value());
  if (!t) return {false, std::nullopt};
  return {true, width ? std::optional<TimeInterval>(bracket_of(*t, *width)) : std::nullopt};
}

}  // namespace exactgeo::ccd::internal
