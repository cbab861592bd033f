#include "exactgeo/ccd/internal/min_separation.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "exactgeo/ccd/internal/bounded_double.hpp"
#include "exactgeo/ccd/internal/culling.hpp"
#include "exactgeo/ccd/internal/real_roots.hpp"
#include "exactgeo/ccd/internal/separation_features.hpp"

namespace exactgeo::ccd::internal {

namespace {

/// The eight points of a query: four at t = 0, the same four at t = 1.
using QueryPoints = std::array<Point3, 8>;

template <class Query>
QueryPoints points_of(const Query& q) noexcept {
  static_assert(sizeof(Query) == sizeof(QueryPoints));
  return std::bit_cast<QueryPoints>(q);
}

// ---- 1. Boxes -------------------------------------------------------------------------

/// The first `split` of the four points form one primitive, the others the other.
bool boxes_apart(const QueryPoints& x, int split, double delta) noexcept {
  for (int axis = 0; axis < 3; ++axis) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int k = 0; k < 8; ++k) {
      const int side = k % 4 < split ? 0 : 1;
      lo[side] = std::min(lo[side], x[k][axis]);
      hi[side] = std::max(hi[side], x[k][axis]);
    }
    if (lo[1] - hi[0] > delta || lo[0] - hi[1] > delta) return true;
  }
  return false;
}

// ---- 2. Bounded doubles on pieces ---------------------------------------------------------

/// x0 + t (x1 - x0), exact at the step's ends.
BoundedDouble position(double x0, double x1, double t) noexcept {
  if (t == 0.0) return x0;
  if (t == 1.0) return x1;
  return BoundedDouble(x0) + BoundedDouble(t) * (BoundedDouble(x1) - BoundedDouble(x0));
}

/// The four points at one time: coordinates as bounded doubles.
using Positions = std::array<std::array<BoundedDouble, 3>, 4>;

Positions positions_at(const QueryPoints& x, double t) noexcept {
  Positions p;
  for (int k = 0; k < 4; ++k) {
    for (int axis = 0; axis < 3; ++axis)
      p[k][axis] = position(x[k][axis], x[k + 4][axis], t);
  }
  return p;
}

/// The points over the piece between the two times, as linear polynomials.
std::array<Moving<BoundedDouble>, 4> moving_between(const Positions& start, const Positions& end) {
  std::array<Moving<BoundedDouble>, 4> m;
  for (int k = 0; k < 4; ++k) {
    for (int axis = 0; axis < 3; ++axis)
      m[k][axis] = Homogeneous<BoundedDouble>::linear(start[k][axis], end[k][axis]);
  }
  return m;
}

bool all_positive(const Homogeneous<BoundedDouble>& p) noexcept {
  for (int k = 0; k <= p.degree; ++k) {
    if (!p.c[k].certainly_positive()) return false;
  }
  return true;
}

bool all_negative(const Homogeneous<BoundedDouble>& p) noexcept {
  for (int k = 0; k <= p.degree; ++k) {
    if (!p.c[k].certainly_negative()) return false;
  }
  return true;
}

/// No time of the piece satisfies the feature's conditions.
bool excluded(const Feature<BoundedDouble>& f) noexcept {
  if (all_positive(f.gap)) return true;
  for (int i = 0; i < f.inside_count; ++i) {
    if (all_negative(f.inside[i])) return true;
  }
  return false;
}

/// Every condition certainly holds at the piece's start (end = false) or end.
bool holds_at_end(const Feature<BoundedDouble>& f, bool end) noexcept {
  auto at = [end](const Homogeneous<BoundedDouble>& p) { return end ? p.at_end() : p.at_start(); };
  if (!at(f.gap).certainly_nonpositive() || !at(f.weight).certainly_positive()) return false;
  for (int i = 0; i < f.inside_count; ++i) {
    if (!at(f.inside[i]).certainly_nonnegative()) return false;
  }
  return true;
}

/// The differences between the two primitives' corners at one time: vertex - face corner
/// (a triangle, H = 3) or a-end - b-end (a parallelogram, H = 4). Every difference of a
/// point of one primitive and a point of the other at that time is a convex combination
/// of them, and over a piece of the step a convex combination of both ends' images.
template <std::size_t H>
using Slice = std::array<std::array<BoundedDouble, 3>, H>;

template <std::size_t H>
Slice<H> slice_of(const Positions& p) noexcept {
  Slice<H> c;
  auto minus = [](const std::array<BoundedDouble, 3>& a, const std::array<BoundedDouble, 3>& b) {
    return std::array<BoundedDouble, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  if constexpr (H == 3) {
    for (std::size_t k = 0; k < 3; ++k)
      c[k] = minus(p[0], p[k + 1]);
  } else {
    c = {minus(p[0], p[2]), minus(p[0], p[3]), minus(p[1], p[3]), minus(p[1], p[2])};
  }
  return c;
}

/// A plane through the origin with every corner image of both slices more than δ on its
/// positive side: n.c > 0 and (n.c)^2 > δ^2 n.n, so the hull of the images, which holds
/// every difference of points of the two primitives during the piece, keeps a distance
/// above δ from the origin. The normal points to the start slice's point closest to the
/// origin (in plain doubles: any normal will do, the certificate is the proof).
template <std::size_t H>
bool apart_by_plane(const Slice<H>& start, const Slice<H>& end,
                    const BoundedDouble& delta2) noexcept {
  std::array<Vector3, H> rounded;
  for (std::size_t k = 0; k < H; ++k) {
    for (int axis = 0; axis < 3; ++axis)
      rounded[k][axis] = start[k][axis].value;
  }
  const Vector3 n = closest_direction(rounded);
  if (!usable(n)) return false;
  const BoundedDouble nn = BoundedDouble(n[0]) * BoundedDouble(n[0]) +
                           BoundedDouble(n[1]) * BoundedDouble(n[1]) +
                           BoundedDouble(n[2]) * BoundedDouble(n[2]);
  const BoundedDouble margin = delta2 * nn;
  auto beyond = [&](const std::array<BoundedDouble, 3>& c) {
    const BoundedDouble side =
        BoundedDouble(n[0]) * c[0] + BoundedDouble(n[1]) * c[1] + BoundedDouble(n[2]) * c[2];
    return side.certainly_positive() && (side * side - margin).certainly_positive();
  };
  // The end slice first: the start slice lies on the normal's side by construction.
  for (const Slice<H>* slice : {&end, &start}) {
    for (const auto& c : *slice) {
      if (!beyond(c)) return false;
    }
  }
  return true;
}

/// How far the bounded-double stage may split before the exact stage takes over.
constexpr int kMaxFilterDepth = 24;
constexpr int kMaxFilterPieces = 96;

struct FilterAnswer {
  bool within;
  std::optional<TimeInterval> earliest;  ///< with a width: the earliest time's bracket
};

/// Stage 2. Depth first, left half first: when a piece is taken, every time before its
/// start is proven apart. So a feature holding at a piece's start makes that start the
/// earliest time within δ, and one holding at its end brackets it in the piece, which is
/// split on until it is no wider than `width`.
template <std::size_t N, class FeaturesOf>
std::optional<FilterAnswer> bounded_within(const QueryPoints& x, double delta,
                                           std::optional<double> width,
                                           FeaturesOf feature_of) noexcept {
  const BoundedDouble delta2 = BoundedDouble(delta) * BoundedDouble(delta);
  struct Piece {
    double a, b;
    int depth;
    std::uint32_t alive;  // features not yet excluded, one bit each
  };
  // At most one pending right half per level.
  std::array<Piece, kMaxFilterDepth + 2> stack;
  std::size_t size = 0;
  stack[size++] = {0.0, 1.0, 0, (1u << N) - 1};
  int pieces_left = kMaxFilterPieces;
  while (size > 0) {
    const Piece piece = stack[--size];
    if (--pieces_left < 0) return std::nullopt;
    constexpr std::size_t H = N == kVertexFaceFeatures ? 3 : 4;
    const Positions start = positions_at(x, piece.a), end = positions_at(x, piece.b);
    if (apart_by_plane<H>(slice_of<H>(start), slice_of<H>(end), delta2)) continue;
    const auto moving = moving_between(start, end);
    std::uint32_t alive = 0;
    bool at_start = false, at_end = false;
    for (std::size_t i = 0; i < N; ++i) {
      if (!(piece.alive >> i & 1u)) continue;
      const Feature<BoundedDouble> f = feature_of(i, moving, delta2);
      at_start = at_start || holds_at_end(f, false);
      at_end = at_end || holds_at_end(f, true);
      if (!excluded(f)) alive |= 1u << i;
    }
    if (at_start) return FilterAnswer{true, TimeInterval{piece.a, piece.a}};
    if (at_end && (!width || piece.b - piece.a <= *width)) {
      return FilterAnswer{true, TimeInterval{piece.a, piece.b}};
    }
    if (alive == 0) continue;
    if (piece.depth >= kMaxFilterDepth) return std::nullopt;
    const double mid = 0.5 * (piece.a + piece.b);
    stack[size++] = {mid, piece.b, piece.depth + 1, alive};
    stack[size++] = {piece.a, mid, piece.depth + 1, alive};
  }
  return FilterAnswer{false, std::nullopt};
}

// ---- 3. Exact roots ------------------------------------------------------------------------

RationalPolynomial power_form(const Homogeneous<mpq_class>& p) {
  return RationalPolynomial::from_homogeneous(
      std::vector<mpq_class>(p.c.begin(), p.c.begin() + p.degree + 1));
}

/// A feature's polynomials in the power basis of the step's time.
struct ExactFeature {
  RationalPolynomial gap;
  RationalPolynomial weight;
  std::vector<RationalPolynomial> inside;

  explicit ExactFeature(const Feature<mpq_class>& f)
      : gap(power_form(f.gap)), weight(power_form(f.weight)) {
    for (int i = 0; i < f.inside_count; ++i)
      inside.push_back(power_form(f.inside[i]));
  }
};

bool holds_at_end(const Feature<mpq_class>& f, bool end) {
  auto sign = [end](const Homogeneous<mpq_class>& p) {
    return sgn(end ? p.at_end() : p.at_start());
  };
  if (sign(f.gap) > 0 || sign(f.weight) <= 0) return false;
  for (int i = 0; i < f.inside_count; ++i) {
    if (sign(f.inside[i]) < 0) return false;
  }
  return true;
}

/// The weight and inside conditions at a root of the squarefree `p`.
bool inside_at_root(const ExactFeature& f, const RationalPolynomial& p, const IsolatedRoot& root) {
  if (sign_at_root(f.weight, p, root) != Sign::positive) return false;
  for (const RationalPolynomial& q : f.inside) {
    if (sign_at_root(q, p, root) == Sign::negative) return false;
  }
  return true;
}

bool inside_at(const ExactFeature& f, const mpq_class& t) {
  if (f.weight.sign_at(t) != Sign::positive) return false;
  for (const RationalPolynomial& q : f.inside) {
    if (q.sign_at(t) == Sign::negative) return false;
  }
  return true;
}

/// A rational strictly between the roots r < s of the squarefree p (either may be an
/// exact sentinel such as 0 or 1).
mpq_class point_between(IsolatedRoot r, IsolatedRoot s, const RationalPolynomial& p) {
  for (;;) {
    const mpq_class upper = r.exact ? *r.exact : r.hi;
    const mpq_class lower = s.exact ? *s.exact : s.lo;
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

WithinTime at_rational(const mpq_class& t) {
  return {{t, t, t}, {}};
}

/// a < b, for two times each isolated against its own polynomial. Equal roots of two
/// polynomials are roots of their gcd, which divides both and so has at most one root in
/// the overlap of the two isolating intervals (whose ends are roots of neither).
bool earlier(WithinTime a, WithinTime b) {
  for (;;) {
    const mpq_class a_hi = a.root.exact ? *a.root.exact : a.root.hi;
    const mpq_class b_lo = b.root.exact ? *b.root.exact : b.root.lo;
    if (a_hi < b_lo) return true;
    const mpq_class a_lo = a.root.exact ? *a.root.exact : a.root.lo;
    const mpq_class b_hi = b.root.exact ? *b.root.exact : b.root.hi;
    if (b_hi < a_lo) return false;
    if (a.root.exact && b.root.exact) return false;  // equal
    if (a.root.exact) {
      if (b.p.sign_at(*a.root.exact) == Sign::zero) return false;  // b's only root there
    } else if (b.root.exact) {
      if (a.p.sign_at(*b.root.exact) == Sign::zero) return false;
    } else {
      const RationalPolynomial g = gcd(a.p, b.p);
      const mpq_class lo = std::max(a_lo, b_lo), hi = std::min(a_hi, b_hi);
      if (g.degree() >= 1 && lo < hi && g.sign_at(lo) != g.sign_at(hi)) return false;
    }
    if (!a.root.exact) halve_isolating_interval(a.p, a.root);
    if (!b.root.exact) halve_isolating_interval(b.p, b.root);
  }
}

/// The feature's earliest time in (0, 1) with its conditions, gap aside (it vanishes
/// identically): tested at every root and between every two roots of the product of its
/// polynomials, in time order.
std::optional<WithinTime> earliest_inside(const ExactFeature& f) {
  if (f.weight.is_zero()) return std::nullopt;
  RationalPolynomial product = f.weight;
  for (const RationalPolynomial& q : f.inside) {
    if (!q.is_zero()) product = product * q;
  }
  const RationalPolynomial p = squarefree_part(product);
  std::vector<IsolatedRoot> samples{{mpq_class(0), 0, 0}};
  for (const IsolatedRoot& r : roots_between(p, 0, 1))
    samples.push_back(r);
  samples.push_back({mpq_class(1), 1, 1});
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
    if (i > 0 && inside_at_root(f, p, samples[i])) return WithinTime{samples[i], p};
    const mpq_class between = point_between(samples[i], samples[i + 1], p);
    if (inside_at(f, between)) return at_rational(between);
  }
  return std::nullopt;
}

/// A rational in (lo, hi) that is not a root of p (one of a few tries: p has few roots).
mpq_class split_point(const RationalPolynomial& p, const mpq_class& lo, const mpq_class& hi) {
  for (int k = 2;; ++k) {
    const mpq_class m = lo + (hi - lo) / k;
    if (p.sign_at(m) != Sign::zero) return m;
  }
}

/// The gap's roots in (lo, hi) (not roots themselves) with the feature's other conditions:
/// a cluster of roots is settled whole when its Tarski queries agree (none with weight > 0,
/// or one inside polynomial negative at every root; or every condition strict at every
/// root), and split otherwise. With `earliest` the first such root, isolated; without,
/// some such root (its interval then need not isolate it).
std::optional<WithinTime> gap_root_in(const ExactFeature& f, const RationalPolynomial& p,
                                      const TarskiQueries& queries, const mpq_class& lo,
                                      const mpq_class& hi, bool earliest) {
  const int n = queries.count(lo, hi);
  if (n == 0) return std::nullopt;
  const int weight = queries.query(0, lo, hi);  // the weight is never negative
  if (weight == 0) return std::nullopt;
  bool all_strict = weight == n;
  bool single_holds = weight == 1;
  for (std::size_t i = 0; i < f.inside.size(); ++i) {
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
  const mpq_class m = split_point(p, lo, hi);
  if (auto left = gap_root_in(f, p, queries, lo, m, earliest)) return left;
  return gap_root_in(f, p, queries, m, hi, earliest);
}

/// The feature's earliest root of its gap in (0, 1) with its other conditions.
std::optional<WithinTime> earliest_root(const ExactFeature& f, bool earliest) {
  RationalPolynomial p = squarefree_part(f.gap);
  // Roots at the step's ends are not inside it: divide them out (p is squarefree).
  if (p.sign_at(0) == Sign::zero) p = p / RationalPolynomial({mpq_class(0), mpq_class(1)});
  if (p.sign_at(1) == Sign::zero) p = p / RationalPolynomial({mpq_class(-1), mpq_class(1)});
  if (p.degree() < 1) return std::nullopt;
  std::vector<RationalPolynomial> conditions{f.weight};
  conditions.insert(conditions.end(), f.inside.begin(), f.inside.end());
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
  std::array<Moving<mpq_class>, 4> m;
  for (int k = 0; k < 4; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      m[k][axis] = Homogeneous<mpq_class>::linear(mpq_class(x[k][axis]), mpq_class(x[k + 4][axis]));
    }
  }
  const mpq_class delta2 = mpq_class(delta) * mpq_class(delta);
  std::vector<Feature<mpq_class>> features;
  for (std::size_t i = 0; i < count; ++i)
    features.push_back(feature_of(i, m, delta2));
  for (const Feature<mpq_class>& f : features) {
    if (holds_at_end(f, false)) return at_rational(0);
  }
  std::optional<WithinTime> best;
  for (const Feature<mpq_class>& g : features) {
    const ExactFeature f(g);
    const auto t = f.gap.is_zero() ? earliest_inside(f) : earliest_root(f, earliest);
    if (t && !earliest) return t;
    if (t && (!best || earlier(*t, *best))) best = t;
  }
  if (best) return best;
  for (const Feature<mpq_class>& f : features) {
    if (holds_at_end(f, true)) return at_rational(1);
  }
  return std::nullopt;
}

/// A bracket of doubles around the time, of width at most `width` where doubles allow:
/// the isolating interval halved until narrow enough, or until its ends would not be
/// doubles; then its ends rounded outward.
TimeInterval bracket_of(WithinTime t, double width) {
  auto is_double = [](const mpq_class& q) { return mpq_class(q.get_d()) == q; };
  while (!t.root.exact && t.root.hi - t.root.lo > mpq_class(width)) {
    IsolatedRoot narrower = t.root;
    halve_isolating_interval(t.p, narrower);
    const bool doubles = narrower.exact ? is_double(*narrower.exact)
                                        : is_double(narrower.lo) && is_double(narrower.hi);
    if (!doubles) break;
    t.root = narrower;
  }
  const mpq_class lo = t.root.exact ? *t.root.exact : t.root.lo;
  const mpq_class hi = t.root.exact ? *t.root.exact : t.root.hi;
  const double start = lo.get_d();  // truncated toward zero: at most lo (lo >= 0)
  double end = hi.get_d();
  if (mpq_class(end) < hi) end = std::nextafter(end, 2.0);
  return {start, end};
}

/// The plane of apart_by_plane over the whole step, in plain doubles with one static
/// bound: the corner differences d = fl(p - q) of input doubles, s = fl(n . d) left to
/// right. With u = 2^-53 and A = fl(|n0 d0| + |n1 d1| + |n2 d2|): |d - (p - q)| <= u |d|
/// per coordinate, and the dot product's rounding is at most 3u / (1 - 3u) times the
/// exact sum of |n_i d_i|, itself below A (1 + 3u); so |s - n.(p - q)| < 4.01 u A, plus
/// 3 2^-1075 where products underflow: E = 6u A + 2^-1070 covers both and the rounding of
/// E itself. Then l = fl(s - E) (1 - 2u) is below n.(p - q) (a positive difference rounds
/// up by at most a factor 1 + u), fl(l l) (1 - 2u) - 2^-1070 below its square, and
/// fl(fl(δ δ) nn) (1 + 16u) + 2^-1070 above δ^2 n.n (nn = fl(n.n): five roundings up).
/// The same certificate as in bounded doubles, for a fraction of the operations.
template <std::size_t H>
bool apart_by_plane_at_ends(const QueryPoints& x, double delta) noexcept {
  constexpr double u = 0x1p-53, tiny = 0x1p-1070;
  auto corners_at = [&](int time) {
    std::array<Vector3, H> c;
    const Point3* p = &x[4 * time];
    auto minus = [](const Point3& a, const Point3& b) {
      return Vector3{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    if constexpr (H == 3) {
      for (std::size_t k = 0; k < 3; ++k)
        c[k] = minus(p[0], p[k + 1]);
    } else {
      c = {minus(p[0], p[2]), minus(p[0], p[3]), minus(p[1], p[3]), minus(p[1], p[2])};
    }
    return c;
  };
  const std::array<Vector3, H> start = corners_at(0), end = corners_at(1);
  const Vector3 n = closest_direction(start);
  if (!usable(n)) return false;
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  const double bound = delta * delta * nn * (1.0 + 16 * u) + tiny;
  if (!std::isfinite(bound)) return false;
  auto beyond = [&](const Vector3& d) {
    const double s = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    const double a = std::fabs(n[0] * d[0]) + std::fabs(n[1] * d[1]) + std::fabs(n[2] * d[2]);
    const double l = (s - (6 * u * a + tiny)) * (1.0 - 2 * u);
    return l > 0.0 && l * l * (1.0 - 2 * u) - tiny > bound;
  };
  for (const std::array<Vector3, H>* slice : {&end, &start}) {
    for (const Vector3& d : *slice) {
      if (!beyond(d)) return false;
    }
  }
  return true;
}

template <std::size_t N, class Query>
bool apart(const Query& query, double delta, int split) noexcept {
  const QueryPoints x = points_of(query);
  if (boxes_apart(x, split, delta)) return true;
  return apart_by_plane_at_ends < N == kVertexFaceFeatures ? 3 : 4 > (x, delta);
}

template <std::size_t N, class Query, class BoundedFeatures, class ExactFeatures>
SeparationVerdict within(const Query& query, double delta, std::optional<double> width,
                         BoundedFeatures bounded, ExactFeatures exact) noexcept {
  const QueryPoints x = points_of(query);
  if (const auto verdict = bounded_within<N>(x, delta, width, bounded)) {
    return {verdict->within, SeparationStage::bounded_doubles, verdict->earliest};
  }
  const auto t = exactly_within(x, delta, N, exact, width.has_value());
  if (!t) return {false, SeparationStage::exact_roots, std::nullopt};
  return {true, SeparationStage::exact_roots,
          width ? std::optional<TimeInterval>(bracket_of(*t, *width)) : std::nullopt};
}

}  // namespace

bool separation_apart(const VertexFaceQuery& query, double delta) noexcept {
  return apart<kVertexFaceFeatures>(query, delta, 1);
}

bool separation_apart(const EdgeEdgeQuery& query, double delta) noexcept {
  return apart<kEdgeEdgeFeatures>(query, delta, 2);
}

SeparationVerdict separation_within(const VertexFaceQuery& query, double delta,
                                    std::optional<double> width) noexcept {
  return within<kVertexFaceFeatures>(
      query, delta, width,
      [](std::size_t i, const auto& m, const BoundedDouble& d2) {
        return vertex_face_feature(i, m, d2);
      },
      [](std::size_t i, const auto& m, const mpq_class& d2) {
        return vertex_face_feature(i, m, d2);
      });
}

SeparationVerdict separation_within(const EdgeEdgeQuery& query, double delta,
                                    std::optional<double> width) noexcept {
  return within<kEdgeEdgeFeatures>(
      query, delta, width,
      [](std::size_t i, const auto& m, const BoundedDouble& d2) {
        return edge_edge_feature(i, m, d2);
      },
      [](std::size_t i, const auto& m, const mpq_class& d2) {
        return edge_edge_feature(i, m, d2);
      });
}

}  // namespace exactgeo::ccd::internal
