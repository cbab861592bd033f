// Self-intersection: face_contact against an oracle written from the rule in GMP
// rationals (triangle pairs: random, one ulp off degenerate, exactly degenerate, at scales
// 2^±500 and subnormal), quad pairs with known answers and the symmetries every answer
// must have, and find_self_intersections against brute force over all pairs on generated
// meshes with planted intersections and planted touching-only contacts (among them
// coplanar faces facing opposite ways: boxes face to face, a sheet folded flat).

#include "exactgeo/mesh/self_intersection.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/mesh/load.hpp"
#include "support/seed.hpp"

namespace exactgeo::mesh {
namespace {

// ---------------------------------------------------------------------------------------
// The oracle: do two triangles intersect by the rule (a point strictly inside both, unless
// they are coplanar and face opposite ways)? Rationals and the definition only.

using Q = mpq_class;
using V = std::array<Q, 3>;
using Triangle = std::array<Point3, 3>;

V exact(const Point3& p) {
  return {Q(p[0]), Q(p[1]), Q(p[2])};
}
V operator-(const V& a, const V& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V operator+(const V& a, const V& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Q dot(const V& a, const V& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool is_zero(const V& a) {
  return a[0] == 0 && a[1] == 0 && a[2] == 0;
}
Q det(const V& r0, const V& r1, const V& r2) {
  return dot(r0, cross(r1, r2));
}

bool degenerate_oracle(const Triangle& t) {
  const V a = exact(t[0]);
  return is_zero(cross(exact(t[1]) - a, exact(t[2]) - a));
}

/// An open interval of reals, ends possibly infinite (nullopt).
struct Interval {
  std::optional<Q> lo, hi;
  bool empty = false;
};

/// {t : P + t d in the open triangle} for a line in the triangle's plane: every
/// barycentric coordinate, an affine function of t, strictly positive.
Interval open_triangle_on_line(const std::array<V, 3>& x, const V& p, const V& d) {
  const V n = cross(x[1] - x[0], x[2] - x[0]);
  Interval in;
  for (int i = 0; i < 3; ++i) {
    const V& u = x[(i + 1) % 3];
    const V& w = x[(i + 2) % 3];
    // lambda_i(y) = ((u - y) x (w - y)) . n / (n . n): the sign is what matters.
    const Q alpha = dot(cross(u - p, w - p), n);
    const V q = p + d;
    const Q beta = dot(cross(u - q, w - q), n) - alpha;
    if (beta == 0) {
      if (alpha <= 0) in.empty = true;
      continue;
    }
    const Q root = -alpha / beta;
    if (beta > 0) {
      if (!in.lo || root > *in.lo) in.lo = root;
    } else {
      if (!in.hi || root < *in.hi) in.hi = root;
    }
  }
  if (in.lo && in.hi && *in.lo >= *in.hi) in.empty = true;
  return in;
}

using Point2 = std::array<Q, 2>;

Q cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/// Sutherland-Hodgman: the part of the polygon on the closed left of the line p -> q.
std::vector<Point2> clip(const std::vector<Point2>& polygon, const Point2& p, const Point2& q) {
  std::vector<Point2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    const Q sa = cross2(p, q, a), sb = cross2(p, q, b);
    if (sa >= 0) out.push_back(a);
    if ((sa > 0 && sb < 0) || (sa < 0 && sb > 0)) {
      const Q t = sa / (sa - sb);
      out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  return out;
}

/// Coplanar triangles: the open triangles meet exactly when the closed ones overlap in
/// positive area (the interior of an intersection of convex bodies is the intersection of
/// their interiors), computed by clipping in a projection that keeps areas nonzero.
bool coplanar_open_triangles_meet(const std::array<V, 3>& a, const std::array<V, 3>& b,
                                  const V& n) {
  const int drop = n[0] != 0 ? 0 : (n[1] != 0 ? 1 : 2);
  const int keep0 = (drop + 1) % 3, keep1 = (drop + 2) % 3;
  const auto flat = [&](const V& v) { return Point2{v[keep0], v[keep1]}; };
  std::vector<Point2> polygon{flat(a[0]), flat(a[1]), flat(a[2])};
  std::array<Point2, 3> clipper{flat(b[0]), flat(b[1]), flat(b[2])};
  if (cross2(clipper[0], clipper[1], clipper[2]) < 0) std::swap(clipper[1], clipper[2]);
  for (int i = 0; i < 3 && !polygon.empty(); ++i)
    polygon = clip(polygon, clipper[i], clipper[(i + 1) % 3]);
  Q area2 = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    area2 += cross2(Point2{0, 0}, polygon[i], polygon[(i + 1) % polygon.size()]);
  return area2 != 0;
}

/// What the oracle finds about a pair.
enum class Truth : std::uint8_t {
  apart,         ///< no point strictly inside both
  intersecting,  ///< a point strictly inside both, and not coplanar facing opposite ways
  sides_touch,   ///< coplanar, open triangles overlapping, normals opposite: not intersecting
};

/// The rule from the definition. Non-degenerate triangles only.
Truth rule_oracle(const Triangle& s, const Triangle& t) {
  const std::array<V, 3> a{exact(s[0]), exact(s[1]), exact(s[2])};
  const std::array<V, 3> b{exact(t[0]), exact(t[1]), exact(t[2])};
  const V na = cross(a[1] - a[0], a[2] - a[0]);
  const V nb = cross(b[1] - b[0], b[2] - b[0]);
  const V d = cross(na, nb);
  if (is_zero(d)) {
    if (dot(na, b[0] - a[0]) != 0) return Truth::apart;  // parallel planes
    if (!coplanar_open_triangles_meet(a, b, na)) return Truth::apart;
    // Parallel normals by corner order: facing opposite ways exactly when na . nb < 0.
    return dot(na, nb) < 0 ? Truth::sides_touch : Truth::intersecting;
  }
  // The planes' common line P + t d: P solves na.x = na.a0, nb.x = nb.b0, d.x = 0 (Cramer).
  const V rhs{dot(na, a[0]), dot(nb, b[0]), Q(0)};
  const Q m = det(na, nb, d);
  V p;
  for (int i = 0; i < 3; ++i) {
    V r0 = na, r1 = nb, r2 = d;
    r0[i] = rhs[0];
    r1[i] = rhs[1];
    r2[i] = rhs[2];
    p[i] = det(r0, r1, r2) / m;
  }
  const Interval ia = open_triangle_on_line(a, p, d);
  const Interval ib = open_triangle_on_line(b, p, d);
  if (ia.empty || ib.empty) return Truth::apart;
  // Open intervals overlap: max(lo) < min(hi).
  std::optional<Q> lo = ia.lo, hi = ia.hi;
  if (ib.lo && (!lo || *ib.lo > *lo)) lo = ib.lo;
  if (ib.hi && (!hi || *ib.hi < *hi)) hi = ib.hi;
  return !lo || !hi || *lo < *hi ? Truth::intersecting : Truth::apart;
}

bool intersect_oracle(const Triangle& s, const Triangle& t) {
  return rule_oracle(s, t) == Truth::intersecting;
}

// ---------------------------------------------------------------------------------------
// Meshes built here.

Mesh two_triangles(const Triangle& s, const Triangle& t) {
  Mesh mesh;
  mesh.vertices = {s[0], s[1], s[2], t[0], t[1], t[2]};
  mesh.faces = {make_triangle(0, 1, 2), make_triangle(3, 4, 5)};
  return mesh;
}

/// The same, with equal points as one vertex (shared indices).
Mesh two_triangles_welded(const Triangle& s, const Triangle& t) {
  Mesh mesh;
  const auto index = [&](const Point3& p) {
    const auto it = std::find(mesh.vertices.begin(), mesh.vertices.end(), p);
    if (it != mesh.vertices.end()) return static_cast<VertexIndex>(it - mesh.vertices.begin());
    mesh.vertices.push_back(p);
    return static_cast<VertexIndex>(mesh.vertices.size() - 1);
  };
  const VertexIndex a = index(s[0]), b = index(s[1]), c = index(s[2]);
  const VertexIndex d = index(t[0]), e = index(t[1]), f = index(t[2]);
  mesh.faces = {make_triangle(a, b, c), make_triangle(d, e, f)};
  return mesh;
}

/// Runs face_contact on the pair (both orders, separate and shared vertices) against the
/// oracle; returns the oracle's answer.
Truth expect_triangles_match_oracle(const Triangle& s, const Triangle& t, const std::string& what) {
  const Truth answer = rule_oracle(s, t);
  const bool truth = answer == Truth::intersecting;
  const FaceContact expected = truth ? FaceContact::intersecting : FaceContact::apart;
  const Mesh separate = two_triangles(s, t);
  const Mesh welded = two_triangles_welded(s, t);
  EXPECT_EQ(face_contact(separate, 0, 1), expected) << what;
  EXPECT_EQ(face_contact(separate, 1, 0), expected) << what;
  EXPECT_EQ(face_contact(welded, 0, 1), expected) << what;
  const SelfIntersections found = find_self_intersections(separate);
  EXPECT_EQ(found.intersecting.size(), truth ? 1u : 0u) << what;
  EXPECT_TRUE(found.undecided.empty()) << what;
  return answer;
}

std::string describe(const Triangle& s, const Triangle& t) {
  std::string text;
  for (const Triangle* tri : {&s, &t}) {
    text += "(";
    for (const Point3& p : *tri) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " [%a %a %a]", p[0], p[1], p[2]);
      text += buf;
    }
    text += " )";
  }
  return text;
}

// ---------------------------------------------------------------------------------------
// Triangle pair generators.

/// Integer lattice points in [-range, range]^3, times 4 (so quarter-weight combinations
/// stay integers): small ranges give every exact degeneracy by chance.
Point3 lattice_point(std::mt19937_64& rng, int range) {
  std::uniform_int_distribution<int> coordinate(-range, range);
  return {4.0 * coordinate(rng), 4.0 * coordinate(rng), 4.0 * coordinate(rng)};
}

/// An affine combination a + s (b - a) + t (c - a) with quarter weights: a point of the
/// triangle's plane, inside, on an edge, at a vertex or outside, exactly.
Point3 in_plane(std::mt19937_64& rng, const Triangle& tri) {
  static constexpr std::array<double, 9> kWeights{-1, -0.5, 0, 0.25, 0.5, 0.75, 1, 1.5, 2};
  std::uniform_int_distribution<std::size_t> pick(0, kWeights.size() - 1);
  const double s = kWeights[pick(rng)], t = kWeights[pick(rng)];
  Point3 p;
  for (std::size_t k = 0; k < 3; ++k)
    p[k] = tri[0][k] + s * (tri[1][k] - tri[0][k]) + t * (tri[2][k] - tri[0][k]);
  return p;
}

/// Exactly degenerate configurations: shared vertices and edges, a vertex or an edge on
/// the other face, coplanar (overlapping, touching, nested, apart), and small-lattice
/// coincidences.
std::pair<Triangle, Triangle> degenerate_pair(std::mt19937_64& rng) {
  const Triangle s{lattice_point(rng, 3), lattice_point(rng, 3), lattice_point(rng, 3)};
  std::uniform_int_distribution<int> kind(0, 5);
  std::uniform_int_distribution<std::size_t> corner(0, 2);
  Triangle t{lattice_point(rng, 3), lattice_point(rng, 3), lattice_point(rng, 3)};
  switch (kind(rng)) {
    case 0:  // one shared vertex
      t[0] = s[corner(rng)];
      break;
    case 1: {  // a shared edge
      const std::size_t i = corner(rng);
      t[0] = s[(i + 1) % 3];
      t[1] = s[i];
      break;
    }
    case 2:  // a vertex in the plane (often on the face)
      t[corner(rng)] = in_plane(rng, s);
      break;
    case 3:  // two vertices in the plane: an edge on the face, or crossing it
      t[0] = in_plane(rng, s);
      t[1] = in_plane(rng, s);
      break;
    case 4:  // coplanar
      t = {in_plane(rng, s), in_plane(rng, s), in_plane(rng, s)};
      break;
    default:  // a tiny lattice: coincidences of every kind
      t = {lattice_point(rng, 1), lattice_point(rng, 1), lattice_point(rng, 1)};
      break;
  }
  return {s, t};
}

/// Moves one coordinate of one vertex of t by one ulp.
void nudge(std::mt19937_64& rng, Triangle& t) {
  std::uniform_int_distribution<std::size_t> pick(0, 2);
  double& x = t[pick(rng)][pick(rng)];
  x = std::nextafter(x, std::bernoulli_distribution(0.5)(rng) ? INFINITY : -INFINITY);
}

void scale(Triangle& t, int exponent) {
  for (Point3& p : t)
    for (double& x : p)
      x = std::ldexp(x, exponent);
}

struct Outcomes {
  int meet = 0;         ///< intersecting
  int apart = 0;        ///< no common interior point
  int sides_touch = 0;  ///< coplanar, overlapping, facing opposite ways (not intersecting)
};

/// Runs `count` non-degenerate pairs from `make` against the oracle.
Outcomes run_against_oracle(int count, const std::function<std::pair<Triangle, Triangle>()>& make) {
  Outcomes outcomes;
  for (int done = 0; done < count;) {
    const auto [s, t] = make();
    if (degenerate_oracle(s) || degenerate_oracle(t)) continue;
    ++done;
    switch (expect_triangles_match_oracle(s, t, describe(s, t))) {
      case Truth::intersecting:
        ++outcomes.meet;
        break;
      case Truth::apart:
        ++outcomes.apart;
        break;
      case Truth::sides_touch:
        ++outcomes.sides_touch;
        break;
    }
  }
  return outcomes;
}

TEST(TriangleContact, RandomPairsMatchOracle) {
  auto rng = testing::seeded_engine("TriangleContact.Random");
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const auto point = [&] { return Point3{coordinate(rng), coordinate(rng), coordinate(rng)}; };
  const Outcomes o = run_against_oracle(2000, [&] {
    return std::pair{Triangle{point(), point(), point()}, Triangle{point(), point(), point()}};
  });
  EXPECT_GT(o.meet, 300);
  EXPECT_GT(o.apart, 300);
}

TEST(TriangleContact, ExactlyDegeneratePairsMatchOracle) {
  auto rng = testing::seeded_engine("TriangleContact.Degenerate");
  const Outcomes o = run_against_oracle(6000, [&] { return degenerate_pair(rng); });
  std::cout << "intersecting " << o.meet << ", apart " << o.apart << ", coplanar facing opposite "
            << o.sides_touch << "\n";
  EXPECT_GT(o.meet, 600);
  EXPECT_GT(o.apart, 600);
  EXPECT_GT(o.sides_touch, 150);
}

TEST(TriangleContact, OneUlpOffDegeneratePairsMatchOracle) {
  auto rng = testing::seeded_engine("TriangleContact.OneUlp");
  const Outcomes o = run_against_oracle(4000, [&] {
    auto pair = degenerate_pair(rng);
    nudge(rng, pair.second);
    return pair;
  });
  EXPECT_GT(o.meet, 400);
  EXPECT_GT(o.apart, 400);
}

TEST(TriangleContact, ExtremeMagnitudesMatchOracle) {
  auto rng = testing::seeded_engine("TriangleContact.Extreme");
  // 2^500 and 2^-500, and subnormal: lattice integers (at most 2^6) times 2^-1072.
  for (const int exponent : {500, -500, -1072}) {
    const Outcomes o = run_against_oracle(1500, [&] {
      auto pair = degenerate_pair(rng);
      scale(pair.first, exponent);
      scale(pair.second, exponent);
      if (std::bernoulli_distribution(0.5)(rng)) nudge(rng, pair.second);
      return pair;
    });
    std::cout << exponent << ": intersecting " << o.meet << ", apart " << o.apart
              << ", coplanar facing opposite " << o.sides_touch << "\n";
    EXPECT_GT(o.meet, 100) << exponent;
    EXPECT_GT(o.apart, 100) << exponent;
    EXPECT_GT(o.sides_touch, 15) << exponent;
  }
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (const int exponent : {500, -500}) {
    const Outcomes o = run_against_oracle(1000, [&] {
      const auto point = [&] {
        return Point3{std::ldexp(coordinate(rng), exponent), std::ldexp(coordinate(rng), exponent),
                      std::ldexp(coordinate(rng), exponent)};
      };
      return std::pair{Triangle{point(), point(), point()}, Triangle{point(), point(), point()}};
    });
    EXPECT_GT(o.meet, 100) << exponent;
    EXPECT_GT(o.apart, 100) << exponent;
  }
}

TEST(TriangleContact, NamedContacts) {
  const Triangle base{{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}};
  // Touching only: apart.
  const Triangle vertex_on_face{{{1, 1, 0}, {1, 1, 3}, {2, 1, 3}}};
  const Triangle edge_on_face{{{1, 1, 0}, {2, 1, 0}, {1, 1, 3}}};
  const Triangle shared_edge_folded{{{4, 0, 0}, {0, 0, 0}, {1, -1, 2}}};
  const Triangle coplanar_edge_to_edge{{{4, 0, 0}, {0, 4, 0}, {4, 4, 0}}};
  const Triangle coplanar_vertex_to_vertex{{{4, 0, 0}, {8, 0, 0}, {8, -1, 0}}};
  const Triangle edge_on_face_across_edge{{{2, -1, 0}, {2, 1, 0}, {2, -1, 3}}};
  const Triangle edge_crosses_edge{{{2, -1, -1}, {2, 1, 1}, {2, -3, 1}}};  // at (2, 0, 0)
  for (const Triangle& t :
       {vertex_on_face, edge_on_face, shared_edge_folded, coplanar_edge_to_edge,
        coplanar_vertex_to_vertex, edge_on_face_across_edge, edge_crosses_edge}) {
    EXPECT_EQ(expect_triangles_match_oracle(base, t, describe(base, t)), Truth::apart);
  }
  // Coplanar, the open triangles overlapping, facing opposite ways (base faces +z, these
  // -z): the two sides of a surface touching, not intersecting. Among them a neighbour
  // across a shared edge folded flat onto base (the edge run the other way, as consistent
  // orientation has it), and base itself with its corners reversed.
  const Triangle overlap_opposite{{{1, 1, 0}, {1, 5, 0}, {5, 1, 0}}};
  const Triangle nested_opposite{{{1, 1, 0}, {1, 2, 0}, {2, 1, 0}}};
  const Triangle folded_flat{{{4, 0, 0}, {0, 0, 0}, {1, 1, 0}}};
  const Triangle reversed_copy{{{0, 0, 0}, {0, 4, 0}, {4, 0, 0}}};
  for (const Triangle& t : {overlap_opposite, nested_opposite, folded_flat, reversed_copy}) {
    EXPECT_EQ(expect_triangles_match_oracle(base, t, describe(base, t)), Truth::sides_touch);
  }
  // Intersecting: pierced, coplanar overlapping facing the same way (partly, nested, the
  // same triangle with its corners rotated, a shared edge run the same way with the faces
  // overlapping).
  const Triangle pierced{{{1, 1, -1}, {1, 1, 1}, {2, 1, 1}}};
  const Triangle coplanar_overlap{{{1, 1, 0}, {5, 1, 0}, {1, 5, 0}}};
  const Triangle nested{{{1, 1, 0}, {2, 1, 0}, {1, 2, 0}}};
  const Triangle duplicate{{{4, 0, 0}, {0, 4, 0}, {0, 0, 0}}};
  const Triangle shared_edge_same_way{{{0, 0, 0}, {4, 0, 0}, {1, 1, 0}}};
  for (const Triangle& t : {pierced, coplanar_overlap, nested, duplicate, shared_edge_same_way}) {
    EXPECT_EQ(expect_triangles_match_oracle(base, t, describe(base, t)), Truth::intersecting);
  }
}

// ---------------------------------------------------------------------------------------
// Quads.

Mesh two_quads(const std::array<Point3, 4>& a, const std::array<Point3, 4>& b) {
  Mesh mesh;
  mesh.vertices = {a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3]};
  mesh.faces = {make_quad(0, 1, 2, 3), make_quad(4, 5, 6, 7)};
  return mesh;
}

/// The skew patch z = u v over the unit square.
const std::array<Point3, 4> kSaddle{{{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}}};

TEST(QuadContact, SkewPatchPiercedByAnEdgeIntersects) {
  // A vertical quad in the plane y = 1/2 whose edge x = 1/2 crosses the saddle at z = 1/4.
  const std::array<Point3, 4> wall{{{0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 0.5, 1}, {3, 0.5, -1}}};
  const Mesh mesh = two_quads(kSaddle, wall);
  EXPECT_EQ(face_contact(mesh, 0, 1), FaceContact::intersecting);
  EXPECT_EQ(face_contact(mesh, 1, 0), FaceContact::intersecting);
  EXPECT_EQ(find_self_intersections(mesh).intersecting, (std::vector<FacePair>{{0, 1}}));
}

TEST(QuadContact, EdgeEndingOnSkewPatchDoesNotIntersect) {
  // A convex kite in the plane x = 1/2, touching the saddle only at its top corner
  // (1/2, 1/2, 1/4) = p(1/2, 1/2), everything else below the saddle. Its edges start on
  // the patch, and no plane through corners separates the faces: undecided, as
  // documented (never intersecting).
  const std::array<Point3, 4> kite{
      {{0.5, 0.5, 0.25}, {0.5, 0.375, -1}, {0.5, 0.5, -2}, {0.5, 0.625, -1}}};
  const Mesh mesh = two_quads(kSaddle, kite);
  EXPECT_EQ(face_contact(mesh, 0, 1), FaceContact::undecided);
  EXPECT_EQ(face_contact(mesh, 1, 0), FaceContact::undecided);
  // The same kite lowered by 1/8 is apart; raised by 1/8 its top edges pierce the saddle.
  for (const double dz : {-0.125, 0.125}) {
    std::array<Point3, 4> moved = kite;
    for (Point3& p : moved)
      p[2] += dz;
    const Mesh m = two_quads(kSaddle, moved);
    EXPECT_EQ(face_contact(m, 0, 1), dz < 0 ? FaceContact::apart : FaceContact::intersecting) << dz;
  }
}

TEST(QuadContact, AdjacentQuadsDoNotIntersect) {
  // Two skew quads sharing an edge, and two sharing only a corner, on the saddle z = x y.
  Mesh mesh;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i)
      mesh.vertices.push_back({double(i - 1), double(j - 1), double((i - 1) * (j - 1))});
  const auto v = [](int i, int j) { return static_cast<VertexIndex>(i + 3 * j); };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      mesh.faces.push_back(make_quad(v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)));
  const SelfIntersections found = find_self_intersections(mesh);
  EXPECT_TRUE(found.intersecting.empty());
  EXPECT_TRUE(found.undecided.empty());
  EXPECT_EQ(found.candidate_pairs, 6u);
}

/// Random quad pairs near the saddle: skew quads, some crossing it.
std::array<Point3, 4> random_quad(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> k(-16, 16);
  std::array<Point3, 4> q;
  for (Point3& p : q)
    p = {k(rng) / 16.0, k(rng) / 16.0, k(rng) / 16.0};
  return q;
}

std::array<Point3, 4> rotated(const std::array<Point3, 4>& q, std::size_t r) {
  std::array<Point3, 4> out;
  for (std::size_t i = 0; i < 4; ++i)
    out[i] = q[(i + r) % 4];
  return out;
}

/// The same corners in the opposite order (the other facing; the same patch for a skew
/// quad, with u and v swapped).
std::array<Point3, 4> reversed(const std::array<Point3, 4>& q) {
  return {q[0], q[3], q[2], q[1]};
}

std::array<Point3, 4> transformed(const std::array<Point3, 4>& q, const std::array<int, 3>& axes,
                                  int exponent) {
  std::array<Point3, 4> out;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      out[i][k] = std::ldexp(q[i][static_cast<std::size_t>(axes[k])], exponent);
  return out;
}

// Reversing one face's corners flips its facing, which can change the answer for coplanar
// faces; reversing both keeps how they face each other, and so does a mirror (axes {2, 1,
// 0}), which flips both.
TEST(QuadContact, InvariantUnderOrderRotationAxesAndScale) {
  auto rng = testing::seeded_engine("QuadContact.Invariance");
  std::map<FaceContact, int> seen;
  std::uniform_int_distribution<std::size_t> rotation(1, 3);
  // 1500 at full effort (tests/support/seed.hpp), at least one of each three kinds; every
  // answer asked of the same share of them.
  const auto trials = static_cast<int>(testing::scaled_trials(1500, 3));
  for (int trial = 0; trial < trials; ++trial) {
    std::array<Point3, 4> a = random_quad(rng);
    std::array<Point3, 4> b = random_quad(rng);
    if (trial % 3 == 0) b[0] = a[1];               // a shared corner
    if (trial % 3 == 1) b[0] = a[1], b[1] = a[0];  // a shared edge
    const FaceContact c = face_contact(two_quads(a, b), 0, 1);
    ++seen[c];
    EXPECT_EQ(face_contact(two_quads(a, b), 1, 0), c) << trial;
    EXPECT_EQ(face_contact(two_quads(rotated(a, rotation(rng)), b), 0, 1), c) << trial;
    EXPECT_EQ(face_contact(two_quads(a, rotated(b, rotation(rng))), 0, 1), c) << trial;
    EXPECT_EQ(face_contact(two_quads(reversed(a), reversed(b)), 0, 1), c) << trial;
    for (const auto& axes : {std::array<int, 3>{1, 2, 0}, std::array<int, 3>{2, 1, 0}}) {
      for (const int exponent : {0, 600, -600}) {
        EXPECT_EQ(
            face_contact(two_quads(transformed(a, axes, exponent), transformed(b, axes, exponent)),
                         0, 1),
            c)
            << trial;
      }
    }
  }
  std::cout << "apart " << seen[FaceContact::apart] << ", intersecting "
            << seen[FaceContact::intersecting] << ", undecided " << seen[FaceContact::undecided]
            << "\n";
  EXPECT_GT(seen[FaceContact::intersecting], 50 * trials / 1500);
  EXPECT_GT(seen[FaceContact::apart], 50 * trials / 1500);
  EXPECT_GT(seen[FaceContact::undecided], 0);
}

/// The plane z = x + 2 y (exact for small integers), tilted against every axis.
Point3 tilted(double x, double y) {
  return {x, y, x + 2 * y};
}

TEST(QuadContact, CoplanarConvexQuadsIntersectOnlyFacingTheSameWay) {
  // Random parallelograms in one tilted plane: the sheared images (x + k y, y) of integer
  // rectangles, so the open faces meet exactly when the open rectangles do (the shear is
  // a bijection of the plane). Each with a random facing and starting corner. Expected:
  // intersecting exactly when the rectangles overlap and the facings agree.
  auto rng = testing::seeded_engine("QuadContact.Coplanar");
  std::uniform_int_distribution<int> coordinate(0, 6), shear(-2, 2);
  std::uniform_int_distribution<std::size_t> rotation(0, 3);
  std::map<std::pair<bool, bool>, int> seen;  // (overlap, same facing)
  for (int trial = 0; trial < 600; ++trial) {
    const int k = shear(rng);
    const auto quad = [&](std::array<int, 2>& lo, std::array<int, 2>& hi, bool up) {
      for (std::size_t i = 0; i < 2; ++i) {
        do {
          lo[i] = coordinate(rng), hi[i] = coordinate(rng);
        } while (lo[i] == hi[i]);
        if (lo[i] > hi[i]) std::swap(lo[i], hi[i]);
      }
      const auto at = [&](int x, int y) { return tilted(x + k * y, y); };
      std::array<Point3, 4> q{at(lo[0], lo[1]), at(hi[0], lo[1]), at(hi[0], hi[1]),
                              at(lo[0], hi[1])};  // counterclockwise seen from +z
      return rotated(up ? q : reversed(q), rotation(rng));
    };
    std::array<int, 2> alo{}, ahi{}, blo{}, bhi{};
    const bool a_up = std::bernoulli_distribution(0.5)(rng);
    const bool b_up = std::bernoulli_distribution(0.5)(rng);
    const std::array<Point3, 4> a = quad(alo, ahi, a_up);
    const std::array<Point3, 4> b = quad(blo, bhi, b_up);
    const bool overlap = alo[0] < bhi[0] && blo[0] < ahi[0] && alo[1] < bhi[1] && blo[1] < ahi[1];
    const bool same = a_up == b_up;
    ++seen[{overlap, same}];
    const FaceContact expected = overlap && same ? FaceContact::intersecting : FaceContact::apart;
    const Mesh mesh = two_quads(a, b);
    EXPECT_EQ(face_contact(mesh, 0, 1), expected) << trial;
    EXPECT_EQ(face_contact(mesh, 1, 0), expected) << trial;
    EXPECT_EQ(face_contact(two_quads(reversed(a), reversed(b)), 0, 1), expected) << trial;
    EXPECT_EQ(find_self_intersections(mesh).intersecting.size(),
              expected == FaceContact::intersecting ? 1u : 0u)
        << trial;
  }
  for (const bool overlap : {false, true})
    for (const bool same : {false, true})
      EXPECT_GT((seen[{overlap, same}]), 50) << overlap << same;
}

TEST(QuadContact, CoplanarNonConvexQuadIsNeverIntersecting) {
  // A dart (concave) and a bow tie (butterfly) in the plane z = 0 with a triangle in the
  // same plane: the edge method's rays lie in the plane, so overlapping pairs are
  // undecided whichever way the faces face, and never intersecting; a triangle away from
  // the quad's corner hull is apart.
  const std::array<Point3, 4> dart{{{0, 0, 0}, {4, 0, 0}, {1, 1, 0}, {0, 4, 0}}};
  const std::array<Point3, 4> bow_tie{{{0, 0, 0}, {4, 4, 0}, {4, 0, 0}, {0, 4, 0}}};
  const Triangle up{{{0.5, 0.25, 0}, {2, 0.25, 0}, {0.5, 2, 0}}};  // faces +z
  const Triangle down{{up[0], up[2], up[1]}};                      // faces -z
  const Triangle away{{{5, 5, 0}, {7, 5, 0}, {5, 7, 0}}};
  for (const auto& quad : {dart, bow_tie}) {
    for (const auto& order : {quad, reversed(quad)}) {
      for (const auto& [t, expected] :
           {std::pair{up, FaceContact::undecided}, std::pair{down, FaceContact::undecided},
            std::pair{away, FaceContact::apart}}) {
        Mesh mesh;
        mesh.vertices = {order[0], order[1], order[2], order[3], t[0], t[1], t[2]};
        mesh.faces = {make_quad(0, 1, 2, 3), make_triangle(4, 5, 6)};
        EXPECT_EQ(face_contact(mesh, 0, 1), expected);
        EXPECT_EQ(face_contact(mesh, 1, 0), expected);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------
// Meshes: broad phase against brute force.

/// Every pair (i < j) by face_contact, sorted.
SelfIntersections brute_force(const Mesh& mesh) {
  SelfIntersections all;
  for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
    for (std::size_t j = i + 1; j < mesh.faces.size(); ++j) {
      switch (face_contact(mesh, i, j)) {
        case FaceContact::intersecting:
          all.intersecting.push_back({i, j});
          break;
        case FaceContact::undecided:
          all.undecided.push_back({i, j});
          break;
        case FaceContact::apart:
          break;
      }
    }
  }
  return all;
}

SelfIntersections expect_matches_brute_force(const Mesh& mesh) {
  const SelfIntersections found = find_self_intersections(mesh);
  const SelfIntersections brute = brute_force(mesh);
  EXPECT_EQ(found.intersecting, brute.intersecting);
  EXPECT_EQ(found.undecided, brute.undecided);
  const std::size_t n = mesh.faces.size();
  EXPECT_GE(found.candidate_pairs, found.intersecting.size() + found.undecided.size());
  EXPECT_LT(found.candidate_pairs, n * (n - 1) / 2);
  return found;
}

/// The surface of the box [0, n]^3 (times `cell`, plus `offset`) as n x n grid quads per
/// side, sharing vertices; each lattice vertex moved by move(lattice point).
void add_grid_box(Mesh& mesh, int n, double cell, const Point3& offset,
                  const std::function<Point3(const std::array<int, 3>&)>& move,
                  bool triangles = false) {
  std::map<std::array<int, 3>, VertexIndex> index;
  const auto vertex = [&](std::array<int, 3> l) {
    const auto [it, added] = index.try_emplace(l, static_cast<VertexIndex>(mesh.vertices.size()));
    if (added) {
      const Point3 d = move(l);
      mesh.vertices.push_back({offset[0] + cell * l[0] + d[0], offset[1] + cell * l[1] + d[1],
                               offset[2] + cell * l[2] + d[2]});
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for (const int side : {0, n}) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          std::array<std::array<int, 3>, 4> l{};
          const std::array<std::array<int, 2>, 4> square{
              {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
          for (std::size_t k = 0; k < 4; ++k) {
            l[k][static_cast<std::size_t>(axis)] = side;
            l[k][static_cast<std::size_t>(b)] = square[k][0];
            l[k][static_cast<std::size_t>(c)] = square[k][1];
          }
          if (side == 0) std::swap(l[1], l[3]);  // outward orientation
          const VertexIndex v0 = vertex(l[0]), v1 = vertex(l[1]), v2 = vertex(l[2]),
                            v3 = vertex(l[3]);
          if (triangles) {
            mesh.faces.push_back(make_triangle(v0, v1, v2));
            mesh.faces.push_back(make_triangle(v0, v2, v3));
          } else {
            mesh.faces.push_back(make_quad(v0, v1, v2, v3));
          }
        }
      }
    }
  }
}

Point3 no_move(const std::array<int, 3>&) {
  return {0, 0, 0};
}

/// Dyadic offsets k/64, |k| <= 4, a function of the seed and the lattice point.
std::function<Point3(const std::array<int, 3>&)> jitter(std::uint64_t seed) {
  return [seed](const std::array<int, 3>& l) {
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(l[0] + 100),
                      static_cast<std::uint32_t>(l[1] + 100),
                      static_cast<std::uint32_t>(l[2] + 100)};
    std::mt19937_64 rng(seq);
    std::uniform_int_distribution<int> k(-4, 4);
    return Point3{k(rng) / 64.0, k(rng) / 64.0, k(rng) / 64.0};
  };
}

/// Closed bounding boxes of two triangles overlap (if not, the triangles are apart).
bool boxes_overlap(const Triangle& s, const Triangle& t) {
  for (std::size_t k = 0; k < 3; ++k) {
    const auto [s_lo, s_hi] = std::minmax({s[0][k], s[1][k], s[2][k]});
    const auto [t_lo, t_hi] = std::minmax({t[0][k], t[1][k], t[2][k]});
    if (s_hi < t_lo || t_hi < s_lo) return false;
  }
  return true;
}

/// Every pair over all faces by the rational oracle (triangle meshes), skipping the
/// oracle only for pairs whose boxes are disjoint.
std::vector<FacePair> oracle_pairs(const Mesh& mesh) {
  std::vector<FacePair> pairs;
  const auto tri = [&](std::size_t f) {
    const auto& c = mesh.faces[f].corners;
    return Triangle{mesh.vertices[c[0]], mesh.vertices[c[1]], mesh.vertices[c[2]]};
  };
  for (std::size_t i = 0; i < mesh.faces.size(); ++i)
    for (std::size_t j = i + 1; j < mesh.faces.size(); ++j)
      if (boxes_overlap(tri(i), tri(j)) && intersect_oracle(tri(i), tri(j)))
        pairs.push_back({i, j});
  return pairs;
}

TEST(SelfIntersections, ClosedMeshesReportNone) {
  const auto rng_seed = testing::test_seed();
  for (const bool triangles : {false, true}) {
    Mesh cube;
    add_grid_box(cube, 1, 1.0, {0, 0, 0}, no_move, triangles);
    const SelfIntersections c = expect_matches_brute_force(cube);
    EXPECT_TRUE(c.intersecting.empty());
    EXPECT_TRUE(c.undecided.empty());
    Mesh jittered;
    add_grid_box(jittered, 5, 1.0, {0, 0, 0}, jitter(rng_seed), triangles);
    const SelfIntersections j = expect_matches_brute_force(jittered);
    EXPECT_TRUE(j.intersecting.empty()) << triangles;
    EXPECT_TRUE(j.undecided.empty()) << triangles;
  }
  for (const char* file : {"spot_quadrangulated.obj", "spot_quad_cc1.ply"}) {
    const Mesh spot = load_mesh(std::string(EXACTGEO_TEST_DATA_DIR) + "/meshes/spot/" + file).mesh;
    const SelfIntersections s = find_self_intersections(spot);
    EXPECT_TRUE(s.intersecting.empty()) << file;
    EXPECT_TRUE(s.undecided.empty()) << file;
    EXPECT_GT(s.candidate_pairs, 4 * spot.faces.size()) << file;  // at least the neighbours
  }
}

TEST(SelfIntersections, OverlappingJitteredBoxesMatchBruteForce) {
  auto rng = testing::seeded_engine("SelfIntersections.OverlappingBoxes");
  std::uniform_int_distribution<int> shift(-24, 24);
  const auto trials = static_cast<int>(testing::scaled_trials(3));  // tests/support/seed.hpp
  for (const bool triangles : {false, true}) {
    for (int trial = 0; trial < trials; ++trial) {
      Mesh mesh;
      add_grid_box(mesh, 4, 1.0, {0, 0, 0}, jitter(rng()), triangles);
      add_grid_box(mesh, 3, 1.0,
                   {2 + shift(rng) / 16.0, 1 + shift(rng) / 16.0, 1 + shift(rng) / 16.0},
                   jitter(rng()), triangles);
      const SelfIntersections found = expect_matches_brute_force(mesh);
      EXPECT_FALSE(found.intersecting.empty()) << trial;
      if (triangles) {
        EXPECT_EQ(found.intersecting, oracle_pairs(mesh)) << trial;
      }
    }
  }
}

// The pairs are decided in batches on several workers: the answer must not depend on how
// many, over more candidate pairs than one batch holds.
TEST(SelfIntersections, SameAnswerForEveryThreadCountOverManyBatches) {
  auto rng = testing::seeded_engine("SelfIntersections.Threads");
  Mesh mesh;
  add_grid_box(mesh, 44, 1.0, {0, 0, 0}, jitter(rng()));
  add_grid_box(mesh, 36, 1.0, {20.25, 5.5, 6.125}, jitter(rng()));
  const SelfIntersections one = find_self_intersections(mesh, 1);
  EXPECT_GT(one.candidate_pairs, std::size_t{1} << 16);  // more than one batch of 2^16
  EXPECT_FALSE(one.intersecting.empty());
  for (const unsigned threads : {2u, 3u, 0u}) {
    const SelfIntersections many = find_self_intersections(mesh, threads);
    EXPECT_EQ(many.candidate_pairs, one.candidate_pairs) << threads;
    EXPECT_EQ(many.intersecting, one.intersecting) << threads;
    EXPECT_EQ(many.undecided, one.undecided) << threads;
  }
}

/// The bar [3.5, 6] x [1.5, 2.5] x [1.5, 2.5] through side x = 4 of the grid box [0, 4]^3:
/// each of the bar's four long sides crosses exactly two grid quads of that side.
TEST(SelfIntersections, PlantedBarThroughBoxIsFoundExactly) {
  Mesh mesh;
  add_grid_box(mesh, 4, 1.0, {0, 0, 0}, no_move);
  const std::size_t box_faces = mesh.faces.size();
  const std::size_t first_bar_vertex = mesh.vertices.size();
  add_grid_box(mesh, 1, 1.0, {0, 0, 0}, no_move);
  for (std::size_t v = first_bar_vertex; v < mesh.vertices.size(); ++v) {
    Point3& p = mesh.vertices[v];
    p = {p[0] == 0 ? 3.5 : 6.0, p[1] == 0 ? 1.5 : 2.5, p[2] == 0 ? 1.5 : 2.5};
  }
  // Expected: (grid quad on x = 4 containing (y, z) in its open square) x (bar side).
  const auto centre = [&](std::size_t f) {
    Point3 c{0, 0, 0};
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        c[k] += mesh.vertices[mesh.faces[f].corners[i]][k] / 4;
    return c;
  };
  std::vector<FacePair> expected;
  for (std::size_t bar = box_faces; bar < mesh.faces.size(); ++bar) {
    const Point3 b = centre(bar);
    if (b[0] != 4.75) continue;  // the two ends of the bar
    for (std::size_t f = 0; f < box_faces; ++f) {
      const Point3 g = centre(f);
      if (g[0] != 4) continue;
      // The bar side y = 1.5 (or 2.5) crosses x = 4 along z in (1.5, 2.5) (or likewise).
      const bool y_side = b[1] == 1.5 || b[1] == 2.5;
      const double at = y_side ? b[1] : b[2];
      const double along = y_side ? g[2] : g[1];
      const double across = y_side ? g[1] : g[2];
      if (std::abs(across - at) < 0.5 && std::abs(along - 2) == 0.5) expected.push_back({f, bar});
    }
  }
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(expected.size(), 8u);
  const SelfIntersections found = expect_matches_brute_force(mesh);
  EXPECT_EQ(found.intersecting, expected);
  EXPECT_TRUE(found.undecided.empty());
}

TEST(SelfIntersections, PlantedVertexPushedThroughIsFound) {
  // One top vertex of a jittered box pushed below the bottom: the faces around it pierce
  // the bottom side. Triangles: exactly the oracle's pairs. Quads: found by the edge method,
  // and every reported pair involves a face around the moved vertex.
  for (const bool triangles : {true, false}) {
    Mesh mesh;
    add_grid_box(mesh, 4, 1.0, {0, 0, 0}, jitter(7), triangles);
    const auto top = std::find(mesh.vertices.begin(), mesh.vertices.end(),
                               Point3{2 + jitter(7)({2, 2, 4})[0], 2 + jitter(7)({2, 2, 4})[1],
                                      4 + jitter(7)({2, 2, 4})[2]});
    ASSERT_NE(top, mesh.vertices.end());
    const auto moved = static_cast<VertexIndex>(top - mesh.vertices.begin());
    *top = {2.3125, 1.8125, -0.75};
    const SelfIntersections found = expect_matches_brute_force(mesh);
    EXPECT_GE(found.intersecting.size(), 4u) << triangles;
    const auto around = [&](std::size_t f) {
      const auto& c = mesh.faces[f].corners;
      return std::find(c.begin(), c.end(), moved) != c.end();
    };
    for (const FacePair& p : found.intersecting)
      EXPECT_TRUE(around(p.first) || around(p.second)) << p.first << " " << p.second;
    if (triangles) {
      EXPECT_EQ(found.intersecting, oracle_pairs(mesh));
      EXPECT_TRUE(found.undecided.empty());
    }
  }
}

TEST(SelfIntersections, PlantedTouchingContactsAreNotIntersections) {
  // Flat grid box [0, 4]^3 with tetrahedra resting with their apex exactly on the top
  // side (inside a quad; at a lattice corner) and one lying with an edge exactly on side
  // y = 0 (across grid lines); and boxes sharing only an edge line or a corner. Every
  // contact is touching-only, so nothing intersects (triangles and flat convex quads:
  // exact).
  Mesh mesh;
  add_grid_box(mesh, 4, 1.0, {0, 0, 0}, no_move);
  const auto add_tetrahedron = [&](const std::array<Point3, 4>& p) {
    const auto base = static_cast<VertexIndex>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), p.begin(), p.end());
    for (const auto& [a, b, c] :
         std::array<std::array<VertexIndex, 3>, 4>{{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}})
      mesh.faces.push_back(make_triangle(base + a, base + b, base + c));
  };
  // Apex (1.25, 2.5, 4) inside a top quad (and one at a lattice corner of the top side).
  add_tetrahedron({{{1, 2, 5}, {2, 2, 5}, {1.5, 3, 5}, {1.25, 2.5, 4}}});
  add_tetrahedron({{{3, 3, 5}, {3.5, 3, 5}, {3, 3.5, 5}, {3, 3, 4}}});
  // Edge (1.25, 0, 1.5)-(2.75, 0, 2.5) on side y = 0, crossing grid lines; the rest at y < 0.
  add_tetrahedron({{{1.25, 0, 1.5}, {2.75, 0, 2.5}, {2, -1, 1}, {2, -1, 3}}});
  Mesh touching_side;
  add_grid_box(touching_side, 1, 2.0, {0, 0, 0}, no_move);
  add_grid_box(touching_side, 1, 2.0, {2, 2, 0}, no_move);   // shares only the edge x = y = 2
  add_grid_box(touching_side, 1, 2.0, {2, -2, 2}, no_move);  // shares only the corner (2, 0, 2)
  for (const Mesh* m : {&mesh, &touching_side}) {
    const SelfIntersections found = expect_matches_brute_force(*m);
    EXPECT_TRUE(found.intersecting.empty());
    EXPECT_TRUE(found.undecided.empty());
    EXPECT_GT(found.candidate_pairs, m->faces.size());
  }
}

TEST(SelfIntersections, BoxesFaceToFaceOnlyTouch) {
  // Two closed boxes, outward normals, pressed face to face: their x = 2 sides overlap in
  // their common plane facing opposite ways (+x and -x), the two sides of the surface
  // meeting, so nothing intersects; the pair does reach face_contact.
  for (const bool triangles : {false, true}) {
    Mesh mesh;
    add_grid_box(mesh, 1, 2.0, {0, 0, 0}, no_move, triangles);
    add_grid_box(mesh, 1, 2.0, {2, 0.5, 0.5}, no_move, triangles);  // x = 2 sides overlap
    const SelfIntersections found = expect_matches_brute_force(mesh);
    EXPECT_TRUE(found.intersecting.empty()) << triangles;
    EXPECT_TRUE(found.undecided.empty()) << triangles;
    if (!triangles) {
      // Side x = 2 of the first box is its face 1 (axis 0, side n); of the second, its
      // face 0 (6 in the mesh).
      EXPECT_EQ(face_contact(mesh, 1, 6), FaceContact::apart);
      EXPECT_GT(found.candidate_pairs, 12u);
    }
  }
}

TEST(SelfIntersections, DuplicatedFaceIntersectsOnlyFacingTheSameWay) {
  // A closed box with side x = 2 (face 1) given twice: with the same corner order (also
  // rotated, and on vertices of its own) the copy faces the same way and intersects the
  // original, and only it; with the corner order reversed it faces the other way and
  // only touches.
  Mesh box;
  add_grid_box(box, 1, 2.0, {0, 0, 0}, no_move);
  const auto& c = box.faces[1].corners;
  const std::array<VertexIndex, 4> same{c[0], c[1], c[2], c[3]};
  const std::array<VertexIndex, 4> turned{c[2], c[3], c[0], c[1]};
  const std::array<VertexIndex, 4> opposite{c[0], c[3], c[2], c[1]};
  for (const bool own_vertices : {false, true}) {
    for (const auto& [copy, same_way] :
         {std::pair{same, true}, std::pair{turned, true}, std::pair{opposite, false}}) {
      Mesh mesh = box;
      std::array<VertexIndex, 4> corners = copy;
      if (own_vertices) {
        for (VertexIndex& v : corners) {
          mesh.vertices.push_back(box.vertices[v]);
          v = static_cast<VertexIndex>(mesh.vertices.size() - 1);
        }
      }
      mesh.faces.push_back(make_quad(corners[0], corners[1], corners[2], corners[3]));
      const SelfIntersections found = expect_matches_brute_force(mesh);
      const std::vector<FacePair> expected =
          same_way ? std::vector<FacePair>{{1, 6}} : std::vector<FacePair>{};
      EXPECT_EQ(found.intersecting, expected) << own_vertices << same_way;
      EXPECT_TRUE(found.undecided.empty());
    }
  }
}

TEST(SelfIntersections, SheetFoldedFlatOnlyTouches) {
  // Convex quads in the plane z = 0, each sharing an edge with the next: folded flat
  // (consistently oriented, so each neighbour runs the shared edge the other way and faces
  // the other way) neighbours only touch. The same neighbour with the shared edge run the
  // same way faces the same way: intersecting.
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 0, 0}, {1, 2, 0}};
  mesh.faces = {make_quad(0, 1, 2, 3), make_quad(2, 1, 4, 5)};  // folded back along x = 2
  {
    const SelfIntersections found = find_self_intersections(mesh);
    EXPECT_TRUE(found.intersecting.empty());
    EXPECT_TRUE(found.undecided.empty());
    EXPECT_EQ(found.candidate_pairs, 1u);
    EXPECT_EQ(face_contact(mesh, 1, 0), FaceContact::apart);
  }
  {
    Mesh same_way = mesh;
    same_way.faces[1] = make_quad(1, 2, 5, 4);
    EXPECT_EQ(find_self_intersections(same_way).intersecting, (std::vector<FacePair>{{0, 1}}));
  }
  {
    // Folded twice (a z-fold): the first and third layers face the same way and overlap,
    // so they intersect by the rule, which sees pairs, not which layer lies between.
    Mesh z_fold = mesh;
    z_fold.vertices.push_back({2, 0, 0});
    z_fold.vertices.push_back({2, 2, 0});
    z_fold.faces.push_back(make_quad(4, 6, 7, 5));  // back along x = 1, over [1, 2]
    const SelfIntersections found = find_self_intersections(z_fold);
    EXPECT_EQ(found.intersecting, (std::vector<FacePair>{{0, 2}}));
    EXPECT_TRUE(found.undecided.empty());
  }
  {
    // The same with triangles: a fan of two triangles folded flat over the first.
    Mesh fan;
    fan.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}};
    fan.faces = {make_triangle(0, 1, 2), make_triangle(1, 0, 3)};
    EXPECT_EQ(face_contact(fan, 0, 1), FaceContact::apart);
    EXPECT_TRUE(find_self_intersections(fan).intersecting.empty());
    fan.faces[1] = make_triangle(0, 1, 3);
    EXPECT_EQ(find_self_intersections(fan).intersecting, (std::vector<FacePair>{{0, 1}}));
  }
}

TEST(SelfIntersections, CoplanarOverlapFacingTheSameWayIntersects) {
  // Two squares in the plane z = 0 overlapping partially ([0, 2]^2 and [1, 3]^2), both
  // facing +z: intersecting; the second reversed (facing -z): apart.
  Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                   {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}};
  mesh.faces = {make_quad(0, 1, 2, 3), make_quad(4, 5, 6, 7)};
  EXPECT_EQ(find_self_intersections(mesh).intersecting, (std::vector<FacePair>{{0, 1}}));
  EXPECT_EQ(face_contact(mesh, 1, 0), FaceContact::intersecting);
  mesh.faces[1] = make_quad(4, 7, 6, 5);
  EXPECT_EQ(face_contact(mesh, 0, 1), FaceContact::apart);
  EXPECT_EQ(face_contact(mesh, 1, 0), FaceContact::apart);
  EXPECT_TRUE(find_self_intersections(mesh).intersecting.empty());
}

TEST(SelfIntersections, SheetsThatMustStayApartCountEveryCoplanarOverlap) {
  // CoplanarOverlap::intersecting: a sheet lying flat on another is in contact whichever
  // way the two face; edges and corners shared or touched are still no intersection.
  constexpr auto kApart = CoplanarOverlap::intersecting;
  Mesh fan;
  fan.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 0}, {4, 4, 0}, {1, -1, 0}};
  fan.faces = {make_triangle(0, 1, 2), make_triangle(1, 0, 3)};  // folded flat onto the first
  EXPECT_EQ(face_contact(fan, 0, 1), FaceContact::apart);
  EXPECT_EQ(face_contact(fan, 0, 1, kApart), FaceContact::intersecting);
  EXPECT_EQ(face_contact(fan, 1, 0, kApart), FaceContact::intersecting);
  EXPECT_EQ(find_self_intersections(fan, 1, kApart).intersecting, (std::vector<FacePair>{{0, 1}}));
  // Neighbours in one plane that tile it: apart under both rules, whichever the facing.
  for (const Face second : {make_triangle(1, 4, 2), make_triangle(2, 4, 1), make_triangle(1, 0, 5),
                            make_triangle(0, 1, 5)}) {
    fan.faces[1] = second;
    EXPECT_EQ(face_contact(fan, 0, 1, kApart), FaceContact::apart);
    EXPECT_TRUE(find_self_intersections(fan, 1, kApart).intersecting.empty());
  }
  // Convex quads overlapping partially, the second facing the other way.
  Mesh quads;
  quads.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                    {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}};
  quads.faces = {make_quad(0, 1, 2, 3), make_quad(4, 7, 6, 5)};
  EXPECT_TRUE(find_self_intersections(quads).intersecting.empty());
  EXPECT_EQ(find_self_intersections(quads, 2, kApart).intersecting,
            (std::vector<FacePair>{{0, 1}}));
  // Touching along a segment only (the second square moved to x in [2, 4]): apart.
  for (VertexIndex v = 4; v < 8; ++v)
    quads.vertices[v][0] += 1.0;
  EXPECT_EQ(face_contact(quads, 0, 1, kApart), FaceContact::apart);
}

}  // namespace
}  // namespace exactgeo::mesh
