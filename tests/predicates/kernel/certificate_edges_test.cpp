// The certificates of the sign stages tested at their edge, not only where signs are easy:
//
//  * every formula's semi-static filter bound, on near-degenerate inputs that are rounded
//    differences (so the evaluation really rounds), at scales across the filter's guard (by
//    factors that are not powers of two), and with magnitudes that differ between the
//    groups a bound multiplies (axes, vectors);
//  * the static det3 bound of one ray (StaticDet3Signs), with corners far smaller or far
//    larger than the ray direction, the part of the bound a careless analysis drops.
//
// For each: whenever the bound certifies, the sign must be the exact one; the largest
// observed error as a fraction of the bound is printed and must not exceed 1. A bound
// weakened by a factor r would be caught by these inputs only where that fraction exceeds
// r; docs/predicates.md records the figures ("How tight the bounds are").

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>

#include "exactgeo/predicates/kernel/exact_stages.hpp"
#include "exactgeo/predicates/kernel/filter.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::kernel {
namespace {

using testing::Rng;

/// A positive factor 2^k (1 + f), f uniform in [0, 1): multiplying by it rounds.
double rounded_scale(Rng& rng, int k) {
  return std::ldexp(testing::uniform(rng, 1.0, 2.0), k);
}

/// What a family of inputs showed about one bound.
struct Edge {
  double worst = 0;    ///< largest |fl(value) - value| / bound
  int certified = 0;   ///< signs the bound certified
  int near_bound = 0;  ///< certified with |fl(value)| < 8 bound: the edge was reached
  int checked = 0;     ///< inputs within the guard

  void print(const char* name) const {
    std::printf(
        "[ info     ] %-34s worst error / bound %.3g over %d inputs (%d certified, %d "
        "within 8x of the bound)\n",
        name, worst, checked, certified, near_bound);
  }
};

/// |approx - exact| / bound, in rationals (the bound is a double, exact as given).
double error_ratio(double approx, const mpq_class& exact, double bound) {
  const mpq_class error = abs(mpq_class(approx) - exact);
  return mpq_class(error / mpq_class(bound)).get_d();
}

/// One input set through one formula's filter, as the exact policy uses it: the certified
/// sign must be the exact sign, and the error must stay within the bound.
template <class Formula, Grouping grouping, std::size_t N>
void check_filter(const Offsets<N>& in, int parameter, Edge& edge) {
  constexpr auto& constant = kFilterConstant<Formula, grouping>;
  const auto x = filter_inputs<Formula>(in, parameter);
  const double value = Formula::evaluate(x, parameter);
  const auto maxima = group_maxima<grouping>(x, parameter);
  double bound = constant.epsilon;
  for (std::size_t g = 0; g < maxima.size(); ++g) {
    if (!(maxima[g] >= constant.guard_low && maxima[g] <= constant.guard_high)) return;
    bound *= std::pow(maxima[g], constant.degree[g]);
  }
  ++edge.checked;
  const mpq_class exact = Formula::evaluate(rational_vectors(in), parameter).value();
  const Sign exact_sign = sign_of(static_cast<double>(sgn(exact)));
  const double ratio = error_ratio(value, exact, bound);
  edge.worst = std::max(edge.worst, ratio);
  ASSERT_LE(ratio, 1.0) << "the filter's error bound does not hold";
  if (const auto f = internal::evaluate_filter<Formula, grouping>(in, parameter); f.certified) {
    ++edge.certified;
    if (std::fabs(value) < 8 * bound) ++edge.near_bound;
    ASSERT_EQ(sign_of(f.value), exact_sign) << "a certified sign is wrong";
  }
}

/// Vectors that own their points: vector v is heads[v] - tails[v], so every input is a
/// rounded difference.
template <std::size_t N>
struct Inputs {
  std::array<Point3, N> heads{};
  std::array<Point3, N> tails{};

  Offsets<N> offsets() const {
    return [&]<std::size_t... v>(std::index_sequence<v...>) {
      return Offsets<N>{Offset::between(tails[v], heads[v])...};
    }
    (std::make_index_sequence<N>{});
  }
};

/// A relative perturbation 2^-k (k uniform in [20, 60]) with a random sign: enough to move a
/// nearly vanishing value anywhere from far below a filter's bound to far above it.
double nudge(Rng& rng) {
  const double size = std::ldexp(1.0, -testing::uniform_int(rng, 20, 60));
  return testing::uniform_int(rng, 0, 1) == 0 ? size : -size;
}

/// Near-degenerate vectors: the last one nearly an affine combination of the others
/// (coefficients summing to 1), which makes det3 and cross2 of the vectors and the volumes
/// and normals of the points nearly vanish; for `orthogonal`, the second one nearly
/// orthogonal to the first (dot3). Each coordinate of the last vector is then nudged.
template <std::size_t N>
std::array<Vector3, N> near_degenerate_vectors(Rng& rng, bool orthogonal) {
  std::array<Vector3, N> v{};
  for (std::size_t k = 0; k + 1 < N; ++k)
    v[k] = testing::random_point(rng, 1.0);
  if (orthogonal) {
    const Vector3 r = testing::random_point(rng, 1.0);
    v[N - 1] = {v[0][1] * r[2] - v[0][2] * r[1], v[0][2] * r[0] - v[0][0] * r[2],
                v[0][0] * r[1] - v[0][1] * r[0]};
  } else {
    std::array<double, N> w{};
    double total = 0;
    for (std::size_t k = 0; k + 2 < N; ++k) {
      w[k] = testing::uniform(rng, -1, 1);
      total += w[k];
    }
    w[N - 2] = 1 - total;
    for (int a = 0; a < 3; ++a) {
      for (std::size_t k = 0; k + 1 < N; ++k)
        v[N - 1][a] += w[k] * v[k][a];
    }
  }
  for (double& x : v[N - 1])
    x *= 1 + nudge(rng);
  return v;
}

/// The vectors as rounded differences of points a few times their size away from the
/// origin, at a random scale within 2^+-max_exponent, each axis (or each vector) scaled
/// again by up to 2^+-spread so that the group maxima differ.
template <std::size_t N>
Inputs<N> as_differences(Rng& rng, const std::array<Vector3, N>& v, int max_exponent, int spread,
                         bool per_axis) {
  Inputs<N> in;
  const double scale = rounded_scale(rng, testing::uniform_int(rng, -max_exponent, max_exponent));
  std::array<double, 3> axis_scale{1, 1, 1};
  std::array<double, N> vector_scale{};
  vector_scale.fill(1.0);
  if (per_axis) {
    for (double& s : axis_scale)
      s = rounded_scale(rng, testing::uniform_int(rng, -spread, spread));
  } else {
    for (double& s : vector_scale)
      s = rounded_scale(rng, testing::uniform_int(rng, -spread, spread));
  }
  for (std::size_t k = 0; k < N; ++k) {
    const Point3 tail = testing::random_point(rng, 4.0);
    for (int a = 0; a < 3; ++a) {
      const double s = scale * axis_scale[a] * vector_scale[k];
      in.tails[k][a] = tail[a] * s;
      in.heads[k][a] = (tail[a] + v[k][a]) * s;
    }
  }
  return in;
}

/// Phi's inputs: the corners of a skew patch relative to an origin that lies nearly on the
/// patch (p(u, v) in double, nudged), so that phi nearly vanishes.
Inputs<4> near_patch(Rng& rng, int max_exponent) {
  std::array<Point3, 4> x;
  for (Point3& p : x)
    p = testing::random_point(rng, 1.0);
  const double u = testing::uniform(rng, 0, 1), w = testing::uniform(rng, 0, 1);
  Point3 o;
  for (int a = 0; a < 3; ++a) {
    // Tensor order: x0 = p00, x1 = p10, x2 = p01, x3 = p11.
    o[a] = (1 - u) * (1 - w) * x[0][a] + u * (1 - w) * x[1][a] + (1 - u) * w * x[2][a] +
           u * w * x[3][a];
    o[a] *= 1 + nudge(rng);
  }
  const double scale = rounded_scale(rng, testing::uniform_int(rng, -max_exponent, max_exponent));
  Inputs<4> in;
  for (std::size_t k = 0; k < 4; ++k) {
    for (int a = 0; a < 3; ++a) {
      in.heads[k][a] = x[k][a] * scale;
      in.tails[k][a] = o[a] * scale;
    }
  }
  return in;
}

template <class Formula, Grouping grouping>
Edge filter_edge(const char* stream, int max_exponent, int parameters) {
  constexpr std::size_t N = Formula::kVectors;
  Rng rng = testing::seeded_engine(stream);
  Edge edge;
  for (int trial = 0; trial < 6000; ++trial) {
    const int spread = trial % 3 == 0 ? 0 : 30;
    const bool per_axis = grouping != Grouping::by_vector;
    Inputs<N> in;
    if constexpr (std::is_same_v<Formula, PhiFormula>) {
      in = near_patch(rng, max_exponent);
    } else {
      const bool orthogonal = std::is_same_v<Formula, Dot3Formula>;
      in = as_differences<N>(rng, near_degenerate_vectors<N>(rng, orthogonal), max_exponent, spread,
                             per_axis);
    }
    check_filter<Formula, grouping>(in.offsets(), trial % parameters, edge);
    if (::testing::Test::HasFatalFailure()) {
      ADD_FAILURE() << stream << ": trial " << trial;
      return edge;
    }
  }
  edge.print(stream);
  return edge;
}

// The guard exponents: 242 (degree 3), 484 (degree 2), 96 (phi, degree 6). Scales stay
// well inside them, so that spreads keep most inputs in the guard.
TEST(CertificateEdges, Det3ByAxisFilter) {
  const Edge e = filter_edge<Det3Formula, Grouping::by_axis>("edges.det3_by_axis", 180, 1);
  EXPECT_GT(e.near_bound, 50);
}
TEST(CertificateEdges, Det3ByVectorFilter) {
  const Edge e = filter_edge<Det3Formula, Grouping::by_vector>("edges.det3_by_vector", 180, 1);
  EXPECT_GT(e.near_bound, 50);
}
TEST(CertificateEdges, Cross2Filter) {
  const Edge e = filter_edge<Cross2Formula, Grouping::by_vector>("edges.cross2", 400, 3);
  EXPECT_GT(e.near_bound, 50);
}
TEST(CertificateEdges, Dot3Filter) {
  const Edge e = filter_edge<Dot3Formula, Grouping::by_vector>("edges.dot3", 400, 1);
  EXPECT_GT(e.near_bound, 50);
}
TEST(CertificateEdges, TetrahedronVolumeFilter) {
  const Edge e =
      filter_edge<TetrahedronVolumeFormula, Grouping::by_axis>("edges.tetrahedron", 180, 1);
  EXPECT_GT(e.near_bound, 50);
}
TEST(CertificateEdges, TriangleNormalFilter) {
  const Edge e = filter_edge<TriangleNormalFormula, Grouping::by_projected_axis>(
      "edges.triangle_normal", 400, 3);
  EXPECT_GT(e.near_bound, 50);
}
TEST(CertificateEdges, PhiFilter) {
  const Edge e = filter_edge<PhiFormula, Grouping::by_axis>("edges.phi", 60, 1);
  EXPECT_GT(e.near_bound, 50);
}

/// cross2 where its rounding is worst with the exact value on the other side of zero. For
/// a = (a1, a2), b = (b1, b2), every input just off a midpoint between two doubles near 1
/// (1 + n 2^-52 + 2^-53, nudged by 2^-105), so each rounds by half an ulp in a chosen
/// direction: a1 and b2 up, a2 and b1 down. With n(a1) + n(b2) = n(a2) + n(b1) and the
/// first pair further apart, a1 b2 - a2 b1 is negative (about -d^2 2^-104), while the
/// rounded inputs give exactly +2^-51: half the bound, with the wrong sign. A bound
/// weakened to a quarter certifies it; the true one must not.
TEST(CertificateEdges, Cross2RoundingAgainstTheSign) {
  Rng rng = testing::seeded_engine("edges.cross2_against_the_sign");
  Edge edge;
  constexpr double kUlp = 0x1p-52;
  for (int trial = 0; trial < 4000; ++trial) {
    const int c = testing::uniform_int(rng, 1, 1 << 20);
    const int d = testing::uniform_int(rng, 1, c);
    const int k = testing::uniform_int(rng, -400, 400);  // exact scaling: within the guard
    // (n, rounds up): a1 = c - d up, b2 = c + d up, a2 = c down, b1 = c down.
    const std::array<std::pair<int, bool>, 4> inputs{
        {{c - d, true}, {c, false}, {c, false}, {c + d, true}}};  // a1, a2, b1, b2
    Inputs<2> in;
    for (int i = 0; i < 4; ++i) {
      const auto [n, up] = inputs[static_cast<std::size_t>(i)];
      const std::size_t vector = static_cast<std::size_t>(i / 2);
      const int axis = i % 2;
      in.heads[vector][axis] = std::ldexp(1 + n * kUlp, k);
      in.tails[vector][axis] = std::ldexp(-(0x1p-53 + (up ? 0x1p-105 : -0x1p-105)), k);
    }
    check_filter<Cross2Formula, Grouping::by_vector>(in.offsets(), 2, edge);
    if (::testing::Test::HasFatalFailure()) {
      ADD_FAILURE() << "trial " << trial << ": c " << c << ", d " << d << ", 2^" << k;
      return;
    }
  }
  edge.print("cross2 rounding against the sign");
  EXPECT_GT(edge.worst, 0.45);  // the rounding is as bad as designed: half the bound
}

/// The static det3 bound of one ray: every det3 sign of a ray test is on corners and the
/// direction, and one bound serves them all. Corners here are 2^-60 to 2^20 times the
/// size of the direction's components (which reach 66 for ray 63), with det[c0, c1, d]
/// nearly zero for the by-vector bound and det[c0, c1, c2] nearly zero for the by-axis one.
TEST(CertificateEdges, StaticDet3BoundCoversCornersAndDirectionOfAnySize) {
  Rng rng = testing::seeded_engine("edges.static_det3");
  Edge by_vector, by_axis;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vector3 d = ray_direction(static_cast<std::size_t>(testing::uniform_int(rng, 0, 63)));
    const double size = rounded_scale(rng, testing::uniform_int(rng, -60, 20));
    std::array<Point3, 4> c;
    c[0] = testing::random_point(rng, size);
    // c1 nearly in the plane of c0 and d; c2 nearly in the plane of c0 and c1.
    const double s = testing::uniform(rng, -1, 1);
    const double t = testing::uniform(rng, -1, 1) * size;
    const double p = testing::uniform(rng, -1, 1);
    const double q = testing::uniform(rng, -1, 1);
    for (int a = 0; a < 3; ++a) {
      c[1][a] = (s * c[0][a] + t * d[a]) * (1 + nudge(rng));
      c[2][a] = (p * c[0][a] + q * c[1][a]) * (1 + nudge(rng));
    }
    c[3] = testing::random_point(rng, size);
    const Offsets<4> corners{Offset::vector(c[0]), Offset::vector(c[1]), Offset::vector(c[2]),
                             Offset::vector(c[3])};
    const Det3Bounds bounds = det3_bounds(corners, d);
    const StaticDet3Signs signs(ExactSigns{}, bounds);
    const Offset direction = Offset::vector(d);

    auto check = [&](const Offset& x, const Offset& y, const Offset& z, double bound, Edge& edge,
                     bool vector_grouping) {
      if (!std::isfinite(bound)) return;
      ++edge.checked;
      const Vec3<double> rx = x.rounded(), ry = y.rounded(), rz = z.rounded();
      const double value = det3(rx, ry, rz);
      const auto q3 = rational_vectors(Offsets<3>{x, y, z});
      const mpq_class exact = det3(q3[0], q3[1], q3[2]).value();
      const double ratio = error_ratio(value, exact, bound);
      edge.worst = std::max(edge.worst, ratio);
      ASSERT_LE(ratio, 1.0) << "trial " << trial << ": the static bound does not hold";
      const Sign expected = sign_of(static_cast<double>(sgn(exact)));
      const Sign got =
          vector_grouping ? signs.det3_by_vector(x, y, z) : signs.det3_by_axis(x, y, z);
      ASSERT_EQ(got, expected) << "trial " << trial;
      if (std::fabs(value) > bound) {
        ++edge.certified;
        if (std::fabs(value) < 8 * bound) ++edge.near_bound;
      }
    };
    check(corners[0], corners[1], direction, bounds.by_vector, by_vector, true);
    check(corners[0], corners[1], corners[2], bounds.by_axis, by_axis, false);
    if (::testing::Test::HasFatalFailure()) return;
  }
  by_vector.print("static det3 bound, by vector");
  by_axis.print("static det3 bound, by axis");
  EXPECT_GT(by_vector.near_bound, 100);
  EXPECT_GT(by_axis.near_bound, 100);
}

}  // namespace
}  // namespace exactgeo::kernel
