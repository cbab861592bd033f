// Mesh-level CCD (mesh_ccd.hpp) against an exhaustive pairwise oracle written here from the
// header's contract: every vertex-face pair whose vertex is not a corner of the face and
// every pair of unique edges that share no vertex, skipping the pairs whose corners all move
// by one vector (standing still included; exact rationals), each decided by the per-pair CCD of
// ccd.hpp with the same method. Random moving meshes (triangle soups, crumpling sheets, sheets
// folding onto themselves), degenerate meshes, the earliest time of impact against dense exact
// bisection, the cache of standing boxes, errors, and the helper API.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using testing::Rng;

// ---------------------------------------------------------------------------------------
// Meshes

/// A triangle mesh and one step of its motion.
struct MovingMesh {
  std::vector<Triangle> faces;
  std::vector<double> t0, t1;  ///< x, y, z of each vertex at the start and the end of the step

  std::size_t vertex_count() const { return t0.size() / 3; }
  StepPositions frames() const { return {t0, t1}; }

  VertexIndex add_vertex(const Point3& p0, const Point3& p1) {
    const auto v = static_cast<VertexIndex>(vertex_count());
    t0.insert(t0.end(), p0.begin(), p0.end());
    t1.insert(t1.end(), p1.begin(), p1.end());
    return v;
  }
  VertexIndex add_standing_vertex(const Point3& p) { return add_vertex(p, p); }
  void add_face(VertexIndex a, VertexIndex b, VertexIndex c) { faces.push_back({a, b, c}); }
  /// A triangle of three new vertices.
  void add_triangle(const std::array<Point3, 3>& p0, const std::array<Point3, 3>& p1) {
    const VertexIndex a = add_vertex(p0[0], p1[0]);
    const VertexIndex b = add_vertex(p0[1], p1[1]);
    add_face(a, b, add_vertex(p0[2], p1[2]));
  }
  /// Appends `other` with its vertex indices shifted past this mesh's vertices.
  void append(const MovingMesh& other) {
    const auto shift = static_cast<VertexIndex>(vertex_count());
    t0.insert(t0.end(), other.t0.begin(), other.t0.end());
    t1.insert(t1.end(), other.t1.begin(), other.t1.end());
    for (const Triangle& f : other.faces)
      add_face(f[0] + shift, f[1] + shift, f[2] + shift);
  }
};

Point3 position(std::span<const double> p, VertexIndex v) {
  return {p[3 * v], p[3 * v + 1], p[3 * v + 2]};
}
void set_position(std::vector<double>& p, VertexIndex v, const Point3& x) {
  std::copy(x.begin(), x.end(), p.begin() + 3 * std::ptrdiff_t{v});
}
Point3 plus(const Point3& a, const Vector3& d) {
  return {a[0] + d[0], a[1] + d[1], a[2] + d[2]};
}
bool stands(const StepPositions& f, VertexIndex v) {
  return position(f.t0, v) == position(f.t1, v);
}

VertexIndex grid_index(int n, int i, int j) {
  return static_cast<VertexIndex>(j * (n + 1) + i);
}

/// An n x n grid of quads of side `spacing` in the plane z = 0 from `origin`, each quad split
/// along a diagonal: (n + 1)^2 standing vertices, 2 n^2 faces.
MovingMesh grid_sheet(int n, double spacing, const Point3& origin = {0, 0, 0}) {
  MovingMesh m;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i)
      m.add_standing_vertex(plus(origin, {i * spacing, j * spacing, 0}));
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const VertexIndex a = grid_index(n, i, j), b = grid_index(n, i + 1, j),
                        c = grid_index(n, i + 1, j + 1), d = grid_index(n, i, j + 1);
      m.add_face(a, b, c);
      m.add_face(a, c, d);
    }
  }
  return m;
}

/// `count` small triangles (corners within `size` of a center) in the cube [-half, half]^3,
/// each moving by a random translation of up to `motion` plus a small per-corner jitter;
/// about one in five stands still.
MovingMesh triangle_soup(Rng& rng, int count, double half, double size, double motion) {
  MovingMesh m;
  for (int k = 0; k < count; ++k) {
    const Point3 center = testing::random_point(rng, half);
    const bool standing = testing::uniform(rng, 0, 1) < 0.2;
    const Vector3 d = standing ? Vector3{0, 0, 0} : testing::random_point(rng, motion);
    std::array<Point3, 3> p0, p1;
    for (int i = 0; i < 3; ++i) {
      p0[i] = plus(center, testing::random_point(rng, size));
      p1[i] = standing ? p0[i] : plus(plus(p0[i], d), testing::random_point(rng, 0.2 * size));
    }
    m.add_triangle(p0, p1);
  }
  return m;
}

/// A unit grid, slightly wavy at t0, whose vertices move by random vectors longer than the
/// grid spacing, so that it crumples through itself; about one vertex in ten stands still.
MovingMesh crumpling_sheet(Rng& rng, int n) {
  MovingMesh m = grid_sheet(n, 1.0);
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    const Point3 p0 = plus(position(m.t0, v), {0, 0, testing::uniform(rng, -0.2, 0.2)});
    set_position(m.t0, v, p0);
    const bool standing = testing::uniform(rng, 0, 1) < 0.1;
    set_position(m.t1, v, standing ? p0 : plus(p0, testing::random_point(rng, 1.5)));
  }
  return m;
}

/// A unit grid (n even) over x in [-n/2, n/2] whose half x < 0 stands in the plane z = 0
/// while the half x > 0 turns about the line x = 0 from the angle `start` (radians, from the
/// +x axis toward +z) to the angle `end` > pi: each of its vertices moves on the chord, so
/// the folding half sweeps past the standing one. The vertices on the line stand still.
MovingMesh folding_sheet(int n, double start, double end) {
  MovingMesh m = grid_sheet(n, 1.0, {-n / 2.0, -n / 2.0, 0});
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    const Point3 p = position(m.t0, v);
    if (p[0] <= 0) continue;
    set_position(m.t0, v, {p[0] * std::cos(start), p[1], p[0] * std::sin(start)});
    set_position(m.t1, v, {p[0] * std::cos(end), p[1], p[0] * std::sin(end)});
  }
  return m;
}

/// Integer coordinates, |x| <= 2^10, integer motion: the position at every dyadic time k/2^m
/// (m <= 20) is exact in double.
void expect_small_integers(const MovingMesh& m) {
  for (const std::vector<double>* frame : {&m.t0, &m.t1}) {
    for (const double x : *frame)
      ASSERT_TRUE(x == std::trunc(x) && std::abs(x) <= 1024.0) << x;
  }
}

/// Triangles with integer corners, one in each cell of a lattice of cubes of side 16, inside
/// the cell at t0 (so none touch at t0), each moving by a random integer translation of up
/// to 16 per axis plus an integer per-corner jitter.
MovingMesh integer_soup(Rng& rng, int cells_per_axis) {
  MovingMesh m;
  for (int i = 0; i < cells_per_axis; ++i) {
    for (int j = 0; j < cells_per_axis; ++j) {
      for (int k = 0; k < cells_per_axis; ++k) {
        const Point3 corner{16.0 * i, 16.0 * j, 16.0 * k};
        const Vector3 d = testing::integer_point(rng, 16);
        std::array<Point3, 3> p0, p1;
        for (int c = 0; c < 3; ++c) {
          p0[c] = plus(corner, {double(testing::uniform_int(rng, 1, 15)),
                                double(testing::uniform_int(rng, 1, 15)),
                                double(testing::uniform_int(rng, 1, 15))});
          p1[c] = plus(plus(p0[c], d), testing::integer_point(rng, 2));
        }
        m.add_triangle(p0, p1);
      }
    }
  }
  return m;
}

/// A flat grid of spacing 4 (no two non-adjacent primitives touch at t0) whose vertices move
/// by random integer vectors, crumpling it through itself.
MovingMesh integer_crumpling_sheet(Rng& rng, int n) {
  MovingMesh m = grid_sheet(n, 4.0);
  for (VertexIndex v = 0; v < m.vertex_count(); ++v)
    set_position(m.t1, v, plus(position(m.t0, v), testing::integer_point(rng, 6)));
  return m;
}

// ---------------------------------------------------------------------------------------
// The exhaustive oracle

std::vector<Edge> unique_edges(std::span<const Triangle> faces) {
  std::vector<Edge> edges;
  for (const Triangle& f : faces) {
    for (int i = 0; i < 3; ++i) {
      const VertexIndex a = f[i], b = f[(i + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

VertexFaceQuery expected_vertex_face_query(const StepPositions& f, std::span<const Triangle> faces,
                                           VertexFacePair pair) {
  const Triangle& t = faces[pair.face];
  const auto& p0 = f.t0;
  const auto& p1 = f.t1;
  return {position(p0, pair.vertex), position(p0, t[0]), position(p0, t[1]), position(p0, t[2]),
          position(p1, pair.vertex), position(p1, t[0]), position(p1, t[1]), position(p1, t[2])};
}

EdgeEdgeQuery expected_edge_edge_query(const StepPositions& f, const EdgeEdgePair& pair) {
  const auto& p0 = f.t0;
  const auto& p1 = f.t1;
  return {position(p0, pair.a[0]), position(p0, pair.a[1]), position(p0, pair.b[0]),
          position(p0, pair.b[1]), position(p1, pair.a[0]), position(p1, pair.a[1]),
          position(p1, pair.b[0]), position(p1, pair.b[1])};
}

bool is_corner(VertexIndex v, const Triangle& t) {
  return t[0] == v || t[1] == v || t[2] == v;
}
bool share_a_vertex(const Edge& a, const Edge& b) {
  return a[0] == b[0] || a[0] == b[1] || a[1] == b[0] || a[1] == b[1];
}

struct Expected {
  std::vector<VertexFacePair> vertex_face;  ///< colliding, sorted
  std::vector<EdgeEdgePair> edge_edge;      ///< colliding, canonical form, sorted
  std::size_t vertex_face_pairs = 0;        ///< every non-adjacent pair with a moving corner
  std::size_t edge_edge_pairs = 0;
};

Options per_pair_options(Method method) {
  Options o;
  o.method = method;
  return o;
}

/// Vertices grouped by their exact displacement p_t1 - p_t0 (GMP rationals): a pair whose
/// corners are all in one group keeps its shape during the step. -1 for every vertex when
/// nothing is to be skipped.
using MotionClasses = std::vector<int>;

MotionClasses motion_classes(const MovingMesh& m, bool group) {
  MotionClasses classes(m.vertex_count(), -1);
  if (!group) return classes;
  std::map<std::array<mpq_class, 3>, int> ids;
  const StepPositions f = m.frames();
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    std::array<mpq_class, 3> d;
    for (std::size_t k = 0; k < 3; ++k)
      d[k] = mpq_class(f.t1[3 * v + k]) - mpq_class(f.t0[3 * v + k]);
    classes[v] = ids.emplace(d, static_cast<int>(ids.size())).first->second;
  }
  return classes;
}

bool same_motion(const MotionClasses& classes, std::initializer_list<VertexIndex> vertices) {
  const int first = classes[*vertices.begin()];
  return first >= 0 && std::all_of(vertices.begin(), vertices.end(),
                                   [&](VertexIndex v) { return classes[v] == first; });
}

void add_vertex_face_pairs(const MovingMesh& m, const MotionClasses& motion, Method method,
                           Expected& out) {
  const StepPositions f = m.frames();
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    for (FaceIndex i = 0; i < m.faces.size(); ++i) {
      const Triangle& t = m.faces[i];
      if (is_corner(v, t)) continue;
      if (same_motion(motion, {v, t[0], t[1], t[2]})) continue;
      ++out.vertex_face_pairs;
      const VertexFacePair pair{v, i};
      if (vertex_face_ccd(expected_vertex_face_query(f, m.faces, pair), per_pair_options(method))
              .collision) {
        out.vertex_face.push_back(pair);
      }
    }
  }
}

void add_edge_edge_pairs(const MovingMesh& m, const MotionClasses& motion, Method method,
                         Expected& out) {
  const StepPositions f = m.frames();
  const std::vector<Edge> edges = unique_edges(m.faces);  // sorted: edges[i] < edges[j]
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge &a = edges[i], &b = edges[j];
      if (share_a_vertex(a, b)) continue;
      if (same_motion(motion, {a[0], a[1], b[0], b[1]})) continue;
      ++out.edge_edge_pairs;
      const EdgeEdgePair pair{a, b};
      if (edge_edge_ccd(expected_edge_edge_query(f, pair), per_pair_options(method)).collision)
        out.edge_edge.push_back(pair);
    }
  }
}

/// Every non-adjacent pair of the mesh through the per-pair CCD, skipping those whose
/// corners all move by the same vector (standing still is the zero vector): what
/// MeshCcd::step must report. With `skip_rigid` false, those pairs are tested too.
Expected exhaustive(const MovingMesh& m, Method method, bool skip_rigid = true) {
  const MotionClasses motion = motion_classes(m, skip_rigid);
  Expected out;
  add_vertex_face_pairs(m, motion, method, out);
  add_edge_edge_pairs(m, motion, method, out);
  std::sort(out.vertex_face.begin(), out.vertex_face.end());
  std::sort(out.edge_edge.begin(), out.edge_edge.end());
  return out;
}

// ---------------------------------------------------------------------------------------
// Comparisons

std::string describe(const VertexFacePair& p) {
  return "(vertex " + std::to_string(p.vertex) + ", face " + std::to_string(p.face) + ")";
}
std::string describe(const EdgeEdgePair& p) {
  return "(edge " + std::to_string(p.a[0]) + "-" + std::to_string(p.a[1]) + ", edge " +
         std::to_string(p.b[0]) + "-" + std::to_string(p.b[1]) + ")";
}

/// The pairs only one of the two sorted lists holds (at most 10 of each kind).
template <class Pair>
std::string difference(const std::vector<Pair>& expected, const std::vector<Pair>& got) {
  std::vector<Pair> missing, extra;
  std::set_difference(expected.begin(), expected.end(), got.begin(), got.end(),
                      std::back_inserter(missing));
  std::set_difference(got.begin(), got.end(), expected.begin(), expected.end(),
                      std::back_inserter(extra));
  std::ostringstream out;
  out << " (" << expected.size() << " expected, " << got.size() << " reported; " << missing.size()
      << " missing, " << extra.size() << " extra";
  if (!std::is_sorted(got.begin(), got.end())) out << "; reported list not sorted";
  out << ")";
  for (std::size_t i = 0; i < std::min<std::size_t>(missing.size(), 10); ++i)
    out << "\n  missing " << describe(missing[i]);
  for (std::size_t i = 0; i < std::min<std::size_t>(extra.size(), 10); ++i)
    out << "\n  extra   " << describe(extra[i]);
  return out.str();
}

/// The pairs of `r` are the oracle's, and its candidate counts lie between the colliding
/// pairs and all the pairs the oracle tested.
void expect_same_pairs(const MeshCcdResult& r, const Expected& e, const std::string& what) {
  EXPECT_TRUE(r.vertex_face == e.vertex_face)
      << what << ": vertex-face pairs differ" << difference(e.vertex_face, r.vertex_face);
  EXPECT_TRUE(r.edge_edge == e.edge_edge)
      << what << ": edge-edge pairs differ" << difference(e.edge_edge, r.edge_edge);
  EXPECT_GE(r.vertex_face_candidates, e.vertex_face.size()) << what;
  EXPECT_LE(r.vertex_face_candidates, e.vertex_face_pairs) << what;
  EXPECT_GE(r.edge_edge_candidates, e.edge_edge.size()) << what;
  EXPECT_LE(r.edge_edge_candidates, e.edge_edge_pairs) << what;
}

bool same_interval(const std::optional<TimeInterval>& a, const std::optional<TimeInterval>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->start == b->start && a->end == b->end);
}

std::string describe(const std::optional<TimeInterval>& t) {
  if (!t) return "none";
  std::ostringstream out;
  out.precision(17);
  out << "[" << t->start << ", " << t->end << "]";
  return out.str();
}

/// Same pairs, candidate counts and time of impact (not the flags and the timings).
void expect_same_result(const MeshCcdResult& a, const MeshCcdResult& b, const std::string& what) {
  EXPECT_TRUE(a.vertex_face == b.vertex_face)
      << what << ": vertex-face pairs differ" << difference(a.vertex_face, b.vertex_face);
  EXPECT_TRUE(a.edge_edge == b.edge_edge)
      << what << ": edge-edge pairs differ" << difference(a.edge_edge, b.edge_edge);
  EXPECT_EQ(a.vertex_face_candidates, b.vertex_face_candidates) << what;
  EXPECT_EQ(a.edge_edge_candidates, b.edge_edge_candidates) << what;
  EXPECT_TRUE(same_interval(a.time_of_impact, b.time_of_impact))
      << what << ": time of impact " << describe(a.time_of_impact) << " vs "
      << describe(b.time_of_impact);
}

MeshCcdOptions mesh_options(Method method, unsigned threads,
                            std::optional<double> time_of_impact_width = std::nullopt) {
  MeshCcdOptions o;
  o.method = method;
  o.threads = threads;
  o.time_of_impact_width = time_of_impact_width;
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// MeshCcd::step against the oracle for each method (exact and parity unless told), on 1, 2
/// and 3 threads (one MeshCcd stepped repeatedly, so a kept cache of standing boxes is used
/// too); the results of the thread counts must be identical. Returns the oracle's exact
/// colliding pairs.
std::size_t expect_matches_oracle(const MovingMesh& m, const std::string& what,
                                  std::initializer_list<Method> methods = {Method::exact,
                                                                           Method::parity}) {
  std::size_t exact_collisions = 0;
  MeshCcd ccd(m.vertex_count(), m.faces);
  for (const Method method : methods) {
    const auto start = std::chrono::steady_clock::now();
    const Expected e = exhaustive(m, method);
    const double oracle_seconds = seconds_since(start);
    if (method == Method::exact) exact_collisions = e.vertex_face.size() + e.edge_edge.size();
    std::optional<MeshCcdResult> one_thread;
    for (const unsigned threads : {1u, 2u, 3u}) {
      const std::string context = what + ", " + std::string(to_string(method)) + ", " +
                                  std::to_string(threads) + " threads";
      const MeshCcdResult r = ccd.step(m.frames(), mesh_options(method, threads));
      expect_same_pairs(r, e, context);
      EXPECT_FALSE(r.time_of_impact.has_value()) << context << ": no width was asked for";
      if (one_thread) {
        expect_same_result(r, *one_thread, context + " vs 1 thread");
      } else {
        one_thread = r;
      }
    }
    std::printf(
        "[ info     ] %s, %s: %zu vertices, %zu faces; %zu + %zu colliding pairs; candidates "
        "%zu of %zu; oracle %.3f s, MeshCcd (1 thread) %.3f s\n",
        what.c_str(), std::string(to_string(method)).c_str(), m.vertex_count(), m.faces.size(),
        e.vertex_face.size(), e.edge_edge.size(), one_thread->candidates(),
        e.vertex_face_pairs + e.edge_edge_pairs, oracle_seconds,
        one_thread->broad_phase_seconds + one_thread->narrow_phase_seconds);
  }
  return exact_collisions;
}

/// The vertices of a pair: the vertex and the face's corners, or the four edge ends.
std::vector<VertexIndex> vertices_of(const MovingMesh& m, const VertexFacePair& p) {
  const Triangle& t = m.faces[p.face];
  return {p.vertex, t[0], t[1], t[2]};
}
std::vector<VertexIndex> vertices_of(const MovingMesh&, const EdgeEdgePair& p) {
  return {p.a[0], p.a[1], p.b[0], p.b[1]};
}

/// How many of `pairs` have every vertex standing, and how many have at least one.
struct StandingCount {
  std::size_t all = 0;
  std::size_t some = 0;
};
template <class Pair>
StandingCount count_standing(const MovingMesh& m, const std::vector<Pair>& pairs) {
  StandingCount count;
  for (const Pair& p : pairs) {
    const std::vector<VertexIndex> vs = vertices_of(m, p);
    const auto standing =
        std::count_if(vs.begin(), vs.end(), [&](VertexIndex v) { return stands(m.frames(), v); });
    count.all += std::size_t(standing) == vs.size();
    count.some += standing > 0;
  }
  return count;
}

// ---------------------------------------------------------------------------------------
// 1. The broad phase loses nothing

TEST(MeshCcdBroadPhase, TriangleSoupMatchesExhaustivePairs) {
  Rng rng = testing::seeded_engine("mesh-ccd-soup");
  for (const int count : {50, 150, 300}) {
    const double half = 0.15 * std::cbrt(double(count));
    const MovingMesh m = triangle_soup(rng, count, half, 0.15, 0.3);
    const std::size_t collisions = expect_matches_oracle(m, "soup of " + std::to_string(count));
    EXPECT_GT(collisions, std::size_t(count / 5)) << "the soup should collide often";
  }
}

TEST(MeshCcdBroadPhase, CrumplingSheetMatchesExhaustivePairs) {
  Rng rng = testing::seeded_engine("mesh-ccd-crumple");
  for (const int n : {5, 9, 14}) {
    const MovingMesh m = crumpling_sheet(rng, n);
    EXPECT_GT(expect_matches_oracle(m, "crumpling " + std::to_string(n)), 0u);
  }
}

TEST(MeshCcdBroadPhase, FoldingSheetMatchesExhaustivePairs) {
  Rng rng = testing::seeded_engine("mesh-ccd-fold");
  for (const int n : {6, 10, 12}) {
    const double start = testing::uniform(rng, 0.55, 0.85) * std::numbers::pi;
    const double end = testing::uniform(rng, 1.05, 1.3) * std::numbers::pi;
    const MovingMesh m = folding_sheet(n, start, end);
    EXPECT_GT(expect_matches_oracle(m, "folding " + std::to_string(n)), 0u);
  }
}

/// `m` with every coordinate multiplied by 2^k.
MovingMesh scaled_mesh(MovingMesh m, int k) {
  for (std::vector<double>* frame : {&m.t0, &m.t1}) {
    for (double& x : *frame)
      x = std::ldexp(x, k);
  }
  return m;
}

TEST(MeshCcdBroadPhase, ExtremeMagnitudesMatchExhaustivePairs) {
  // Beyond the float range (2^1000, 2^140), below its normal range (2^-140, 2^-1000) and
  // near its ends: rounding the boxes to float must still keep every pair. (Exact only: the
  // parity oracle is slow on tiny magnitudes, and the broad phase is the same.)
  Rng rng = testing::seeded_engine("mesh-ccd-magnitudes");
  const MovingMesh soup = triangle_soup(rng, 40, 0.15 * std::cbrt(40.0), 0.15, 0.3);
  for (const int k : {-1000, -140, -120, 120, 140, 1000}) {
    EXPECT_GT(expect_matches_oracle(scaled_mesh(soup, k), "soup scaled by 2^" + std::to_string(k),
                                    {Method::exact}),
              0u);
  }
}

/// The float boxes are made after an exact power-of-two scaling of the step, so a mesh
/// scaled by 2^k has exactly the candidates of the original: at 2^±1000 the boxes prune as
/// at 1 (without the scaling, a soup of a few thousand triangles went from thousands of
/// candidates to millions there).
TEST(MeshCcdBroadPhase, ExtremeMagnitudesPruneLikeScaleOne) {
  Rng rng = testing::seeded_engine("mesh-ccd-magnitude-pruning");
  const MovingMesh soup = triangle_soup(rng, 400, 0.15 * std::cbrt(400.0), 0.15, 0.3);
  MeshCcd at_one(soup.vertex_count(), soup.faces);
  const MeshCcdResult reference = at_one.step(soup.frames());
  ASSERT_GT(reference.candidates(), 0u);
  ASSERT_LT(reference.candidates(), 20u * soup.faces.size());
  for (const int k : {-1000, -140, -120, 120, 140, 1000}) {
    const MovingMesh scaled = scaled_mesh(soup, k);
    MeshCcd ccd(scaled.vertex_count(), scaled.faces);
    const MeshCcdResult result = ccd.step(scaled.frames());
    EXPECT_EQ(result.vertex_face_candidates, reference.vertex_face_candidates) << "2^" << k;
    EXPECT_EQ(result.edge_edge_candidates, reference.edge_edge_candidates) << "2^" << k;
    EXPECT_EQ(result.vertex_face, reference.vertex_face) << "2^" << k;
    EXPECT_EQ(result.edge_edge, reference.edge_edge) << "2^" << k;
  }
}

/// Contacts at coordinates that are not floats: a standing triangle in the plane z = c; two
/// triangles whose lowest (highest) corner reaches it exactly at t = 1 from above (below),
/// one whose corner leaves it at t = 0; a standing edge at height c that a falling edge
/// reaches exactly at t = 1. Every point is then mapped by `map`.
MovingMesh contacts_at_height(double c, const std::function<Point3(const Point3&)>& map) {
  MovingMesh m;
  const std::array<Point3, 3> floor{{{0.1, 0.1, c}, {1.1, 0.1, c}, {0.1, 1.1, c}}};
  m.add_triangle(floor, floor);
  auto add_moving = [&](const Point3& apex_t0, const Point3& apex_t1, double side) {
    auto corners = [&](const Point3& apex) {
      return std::array<Point3, 3>{apex, plus(apex, {0.2, 0, side}), plus(apex, {0, 0.2, side})};
    };
    m.add_triangle(corners(apex_t0), corners(apex_t1));
  };
  add_moving({0.35, 0.35, c + 1}, {0.35, 0.35, c}, 1);
  add_moving({0.5, 0.2, c - 1}, {0.5, 0.2, c}, -1);
  add_moving({0.2, 0.5, c}, {0.2, 0.5, c + 1}, 1);
  const std::array<Point3, 3> wall{{{2.1, 0.1, c}, {3.1, 0.1, c}, {2.6, 0.1, c - 1}}};
  m.add_triangle(wall, wall);
  m.add_triangle({{{2.6, -0.4, c + 1}, {2.6, 0.6, c + 1}, {2.6, 0.1, c + 2}}},
                 {{{2.6, -0.4, c}, {2.6, 0.6, c}, {2.6, 0.1, c + 1}}});
  for (std::vector<double>* frame : {&m.t0, &m.t1}) {
    for (VertexIndex v = 0; v < m.vertex_count(); ++v)
      set_position(*frame, v, map(position(*frame, v)));
  }
  return m;
}

/// Axis permutations and mirrors, 0 the identity.
constexpr int kAxisMaps = 5;
Point3 axis_map(const Point3& p, int map) {
  switch (map) {
    case 1:
      return {p[1], p[2], p[0]};
    case 2:
      return {p[2], p[0], p[1]};
    case 3:
      return {-p[0], p[1], -p[2]};
    case 4:
      return {-p[2], -p[0], -p[1]};
    default:
      return p;
  }
}

TEST(MeshCcdBroadPhase, ContactsAtNonFloatCoordinatesAreKept) {
  for (const double c : {0.1, -0.3, 1e5 + 0.1, 1 + 0x1p-40, -0x1p-140}) {
    for (int map = 0; map < kAxisMaps; ++map) {
      std::ostringstream what;
      what.precision(17);
      what << "contacts at " << c << ", axis map " << map;
      const MovingMesh m = contacts_at_height(c, [&](const Point3& p) { return axis_map(p, map); });
      EXPECT_GE(expect_matches_oracle(m, what.str()), 4u);
    }
  }
}

// ---------------------------------------------------------------------------------------
// 2. Time of impact

constexpr double kBisectionWidth = 0x1p-16;
constexpr double kImpactWidth = 0x1p-10;

/// The position at time t; exact for the integer meshes at dyadic times.
Point3 position_at(const MovingMesh& m, VertexIndex v, double t) {
  const Point3 a = position(m.t0, v), b = position(m.t1, v);
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

/// The motion of the pair over [a, b] as a step of its own.
VertexFaceQuery query_over(const MovingMesh& m, VertexFacePair p, double a, double b) {
  const Triangle& t = m.faces[p.face];
  return {position_at(m, p.vertex, a), position_at(m, t[0], a),     position_at(m, t[1], a),
          position_at(m, t[2], a),     position_at(m, p.vertex, b), position_at(m, t[0], b),
          position_at(m, t[1], b),     position_at(m, t[2], b)};
}
EdgeEdgeQuery query_over(const MovingMesh& m, const EdgeEdgePair& p, double a, double b) {
  return {position_at(m, p.a[0], a), position_at(m, p.a[1], a), position_at(m, p.b[0], a),
          position_at(m, p.b[1], a), position_at(m, p.a[0], b), position_at(m, p.a[1], b),
          position_at(m, p.b[0], b), position_at(m, p.b[1], b)};
}

bool collides(const VertexFaceQuery& q) {
  return vertex_face_ccd(q).collision;
}
bool collides(const EdgeEdgeQuery& q) {
  return edge_edge_ccd(q).collision;
}

/// [lo, lo + 2^-16] holding the earliest root of a colliding pair, with no root before lo:
/// exact CCD on halves of the step, always descending into the earliest half that collides.
template <class Pair>
TimeInterval earliest_root(const MovingMesh& m, const Pair& pair) {
  double lo = 0, hi = 1;
  EXPECT_TRUE(collides(query_over(m, pair, lo, hi))) << describe(pair);
  while (hi - lo > kBisectionWidth) {
    const double mid = lo + (hi - lo) / 2;
    if (collides(query_over(m, pair, lo, mid))) {
      hi = mid;
    } else {
      EXPECT_TRUE(collides(query_over(m, pair, mid, hi)))
          << describe(pair) << " lost its root in [" << lo << ", " << hi << "]";
      lo = mid;
    }
  }
  return {lo, hi};
}

/// The bracket of the mesh's earliest root: [min lo, min hi] over the colliding pairs.
TimeInterval earliest_mesh_root(const MovingMesh& m, const Expected& e) {
  TimeInterval earliest{1, 1};
  auto take = [&](const TimeInterval& t) {
    earliest.start = std::min(earliest.start, t.start);
    earliest.end = std::min(earliest.end, t.end);
  };
  for (const VertexFacePair& p : e.vertex_face)
    take(earliest_root(m, p));
  for (const EdgeEdgePair& p : e.edge_edge)
    take(earliest_root(m, p));
  return earliest;
}

/// Checks the time of impact of `m` against dense bisection, on 1, 2 and 3 threads.
/// Returns whether the mesh collides.
bool expect_time_of_impact_brackets_earliest_root(const MovingMesh& m, const std::string& what) {
  expect_small_integers(m);
  const Expected e = exhaustive(m, Method::exact);
  const bool collision = !e.vertex_face.empty() || !e.edge_edge.empty();
  const TimeInterval earliest = collision ? earliest_mesh_root(m, e) : TimeInterval{};
  std::optional<MeshCcdResult> one_thread;
  for (const unsigned threads : {1u, 2u, 3u}) {
    const std::string context = what + ", " + std::to_string(threads) + " threads";
    const MeshCcdResult r =
        MeshCcd(m.vertex_count(), m.faces)
            .step(m.frames(), mesh_options(Method::exact, threads, kImpactWidth));
    expect_same_pairs(r, e, context);
    EXPECT_EQ(r.time_of_impact.has_value(), collision) << context;
    if (r.time_of_impact && collision) {
      const TimeInterval& t = *r.time_of_impact;
      EXPECT_LE(0.0, t.start) << context;
      EXPECT_LE(t.start, t.end) << context;
      EXPECT_LE(t.end, 1.0) << context;
      EXPECT_LE(t.end - t.start, kImpactWidth) << context << ": " << describe(r.time_of_impact);
      EXPECT_LE(t.start, earliest.end)
          << context << ": a root before the time of impact " << describe(r.time_of_impact)
          << ", bisection " << describe(earliest);
      EXPECT_GE(t.end, earliest.start)
          << context << ": no root by the end of " << describe(r.time_of_impact) << ", bisection "
          << describe(earliest);
    }
    if (one_thread) {
      expect_same_result(r, *one_thread, context + " vs 1 thread");
    } else {
      one_thread = r;
    }
  }
  if (collision) {
    std::printf("[ info     ] %s: earliest root in [%.10f, %.10f], time of impact %s\n",
                what.c_str(), earliest.start, earliest.end,
                describe(one_thread->time_of_impact).c_str());
  }
  return collision;
}

TEST(MeshCcdTimeOfImpact, IntegerMeshesMatchDenseBisection) {
  Rng rng = testing::seeded_engine("mesh-ccd-toi");
  int colliding = 0;
  for (const int cells : {4, 5}) {
    colliding += expect_time_of_impact_brackets_earliest_root(
        integer_soup(rng, cells), "integer soup of " + std::to_string(cells * cells * cells));
  }
  for (const int n : {6, 10}) {
    colliding += expect_time_of_impact_brackets_earliest_root(
        integer_crumpling_sheet(rng, n), "integer crumpling " + std::to_string(n));
  }
  EXPECT_GE(colliding, 3);
}

TEST(MeshCcdTimeOfImpact, NoCollisionNoTimeOfImpact) {
  // A flat integer grid lifted along its normal: every distance stays the same.
  MovingMesh m = grid_sheet(6, 4.0);
  for (VertexIndex v = 0; v < m.vertex_count(); ++v)
    set_position(m.t1, v, plus(position(m.t0, v), {0, 0, 5}));
  EXPECT_FALSE(expect_time_of_impact_brackets_earliest_root(m, "lifted grid"));
}

/// A vertex falling onto a standing triangle at t = 3/4: the lowest corner of a triangle
/// moving down by 4 from height 3, over the interior of the standing triangle.
MovingMesh vertex_falls_onto_triangle() {
  MovingMesh m;
  m.add_triangle({{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}}, {{{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}});
  m.add_triangle({{{1, 1, 3}, {1, 2, 5}, {2, 1, 5}}}, {{{1, 1, -1}, {1, 2, 1}, {2, 1, 1}}});
  return m;
}

/// An edge falling across another at t = 1/4: a standing vertical triangle in the plane
/// y = 0 with its top edge on the x axis from 10 to 14, and a vertical triangle in the plane
/// x = 12 whose bottom edge (along y, at height 1) moves down by 4.
MovingMesh edge_falls_across_edge() {
  MovingMesh m;
  m.add_triangle({{{10, 0, 0}, {14, 0, 0}, {12, 0, -4}}}, {{{10, 0, 0}, {14, 0, 0}, {12, 0, -4}}});
  m.add_triangle({{{12, -2, 1}, {12, 2, 1}, {12, 0, 3}}},
                 {{{12, -2, -3}, {12, 2, -3}, {12, 0, -1}}});
  return m;
}

void expect_time_of_impact_contains(const MovingMesh& m, double t_star, const std::string& what) {
  for (const double width : {0x1p-4, kImpactWidth, 0x1p-30}) {
    const MeshCcdResult r =
        find_collisions(m.faces, m.frames(), mesh_options(Method::exact, 1, width));
    ASSERT_TRUE(r.collision()) << what;
    ASSERT_TRUE(r.time_of_impact.has_value()) << what;
    EXPECT_LE(r.time_of_impact->start, t_star) << what << " " << describe(r.time_of_impact);
    EXPECT_GE(r.time_of_impact->end, t_star) << what << " " << describe(r.time_of_impact);
    EXPECT_LE(r.time_of_impact->end - r.time_of_impact->start, width) << what;
  }
  expect_time_of_impact_brackets_earliest_root(m, what);
}

TEST(MeshCcdTimeOfImpact, KnownFirstContactTimes) {
  const MovingMesh vertex_face = vertex_falls_onto_triangle();
  expect_time_of_impact_contains(vertex_face, 0.75, "vertex onto triangle");
  const MovingMesh edge_edge = edge_falls_across_edge();
  expect_time_of_impact_contains(edge_edge, 0.25, "edge across edge");
  MovingMesh both = vertex_face;
  both.append(edge_edge);
  expect_time_of_impact_contains(both, 0.25, "both");
  // The first contacts are the expected kinds of pairs.
  const Expected e = exhaustive(vertex_face, Method::exact);
  EXPECT_TRUE(std::find(e.vertex_face.begin(), e.vertex_face.end(), VertexFacePair{3, 0}) !=
              e.vertex_face.end());
  const Expected ee = exhaustive(edge_edge, Method::exact);
  EXPECT_TRUE(std::find(ee.edge_edge.begin(), ee.edge_edge.end(), EdgeEdgePair{{0, 1}, {3, 4}}) !=
              ee.edge_edge.end());
}

// ---------------------------------------------------------------------------------------
// 3. Degenerate meshes

/// A 4 x 4 grid of spacing 4 at z = 0 whose vertices move by small integer heights.
MovingMesh wavy_integer_sheet() {
  MovingMesh m = grid_sheet(4, 4.0);
  for (VertexIndex v = 0; v < m.vertex_count(); ++v)
    set_position(m.t1, v, plus(position(m.t0, v), {0, 0, double(int(v % 5) - 2)}));
  return m;
}

TEST(MeshCcdDegenerate, ZeroAreaFacesMatchExhaustivePairs) {
  MovingMesh m = wavy_integer_sheet();
  const Vector3 down{0, 0, -6};
  // Three collinear corners falling through the sheet.
  m.add_triangle({{{1, 1, 3}, {3, 3, 3}, {5, 5, 3}}}, {{{1, 1, -3}, {3, 3, -3}, {5, 5, -3}}});
  // Collinear, lying in the sheet's plane and sliding along it across grid edges.
  m.add_triangle({{{2, 6, 0}, {4, 6, 0}, {7, 6, 0}}}, {{{5, 6, 0}, {7, 6, 0}, {10, 6, 0}}});
  // Two corners at the same position (distinct indices), falling through the sheet.
  const Point3 a{6, 2, 3}, c{9, 5, 4};
  m.add_triangle({{a, a, c}}, {{plus(a, down), plus(a, down), plus(c, down)}});
  // Two coincident corners at t0 that separate, and all three coincident.
  const Point3 b{10, 13, 1};
  m.add_triangle({{b, b, {11, 14, 2}}}, {{{10, 13, -2}, {13, 10, -1}, {11, 14, -3}}});
  const Point3 d{13, 13, 2};
  m.add_triangle({{d, d, d}}, {{plus(d, down), plus(d, down), plus(d, down)}});
  const std::size_t collisions = expect_matches_oracle(m, "zero-area faces");
  EXPECT_GT(collisions, 0u);
}

TEST(MeshCcdDegenerate, CoincidentVerticesMatchExhaustivePairs) {
  MovingMesh m = wavy_integer_sheet();
  // A triangle with a corner at the sheet's vertex (2, 2) at t0, moving away from it.
  const VertexIndex at = grid_index(4, 2, 2);
  const Point3 p = position(m.t0, at);
  m.add_triangle({{p, plus(p, {1, 0, 5}), plus(p, {0, 1, 5})}},
                 {{plus(p, {0, 0, 4}), plus(p, {1, 0, 9}), plus(p, {0, 1, 9})}});
  // A triangle with a corner that follows the sheet's vertex (1, 3) all through the step.
  const VertexIndex with = grid_index(4, 1, 3);
  const Point3 q0 = position(m.t0, with), q1 = position(m.t1, with);
  m.add_triangle({{q0, plus(q0, {-2, 1, 3}), plus(q0, {1, -2, 3})}},
                 {{q1, plus(q1, {-2, 1, 3}), plus(q1, {1, -2, 3})}});
  // Two separate triangles whose corners coincide at t0 and slide apart in their plane.
  const Point3 r{30, 30, 0};
  m.add_triangle({{r, plus(r, {2, 0, 0}), plus(r, {0, 2, 0})}},
                 {{plus(r, {1, 1, 0}), plus(r, {3, 1, 0}), plus(r, {1, 3, 0})}});
  m.add_triangle({{r, plus(r, {-2, 0, 0}), plus(r, {0, -2, 0})}},
                 {{plus(r, {-1, -1, 0}), plus(r, {-3, -1, 0}), plus(r, {-1, -3, 0})}});
  const std::size_t collisions = expect_matches_oracle(m, "coincident vertices");
  EXPECT_GT(collisions, 0u);
}

/// Standing floor (a grid and a triangle piercing it: they intersect all through the step)
/// with a wavy sheet falling through it.
MovingMesh floor_and_falling_sheet() {
  MovingMesh m = grid_sheet(6, 2.0);
  m.add_triangle({{{5, 5, -2}, {7, 5, 2}, {5, 7, 2}}}, {{{5, 5, -2}, {7, 5, 2}, {5, 7, 2}}});
  MovingMesh sheet = grid_sheet(4, 3.0, {0.5, 0.5, 3});
  for (VertexIndex v = 0; v < sheet.vertex_count(); ++v) {
    set_position(sheet.t1, v, plus(position(sheet.t0, v), {0, 0, -6.0 + 0.25 * double(v % 7)}));
  }
  m.append(sheet);
  return m;
}

/// Two triangles that touch (a corner of one on the other's interior) and translate by
/// `d_touching` and `d_other`.
MovingMesh touching_pair(const Vector3& d_touching, const Vector3& d_other) {
  MovingMesh m;
  const std::array<Point3, 3> base{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const std::array<Point3, 3> apex{{{0.25, 0.25, 0}, {0.25, 0.25, 1}, {0.75, 0.25, 1}}};
  std::array<Point3, 3> base1{}, apex1{};
  for (std::size_t i = 0; i < 3; ++i) {
    base1[i] = plus(base[i], d_other);
    apex1[i] = plus(apex[i], d_touching);
  }
  m.add_triangle(base, base1);
  m.add_triangle(apex, apex1);
  return m;
}

TEST(MeshCcdDegenerate, PairsTranslatingTogetherAreSkipped) {
  // Both move by one vector, exactly: the contact lasts the whole step, as for standing
  // pairs, and is not reported; the oracle with the skip turned off does see it.
  const Vector3 d{0.5, -0.25, 0.125};
  const MovingMesh together = touching_pair(d, d);
  EXPECT_FALSE(exhaustive(together, Method::exact, /*skip_rigid=*/false).vertex_face.empty());
  EXPECT_EQ(expect_matches_oracle(together, "translating together"), 0u);

  // One ulp apart in one coordinate: the shapes move relative to each other, so the
  // contact at t0 is a collision of this step.
  const Vector3 apart{d[0], d[1], std::nextafter(d[2], 1.0)};
  EXPECT_GT(expect_matches_oracle(touching_pair(apart, d), "one ulp apart"), 0u);
}

/// A grid sheet at `origin` whose vertices all move to t1 = t0 + d, with t0 z replaced by
/// `z0` (to make the displacement inexact when asked).
MovingMesh translating_sheet(const Point3& origin, const Vector3& d, double z0) {
  MovingMesh m = grid_sheet(5, 0.5, origin);
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    Point3 p = position(m.t0, v);
    set_position(m.t1, v, plus(p, d));
    p[2] = z0;
    set_position(m.t0, v, p);
  }
  return m;
}

TEST(MeshCcdDegenerate, RigidlyMovingSheetsMatchExhaustivePairs) {
  // Whole sheets, each moving by one vector, so the broad phase can drop node pairs whole
  // (box_tree.hpp): a and c lie in one plane and move together (their contacts are
  // rigid, dropped), b crosses both. Sheet d ends where a
  // ends, but starts 2^-60 above z = 0: its displacement 1 - 2^-60 rounds to a's 1.0, yet
  // it is not exact, so d must not count as moving with a; they meet at t = 1.
  MovingMesh m = translating_sheet({0, 0, 0}, {0, 0, 1}, 0.0);
  m.append(translating_sheet({0.1, 0.2, 0}, {0, 0, -1}, 0.75));
  m.append(translating_sheet({0.3, 0.1, 0}, {0, 0, 1}, 0.0));
  MovingMesh d = translating_sheet({0.2, 0.05, 0}, {0, 0, 1}, 0x1p-60);
  for (VertexIndex v = 0; v < d.vertex_count(); ++v) {
    Point3 p = position(d.t1, v);
    p[2] = 1.0;
    set_position(d.t1, v, p);
  }
  m.append(d);
  EXPECT_GT(expect_matches_oracle(m, "rigid sheets"), 0u);
  const Expected with_rigid = exhaustive(m, Method::exact, /*skip_rigid=*/false);
  const Expected without = exhaustive(m, Method::exact);
  EXPECT_GT(with_rigid.vertex_face.size() + with_rigid.edge_edge.size(),
            without.vertex_face.size() + without.edge_edge.size())
      << "some pairs are rigid, so skipping them is visible";
}

/// A rigid motion by a vector that is not a double: every vertex moves by (1 - 2^60, 0, 0),
/// which needs 61 bits. The pair of triangles touches (vertex 3 on face 0) all through the
/// step, rigidly, so it is skipped as when the vector is a double.
TEST(MeshCcdDegenerate, RigidPairsMovingByAVectorThatIsNotADoubleAreSkipped) {
  const double x = 0x1p60;
  const std::vector<double> t0{x,       0,   0, x + 1024, 0,   0,    x,        1024, 0,
                               x + 256, 256, 0, x + 256,  256, 1024, x + 1024, 1024, 1024};
  const std::vector<double> t1{1,   0,   0, 1025, 0,   0,    1,    1024, 0,
                               257, 256, 0, 257,  256, 1024, 1025, 1024, 1024};
  const std::vector<Triangle> faces{{0, 1, 2}, {3, 4, 5}};
  const MeshCcdResult r = find_collisions(faces, {t0, t1});
  EXPECT_TRUE(r.vertex_face.empty() && r.edge_edge.empty());
  // Not skipped when the two move apart by a hair: the touch at t = 0 is a collision.
  std::vector<double> apart = t1;
  apart[9] += 1.0;  // vertex 3 ends one unit further along x than the rigid motion takes it
  EXPECT_FALSE(find_collisions(faces, {t0, apart}).vertex_face.empty());
}

TEST(MeshCcdDegenerate, StandingPairsAreSkippedMovingAgainstStandingAreNot) {
  const MovingMesh m = floor_and_falling_sheet();
  // The standing parts do intersect each other, so skipping them is visible.
  const Expected with_standing = exhaustive(m, Method::exact, /*skip_rigid=*/false);
  EXPECT_GT(count_standing(m, with_standing.vertex_face).all +
                count_standing(m, with_standing.edge_edge).all,
            0u);

  expect_matches_oracle(m, "standing floor");
  const MeshCcdResult r = MeshCcd(m.vertex_count(), m.faces).step(m.frames());
  EXPECT_EQ(count_standing(m, r.vertex_face).all, 0u);
  EXPECT_EQ(count_standing(m, r.edge_edge).all, 0u);
  EXPECT_GT(count_standing(m, r.vertex_face).some, 0u) << "moving against standing is reported";
  EXPECT_GT(count_standing(m, r.edge_edge).some, 0u) << "moving against standing is reported";
}

TEST(MeshCcdDegenerate, FlatSheetSlidingInItsPlaneMatchesExhaustivePairs) {
  // Every vertex moves by the same in-plane vector: the non-adjacent primitives of a planar
  // grid are disjoint closed sets at a constant offset, so exhaustive CCD finds no pair, but
  // every pair is coplanar all through the step.
  MovingMesh m = grid_sheet(6, 1.0);
  for (VertexIndex v = 0; v < m.vertex_count(); ++v)
    set_position(m.t1, v, plus(position(m.t0, v), {3, 2, 0}));
  EXPECT_EQ(expect_matches_oracle(m, "sliding sheet"), 0u);
  const Expected e = exhaustive(m, Method::exact);
  EXPECT_TRUE(e.vertex_face.empty() && e.edge_edge.empty());
  // Two such sheets in the same plane sliding into each other: coplanar contacts.
  MovingMesh two = grid_sheet(4, 1.0);
  MovingMesh other = grid_sheet(4, 1.0, {5, 0.5, 0});
  for (VertexIndex v = 0; v < two.vertex_count(); ++v)
    set_position(two.t1, v, plus(position(two.t0, v), {2, 0, 0}));
  for (VertexIndex v = 0; v < other.vertex_count(); ++v)
    set_position(other.t1, v, plus(position(other.t0, v), {-2, 0, 0}));
  two.append(other);
  EXPECT_GT(expect_matches_oracle(two, "coplanar sheets sliding into each other"), 0u);
}

TEST(MeshCcdDegenerate, MeshThatDoesNotMoveHasNoPairs) {
  Rng rng = testing::seeded_engine("mesh-ccd-still");
  // Crumpled and intersecting itself, but standing: every pair is skipped.
  MovingMesh m = crumpling_sheet(rng, 8);
  m.t0 = m.t1;
  for (const Method method : {Method::exact, Method::parity}) {
    const MeshCcdResult r =
        MeshCcd(m.vertex_count(), m.faces).step(m.frames(), mesh_options(method, 2, kImpactWidth));
    EXPECT_TRUE(r.vertex_face.empty());
    EXPECT_TRUE(r.edge_edge.empty());
    EXPECT_EQ(r.candidates(), 0u);
    EXPECT_FALSE(r.collision());
    EXPECT_FALSE(r.time_of_impact.has_value());
    const Expected e = exhaustive(m, method);
    EXPECT_EQ(e.vertex_face_pairs + e.edge_edge_pairs, 0u);
  }
}

TEST(MeshCcdDegenerate, VertexInNoFaceIsTestedAgainstFaces) {
  MovingMesh m = wavy_integer_sheet();
  m.add_vertex({5, 6, 4}, {5, 6, -4});  // in no face, falling through the sheet
  m.add_vertex({100, 100, 100}, {100, 100, 100});
  EXPECT_GT(expect_matches_oracle(m, "vertex in no face"), 0u);
}

TEST(MeshCcdDegenerate, EmptyAndSingleTriangleMeshesHaveNoPairs) {
  const MovingMesh empty;
  MeshCcd none(0, empty.faces);
  const MeshCcdResult r0 = none.step(empty.frames(), mesh_options(Method::exact, 1, kImpactWidth));
  EXPECT_FALSE(r0.collision());
  EXPECT_EQ(r0.candidates(), 0u);
  EXPECT_TRUE(none.edges().empty());
  MovingMesh one;
  one.add_triangle({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 1}, {1, 0, -1}, {0, 1, 0}}});
  const MeshCcdResult r1 = find_collisions(one.faces, one.frames());
  EXPECT_FALSE(r1.collision());
  EXPECT_EQ(r1.candidates(), 0u);
}

// ---------------------------------------------------------------------------------------
// 4. The trees kept from step to step

/// `m` with the falling sheet of floor_and_falling_sheet() given new random heights.
MovingMesh with_new_fall(MovingMesh m, Rng& rng) {
  for (VertexIndex v = 52; v < m.vertex_count(); ++v)
    set_position(m.t1, v, plus(position(m.t0, v), {0, 0, testing::uniform(rng, -7, -4)}));
  return m;
}

/// `m` with its vertices' positions handed to the vertices in a random order: the same
/// kind of scene, but every triangle now spans it, so a tree kept from before is useless.
MovingMesh scrambled(MovingMesh m, Rng& rng) {
  std::vector<VertexIndex> order(m.vertex_count());
  std::iota(order.begin(), order.end(), VertexIndex{0});
  std::shuffle(order.begin(), order.end(), rng);
  const MovingMesh before = m;
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    set_position(m.t0, v, position(before.t0, order[v]));
    set_position(m.t1, v, position(before.t1, order[v]));
  }
  return m;
}

/// One step of `ccd` against a fresh MeshCcd and the oracle; returns trees_rebuilt.
/// (The time of impact only on some steps: it costs more than the rest of the step.)
bool step_and_compare(MeshCcd& ccd, const MovingMesh& m, const std::string& what,
                      std::optional<double> time_of_impact_width = std::nullopt) {
  const MeshCcdOptions o = mesh_options(Method::exact, 2, time_of_impact_width);
  const MeshCcdResult r = ccd.step(m.frames(), o);
  const MeshCcdResult fresh = MeshCcd(m.vertex_count(), m.faces).step(m.frames(), o);
  EXPECT_TRUE(fresh.trees_rebuilt) << what;
  expect_same_result(r, fresh, what + " vs a fresh MeshCcd");
  expect_same_pairs(r, exhaustive(m, Method::exact), what);
  return r.trees_rebuilt;
}

TEST(MeshCcdKeptTrees, RefittedTreesFindWhatFreshTreesFind) {
  Rng rng = testing::seeded_engine("mesh-ccd-kept-trees");
  MovingMesh m = with_new_fall(floor_and_falling_sheet(), rng);
  MeshCcd ccd(m.vertex_count(), m.faces);
  EXPECT_TRUE(step_and_compare(ccd, m, "first step", kImpactWidth));
  m = with_new_fall(m, rng);
  EXPECT_FALSE(step_and_compare(ccd, m, "new fall"));
  EXPECT_FALSE(step_and_compare(ccd, m, "same step again"));

  // A standing floor vertex lifted into the sheet's path, still standing.
  const VertexIndex lifted = grid_index(6, 3, 2);
  const Point3 up = plus(position(m.t0, lifted), {0, 0, 1.5});
  set_position(m.t0, lifted, up);
  set_position(m.t1, lifted, up);
  step_and_compare(ccd, m, "floor vertex lifted", kImpactWidth);
  step_and_compare(ccd, with_new_fall(m, rng), "lifted floor, new fall");

  // A floor vertex that starts moving, up through the falling sheet.
  const VertexIndex rising = grid_index(6, 4, 4);
  set_position(m.t1, rising, plus(position(m.t0, rising), {0, 0, 4}));
  step_and_compare(ccd, m, "floor vertex moving");

  // It stands again, elsewhere.
  set_position(m.t0, rising, position(m.t1, rising));
  step_and_compare(ccd, m, "floor vertex standing again");

  // Everything stands: no pairs at all.
  m.t0 = m.t1;
  step_and_compare(ccd, m, "everything standing");
  EXPECT_EQ(ccd.step(m.frames()).candidates(), 0u);

  // A MeshCcd moved to another object keeps working.
  MeshCcd moved = std::move(ccd);
  step_and_compare(moved, m, "after a move");
  m = with_new_fall(floor_and_falling_sheet(), rng);
  step_and_compare(moved, m, "after a move, new motion", kImpactWidth);
}

TEST(MeshCcdKeptTrees, TreesAreRebuiltWhenTheMeshIsScrambled) {
  Rng rng = testing::seeded_engine("mesh-ccd-scrambled");
  MovingMesh m = with_new_fall(floor_and_falling_sheet(), rng);
  MeshCcd ccd(m.vertex_count(), m.faces);
  EXPECT_TRUE(step_and_compare(ccd, m, "first step"));
  m = scrambled(m, rng);
  EXPECT_TRUE(step_and_compare(ccd, m, "scrambled"));
  EXPECT_FALSE(step_and_compare(ccd, m, "scrambled, same step again"));
  EXPECT_FALSE(step_and_compare(ccd, with_new_fall(m, rng), "scrambled, new fall"));
}

// ---------------------------------------------------------------------------------------
// 5. Errors

/// The message of the std::invalid_argument thrown by f (a test failure if none is).
std::string invalid_argument_message(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "no std::invalid_argument thrown";
  return {};
}

TEST(MeshCcdErrors, ConstructorRejectsOutOfRangeAndRepeatedCorners) {
  const std::vector<Triangle> good{{0, 1, 2}, {1, 3, 2}};
  EXPECT_NO_THROW(MeshCcd ccd(4, good));
  const std::vector<Triangle> out_of_range{{0, 1, 2}, {1, 4, 2}};
  EXPECT_THROW(MeshCcd ccd(4, out_of_range), std::invalid_argument);
  EXPECT_THROW(MeshCcd ccd(0, good), std::invalid_argument);
  for (const Triangle repeated :
       {Triangle{1, 1, 2}, Triangle{1, 2, 1}, Triangle{0, 2, 2}, Triangle{3, 3, 3}}) {
    const std::vector<Triangle> faces{{0, 1, 2}, repeated};
    EXPECT_THROW(MeshCcd ccd(4, faces), std::invalid_argument);
  }
  const std::vector<double> frame(12, 0.0);
  EXPECT_THROW(find_collisions(out_of_range, {frame, frame}), std::invalid_argument);
}

TEST(MeshCcdErrors, StepRejectsWrongSizesAndNonFiniteCoordinates) {
  Rng rng = testing::seeded_engine("mesh-ccd-errors");
  const MovingMesh m = crumpling_sheet(rng, 12);  // 169 vertices
  MeshCcd ccd(m.vertex_count(), m.faces);
  const std::vector<double> short_frame(m.t0.begin(), m.t0.end() - 1);
  std::vector<double> long_frame = m.t1;
  long_frame.insert(long_frame.end(), {0.0, 0.0, 0.0});
  EXPECT_THROW(ccd.step({short_frame, m.t1}), std::invalid_argument);
  EXPECT_THROW(ccd.step({m.t0, long_frame}), std::invalid_argument);
  EXPECT_THROW(ccd.step({std::span<const double>{}, m.t1}), std::invalid_argument);

  struct Bad {
    bool at_t1;
    VertexIndex vertex;
    int axis;
    double value;
  };
  for (const Bad bad : {Bad{false, 137, 1, std::numeric_limits<double>::quiet_NaN()},
                        Bad{true, 94, 2, std::numeric_limits<double>::infinity()},
                        Bad{true, 158, 0, -std::numeric_limits<double>::infinity()}}) {
    MovingMesh broken = m;
    (bad.at_t1 ? broken.t1 : broken.t0)[3 * bad.vertex + bad.axis] = bad.value;
    const std::string message = invalid_argument_message([&] { ccd.step(broken.frames()); });
    EXPECT_NE(message.find(std::to_string(bad.vertex)), std::string::npos)
        << "the message should name vertex " << bad.vertex << ": " << message;
  }
  // After the errors the same MeshCcd still answers like a fresh one.
  expect_same_result(ccd.step(m.frames()), find_collisions(m.faces, m.frames()), "after errors");
}

// ---------------------------------------------------------------------------------------
// 6. find_collisions and the per-pair queries

TEST(MeshCcdApi, FindCollisionsEqualsStep) {
  Rng rng = testing::seeded_engine("mesh-ccd-find");
  const MovingMesh m = triangle_soup(rng, 120, 0.3 * std::cbrt(120.0), 0.15, 0.3);
  for (const MeshCcdOptions& o :
       {mesh_options(Method::exact, 0), mesh_options(Method::exact, 2, kImpactWidth),
        mesh_options(Method::parity, 1)}) {
    const MeshCcdResult step = MeshCcd(m.vertex_count(), m.faces).step(m.frames(), o);
    const MeshCcdResult found = find_collisions(m.faces, m.frames(), o);
    expect_same_result(found, step, "find_collisions, " + std::string(to_string(o.method)));
  }
  EXPECT_TRUE(find_collisions(m.faces, m.frames()).collision());
}

TEST(MeshCcdApi, CandidatesAreTheNarrowPhasesInput) {
  // The narrow phase run on candidates() gives step()'s pairs, as many as it counted, at
  // scale 1 and 2^1000 (the broad phase works on the frames brought to magnitude 1).
  Rng rng = testing::seeded_engine("mesh-ccd-candidates");
  const MovingMesh crumpling = crumpling_sheet(rng, 9);
  for (const double scale : {1.0, 0x1p1000}) {
    MovingMesh m = crumpling;
    for (double& x : m.t0)
      x *= scale;
    for (double& x : m.t1)
      x *= scale;
    MeshCcd ccd(m.vertex_count(), m.faces);
    const MeshCcdCandidates found = ccd.candidates(m.frames(), mesh_options(Method::cubic, 1));
    const MeshCcdResult step = MeshCcd(m.vertex_count(), m.faces).step(m.frames());
    ASSERT_TRUE(step.collision());
    EXPECT_EQ(found.vertex_face.size(), step.vertex_face_candidates);
    EXPECT_EQ(found.edge_edge.size(), step.edge_edge_candidates);
    std::vector<VertexFacePair> vertex_face;
    for (const VertexFacePair& p : found.vertex_face) {
      EXPECT_FALSE(is_corner(p.vertex, m.faces[p.face])) << describe(p);
      if (vertex_face_ccd(vertex_face_query(m.frames(), m.faces, p)).collision)
        vertex_face.push_back(p);
    }
    std::vector<EdgeEdgePair> edge_edge;
    for (const EdgeEdgePair& p : found.edge_edge) {
      EXPECT_FALSE(share_a_vertex(p.a, p.b)) << describe(p);
      if (edge_edge_ccd(edge_edge_query(m.frames(), p)).collision) edge_edge.push_back(p);
    }
    std::sort(vertex_face.begin(), vertex_face.end());
    std::sort(edge_edge.begin(), edge_edge.end());
    EXPECT_EQ(vertex_face, step.vertex_face) << "scale " << scale;
    EXPECT_EQ(edge_edge, step.edge_edge) << "scale " << scale;
    // The trees are kept: the next step on the same MeshCcd agrees too.
    expect_same_result(ccd.step(m.frames()), step, "step after candidates()");
  }
  MeshCcd ccd(crumpling.vertex_count(), crumpling.faces);
  const std::vector<double> short_frame(3, 0.0);
  EXPECT_THROW(ccd.candidates({crumpling.t0, short_frame}), std::invalid_argument);
}

/// The step's positions at `fraction` of it (each vertex on its segment, rounded).
std::vector<double> cut_at(const StepPositions& step, double fraction) {
  std::vector<double> cut(step.t0.size());
  for (std::size_t i = 0; i < cut.size(); ++i)
    cut[i] = step.t0[i] + fraction * (step.t1[i] - step.t0[i]);
  return cut;
}

/// The largest collision-free fraction of a step within a separation (what
/// ipc-toolkit's compute_collision_free_stepsize answers), by the recipe of docs/ccd.md:
/// the start of the time of impact within `delta`, then the step cut there checked again
/// with the same separation and halved until the check is clean (rounding the cut
/// positions, or a root at the start itself, can leave a contact at its end).
struct Stepsize {
  double fraction = 1.0;
  int halvings = 0;
  std::optional<TimeInterval> time_of_impact;
};
Stepsize collision_free_stepsize(MeshCcd& ccd, const StepPositions& step, double delta) {
  MeshCcdOptions first;
  first.time_of_impact_width = 0x1p-20;
  first.min_separation = delta;
  Stepsize out;
  out.time_of_impact = ccd.step(step, first).time_of_impact;
  if (!out.time_of_impact) return out;
  MeshCcdOptions check;
  check.min_separation = delta;
  for (out.fraction = out.time_of_impact->start; out.fraction > 0.0; out.fraction /= 2) {
    const std::vector<double> cut = cut_at(step, out.fraction);
    if (!ccd.step({step.t0, cut}, check).collision()) return out;
    ++out.halvings;
  }
  return out;
}

TEST(MeshCcdApi, TheTimeOfImpactGivesACollisionFreeStepsize) {
  // The simulator's question, answered by MeshCcd::step: the step cut at the fraction
  // found has no collision within the separation (checked by a MeshCcd of its own, exact
  // method), and the step cut at the time of impact's end has one; at 2^0 and 2^+-1000.
  Rng rng = testing::seeded_engine("mesh-ccd-stepsize");
  int cut_short = 0, reached = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const MovingMesh base = crumpling_sheet(rng, 6);
    for (const int exponent : {0, 1000, -1000}) {
      const MovingMesh m = scaled_mesh(base, exponent);
      for (const double delta : {0.0, std::ldexp(1.0, exponent - 6)}) {
        MeshCcd ccd(m.vertex_count(), m.faces);
        const Stepsize found = collision_free_stepsize(ccd, m.frames(), delta);
        const std::string what = "trial " + std::to_string(trial) + ", 2^" +
                                 std::to_string(exponent) + ", delta " + std::to_string(delta);
        MeshCcdOptions check;
        check.min_separation = delta;
        const std::vector<double> cut = cut_at(m.frames(), found.fraction);
        EXPECT_FALSE(MeshCcd(m.vertex_count(), m.faces).step({m.t0, cut}, check).collision())
            << what << ": the cut at " << found.fraction << " collides";
        if (!found.time_of_impact) continue;
        ++cut_short;
        EXPECT_LE(found.halvings, 1) << what;
        EXPECT_LE(found.time_of_impact->end - found.time_of_impact->start, 0x1p-20) << what;
        const std::vector<double> past = cut_at(m.frames(), found.time_of_impact->end);
        reached += MeshCcd(m.vertex_count(), m.faces).step({m.t0, past}, check).collision();
      }
    }
  }
  std::cout << "[ info     ] " << cut_short << " steps cut short, " << reached
            << " colliding when cut at the time of impact's end\n";
  EXPECT_GT(cut_short, 30);
  EXPECT_EQ(reached, cut_short);
}

bool same_points(std::span<const Point3> a, std::span<const Point3> b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}
std::array<Point3, 8> points_of(const VertexFaceQuery& q) {
  return {q.v_t0, q.f0_t0, q.f1_t0, q.f2_t0, q.v_t1, q.f0_t1, q.f1_t1, q.f2_t1};
}
std::array<Point3, 8> points_of(const EdgeEdgeQuery& q) {
  return {q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0, q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1};
}

/// A separation so large that the boxes grown by it reach past the float range (to -inf
/// and +inf): every pair that is not adjacent and not rigid comes within it, so the pairs
/// are known by counting, and the trees' empty lanes must still overlap nothing.
TEST(MeshCcdApi, ASeparationPastTheFloatRangeReportsEveryPairOnce) {
  Rng rng = testing::seeded_engine("mesh-ccd-huge-separation");
  const MovingMesh m = triangle_soup(rng, 13, 1.0, 0.3, 0.5);  // 39 vertices: odd leaves
  const auto stands = [&](VertexIndex v) { return ::exactgeo::ccd::stands(m.frames(), v); };
  std::size_t vertex_face = 0, edge_edge = 0;
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    for (const Triangle& f : m.faces) {
      if (is_corner(v, f)) continue;
      vertex_face += stands(v) && stands(f[0]) && stands(f[1]) && stands(f[2]) ? 0 : 1;
    }
  }
  const std::vector<Edge> edges = unique_edges(m.faces);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge &a = edges[i], &b = edges[j];
      if (share_a_vertex(a, b)) continue;
      edge_edge += stands(a[0]) && stands(a[1]) && stands(b[0]) && stands(b[1]) ? 0 : 1;
    }
  }
  for (const double delta : {1e39, 1e300}) {
    MeshCcdOptions options;
    options.min_separation = delta;
    const MeshCcdResult r = find_collisions(m.faces, m.frames(), options);
    EXPECT_EQ(r.vertex_face.size(), vertex_face) << delta;
    EXPECT_EQ(r.edge_edge.size(), edge_edge) << delta;
    EXPECT_EQ(r.candidates(), vertex_face + edge_edge) << delta;
  }
}

TEST(MeshCcdApi, PairQueriesAreTheOraclesQueries) {
  Rng rng = testing::seeded_engine("mesh-ccd-queries");
  const MovingMesh m = crumpling_sheet(rng, 5);
  const StepPositions f = m.frames();
  for (VertexIndex v = 0; v < m.vertex_count(); ++v) {
    for (FaceIndex i = 0; i < m.faces.size(); ++i) {
      if (is_corner(v, m.faces[i])) continue;
      const VertexFacePair p{v, i};
      ASSERT_TRUE(same_points(points_of(vertex_face_query(f, m.faces, p)),
                              points_of(expected_vertex_face_query(f, m.faces, p))))
          << describe(p);
    }
  }
  const std::vector<Edge> edges = unique_edges(m.faces);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      if (share_a_vertex(edges[i], edges[j])) continue;
      const EdgeEdgePair p{edges[i], edges[j]};
      ASSERT_TRUE(
          same_points(points_of(edge_edge_query(f, p)), points_of(expected_edge_edge_query(f, p))))
          << describe(p);
    }
  }
}

// ---------------------------------------------------------------------------------------
// 7. Edges

TEST(MeshCcdApi, EdgesAreSortedUniqueAndComplete) {
  for (int n = 1; n <= 8; ++n) {
    const MovingMesh m = grid_sheet(n, 1.0);
    const MeshCcd ccd(m.vertex_count(), m.faces);
    EXPECT_EQ(ccd.vertex_count(), m.vertex_count());
    EXPECT_TRUE(std::equal(ccd.faces().begin(), ccd.faces().end(), m.faces.begin(), m.faces.end()));
    const std::span<const Edge> edges = ccd.edges();
    EXPECT_EQ(edges.size(), std::size_t(3 * n * n + 2 * n)) << n;
    EXPECT_TRUE(std::adjacent_find(edges.begin(), edges.end(), std::greater_equal<Edge>()) ==
                edges.end())
        << "sorted and unique, n = " << n;
    EXPECT_TRUE(std::all_of(edges.begin(), edges.end(), [](const Edge& e) { return e[0] < e[1]; }));
    const std::vector<Edge> expected = unique_edges(m.faces);
    EXPECT_TRUE(std::equal(edges.begin(), edges.end(), expected.begin(), expected.end())) << n;
  }
  Rng rng = testing::seeded_engine("mesh-ccd-edges");
  const MovingMesh soup = triangle_soup(rng, 40, 1.0, 0.2, 0.1);
  EXPECT_EQ(MeshCcd(soup.vertex_count(), soup.faces).edges().size(), 3 * soup.faces.size());
}

}  // namespace
}  // namespace exactgeo::ccd
