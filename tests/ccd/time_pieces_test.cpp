// Pieces of the time step (internal/time_pieces.hpp) against GMP: the whole step holds the
// query's corner images exactly, every half holds the exact midpoints of its parent's
// corners, and every piece down a path of splits holds the corner images at its own start
// and end times, each piece up to one power-of-two scale of its own; the rounded corners
// the filter reads are within u of the exact ones; a piece is splittable exactly when its
// midpoint time is a double; extreme magnitudes (2^+-1000) and spans the pieces cannot
// store.

#include "exactgeo/ccd/internal/time_pieces.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "ccd/known_roots.hpp"
#include "ccd/query_transforms.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

using testing::Rng;

/// Exact values are dyadic: they are kept as integers, each a value times 2^kFixed (or
/// times a higher power of two, for products), so that comparisons need no gcd. Two lists
/// of values are compared only up to one power-of-two factor anyway.
constexpr int kFixed = 1200;
using ExactPoint = std::array<mpz_class, 3>;
template <std::size_t C>
using ExactCorners = std::array<ExactPoint, C>;

/// x 2^kFixed, an integer for every double.
mpz_class fixed(double x) {
  if (x == 0.0) return 0;
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m 2^e, m 2^53 an integer
  mpz_class r(std::ldexp(m, 53));
  r <<= static_cast<mp_bitcnt_t>(e - 53 + kFixed);  // e >= -1073
  return r;
}

/// c t 2^kFixed, with the product taken on t's 53-bit significand alone (a shift does the
/// rest: multiplying by the whole of fixed(t) would cost thousands of bits).
mpz_class times(const mpz_class& c, double t) {
  if (t == 0.0) return 0;
  int e = 0;
  const double m = std::frexp(t, &e);
  mpz_class r = c * static_cast<long>(std::ldexp(m, 53));
  r <<= static_cast<mp_bitcnt_t>(e - 53 + kFixed);
  return r;
}

mpz_class exact(const Coordinate& x) {
  mpz_class sum = 0;
  for (int i = 0; i < x.size(); ++i)
    sum += fixed(x.data()[i]);
  return sum;
}

template <std::size_t C>
ExactCorners<C> exact_corners(const TimePiece<C>& p) {
  ExactCorners<C> out;
  for (std::size_t k = 0; k < C; ++k) {
    for (int axis = 0; axis < 3; ++axis)
      out[k][axis] = exact(p.corners[k].exact[axis]);
  }
  return out;
}

/// The corner images of the query at times ta (corners 0 .. C/2 - 1) and tb (the others):
/// c(t) = (1 - t) c(0) + t c(1), from the exact differences of the query's points (times
/// 2^(2 kFixed)).
template <std::size_t C>
ExactCorners<C> images_at(const Offsets<C>& a, double ta, double tb) {
  constexpr std::size_t H = C / 2;
  ExactCorners<C> out;
  for (std::size_t k = 0; k < C; ++k) {
    const double t = k < H ? ta : tb;
    const std::size_t j = k % H;
    for (int axis = 0; axis < 3; ++axis) {
      const mpz_class c0 = fixed(a[j].head(axis)) - fixed(a[j].tail(axis));
      const mpz_class c1 = fixed(a[H + j].head(axis)) - fixed(a[H + j].tail(axis));
      out[k][axis] = (c0 << kFixed) - times(c0, t) + times(c1, t);  // (1 - t) c0 + t c1
    }
  }
  return out;
}

/// |x| without its factors 2.
mpz_class odd_part(const mpz_class& x) {
  mpz_class r = abs(x);
  r >>= static_cast<mp_bitcnt_t>(mpz_scan1(r.get_mpz_t(), 0));
  return r;
}

/// Whether got = s want for one positive power of two s (the piece's own scale) for
/// every corner.
template <std::size_t C>
::testing::AssertionResult equal_up_to_scale(const ExactCorners<C>& got,
                                             const ExactCorners<C>& want) {
  bool first = true;
  long shift = 0;  // got = want 2^shift
  for (std::size_t k = 0; k < C; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      const mpz_class& g = got[k][axis];
      const mpz_class& w = want[k][axis];
      if (sgn(w) == 0 || sgn(g) == 0) {
        if (sgn(g) != sgn(w)) {
          return ::testing::AssertionFailure()
                 << "corner " << k << " axis " << axis << ": zero against nonzero";
        }
        continue;
      }
      if (first) {
        first = false;
        if (sgn(g) != sgn(w) || odd_part(g) != odd_part(w)) {
          return ::testing::AssertionFailure() << "the scale is not a positive power of two";
        }
        shift = static_cast<long>(mpz_scan1(g.get_mpz_t(), 0)) -
                static_cast<long>(mpz_scan1(w.get_mpz_t(), 0));
      } else if (shift >= 0 ? g != mpz_class(w << static_cast<mp_bitcnt_t>(shift))
                            : mpz_class(g << static_cast<mp_bitcnt_t>(-shift)) != w) {
        return ::testing::AssertionFailure()
               << "corner " << k << " axis " << axis << " has another scale than the first";
      }
    }
  }
  return ::testing::AssertionSuccess();
}

/// What a stored piece promises besides its values: rounded corners within u |rounded|
/// of the exact ones when filterable (with the exact one's sign always), components
/// within [2^-32, 2^33) unless scaling them there could take a bit below 2^-1074 (some
/// component is then far below the normal magnitudes, here below 2^-900), never above
/// 2^1000 (a split doubles them), views of its own corners.
template <std::size_t C>
::testing::AssertionResult well_stored(const TimePiece<C>& p) {
  bool all_filterable = true;
  int top = -2000;
  bool at_the_bottom = false;
  for (std::size_t k = 0; k < C; ++k) {
    const ExactVector& v = p.corners[k];
    all_filterable = all_filterable && v.filterable;
    for (int axis = 0; axis < 3; ++axis) {
      const mpz_class x = exact(v.exact[axis]);
      const mpz_class r = fixed(v.rounded[axis]);
      if (sgn(r) != sgn(x)) return ::testing::AssertionFailure() << "rounded with another sign";
      if (v.filterable && mpz_class(abs(r - x) << 53) > abs(r)) {
        return ::testing::AssertionFailure() << "rounded corner " << k << " off by more than u";
      }
      for (int i = 0; i < v.exact[axis].size(); ++i) {
        const double c = v.exact[axis].data()[i];
        top = std::max(top, std::ilogb(c));
        at_the_bottom = at_the_bottom || std::fabs(c) < 0x1p-900;
      }
    }
    const Offset o = p.offsets()[k];
    if (!o.is_exact_vector() || &o.exact_vector() != &v) {
      return ::testing::AssertionFailure() << "offset " << k << " is not a view of the corner";
    }
  }
  if (p.filterable() != all_filterable) return ::testing::AssertionFailure() << "filterable()";
  if (top != -2000 && (top > 1000 || ((top > 32 || top < -32) && !at_the_bottom))) {
    return ::testing::AssertionFailure() << "largest component 2^" << top;
  }
  return ::testing::AssertionSuccess();
}

/// The exact midpoint of two doubles.
mpq_class midpoint(double a, double b) {
  return (mpq_class(a) + mpq_class(b)) / 2;
}

bool is_double(const mpq_class& t) {
  return mpq_class(t.get_d()) == t;
}

/// Down one random path of splits from the whole step (or a given direction), checking
/// both halves at every level against their parent and against the query itself.
/// Returns the depth reached. A half that cannot be stored is a failure unless
/// `refusals` counts them (the walk then ends there).
template <std::size_t C>
int walk_and_check(const Offsets<C>& a, const std::string& what, Rng* rng, int max_depth,
                   std::optional<Half> always = std::nullopt, int* refusals = nullptr) {
  const std::optional<TimePiece<C>> whole = whole_step<C>(a);
  if (!whole) {
    ADD_FAILURE() << what << ": the whole step cannot be stored";
    return -1;
  }
  EXPECT_EQ(whole->t_start, 0.0);
  EXPECT_EQ(whole->t_end, 1.0);
  EXPECT_EQ(whole->depth, 0);
  EXPECT_TRUE(equal_up_to_scale<C>(exact_corners(*whole), images_at<C>(a, 0, 1))) << what;
  EXPECT_TRUE(well_stored(*whole)) << what;
  TimePiece<C> p = *whole;
  constexpr std::size_t H = C / 2;
  while (p.depth < max_depth && splittable(p)) {
    const ExactCorners<C> parent = exact_corners(p);
    const mpq_class mid = midpoint(p.t_start, p.t_end);
    std::array<std::optional<TimePiece<C>>, 2> halves{half(p, Half::left), half(p, Half::right)};
    for (const Half which : {Half::left, Half::right}) {
      const auto& child = halves[which == Half::left ? 0 : 1];
      if (!child) {
        if (refusals) {
          ++*refusals;
        } else {
          ADD_FAILURE() << what << ": a half cannot be stored at depth " << p.depth;
        }
        return p.depth;
      }
      EXPECT_EQ(child->depth, p.depth + 1);
      EXPECT_EQ(mpq_class(which == Half::left ? child->t_end : child->t_start), mid) << what;
      EXPECT_EQ(which == Half::left ? child->t_start : child->t_end,
                which == Half::left ? p.t_start : p.t_end);
      // Against the parent: its start (or end) corners and the exact midpoints, all
      // doubled here (the scale absorbs it).
      ExactCorners<C> want;
      for (std::size_t k = 0; k < H; ++k) {
        for (int axis = 0; axis < 3; ++axis) {
          const mpz_class twice_mid = parent[k][axis] + parent[H + k][axis];
          want[k][axis] = which == Half::left ? mpz_class(2 * parent[k][axis]) : twice_mid;
          want[H + k][axis] = which == Half::left ? twice_mid : mpz_class(2 * parent[H + k][axis]);
        }
      }
      EXPECT_TRUE(equal_up_to_scale<C>(exact_corners(*child), want))
          << what << " depth " << child->depth;
      // Against the query at the child's own times.
      EXPECT_TRUE(equal_up_to_scale<C>(exact_corners(*child),
                                       images_at<C>(a, child->t_start, child->t_end)))
          << what << " depth " << child->depth;
      EXPECT_TRUE(well_stored(*child)) << what << " depth " << child->depth;
    }
    if (::testing::Test::HasFailure()) return p.depth;
    const bool left = always ? *always == Half::left : testing::uniform_int(*rng, 0, 1) == 0;
    p = *halves[left ? 0 : 1];
  }
  return p.depth;
}

TEST(TimePieces, SplittableExactlyWhenTheMidpointTimeIsADouble) {
  Rng rng = testing::seeded_engine("time-pieces-splittable");
  int splittable_pieces = 0, unsplittable = 0;
  auto check = [&](double a, double b) {
    TimePiece<6> p;
    p.t_start = a;
    p.t_end = b;
    const mpq_class mid = midpoint(a, b);
    const bool expected = is_double(mid) && mpq_class(a) < mid && mid < mpq_class(b);
    ASSERT_EQ(splittable(p), expected) << std::hexfloat << a << " " << b;
    (expected ? splittable_pieces : unsplittable) += 1;
  };
  for (int i = 0; i < 4000; ++i) {
    // A dyadic piece of the step at depth d, k 2^-d .. (k + 1) 2^-d, and its neighbours.
    const int d = testing::uniform_int(rng, 0, 1100);
    const double width = std::ldexp(1.0, -std::min(d, 1074));
    const double span = std::ldexp(1.0, std::min(d, 1074)) - 1.0;
    const double k = std::floor(testing::uniform(rng, 0.0, 1.0) * std::min(span, 0x1p52));
    const double start = i % 4 == 0 ? 1.0 - width : k * width;
    check(start, start + width);
    // Pieces one and two doubles wide, anywhere in [0, 1].
    const double t = i % 3 == 0 ? std::ldexp(testing::uniform(rng, 0.0, 1.0), -d)
                                : testing::uniform(rng, 0.0, 1.0);
    const double next = std::nextafter(t, 2.0);
    check(t, next);
    check(t, std::nextafter(next, 2.0));
    if (::testing::Test::HasFatalFailure()) return;
  }
  check(0.0, 0x1p-1074);  // one subnormal spacing: its midpoint is not a double
  check(0.0, 0x1p-1073);
  check(std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0));  // 1 lies between, not at the midpoint
  check(0.5, 1.0);
  EXPECT_GT(splittable_pieces, 1000);
  EXPECT_GT(unsplittable, 1000);
}

template <class Query>
void random_paths(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  for (int i = 0; i < 20; ++i) {
    Query q = varied_query<Query>(rng, i);
    if (i % 6 == 5) {
      // Mixed magnitudes, 2^-500 to 2^500 in one query.
      q = mapped(q, [&](const Point3&) { return testing::random_magnitude_point(rng, -500, 500); });
    }
    // Beyond 52 halvings a coordinate of four far apart doubles may outgrow its capacity,
    // and a query spanning 2000 binades leaves no room to split (below); here every half
    // is stored.
    walk_and_check(corner_images(q), std::string(stream) + " #" + std::to_string(i), &rng, 52);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(TimePieces, RandomVertexFaceSplitPathsAreExact) {
  random_paths<VertexFaceQuery>("time-pieces-vf");
}

TEST(TimePieces, RandomEdgeEdgeSplitPathsAreExact) {
  random_paths<EdgeEdgeQuery>("time-pieces-ee");
}

/// Splitting always to one side goes down to one double spacing: at 0 the subnormal
/// 2^-1074 (depth 1074), at 1 the spacing 2^-53 below it (depth 53). Toward 3/10 the
/// pieces stop at one double spacing there, [3/10 - ..., 3/10 + ...] 2^-54 wide.
TEST(TimePieces, PathsEndAtOneDoubleSpacing) {
  const VertexFaceQuery q = known_roots::falling_vertex();
  const auto a = corner_images(q);
  EXPECT_EQ(walk_and_check<6>(a, "leftmost", nullptr, 2000, Half::left), 1074);
  EXPECT_EQ(walk_and_check<6>(a, "rightmost", nullptr, 2000, Half::right), 53);
  // Toward the root time 3/10: each split keeps the half that holds it.
  std::optional<TimePiece<6>> p = whole_step<6>(a);
  const mpq_class target(3, 10);
  while (p && splittable(*p)) {
    const bool left = target < midpoint(p->t_start, p->t_end);
    p = half(*p, left ? Half::left : Half::right);
  }
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(std::nextafter(p->t_start, 1.0), p->t_end) << "one double spacing";
  EXPECT_LE(mpq_class(p->t_start), target);
  EXPECT_GE(mpq_class(p->t_end), target);
  EXPECT_EQ(p->t_end - p->t_start, 0x1p-54);
  EXPECT_TRUE(equal_up_to_scale<6>(exact_corners(*p), images_at<6>(a, p->t_start, p->t_end)));
}

/// At 2^+-1000 (and at the largest doubles, first scaled by 1/4) the pieces are exact as at
/// magnitude 1; spans wider than the pieces can store are refused, never rounded.
TEST(TimePieces, ExtremeMagnitudesAndSpansTooWide) {
  Rng rng = testing::seeded_engine("time-pieces-extreme");
  for (const int k : {-1000, -600, 600, 1000, 1021}) {
    const VertexFaceQuery vf = mapped(known_roots::falling_vertex(),
                                      [k](const Point3& x) { return testing::scaled(x, k); });
    walk_and_check(corner_images(vf), "falling vertex 2^" + std::to_string(k), &rng, 80);
    const EdgeEdgeQuery ee = mapped(known_roots::through_and_back(),
                                    [k](const Point3& x) { return testing::scaled(x, k); });
    walk_and_check(corner_images(ee), "through and back 2^" + std::to_string(k), &rng, 80);
  }
  // The largest doubles: the differences overflow unless scaled first.
  const double big = std::ldexp(1.5, 1023);
  const VertexFaceQuery huge{{big, -big, 1},  {-big, big, 0.5}, {0, 0, 0}, {1, 0, 0},
                             {-big, big, -1}, {big, -big, 0},   {0, 1, 0}, {1, 1, 1}};
  walk_and_check(corner_images(huge), "largest doubles", &rng, 40);
  // 2^1023 with 2^-1030 in one query: the 1/4 scaling would lose the small one's bits.
  const VertexFaceQuery lost{{0x1p1023, 0, 0}, {0, 0, 0x1p-1030}, {1, 0, 0}, {0, 1, 0},
                             {0x1p1023, 0, 1}, {0, 0, 0},         {1, 0, 0}, {0, 1, 0}};
  EXPECT_FALSE(whole_step<6>(corner_images(lost)).has_value());
  // 2^1021 with 2^-1074: more binades than a stored piece may span.
  const VertexFaceQuery wide{{0x1p1021, 0, 0}, {0, 0, 0x1p-1074}, {1, 0, 0}, {0, 1, 0},
                             {0x1p1021, 0, 1}, {0, 0, 0},         {1, 0, 0}, {0, 1, 0}};
  EXPECT_FALSE(whole_step<6>(corner_images(wide)).has_value());
  // 2^1000 with 2^-1000 fits.
  const VertexFaceQuery fits{{0x1p1000, 0, 0}, {0, 0, 0x1.8p-1000}, {1, 0, 0}, {0, 1, 0},
                             {0x1p1000, 0, 1}, {0, 0, 0},           {1, 0, 0}, {0, 1, 0}};
  walk_and_check(corner_images(fits), "2^1000 with 2^-1000", &rng, 60);
}

/// Coordinates spread over 2^-1000 .. 2^1000, and paths deeper than 52 halvings: a half
/// whose corners need more components than a coordinate holds, or more binades than
/// doubles have, is refused; every piece stored before is exact.
TEST(TimePieces, WhatCannotBeStoredIsRefusedNeverRounded) {
  Rng rng = testing::seeded_engine("time-pieces-refused");
  int refusals = 0;
  for (int i = 0; i < 6; ++i) {
    const EdgeEdgeQuery q = mapped(random_dyadic_query<EdgeEdgeQuery>(rng), [&](const Point3&) {
      return testing::random_magnitude_point(rng, -1000, 1000);
    });
    if (!whole_step<8>(corner_images(q))) {
      ++refusals;
      continue;
    }
    walk_and_check(corner_images(q), "spread #" + std::to_string(i), &rng, 80, std::nullopt,
                   &refusals);
    if (::testing::Test::HasFailure()) return;
  }
  // A vertex from 2^1000 to 1.5 2^-1000: every split adds a bit below the lowest, which
  // pins the piece's scale while the split doubles its top; within 80 halvings the top
  // would pass 2^1000.
  const Point3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0};
  const VertexFaceQuery far_apart{{0x1p1000, 0, 0}, o, x, y, {0x1.8p-1000, 0, 0}, o, x, y};
  int refused_here = 0;
  walk_and_check(corner_images(far_apart), "2^1000 to 2^-1000", nullptr, 80, Half::left,
                 &refused_here);
  EXPECT_EQ(refused_here, 1);
}

}  // namespace
}  // namespace exactgeo::ccd::internal
