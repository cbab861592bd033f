// The feature conditions of minimum separation (separation/internal/features.hpp), in GMP
// rationals: the homogeneous Bernstein arithmetic against evaluation; each feature's
// polynomials at fixed times against the quantities computed there directly (squared
// distances, barycentric weights, the lines' closest parameters); and their union against
// the exact static distance of static_distance.hpp (clamped projections): some feature
// holds exactly when the distance is at most δ, with δ at the distance itself and a hair
// either side, on random, exactly degenerate (zero-length edges, collinear triangles,
// parallel edges) and 2^+-1000 queries.

#include "exactgeo/ccd/separation/internal/features.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <type_traits>
#include <vector>

#include "ccd/query_transforms.hpp"
#include "ccd/separation/static_distance.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

using testing::Rng;
using Q = mpq_class;
using H = Homogeneous<Q>;
using Exact3 = std::array<Q, 3>;

/// num / den in lowest terms (GMP works on canonical fractions only).
Q fraction(long num, long den = 1) {
  Q r(num, den);
  r.canonicalize();
  return r;
}

/// p(s) = sum_k c_k (1 - s)^(n - k) s^k.
Q value(const H& p, const Q& s) {
  Q sum = 0;
  for (int k = 0; k <= p.degree; ++k) {
    Q term = p.c[k];
    for (int i = 0; i < p.degree - k; ++i)
      term *= 1 - s;
    for (int i = 0; i < k; ++i)
      term *= s;
    sum += term;
  }
  return sum;
}

H random_homogeneous(Rng& rng, int degree) {
  H p;
  p.degree = degree;
  for (int k = 0; k <= degree; ++k)
    p.c[k] = fraction(testing::uniform_int(rng, -20, 20), testing::uniform_int(rng, 1, 9));
  return p;
}

Q random_time(Rng& rng) {
  switch (testing::uniform_int(rng, 0, 3)) {
    case 0:
      return Q(testing::uniform_int(rng, 0, 1));
    case 1:
      return fraction(testing::uniform_int(rng, 0, 16), 16);
    default:
      return fraction(testing::uniform_int(rng, 0, 1000), 1000) +
             fraction(1, 3 * 1024);  // not dyadic
  }
}

TEST(Features, HomogeneousArithmeticEvaluatesPointwise) {
  Rng rng = testing::seeded_engine("features-homogeneous");
  for (int i = 0; i < 300; ++i) {
    const int da = testing::uniform_int(rng, 0, 3), db = testing::uniform_int(rng, 0, 3);
    const H a = random_homogeneous(rng, da), b = random_homogeneous(rng, db);
    const Q s = fraction(testing::uniform_int(rng, -50, 50), testing::uniform_int(rng, 1, 30));
    const H e = elevated(a, 6);
    ASSERT_EQ(e.degree, 6);
    ASSERT_EQ(value(e, s), value(a, s));
    ASSERT_EQ(value(a + b, s), value(a, s) + value(b, s));
    ASSERT_EQ(value(a - b, s), value(a, s) - value(b, s));
    ASSERT_EQ((a * b).degree, da + db);
    ASSERT_EQ(value(a * b, s), value(a, s) * value(b, s));
    ASSERT_EQ(a.at_start(), value(a, 0));
    ASSERT_EQ(a.at_end(), value(a, 1));
  }
  const H line = H::linear(Q(3), Q(-5));
  EXPECT_EQ(value(line, fraction(1, 4)), Q(1));  // 3 (3/4) - 5 (1/4)
  EXPECT_EQ(H::constant(Q(7)).degree, 0);
  EXPECT_EQ(value(H::constant(Q(7)), fraction(5, 3)), Q(7));
}

// ---------------------------------------------------------------------------------------
// Queries at a fixed time.

/// The four moving points of a query (vertex-face: v, f0, f1, f2; edge-edge: a0, a1, b0,
/// b1) as the exact method builds them, and their positions at time s.
template <class Query>
std::array<Moving<Q>, 4> moving_points(const Query& q) {
  Query copy = q;
  const std::array<Point3*, 8> p = points(copy);
  std::array<Moving<Q>, 4> m;
  for (int k = 0; k < 4; ++k) {
    for (int axis = 0; axis < 3; ++axis)
      m[k][axis] = H::linear(Q((*p[k])[axis]), Q((*p[k + 4])[axis]));
  }
  return m;
}

template <class Query>
std::array<Exact3, 4> positions_at(const Query& q, const Q& s) {
  Query copy = q;
  const std::array<Point3*, 8> p = points(copy);
  std::array<Exact3, 4> x;
  for (int k = 0; k < 4; ++k) {
    for (int axis = 0; axis < 3; ++axis)
      x[k][axis] = (1 - s) * Q((*p[k])[axis]) + s * Q((*p[k + 4])[axis]);
  }
  return x;
}

Exact3 minus(const Exact3& a, const Exact3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Q dot(const Exact3& a, const Exact3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Exact3 cross(const Exact3& a, const Exact3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// A feature's polynomials at s.
struct At {
  Q gap;
  Q weight;
  std::vector<Q> in_feature;
  bool holds() const {
    if (sgn(weight) <= 0 || sgn(gap) > 0) return false;
    for (const Q& x : in_feature) {
      if (sgn(x) < 0) return false;
    }
    return true;
  }
};

At at(const Feature<Q>& f, const Q& s) {
  At a{value(f.gap, s), value(f.weight, s), {}};
  for (int i = 0; i < f.in_feature_count; ++i)
    a.in_feature.push_back(value(f.in_feature[i], s));
  return a;
}

/// Point p against the point a, the segment (a, b), the triangle (a, b, c), computed at
/// the time directly.
void expect_vertex(const At& f, const Exact3& p, const Exact3& a, const Q& d2,
                   const std::string& what) {
  EXPECT_EQ(f.weight, 1) << what;
  EXPECT_TRUE(f.in_feature.empty()) << what;
  EXPECT_EQ(f.gap, dot(minus(p, a), minus(p, a)) - d2) << what;
}

void expect_edge(const At& f, const Exact3& p, const Exact3& a, const Exact3& b, const Q& d2,
                 const std::string& what) {
  const Exact3 e = minus(b, a), w = minus(p, a);
  const Q ee = dot(e, e);
  EXPECT_EQ(f.weight, ee) << what;
  ASSERT_EQ(f.in_feature.size(), 2u) << what;
  // The projection's parameter along the edge, times e.e, and its complement.
  EXPECT_EQ(f.in_feature[0], dot(w, e)) << what;
  EXPECT_EQ(f.in_feature[1], ee - dot(w, e)) << what;
  // e.e times the squared distance to the line: |w x e|^2 (Lagrange).
  const Exact3 n = cross(w, e);
  EXPECT_EQ(f.gap, dot(n, n) - d2 * ee) << what;
  if (sgn(ee) > 0) {
    const Q t = dot(w, e) / ee;
    const Exact3 foot{a[0] + t * e[0], a[1] + t * e[1], a[2] + t * e[2]};
    const Exact3 off = minus(p, foot);
    EXPECT_EQ(f.gap / ee, dot(off, off) - d2) << what << ": the distance to the line";
  }
}

void expect_face(const At& f, const Exact3& p, const Exact3& a, const Exact3& b, const Exact3& c,
                 const Q& d2, const std::string& what) {
  const Exact3 n = cross(minus(b, a), minus(c, a));
  const Q nn = dot(n, n);
  EXPECT_EQ(f.weight, nn) << what;
  ASSERT_EQ(f.in_feature.size(), 3u) << what;
  // n.n times the projection's barycentric coordinates: they sum to n.n.
  EXPECT_EQ(f.in_feature[0] + f.in_feature[1] + f.in_feature[2], nn) << what;
  if (sgn(nn) > 0) {
    // The projection q = p - (n.(p - a) / n.n) n, written in the triangle's frame.
    const Q h = dot(n, minus(p, a)) / nn;
    const Exact3 proj{p[0] - h * n[0], p[1] - h * n[1], p[2] - h * n[2]};
    const Exact3 nab = cross(minus(b, a), minus(proj, a));  // 2 area (a, b, q) times n
    EXPECT_EQ(f.in_feature[0], dot(n, nab)) << what;
    EXPECT_EQ(f.in_feature[1], dot(n, cross(minus(c, b), minus(proj, b)))) << what;
    EXPECT_EQ(f.gap / nn, h * h * nn - d2) << what << ": the squared height";
  } else {
    EXPECT_EQ(f.gap, 0) << what;
  }
}

void expect_segments(const At& f, const Exact3& a0, const Exact3& a1, const Exact3& b0,
                     const Exact3& b1, const Q& d2, const std::string& what) {
  const Exact3 da = minus(a1, a0), db = minus(b1, b0), r = minus(b0, a0);
  const Exact3 w = cross(da, db);
  const Q ww = dot(w, w);
  EXPECT_EQ(f.weight, ww) << what;
  ASSERT_EQ(f.in_feature.size(), 4u) << what;
  if (sgn(ww) > 0) {
    // The lines' closest parameters from the normal equations (Cramer), times w.w:
    // s da.da - u da.db = r.da, s da.db - u db.db = r.db, determinant -(w.w).
    const Q aa = dot(da, da), ab = dot(da, db), bb = dot(db, db);
    const Q det = ab * ab - aa * bb;
    const Q s = (dot(r, db) * ab - dot(r, da) * bb) / det;
    const Q u = (aa * dot(r, db) - ab * dot(r, da)) / det;
    EXPECT_EQ(f.in_feature[0], s * ww) << what;
    EXPECT_EQ(f.in_feature[1], ww - s * ww) << what;
    EXPECT_EQ(f.in_feature[2], u * ww) << what;
    EXPECT_EQ(f.in_feature[3], ww - u * ww) << what;
    // The squared distance of the closest points.
    const Exact3 gap{r[0] + u * db[0] - s * da[0], r[1] + u * db[1] - s * da[1],
                     r[2] + u * db[2] - s * da[2]};
    EXPECT_EQ(f.gap / ww, dot(gap, gap) - d2) << what;
  } else {
    EXPECT_EQ(f.gap, 0) << what;
  }
}

/// All the features of a query, as the exact stage builds them.
std::vector<Feature<Q>> features_of(const VertexFaceQuery& q, const Q& d2) {
  const auto m = moving_points(q);
  std::vector<Feature<Q>> out;
  for (std::size_t i = 0; i < kVertexFaceFeatures; ++i)
    out.push_back(vertex_face_feature(i, m, d2));
  return out;
}

std::vector<Feature<Q>> features_of(const EdgeEdgeQuery& q, const Q& d2) {
  const auto m = moving_points(q);
  std::vector<Feature<Q>> out;
  for (std::size_t i = 0; i < kEdgeEdgeFeatures; ++i)
    out.push_back(edge_edge_feature(i, m, d2));
  return out;
}

/// Feature i at s for δ^2 = d2: from the features built for d2, or from those for δ^2 = 0
/// (every gap is its value at δ = 0 minus δ^2 times the weight; the random tests below
/// check that on every query).
At feature_at(std::size_t i, const Q& s, const Q& d2, const std::vector<Feature<Q>>& built,
              bool built_at_zero) {
  At f = at(built[i], s);
  if (built_at_zero) f.gap -= d2 * f.weight;
  return f;
}

/// Every feature of the query at s against the direct quantities, and the union of their
/// conjunctions against the static distance. Returns whether some feature holds.
bool check_at(const VertexFaceQuery& q, const Q& s, const Q& d2, const std::string& what,
              const std::vector<Feature<Q>>* at_zero = nullptr) {
  const std::vector<Feature<Q>> own = at_zero ? std::vector<Feature<Q>>{} : features_of(q, d2);
  const std::vector<Feature<Q>>& built = at_zero ? *at_zero : own;
  const auto x = positions_at(q, s);
  const auto& [v, f0, f1, f2] = x;
  bool within = false;
  for (std::size_t i = 0; i < kVertexFaceFeatures; ++i) {
    const At f = feature_at(i, s, d2, built, at_zero != nullptr);
    const std::string w = what + " feature " + std::to_string(i);
    switch (i) {
      case 0:
        expect_vertex(f, v, f0, d2, w);
        break;
      case 1:
        expect_vertex(f, v, f1, d2, w);
        break;
      case 2:
        expect_vertex(f, v, f2, d2, w);
        break;
      case 3:
        expect_edge(f, v, f0, f1, d2, w);
        break;
      case 4:
        expect_edge(f, v, f1, f2, d2, w);
        break;
      case 5:
        expect_edge(f, v, f2, f0, d2, w);
        break;
      default:
        expect_face(f, v, f0, f1, f2, d2, w);
        break;
    }
    within = within || f.holds();
  }
  EXPECT_EQ(within, testing::distance2_at(q, s) <= d2) << what;
  return within;
}

bool check_at(const EdgeEdgeQuery& q, const Q& s, const Q& d2, const std::string& what,
              const std::vector<Feature<Q>>* at_zero = nullptr) {
  const std::vector<Feature<Q>> own = at_zero ? std::vector<Feature<Q>>{} : features_of(q, d2);
  const std::vector<Feature<Q>>& built = at_zero ? *at_zero : own;
  const auto x = positions_at(q, s);
  const auto& [a0, a1, b0, b1] = x;
  bool within = false;
  for (std::size_t i = 0; i < kEdgeEdgeFeatures; ++i) {
    const At f = feature_at(i, s, d2, built, at_zero != nullptr);
    const std::string w = what + " feature " + std::to_string(i);
    const std::array<std::array<const Exact3*, 2>, 4> pairs{
        {{&a0, &b0}, {&a0, &b1}, {&a1, &b0}, {&a1, &b1}}};
    if (i < 4) {
      expect_vertex(f, *pairs[i][0], *pairs[i][1], d2, w);
    } else if (i == 4 || i == 5) {
      expect_edge(f, i == 4 ? a0 : a1, b0, b1, d2, w);
    } else if (i == 6 || i == 7) {
      expect_edge(f, i == 6 ? b0 : b1, a0, a1, d2, w);
    } else {
      expect_segments(f, a0, a1, b0, b1, d2, w);
    }
    within = within || f.holds();
  }
  EXPECT_EQ(within, testing::distance2_at(q, s) <= d2) << what;
  return within;
}

/// Queries of the usual mix near magnitude 1, and degenerate ones: vertex-face, a triangle with two
/// corners in one point at the start and collinear ones at the end, or a triangle that is one point
/// throughout; edge-edge, an edge of zero length at the start, or parallel edges.
template <class Query>
Query query_of_kind(Rng& rng, int i) {
  // The mix at magnitude 1 (the extreme magnitudes have their own test below).
  Query q = i % 5 == 2   ? random_dyadic_query<Query>(rng)
            : i % 5 == 4 ? near_degenerate_query<Query>(rng, 0)
                         : varied_query<Query>(rng, i);
  const std::array<Point3*, 8> p = points(q);
  constexpr bool vertex_face = std::is_same_v<Query, VertexFaceQuery>;
  if (i % 7 == 5) {
    *p[3] = *p[2];
    *p[7] = testing::rounded_affine(*p[5], *p[6], *p[6], 2.0, 0.0);  // on the line p5 p6
  } else if (i % 7 == 6 && vertex_face) {
    for (const int t : {0, 4})
      *p[2 + t] = *p[3 + t] = *p[1 + t];
  } else if (i % 7 == 6) {
    const Vector3 d = testing::nonzero_integer_direction(rng, 2);
    for (const int t : {0, 4}) {
      for (const int k : {1, 3})
        *p[k + t] = {(*p[k - 1 + t])[0] + d[0], (*p[k - 1 + t])[1] + d[1],
                     (*p[k - 1 + t])[2] + d[2]};
    }
  }
  return q;
}

template <class Query>
void features_agree_with_the_distance(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  int within = 0, apart = 0;
  for (int i = 0; i < 28; ++i) {
    const Query q = query_of_kind<Query>(rng, i);
    const std::string what = std::string(stream) + " #" + std::to_string(i);
    const std::vector<Feature<Q>> at_zero = features_of(q, Q(0));
    const Q r = fraction(testing::uniform_int(rng, 1, 64), 16);
    const std::vector<Feature<Q>> at_r = features_of(q, r);
    for (int j = 0; j < 3; ++j) {
      const Q s = random_time(rng);
      for (std::size_t k = 0; k < at_zero.size(); ++k) {
        const At zero = at(at_zero[k], s), with_r = at(at_r[k], s);
        ASSERT_EQ(with_r.gap, zero.gap - r * zero.weight) << what << " feature " << k;
        ASSERT_EQ(with_r.weight, zero.weight) << what;
        ASSERT_EQ(with_r.in_feature, zero.in_feature) << what;
      }
      const Q d2 = testing::distance2_at(q, s);
      // At the distance itself (a tangent: must hold), a hair below (must not) and above,
      // and a random δ.
      const Q hair = d2 / Q(mpz_class(1) << 70) + Q(1, mpz_class(1) << 200);
      for (const Q& delta2 : std::vector<Q>{d2, Q(d2 - hair), Q(d2 + hair),
                                            fraction(testing::uniform_int(rng, 0, 40), 16)}) {
        if (sgn(delta2) < 0) continue;
        (check_at(q, s, delta2, what + " at " + s.get_str(), &at_zero) ? within : apart) += 1;
      }
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GT(within, 80);
  EXPECT_GT(apart, 80);
}

TEST(Features, VertexFaceFeaturesAgreeWithTheDistance) {
  features_agree_with_the_distance<VertexFaceQuery>("features-vf");
}

TEST(Features, EdgeEdgeFeaturesAgreeWithTheDistance) {
  features_agree_with_the_distance<EdgeEdgeQuery>("features-ee");
}

/// A zero-area triangle and parallel edges have zero weights where they degenerate: their
/// face and interior features never hold, and the vertices and edges cover them.
TEST(Features, DegenerateFeaturesHaveZeroWeight) {
  const Point3 o{0, 0, 0};
  const VertexFaceQuery collinear{{0.5, 1, 0}, o, {1, 0, 0}, {2, 0, 0},
                                  {0.5, 1, 0}, o, {1, 0, 0}, {2, 0, 0}};
  const auto m = moving_points(collinear);
  for (const Q& s : {Q(0), fraction(1, 3), Q(1)}) {
    EXPECT_EQ(value(vertex_face_feature(6, m, Q(4)).weight, s), 0);
    EXPECT_FALSE(at(vertex_face_feature(6, m, Q(4)), s).holds());
    EXPECT_TRUE(check_at(collinear, s, Q(1), "collinear"));  // distance exactly 1: within
    EXPECT_FALSE(check_at(collinear, s, Q(1) - Q(1, mpz_class(1) << 100), "collinear"));
  }
  const EdgeEdgeQuery parallel{o, {2, 0, 0}, {1, 1, 0}, {3, 1, 0},
                               o, {2, 0, 0}, {1, 1, 1}, {3, 1, 1}};
  const auto e = moving_points(parallel);
  for (const Q& s : {Q(0), fraction(1, 2), Q(1)}) {
    EXPECT_EQ(value(edge_edge_feature(8, e, Q(4)).weight, s), 0);
    EXPECT_FALSE(at(edge_edge_feature(8, e, Q(4)), s).holds());
    const Q d2 = 1 + s * s;  // the edges overlap in x; apart by (0, 1, s)
    EXPECT_TRUE(check_at(parallel, s, d2, "parallel"));
    EXPECT_FALSE(check_at(parallel, s, d2 - Q(1, mpz_class(1) << 100), "parallel"));
  }
}

/// At 2^+-1000, with δ scaled alike, the same features hold as at magnitude 1.
TEST(Features, ExtremeMagnitudesHoldTheSameFeatures) {
  Rng rng = testing::seeded_engine("features-extreme");
  for (int i = 0; i < 6; ++i) {
    const VertexFaceQuery vf = random_dyadic_query<VertexFaceQuery>(rng);
    const EdgeEdgeQuery ee = random_dyadic_query<EdgeEdgeQuery>(rng);
    const Q s = random_time(rng);
    for (const int k : {-1000, 1000}) {
      const Q scale2 = k > 0 ? Q(mpz_class(1) << 2000) : Q(1, mpz_class(1) << 2000);
      const auto big_vf = mapped(vf, [k](const Point3& x) { return testing::scaled(x, k); });
      const auto big_ee = mapped(ee, [k](const Point3& x) { return testing::scaled(x, k); });
      for (const Q& d2 : {testing::distance2_at(vf, s), fraction(1, 4)}) {
        EXPECT_EQ(check_at(big_vf, s, d2 * scale2, "vf 2^" + std::to_string(k)),
                  check_at(vf, s, d2, "vf"));
      }
      for (const Q& d2 : {testing::distance2_at(ee, s), fraction(1, 4)}) {
        EXPECT_EQ(check_at(big_ee, s, d2 * scale2, "ee 2^" + std::to_string(k)),
                  check_at(ee, s, d2, "ee"));
      }
    }
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace exactgeo::ccd::internal
