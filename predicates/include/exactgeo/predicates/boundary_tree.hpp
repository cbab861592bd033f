#pragma once

// The boundary term of boundary_term.hpp without visiting every boundary edge: a tree of
// boxes over the edges, whose far nodes stand in for their edges by a few edges to their
// box's centre and a certified bound on what that leaves out.
//
// The identity. Let q = p - r (r the ray), Omega(x, y, z) the signed solid angle of the
// triangle (x, y, z) seen from p, and c any point. The four triangles (a, b, c),
// (c, b, q), (a, c, q) and (b, a, q) bound the tetrahedron (a, b, c, q) (their edges cancel
// in pairs), so, for p on none of them,
//
//     Omega(a, b, q) = Omega(a, b, c) + Omega(c, b, q) - Omega(c, a, q) + 4 pi k,
//
// with k = 0 unless p lies inside the tetrahedron (Omega(a, c, q) = -Omega(c, a, q)). Over
// a set E of edges a -> b with multiplicities m, the middle terms gather by vertex:
//
//     sum_E m Omega(a, b, q) = sum_x delta(x) Omega(c, x, q) + sum_E m Omega(a, b, c)
//                              + 4 pi K,
//
// delta(x) the multiplicity E brings into x minus what it takes out of x. So E's cone
// terms are those of the edges c -> x with multiplicity delta(x) (its "ends": for a piece
// of a trail, c -> its last vertex and its first vertex -> c; none for closed loops), plus
// E's fan around c, plus K.
//
// When K = 0 and the fan is small. p lies in the closed tetrahedron (a, b, c, q) exactly
// when p = l_a a + l_b b + l_c c + l_q (p - r) with l >= 0 summing to 1, that is, when
// p + t r (t = l_q / (1 - l_q) >= 0) lies in the triangle (a, b, c): when the ray meets it.
// p lies on (c, x, q) only if the ray meets the segment c-x, and on (a, b, c) only if
// the ray meets it at t = 0. With every vertex of E and c in a box B (convex, so holding
// every triangle (a, b, c) and segment c-x), a ray that misses B leaves p off all of
// these, and K = 0. A triangle's solid angle is the integral over it of
// n.(y - p) / |y - p|^3, at most 1 / d^2 in magnitude where every y of it is at least d
// from p: |Omega(a, b, c)| <= area(a, b, c) / d^2 with d the distance from p to B. Hence,
// in the half angles theta = Omega / 2 that the filter sums,
//
//     | sum_E m theta(a, b, q) - sum_x delta(x) theta(c, x, q) | <= F / (2 d^2),
//     F = sum_E |m| area(a, b, c).
//
// p lies on the cone triangle (a, b, q) itself only if the ray meets a-b, also in B.
//
// Chords. The ends come in pairs: the deltas add up to 0, so the starts (delta < 0) and
// the finishes (delta > 0) can be joined by chords s -> f of multiplicity m (each start's
// lack and each finish's excess spent exactly). E plus its chords reversed is a closed
// chain Z (delta = 0 everywhere), whose cone terms are its fan about c plus 4 pi K by
// the identity above, with no ends; and E's cone terms are Z's plus its chords'. So
//
//     sum_E m Omega(a, b, q) = sum_chords m Omega(s, f, q) + sum_Z m Omega(a, b, c) + 4 pi K,
//
// one angle per chord where the ends took two (a piece of trail s -> ... -> f: one chord
// s -> f instead of c -> f and s -> c). Every chord and every triangle (a, b, c) of Z
// lies in B (s, f in B, convex), so a ray that misses B meets none: K = 0, and the
// bound, the nested bound and the expansion below hold with Z for E: F = sum over Z of
// |m| area(a, b, c). (With the centre's ends the node's edges were closed by the two
// radii c -> f and s -> c; a chord closes them by one segment. Which ends a chord joins
// is a cost, not part of the argument: the nearest first, for small triangles.)
//
// Nested bounds. The bound holds for any set of triangles in B whose solid angles add up
// to the difference, with F the sum of |m| area over them. A node's children L and R give
// one: as chains, Z_N = Z_L + Z_R + (L's chords + R's chords - N's chords), the last a
// closed chain (the others are, and E_N = E_L + E_R), all of it in B; so
// F_N = F_L + F_R + sum over L's, R's and N's chords of |m| area(s, f, c) bounds it too,
// and the node keeps the smaller. For small closed loops far from c the direct fan is a
// set of long thin triangles, and the nested bound is about the loops' own areas.
//
// Second order. With g(y) = (y - p) / |y - p|^3 = -grad 1/|y - p|, a triangle's solid
// angle is the integral of n.g over it. The k-th derivative of 1/|y - p| has norm
// k! / |y - p|^(k+1) (along a unit u it is k! P_k(cos) / |y - p|^(k+1), the Legendre
// polynomials' generating function, |P_k| <= 1; a symmetric form's norm is its largest
// value on a unit vector), so |Dg| <= 2 / |y - p|^3 and |D^2 g| <= 6 / |y - p|^4. Taylor's
// formula about c along the segment c-y (in B, so at least d from p) leaves
// |g(y) - g(c) - Dg(c)(y - c)| <= 3 |y - c|^2 / d^4 <= 3 rho^2 / d^4, rho the box's reach
// from c. Integrated over the triangles of either decomposition, the fan is
//
//     M.g(c) + sum_ij Dg(c)_ij Q_ij,   M = sum m (vector area),
//     Q_ij = sum m (vector area)_i (centroid - c)_j,
//
// within 3 rho^2 F / d^4 (in half angles, half of all three). M depends only on the
// decompositions' common boundary (Z); Q differs between two of them by
// delta_ij times the volume their difference encloses (the divergence theorem), which
// Dg(c) = (I - 3 u u^T) / |c - p|^3 (u the unit vector along c - p) does not see: its
// trace is 0. So Q is taken from Z's direct fan, where Q = sum m (1/6) (a - c) x (b - c)
// ((a - c) + (b - c))^T, and its symmetric part kept. Where d > 2 rho this bound is
// below the zero-order one (by 3 rho^2 / d^2), and the node adds the expansion to the sum
// and that bound to the error. (The first-order bound, rho F / d^3, is larger than this
// one wherever d > 1.5 rho.)
//
// Refinement. A point's term is the sum over a cut of the tree: far nodes (their chords,
// expansion and bound) and leaves' edges. The cut starts where every far node's bound is
// at most kBoundaryTreeFirstCut; then, while the sum's enclosure holds a level (or is
// wider than asked), the far node of largest bound is opened: its value and bound leave
// the sum, its children (or a leaf's edges) enter it. Every angle evaluated stays in the
// sum; none is computed twice. The sum's own rounding is bounded from the magnitudes of
// everything ever added or taken away (recursive summation of k terms errs by at most
// (k - 1) u times their magnitudes), the far bounds' running total likewise, and each
// node's errors (its angles', its expansion's) stay counted after it is opened.
//
// Certified. F is computed once per node in outward-rounded intervals (its upper end);
// M and Q likewise, kept as midpoints with bounds on their distance from the exact
// ones; d^2 from below and the ray-box test from the slabs with a priori error bounds
// (in the source), so that the test says "misses" only when the ray does. c is the box's
// centre, a double clamped into the box. The cone terms of the chords and of the near
// edges are the filter's of boundary_term_filter.cpp, each with its error bound; what the
// refinement cannot settle goes back to the full term over every edge (the caller's),
// whose stages reach the exact ones. Far from magnitude 1 (areas beyond the doubles'
// range) every node is near and the tree sums every edge; the classifier builds it in
// its unit frame, where this does not happen.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "exactgeo/predicates/boundary_term.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo {

namespace internal {
struct Moments;  // far_field.hpp
}  // namespace internal

/// The first cut of the refinement: nodes whose bound is above this (radians of half
/// angle; the levels lie 2 pi apart) are opened before any angle is computed; later, a
/// node is opened straight away where its bound exceeds an eighth of the smallest bound
/// opened so far. Costs, not certificates: any positive values give the enclosures'
/// guarantee (their costs as measured: docs/predicates.md, "Refinement").
inline constexpr double kBoundaryTreeFirstCut = 1.0;
/// The finest first cut a point's term (BoundaryTree::term) starts from: after a point
/// whose first cut did not settle it, the next one's is halved down to this; after one it
/// settled, doubled back up to kBoundaryTreeFirstCut. A cost, not a certificate, and the
/// labels do not depend on it (enclosures and winding numbers keep the fixed first cut,
/// so that their digits do not depend on the points' order; its cost as measured:
/// docs/predicates.md, "Refinement").
inline constexpr double kBoundaryTreeFinestFirstCut = 0.125;
/// The same floor for points visited in a spatial order (inside::classify_batch), where
/// the point before is a neighbour whose cut fits: finer pays there, and costs in a random
/// order. A cost, not a certificate, as above.
inline constexpr double kBoundaryTreeSpatialFirstCut = 0x1p-6;
/// The ratio between a node's bound and the largest its children may enter with.
inline constexpr double kBoundaryTreeOpening = 8.0;
/// The most edges a leaf holds.
inline constexpr std::uint32_t kBoundaryTreeLeafEdges = 4;

class BoundaryTree {
 public:
  /// The edges, indexing `vertices`, copied with their vertices (and the nodes' centres)
  /// into the tree. Precondition: finite coordinates, edges index into vertices.
  BoundaryTree(std::span<const Point3> vertices, std::span<const BoundaryEdge> edges);
  BoundaryTree() = default;

  bool empty() const noexcept { return nodes_.empty(); }

  /// A point's refinement: the far nodes of its cut, and what the last call left.
  struct Refinement {
    struct Far {
      double bound = 0.0;  ///< radians of half angle
      double value = 0.0;  ///< its chords' angles and its expansion, in the sum
      std::uint32_t node = 0;
      bool expanded = false;
    };
    /// A node to visit, and whether the ray is known to miss its box (it missed its
    /// parent's: a child's box lies in its parent's).
    struct Visit {
      std::uint32_t node = 0;
      bool misses = false;
    };
    std::vector<Far> heap;  ///< a max-heap by bound
    std::vector<Visit> stack;
    std::size_t angles = 0;      ///< edges and chords whose angle was computed
    std::size_t far_nodes = 0;   ///< far nodes in the final cut
    std::size_t expansions = 0;  ///< of those, with a second-order expansion
    double slack = 0.0;          ///< their bounds' sum, radians of half angle
    bool opened = false;         ///< whether the first cut left it unsettled
    /// The next term's first cut (kBoundaryTreeFinestFirstCut, a cost).
    double first_cut = kBoundaryTreeFirstCut;
    /// The floor it is halved down to: kBoundaryTreeFinestFirstCut, or
    /// kBoundaryTreeSpatialFirstCut for points visited in a spatial order (a cost).
    double finest_first_cut = kBoundaryTreeFinestFirstCut;
  };

  /// The term of boundary_term.hpp with both levels settled (kind enclosed), refined
  /// until it is; nullopt when the refinement cannot settle them (a level within the
  /// filter's errors, or the refinement costs as much as every edge) or the ray meets an
  /// edge (then boundary_term over every edge decides).
  std::optional<BoundaryTerm> term(const Point3& point, const Vector3& ray,
                                   std::array<double, 2> levels, Refinement& scratch) const;

  /// Bounds, in turns, on the term (1/4 pi) sum m Omega(p; a, b, p - r) over every edge,
  /// refined until at most `width` turns apart or every node is open; nullopt when the
  /// filter cannot bound it or the ray meets an edge.
  std::optional<Enclosure> enclosure(const Point3& point, const Vector3& ray, double width,
                                     Refinement& scratch) const;

  /// The boundary vertices.
  std::span<const Point3> vertices() const noexcept { return vertices_; }
  std::size_t edge_count() const noexcept { return edges_.size(); }

 private:
  struct Node {
    Point3 lower{}, upper{};                           // the box of the node's edges' vertices
    std::uint32_t first = 0, count = 0;                // its edges: edges_[first, first + count)
    std::uint32_t chords_first = 0, chords_count = 0;  // its chords: chords_[...]
    std::uint32_t left = 0, right = 0;                 // children; 0 for a leaf
    double fan = 0.0;                                  // F, rounded up
    bool far_pays = false;                             // chords fewer than half its edges
    // The expansion ("Second order" above): the centre, the fan's vector area M (its
    // enclosure's midpoint, within moment_error of M, at most moment_size long), the
    // symmetric part of Q (xx, yy, zz, xy, xz, yz: midpoints, whose nine entries' errors
    // add up to at most quad_error and magnitudes to at most quad_size), and the box's
    // reach from the centre (rounded up).
    Point3 centre{};
    Vector3 moment{};
    std::array<double, 6> quad{};
    double moment_error = 0.0, moment_size = 0.0, quad_error = 0.0, quad_size = 0.0;
    double reach = 0.0;
    bool expansion = false;  // all of these finite
    // The expansion's bound's coefficients, each rounded up (predicates/src/far_field.hpp):
    // 4 rho^2, where it is first tried, and the numerators of its three terms over d^4,
    // d^2 and d^3.
    double reach4 = 0.0, second_fan = 0.0, second_moment = 0.0, second_quad = 0.0;
  };
  /// A far node's part of the sum: its chords' angles and expansion, their errors (in
  /// radians) and its bound.
  struct FarValue {
    double value = 0.0, error = 0.0, bound = 0.0;
    bool expanded = false;
  };
  struct Query;
  std::uint32_t build(std::uint32_t first, std::uint32_t count);
  void join_chords(std::vector<std::pair<VertexIndex, std::int64_t>>& starts,
                   std::vector<std::pair<VertexIndex, std::int64_t>>& finishes);
  internal::Moments fan_moments(const Point3& centre, std::span<const BoundaryEdge> edges) const;
  std::optional<FarValue> far_value(const Node& node, const Query& query, double limit,
                                    bool misses) const;
  /// The refinement's sum: kind enclosed with its bounds in radians of half angle, or
  /// ray_on_edge; nullopt when the filter cannot bound an angle or the refinement costs
  /// more than `most_angles` angles. `done(lower, upper)` ends it early.
  struct Refined {
    BoundaryTermKind kind = BoundaryTermKind::enclosed;
    double lower = 0.0, upper = 0.0;
  };
  template <class Done>
  std::optional<Refined> refine(const Point3& point, const Vector3& ray, Refinement& scratch,
                                std::size_t most_angles, double first_cut, const Done& done) const;

 public:
  /// While building: an edge's piece of trail and its place in it (boundary_tree.cpp).
  struct TrailPlace {
    Point3 key{};
    std::uint32_t trail = 0;  // the piece's number
    std::uint32_t position = 0;
  };

 private:
  std::vector<TrailPlace> places_;  // beside edges_, while building

  std::vector<Point3> vertices_;
  std::vector<BoundaryEdge> edges_;
  std::vector<BoundaryEdge> chords_;
  std::vector<Node> nodes_;
};

}  // namespace exactgeo
