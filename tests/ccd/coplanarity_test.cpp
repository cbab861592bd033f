// The coplanarity certificate (internal/coplanarity.hpp): whenever it says the cubic has no
// zero on a piece of the step, the exact cubic, built here in GMP rationals and checked
// with Sturm sequences, has none there; whenever it says the cubic changes sign, the exact
// values at the piece's ends have opposite signs. Pieces are reached by the certificate's
// own midpoint splits along random paths, down to depth 48, on data, random dyadic-grid
// queries (often exactly degenerate), the same one ulp away, and extreme magnitudes.

#include "exactgeo/ccd/internal/coplanarity.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <vector>

#include "ccd/query_transforms.hpp"
#include "cli/ccd_queries.hpp"
#include "exactgeo/ccd/internal/boundary_image.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

namespace fs = std::filesystem;
using testing::Rng;

/// A polynomial in t with rational coefficients, lowest degree first.
using Polynomial = std::vector<mpq_class>;

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  Polynomial r(a.size() + b.size() - 1, mpq_class(0));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j)
      r[i + j] += a[i] * b[j];
  }
  return r;
}

Polynomial operator+(Polynomial a, const Polynomial& b) {
  if (a.size() < b.size()) a.resize(b.size(), mpq_class(0));
  for (std::size_t i = 0; i < b.size(); ++i)
    a[i] += b[i];
  return a;
}

Polynomial operator-(const Polynomial& a) {
  Polynomial r = a;
  for (mpq_class& c : r)
    c = -c;
  return r;
}

void trim(Polynomial& p) {
  while (!p.empty() && p.back() == 0)
    p.pop_back();
}

mpq_class evaluate(const Polynomial& p, const mpq_class& t) {
  mpq_class value = 0;
  for (std::size_t i = p.size(); i-- > 0;)
    value = value * t + p[i];
  return value;
}

/// The remainder of a divided by b (b nonzero, trimmed).
Polynomial remainder(Polynomial a, const Polynomial& b) {
  trim(a);
  while (a.size() >= b.size() && !a.empty()) {
    const mpq_class factor = a.back() / b.back();
    const std::size_t shift = a.size() - b.size();
    for (std::size_t i = 0; i < b.size(); ++i)
      a[shift + i] -= factor * b[i];
    trim(a);
  }
  return a;
}

/// Whether the nonzero polynomial p has a root in the closed interval [a, b] (Sturm).
bool has_root_in(Polynomial p, const mpq_class& a, const mpq_class& b) {
  trim(p);
  if (evaluate(p, a) == 0 || evaluate(p, b) == 0) return true;
  std::vector<Polynomial> sequence{p};
  Polynomial derivative;
  for (std::size_t i = 1; i < p.size(); ++i)
    derivative.push_back(p[i] * static_cast<long>(i));
  trim(derivative);
  if (!derivative.empty()) sequence.push_back(derivative);
  while (sequence.size() >= 2 && !sequence.back().empty()) {
    Polynomial next = -remainder(sequence[sequence.size() - 2], sequence.back());
    trim(next);
    if (next.empty()) break;
    sequence.push_back(next);
  }
  auto variations = [&](const mpq_class& t) {
    int count = 0;
    int previous = 0;
    for (const Polynomial& q : sequence) {
      const int s = sgn(evaluate(q, t));
      if (s == 0) continue;
      if (previous != 0 && s != previous) ++count;
      previous = s;
    }
    return count;
  };
  return variations(a) - variations(b) > 0;
}

/// A point's coordinate along the step, (1 - t) x0 + t x1, as a polynomial.
Polynomial moving(double x0, double x1) {
  return {mpq_class(x0), mpq_class(x1) - mpq_class(x0)};
}

using MovingVector = std::array<Polynomial, 3>;

MovingVector difference(const Point3& to_t0, const Point3& to_t1, const Point3& from_t0,
                        const Point3& from_t1) {
  MovingVector r;
  for (int k = 0; k < 3; ++k)
    r[k] = moving(to_t0[k], to_t1[k]) + -moving(from_t0[k], from_t1[k]);
  return r;
}

Polynomial det3(const MovingVector& a, const MovingVector& b, const MovingVector& c) {
  return a[0] * (b[1] * c[2] + -(b[2] * c[1])) + a[1] * (b[2] * c[0] + -(b[0] * c[2])) +
         a[2] * (b[0] * c[1] + -(b[1] * c[0]));
}

/// The coplanarity cubic, straight from its definition: vertex-face det[v - f0, v - f1,
/// v - f2]; edge-edge det[a0 - b0, a0 - b1, a1 - b0].
Polynomial coplanarity_oracle(const VertexFaceQuery& q) {
  return det3(difference(q.v_t0, q.v_t1, q.f0_t0, q.f0_t1),
              difference(q.v_t0, q.v_t1, q.f1_t0, q.f1_t1),
              difference(q.v_t0, q.v_t1, q.f2_t0, q.f2_t1));
}
Polynomial coplanarity_oracle(const EdgeEdgeQuery& q) {
  return det3(difference(q.ea0_t0, q.ea0_t1, q.eb0_t0, q.eb0_t1),
              difference(q.ea0_t0, q.ea0_t1, q.eb1_t0, q.eb1_t1),
              difference(q.ea1_t0, q.ea1_t1, q.eb0_t0, q.eb0_t1));
}

struct Tally {
  int pieces = 0;
  int proven_nonzero = 0;
  int sign_changes = 0;
};

/// Walks `paths` random split paths of the query's step and checks every claim made.
template <class Query>
void check_claims(const Query& q, Rng& rng, int paths, Tally& tally) {
  const auto image = internal::boundary_image(q);
  const auto certificate = internal::Coplanarity::of(image.corners);
  if (!certificate) return;
  Polynomial p = coplanarity_oracle(q);
  trim(p);
  for (int path = 0; path < paths; ++path) {
    internal::CoplanarityCoefficients b = certificate->whole_step();
    mpq_class start = 0;
    mpq_class end = 1;
    const int depth = testing::uniform_int(rng, 0, 48);
    for (int d = 0;; ++d) {
      ++tally.pieces;
      if (certificate->nonzero(b)) {
        ++tally.proven_nonzero;
        ASSERT_FALSE(p.empty() || has_root_in(p, start, end))
            << "claimed no zero on [" << start << ", " << end << "]";
      }
      if (certificate->changes_sign(b)) {
        ++tally.sign_changes;
        ASSERT_FALSE(p.empty());
        ASSERT_LT(sgn(evaluate(p, start)) * sgn(evaluate(p, end)), 0)
            << "claimed a sign change on [" << start << ", " << end << "]";
      }
      if (d == depth) break;
      const auto [left, right] = internal::split_coefficients(b);
      const mpq_class middle = (start + end) / 2;
      if (testing::uniform_int(rng, 0, 1) == 0) {
        b = left;
        end = middle;
      } else {
        b = right;
        start = middle;
      }
    }
  }
}

TEST(Coplanarity, ClaimsHoldOnTheBundledData) {
  Rng rng = testing::seeded_engine("Coplanarity.Data");
  Tally tally;
  for (const cli::QueryFile& file :
       cli::read_query_files({(fs::path(EXACTGEO_TEST_DATA_DIR) / "ccd").string()})) {
    for (const cli::CcdRecord& record : file.records) {
      if (file.type == cli::QueryType::edge_edge) {
        check_claims(cli::edge_edge_query(record), rng, 4, tally);
      } else {
        check_claims(cli::vertex_face_query(record), rng, 4, tally);
      }
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  std::printf("data: %d pieces, %d proven free of coplanarity, %d sign changes\n", tally.pieces,
              tally.proven_nonzero, tally.sign_changes);
  EXPECT_GT(tally.proven_nonzero, tally.pieces / 10);  // the certificate does work
  EXPECT_GT(tally.sign_changes, 0);
}

template <class Query>
void check_random_queries(const char* stream) {
  Rng rng = testing::seeded_engine(stream);
  Tally tally;
  for (int i = 0; i < 1500; ++i) {
    Query q = random_dyadic_query<Query>(rng);
    switch (i % 4) {
      case 0:  // on the grid: often exactly coplanar at dyadic times, or throughout
        break;
      case 1: {  // one ulp off the grid
        Point3* p = points(q)[testing::uniform_int(rng, 0, 7)];
        *p = testing::ulp_step(*p, testing::uniform_int(rng, 0, 2),
                               testing::uniform_int(rng, 0, 1) * 2 - 1);
        break;
      }
      case 2: {  // extreme magnitudes, exactly scaled
        const int k = testing::uniform_int(rng, 0, 1) == 0 ? testing::uniform_int(rng, 200, 1000)
                                                           : -testing::uniform_int(rng, 200, 1000);
        q = mapped(q, [k](const Point3& x) { return testing::scaled(x, k); });
        break;
      }
      default:  // generic
        q = mapped(q, [&](const Point3& x) {
          return Point3{x[0] + testing::uniform(rng, -0.5, 0.5),
                        x[1] + testing::uniform(rng, -0.5, 0.5),
                        x[2] + testing::uniform(rng, -0.5, 0.5)};
        });
        break;
    }
    check_claims(q, rng, 3, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf("%s: %d pieces, %d proven free of coplanarity, %d sign changes\n", stream,
              tally.pieces, tally.proven_nonzero, tally.sign_changes);
  EXPECT_GT(tally.proven_nonzero, tally.pieces / 10);
  EXPECT_GT(tally.sign_changes, 0);
}

TEST(Coplanarity, ClaimsHoldOnRandomVertexFaceQueries) {
  check_random_queries<VertexFaceQuery>("Coplanarity.VertexFace");
}

TEST(Coplanarity, ClaimsHoldOnRandomEdgeEdgeQueries) {
  check_random_queries<EdgeEdgeQuery>("Coplanarity.EdgeEdge");
}

TEST(Coplanarity, NoCertificateBeyondTheFilterGuard) {
  // Corners near the top of the double range: the products would overflow.
  const VertexFaceQuery q{{0x1p1000, 0, 0}, {0, 0x1p1000, 0}, {0, 0, 0x1p1000}, {1, 1, 1},
                          {0x1p1000, 1, 0}, {0, 0x1p1000, 1}, {1, 0, 0x1p1000}, {2, 1, 1}};
  EXPECT_FALSE(internal::Coplanarity::of(internal::boundary_image(q).corners).has_value());
}

}  // namespace
}  // namespace exactgeo::ccd
