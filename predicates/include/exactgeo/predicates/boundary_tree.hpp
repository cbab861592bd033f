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
// Nested bounds. The bound holds for any set of triangles in B whose solid angles add up
// to the difference, with F the sum of |m| area over them. A node's children L and R give
// one: E's sum is L's ends' and R's ends' cone terms plus their differences (bounded by
// F_L and F_R, their triangles in their boxes, inside B), and L's and R's ends together
// are an edge set with the same flow as E (an edge set and its ends have one boundary:
// sum delta(x) (x - c) = sum delta(x) x, since the deltas add up to 0), whose ends about
// c are E's; so F_N = F_L + F_R + sum over L's and R's ends of |m| area(end, c) bounds it
// too, and the node keeps the smaller. For small closed loops far from c the direct fan
// is a set of long thin triangles, and the nested bound is about the loops' own areas.
//
// First order. Expanding g(y) = (y - p) / |y - p|^3 about c, g(y) - g(c) is the
// integral of Dg along the segment c-y (in B, so at least d from p), and
// |Dg| = |I - 3 u u^T| / |y - p|^3 <= 2 / d^3; so a triangle's solid angle
// (the integral of n.g over it) is its vector area times g(c), within 2 rho area / d^3,
// rho the box's reach from c. The triangles of either decomposition have the vector
// area M = (1/2) sum m (a - c) x (b - c) in all (it depends only on their common
// boundary: E less its ends). In half angles the node's fan is therefore
// (1/2) M.g(c) within rho F / d^3: the dipole term is added to the sum and that bound
// to the error where it is below F / (2 d^2), which is where d > 2 rho or so.
//
// Certified. F is computed once per node in outward-rounded intervals (its upper end);
// d^2 from below and the ray-box test from the slabs with a priori error bounds (in the
// source), so that the test says "misses" only when the ray does. c is the box's centre,
// a double clamped into the box. The cone terms of the ends and of the near edges go
// through the filter of boundary_term_filter.cpp with the bounds added to its error;
// what the filter cannot settle goes back to the full term over every edge (the
// caller's), whose stages reach the exact ones. Far from magnitude 1 (areas beyond the
// doubles' range) every node is near and the tree sums every edge; the classifier builds
// it in its unit frame, where this does not happen.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/predicates/boundary_term.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo {

/// The budgets tried in turn: a node is replaced by its ends (and dipole term) where its
/// bound is at most the budget, in radians of half angle (the levels lie 2 pi apart in
/// these units: a point whose w is 0.1 from a level has 0.63 to spare). The first
/// settles almost every point, the finer ones the points nearer a level. A pass whose
/// bounds add up to pi or more is skipped (its enclosure would hold a level), and one
/// that selects more than half the edges ends the tree's attempt.
inline constexpr std::array<double, 3> kBoundaryTreeBudgets{0x1p-3, 0x1p-7, 0x1p-11};
/// The most edges a leaf holds.
inline constexpr std::uint32_t kBoundaryTreeLeafEdges = 4;

class BoundaryTree {
 public:
  /// The edges, indexing `vertices`, copied with their vertices (and the nodes' centres)
  /// into the tree. Precondition: finite coordinates, edges index into vertices.
  BoundaryTree(std::span<const Point3> vertices, std::span<const BoundaryEdge> edges);
  BoundaryTree() = default;

  bool empty() const noexcept { return nodes_.empty(); }

  /// The edges a point's term is summed over, indexing vertices(): near nodes' own edges
  /// and far nodes' ends; `slack` bounds, in radians of half angle, what the far nodes'
  /// fans add (the exact term, in half angles, is within slack of theirs).
  struct Selection {
    std::vector<BoundaryEdge> edges;
    double offset = 0.0;  ///< far nodes' dipole terms, added to the edges' sum
    double slack = 0.0;
  };
  void select(const Point3& point, const Vector3& ray, double budget, Selection& out) const;

  /// The term of boundary_term.hpp from a selection at each budget in turn, with both
  /// levels settled (kind enclosed); nullopt when none settles them or the ray meets an
  /// edge (then boundary_term over every edge decides).
  std::optional<BoundaryTerm> term(const Point3& point, const Vector3& ray,
                                   std::array<double, 2> levels, Selection& scratch) const;

  /// Bounds, in turns, on the term (1/4 pi) sum m Omega(p; a, b, p - r) over every edge,
  /// from a selection; nullopt when the filter cannot bound it or the ray meets an edge.
  std::optional<Enclosure> enclosure(const Point3& point, const Vector3& ray, double budget,
                                     Selection& scratch) const;

  /// The boundary vertices and the nodes' centres.
  std::span<const Point3> vertices() const noexcept { return vertices_; }
  std::size_t edge_count() const noexcept { return edges_.size(); }

 private:
  struct Node {
    Point3 lower{}, upper{};                       // the box of the node's edges' vertices
    std::uint32_t first = 0, count = 0;            // its edges: edges_[first, first + count)
    std::uint32_t ends_first = 0, ends_count = 0;  // its ends: ends_[...]
    std::uint32_t left = 0, right = 0;             // children; 0 for a leaf
    double fan = 0.0;                              // F, rounded up
    bool far_pays = false;                         // fewer ends than edges
    // The dipole term ("First order" above): the centre, the fan's vector area M (its
    // enclosure's midpoint, within moment_error of M, at most moment_size long), and
    // the box's reach from the centre (rounded up).
    Point3 centre{};
    Vector3 moment{};
    double moment_error = 0.0, moment_size = 0.0, reach = 0.0;
    bool dipole = false;  // all of these finite
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);
  void set_dipole(Node& node, std::span<const BoundaryEdge> edges) const;

 public:
  /// While building: an edge's trail and its place in it (boundary_tree.cpp).
  struct TrailPlace {
    Point3 key{};
    std::uint32_t trail = 0;
    std::uint32_t position = 0;
    bool short_trail = false;
  };

 private:
  std::vector<TrailPlace> places_;  // beside edges_, while building

  std::vector<Point3> vertices_;
  std::vector<BoundaryEdge> edges_;
  std::vector<BoundaryEdge> ends_;
  std::vector<Node> nodes_;
};

}  // namespace exactgeo
