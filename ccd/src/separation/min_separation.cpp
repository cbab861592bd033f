#include "exactgeo/ccd/separation/internal/min_separation.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "exactgeo/ccd/common/internal/closest_direction.hpp"
#include "exactgeo/ccd/separation/internal/bounded_double.hpp"
#include "exactgeo/ccd/separation/internal/exact_roots.hpp"
#include "exactgeo/ccd/separation/internal/features.hpp"
#include "exactgeo/predicates/kernel/power_of_two.hpp"

namespace exactgeo::ccd::internal {

namespace {

template <class Query>
QueryPoints points_of(const Query& q) noexcept {
  static_assert(sizeof(Query) == sizeof(QueryPoints));
  return std::bit_cast<QueryPoints>(q);
}

/// The differences between the two primitives' corners at one time: vertex - face corner
/// (a triangle, H = 3) or a-end - b-end (a parallelogram, H = 4). Every difference of a
/// point of one primitive and a point of the other at that time is a convex combination
/// of them, and over a piece of the step a convex combination of both ends' images.
template <std::size_t H, class T>
std::array<std::array<T, 3>, H> corner_differences(const std::array<std::array<T, 3>, 4>& p) {
  auto minus = [](const std::array<T, 3>& a, const std::array<T, 3>& b) {
    return std::array<T, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  if constexpr (H == 3) {
    return {minus(p[0], p[1]), minus(p[0], p[2]), minus(p[0], p[3])};
  } else {
    return {minus(p[0], p[2]), minus(p[0], p[3]), minus(p[1], p[3]), minus(p[1], p[2])};
  }
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

/// n scaled by the power of two that brings its largest component into [1, 2): any
/// normal serves a separating plane, and this one has n.n in [1, 12), so that an absolute
/// rounding (a product that underflows) is not magnified by n.n. Components far below the
/// largest may round on the way: the rounded vector is the normal used.
Vector3 unit_scaled(const Vector3& n) noexcept {
  int e = 0;
  std::frexp(std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])}), &e);
  const kernel::PowerOfTwo scale(1 - e);  // largest in [2^(e-1), 2^e): to [1, 2)
  return {scale(n[0]), scale(n[1]), scale(n[2])};
}

/// The plane of apart_by_plane over the whole step, in plain doubles with one static
/// bound. u = 2^-53; n is unit_scaled, so 1 <= n.n < 12. Roundings are relative (at most u
/// times the result) except where a product underflows, which loses at most 2^-1075
/// absolutely (sums and differences of doubles are exact in the subnormal range).
/// - The side: the corner differences d = fl(p - q) of input doubles, s = fl(n . d) left
///   to right. With A = fl(|n0 d0| + |n1 d1| + |n2 d2|): |d - (p - q)| <= u |d| per
///   coordinate, and the dot product's rounding is at most 3u / (1 - 3u) times the exact
///   sum of |n_i d_i|, itself below A (1 + 3u), plus 3 2^-1075 from underflowing
///   products; so |s - n.(p - q)| < 4.01 u A + 3 2^-1075, and E = 6u A + 2^-1070 covers
///   it and the rounding of E itself. Then l = fl(s - E) (1 - 2u) is below n.(p - q) (a
///   positive difference rounds up by at most a factor 1 + u), and
///   fl(l l) (1 - 2u) - 2^-1070 below its square.
/// - The margin: fl(δ δ) >= δ^2 (1 - u) - 2^-1075 (the square may underflow: below 2^-537
///   it is 0), fl(n.n) >= n.n (1 - 3u) - 3 2^-1075, and their product rounds by a factor
///   or by 2^-1075 more: fl(fl(δ δ) fl(n.n)) >= δ^2 n.n (1 - 5.01u) - 15 2^-1075 with
///   n.n < 12. So fl(fl(δ δ) nn) (1 + 16u) + 2^-1070 (32 2^-1075), rounded twice more,
///   is above δ^2 n.n.
/// Overflow makes the margin infinite (no proof) or l infinite, which proves the side
/// (l <= n.(p - q), and l^2 is then beyond every double).
template <std::size_t H>
bool apart_by_plane_at_ends(const QueryPoints& x, double delta) noexcept {
  constexpr double u = 0x1p-53, tiny = 0x1p-1070;
  auto corners_at = [&](int time) {
    const std::array<Point3, 4> p{x[4 * time], x[4 * time + 1], x[4 * time + 2], x[4 * time + 3]};
    return corner_differences<H>(p);
  };
  const std::array<Vector3, H> start = corners_at(0), end = corners_at(1);
  const Vector3 closest = closest_direction(start);
  if (!usable(closest)) return false;
  const Vector3 n = unit_scaled(closest);
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
  for (int i = 0; i < f.in_feature_count; ++i) {
    if (all_negative(f.in_feature[i])) return true;
  }
  return false;
}

/// Every condition certainly holds at the piece's start (end = false) or end.
bool holds_at_end(const Feature<BoundedDouble>& f, bool end) noexcept {
  auto at = [end](const Homogeneous<BoundedDouble>& p) { return end ? p.at_end() : p.at_start(); };
  if (!at(f.gap).certainly_nonpositive() || !at(f.weight).certainly_positive()) return false;
  for (int i = 0; i < f.in_feature_count; ++i) {
    if (!at(f.in_feature[i]).certainly_nonnegative()) return false;
  }
  return true;
}

/// A time slice's corner differences (corner_differences) in bounded doubles.
template <std::size_t H>
using Slice = std::array<std::array<BoundedDouble, 3>, H>;

template <std::size_t H>
Slice<H> slice_of(const Positions& p) noexcept {
  return corner_differences<H>(p);
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

/// Test 2. Depth first, left half first: when a piece is taken, every time before its
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

template <std::size_t N, class Query>
bool apart(const Query& query, double delta, int split) noexcept {
  const QueryPoints x = points_of(query);
  if (boxes_apart(x, split, delta)) return true;
  return apart_by_plane_at_ends < N == kVertexFaceFeatures ? 3 : 4 > (x, delta);
}

/// feature_of(i, points, δ^2): feature i, for bounded doubles and for rationals alike.
template <std::size_t N, class Query, class FeatureOf>
SeparationVerdict within(const Query& query, double delta, std::optional<double> width,
                         FeatureOf feature_of) noexcept {
  const QueryPoints x = points_of(query);
  if (const auto verdict = bounded_within<N>(x, delta, width, feature_of)) {
    return {verdict->within, DecidedBy::separation, verdict->earliest};
  }
  const ExactSeparation exact = exact_separation(x, N == kVertexFaceFeatures, delta, width);
  return {exact.within, DecidedBy::separation_roots, exact.earliest};
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
      [](std::size_t i, const auto& m, const auto& d2) { return vertex_face_feature(i, m, d2); });
}

SeparationVerdict separation_within(const EdgeEdgeQuery& query, double delta,
                                    std::optional<double> width) noexcept {
  return within<kEdgeEdgeFeatures>(
      query, delta, width,
      [](std::size_t i, const auto& m, const auto& d2) { return edge_edge_feature(i, m, d2); });
}

}  // namespace exactgeo::ccd::internal
