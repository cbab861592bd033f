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

template <class Query>
Query time_reversed(Query q) {
  auto p = points(q);
  for (int i = 0; i < 4; ++i)
    std::swap(*p[i], *p[i + 4]);
  return q;
}

}  // namespace exactgeo::ccd
