#pragma once

// Transformations of CCD queries that must not change any answer (the symmetry tests of
// every CCD method), and random queries on a small dyadic grid where degenerate
// configurations are common.

#include <array>
#include <utility>

#include "exactgeo/ccd/queries.hpp"
#include "support/generators.hpp"

namespace exactgeo::ccd {

inline std::array<Point3*, 8> points(VertexFaceQuery& q) {
  return {&q.v_t0, &q.f0_t0, &q.f1_t0, &q.f2_t0, &q.v_t1, &q.f0_t1, &q.f1_t1, &q.f2_t1};
}
inline std::array<Point3*, 8> points(EdgeEdgeQuery& q) {
  return {&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0, &q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1};
}

template <class Query>
Query mapped(Query q, auto&& f) {
  for (Point3* p : points(q))
    *p = f(*p);
  return q;
}

template <class Query>
Query random_dyadic_query(testing::Rng& rng) {
  Query q;
  for (Point3* p : points(q))
    *p = testing::integer_point(rng, 2);
  return q;
}

/// A grid query moved by a random non-dyadic offset and scaled by 2^k, |k| <= max_exponent:
/// the rounding of the moved points breaks the grid's exact degeneracies by about an ulp,
/// and every product of their differences rounds. Where filters must hand over to exact
/// arithmetic, and where a certificate's error bound is tested hardest.
template <class Query>
Query near_degenerate_query(testing::Rng& rng, int max_exponent = 700) {
  const Point3 offset = testing::random_point(rng, 4.0);
  const int k = testing::uniform_int(rng, -max_exponent, max_exponent);
  return mapped(random_dyadic_query<Query>(rng), [&](const Point3& x) {
    return testing::scaled({x[0] + offset[0], x[1] + offset[1], x[2] + offset[2]}, k);
  });
}

/// Query `i` of a mix that certificates must survive, from a grid query: as it is (often
/// exactly degenerate), one point one ulp off the grid, exactly scaled by 2^k with |k| in
/// [200, 1000], moved off the grid by random amounts (generic), or near-degenerate.
template <class Query>
Query varied_query(testing::Rng& rng, int i) {
  if (i % 5 == 4) return near_degenerate_query<Query>(rng);
  Query q = random_dyadic_query<Query>(rng);
  switch (i % 5) {
    case 0:
      break;
    case 1: {
      Point3* p = points(q)[testing::uniform_int(rng, 0, 7)];
      *p = testing::ulp_step(*p, testing::uniform_int(rng, 0, 2),
                             testing::uniform_int(rng, 0, 1) * 2 - 1);
      break;
    }
    case 2: {
      const int magnitude = testing::uniform_int(rng, 200, 1000);
      const int k = testing::uniform_int(rng, 0, 1) == 0 ? magnitude : -magnitude;
      q = mapped(q, [k](const Point3& x) { return testing::scaled(x, k); });
      break;
    }
    default:
      q = mapped(q, [&](const Point3& x) {
        return Point3{x[0] + testing::uniform(rng, -0.5, 0.5),
                      x[1] + testing::uniform(rng, -0.5, 0.5),
                      x[2] + testing::uniform(rng, -0.5, 0.5)};
      });
      break;
  }
  return q;
}

template <class Query>
Query time_reversed(Query q) {
  auto p = points(q);
  for (int i = 0; i < 4; ++i)
    std::swap(*p[i], *p[i + 4]);
  return q;
}

}  // namespace exactgeo::ccd
