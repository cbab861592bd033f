#pragma once

// The generalized winding number of an open surface through a fixed cap instead of the
// ray's cone (boundary_term.hpp, boundary_tree.hpp), measured against the boundary tree
// (below). The classifier (inside/classifier.hpp) builds the cap and its tree once, in its
// unit frame, and labels a point from S - w_Cap with exact and rational arithmetic, S its
// ray's signed crossings with F and the cap triangles; the cone's term where the point
// lies on a cap triangle or enclosure_apart gives nullopt (docs/inside.md, "Open
// surfaces").
//
// The cap. The boundary chain of a surface F (mesh/boundary_chain.hpp: edges a -> b with
// multiplicities, a closed 1-chain) splits into closed loops: walk unused edges until the
// walk returns to a vertex it holds, and cut off the loop it closed (every vertex of a
// closed chain has as much entering as leaving, so a walk can only stop where it began).
// Each loop v_0 -> v_1 -> ... -> v_n = v_0 is triangulated with its own vertices by
// recursive halving: the triangle (v_i, v_j, v_k), k = (i + j) / 2, then the ranges
// [i, k] and [k, j], from [0, n]. The triangles over [i, j] have the boundary
// v_i -> v_j minus the path v_i -> ... -> v_j (by induction: the triangle's edges
// v_i -> v_j, v_j -> v_k, v_k -> v_i cancel the halves' chords v_i -> v_k and v_k -> v_j
// and leave v_i -> v_j), so over [0, n] (whose chord v_0 -> v_0 is nothing) the boundary
// is minus the loop: F + Cap has every edge balanced, a closed 2-chain. cap_triangles
// merges equal triangles (a rim run twice gives its cap's triangles multiplicity 2; the
// tree keeps each loop's own, a cost), and triangles
// with corners on one line (repeated ones included) left out: they have no area, and no
// solid angle. The halving keeps the triangles of a range near the range's vertices, so
// that a node's triangles are compact where the rim is.
//
// The identity. For p on neither F nor the cap, w_F(p) + w_Cap(p) = w_{F+Cap}(p) is an
// integer: the signed crossing count S of any ray from p that meets F and the cap
// transversally (exact predicates). So w_F = S - w_Cap, with no ray in w_Cap: no cones,
// no chords, no ray-box test. A label against the levels +-1/2 needs w_Cap only as far as
// the half-integer k - 1/2 or k + 1/2 nearest it: an enclosure of w_Cap strictly between
// two consecutive half-integers decides w = S - w_Cap against +-1/2 for every integer S.
//
// Far nodes. A cluster of cap triangles in a box B at distance d from p has
// |sum m Omega| <= F / d^2, F = sum |m| area (a triangle's solid angle is the integral
// of n.(y - p) / |y - p|^3 over it), and the second-order expansion about the box's
// centre c, M.g(c) + sum_ij Dg(c)_ij Q_ij with M = sum m (vector area) and
// Q_ij = sum m (vector area)_i (centroid - c)_j (exact for flat triangles: n is constant
// on each), within 3 rho^2 F / d^4 (boundary_tree.hpp, "Second order": the same
// argument, over these triangles instead of a fan). In half angles, as summed, half of
// each. The rest is BoundaryTree's: a first cut of far nodes whose bound is at most the
// first cut (opened nodes' own triangles, and leaves'), then the far node of largest
// bound opened until the enclosure settles.
//
// Measured (callgrind, instructions per point of enclosure_apart against those of
// BoundaryTree::term for the same points and rays, 25,000 points, uniform in the box
// but for b9's given set, in Morton order): b9_mesh.off (1,708 boundary edges, 1,556 cap
// triangles) 50.3k against 63.9k; elephant-with-holes.off (1,353, 1,139) 11.5k against
// 15.8k; pig.stl (1,296, 548) 5.8k against 24.3k. The labels agreed on every point.
// Not counted: the cap triangles in the ray's crossing count. Wired into the classifier,
// the whole command `exactgeo inside MESH POINTS --threads 1` on the same points took
// 0.90 times the instructions of the cone's on b9_mesh.off, 0.95 on
// elephant-with-holes.off and 0.52 on pig.stl (docs/inside.md, "End to end").
//
// Variation over a box (the certified space cells of an open surface). Off the surface w
// is smooth, and its gradient depends on the boundary only: each face's solid angle has
// the gradient of the Biot-Savart law for a unit current around its edges, and the
// faces' shared edges cancel. The cap's triangles have the same boundary, reversed: the
// field of the surface's rim is minus the sum of the cap triangles' loops' fields, each
// the gradient of that triangle's solid angle, smooth off the triangle's edges even
// where the triangle itself passes. A flat triangle's gradient is the integral over it of
// the derivative of n.(y - p) / |y - p|^3, whose norm is at most 2 / |y - p|^3 (the
// eigenvalues of (I - 3 u u^T) / |u|^3 are 1, 1 and -2 over |u|^3): at most 2 area / d^3
// at distance d from its box, and as a loop's Biot-Savart field at most sum |e| / d_e^2
// over its edges, d_e from each edge's box. So for y in a box C,
// |grad w(y)| <= (1/4 pi) sum over a cut of the tree of 2 F_N / dist(C, B_N)^3, with near
// nodes' own triangles each at the smaller of its two bounds. Where C misses the surface
// (it may meet the cap), the segment from its centre c to any p of C lies in C, off the
// surface, and |w(p) - w(c)| <= rho max |grad w|, rho the reach of C from c. Any cut gives
// a bound; the walk takes a node whole where its box is two of its diagonals from C or
// its bound is small beside what the caller can use, opens the others (the nearer child
// first), and stops once the sum passes that. A box near a large cap triangle (a wide
// hole's) has no useful bound: the cap spans the hole where the rim's own field is
// small. Measured on the classifier's space cells (docs/inside.md, "Open surfaces"):
// more cells labelled than the boundary tree's chords and fans allowed on Spot with holes,
// elephant-with-holes and pig, none on b9_mesh.off either way.
//
// Certified. Per node F rounded up, M and Q as midpoints of outward-rounded intervals
// with bounds on their distance from the exact ones (a node's from its own triangles and
// its children's, whose Q moves to the node's centre c as Q + M (c' - c)^T, c' theirs), d^2 from
// below (box_distance.hpp), each leaf triangle's half angle in plain doubles with an a priori error
// bound (cap_tree.cpp derives it; near its branch cut, p near the triangle itself, the exact sign
// of det[a - p, b - p, c - p] says on which side p is). The tree is for inputs of magnitude 1 as
// BoundaryTree is (areas and d^2 in the doubles' range; the classifier builds it in its unit
// frame): far from it every node is near and the query sums every triangle, or gives up. The
// variation's bound: each triangle's area and edge lengths from above once (outward-rounded
// intervals; a length's nine roundings within 2^-49), each term's quotients and products within u
// and counted so in the sum's rounding bound, the dipole bound's within 7u (a factor 1 + 2^-49),
// and rho rounded up.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "exactgeo/predicates/boundary_term.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo {

/// A cap triangle (a, b, c), indexing the surface's vertices, counted `multiplicity`
/// times (nonzero, either sign).
struct CapTriangle {
  VertexIndex a = 0, b = 0, c = 0;
  std::int32_t multiplicity = 1;
};

/// The cap of a closed boundary chain (above): triangles on the chain's own vertices
/// whose boundary is minus the chain. Throws std::invalid_argument where the chain is
/// not closed (a vertex with more entering than leaving). Precondition: edges index into
/// `vertices`, finite coordinates.
std::vector<CapTriangle> cap_triangles(std::span<const Point3> vertices,
                                       std::span<const BoundaryEdge> edges);

/// The longest range of a loop a leaf holds (its triangles: one fewer).
inline constexpr std::size_t kCapTreeLeafSpan = 4;

class CapTree {
 public:
  /// The cap of the closed chain `edges` (cap_triangles' loops and halving, with equal
  /// triangles not merged), its corners copied into the tree. Its nodes follow the
  /// halving: a loop's range [i, j] holds its triangle (v_i, v_j, v_k) and its halves'
  /// nodes, all in the box of v_i, ..., v_j; the loops are halved by their centres above
  /// them. Throws std::invalid_argument where the chain is not closed.
  CapTree(std::span<const Point3> vertices, std::span<const BoundaryEdge> edges);
  CapTree() = default;

  bool empty() const noexcept { return nodes_.empty(); }
  std::size_t triangle_count() const noexcept { return triangles_.size(); }
  std::size_t node_count() const noexcept { return nodes_.size(); }
  /// The cap's triangles (indexing the vertices given), in the tree's order.
  std::span<const CapTriangle> triangles() const noexcept { return cap_; }

  /// A point's refinement: its far nodes, and the counts of the last query.
  struct Refinement {
    struct Far {
      double bound = 0.0;  ///< radians of half angle
      double value = 0.0;  ///< its expansion (0 without), in the sum
      std::uint32_t node = 0;
      bool expanded = false;
    };
    std::vector<Far> heap;  ///< a max-heap by bound
    std::vector<std::uint32_t> stack;
    /// The first cut (radians of half angle): a cost, not a certificate. enclosure_apart
    /// carries it from point to point, as BoundaryTree::term does: halved (down to
    /// finest_first_cut) after a point its first cut did not settle, doubled (up to
    /// coarsest_first_cut) after one it did. Fixed, the best differed by mesh: 0.25 on
    /// b9_mesh.off, 1 on elephant-with-holes.off, 4 on pig.stl.
    double first_cut = 1.0;
    double finest_first_cut = 0.0625;
    double coarsest_first_cut = 4.0;
    std::size_t tested = 0;      ///< nodes tested as far nodes
    std::size_t triangles = 0;   ///< leaf triangles whose angle was computed
    std::size_t far_nodes = 0;   ///< far nodes in the final cut
    std::size_t expansions = 0;  ///< far nodes taken with their expansion, ever
    std::size_t opened = 0;      ///< far nodes opened after the first cut
  };

  /// Bounds, in turns, on w_Cap(p) = (1/4 pi) sum m Omega(p; a, b, c) over the
  /// triangles, refined until they lie strictly between two consecutive half-integers
  /// with `margin` turns to spare, k - 1/2 < lower - margin <= upper + margin < k + 1/2
  /// (a box of space cells asks for its variation as the margin); nullopt where that
  /// cannot be done (p within rounding of a triangle, every node opened and still not,
  /// or, for a positive margin, no value in the bounds found so far could be).
  std::optional<Enclosure> enclosure_apart(const Point3& point, Refinement& scratch,
                                           double margin = 0.0) const;

  /// Bounds, in turns, on w_Cap(p), refined until at most `width` turns apart or every
  /// node is open; nullopt where p lies within rounding of a triangle.
  std::optional<Enclosure> enclosure(const Point3& point, double width, Refinement& scratch) const;

  /// An upper bound, in turns, on |w(p) - w(centre)| for every p of the box [lower,
  /// upper], w the generalized winding number of a surface whose boundary is minus the
  /// cap's ("Variation over a box" above). Precondition: the box misses that surface (it
  /// may meet the cap) and holds `centre`. nullopt where the bound exceeds `most`, the
  /// box meets a near cap triangle's box and one of its edges' boxes, or a square
  /// overflows.
  std::optional<double> variation(const Point3& lower, const Point3& upper, const Point3& centre,
                                  double most) const;

 private:
  struct Node {
    Point3 lower{}, upper{};
    std::uint32_t first = 0, count = 0;  // its triangles: triangles_[first, first + count)
    std::uint32_t own = 0;               // the first `own` of them, not its children's
    std::uint32_t left = 0, right = 0;   // children; 0 for a leaf
    double fan = 0.0;                    // F, rounded up
    double two_fan = 0.0;                // 2 F rounded up: the quick test's
    Point3 centre{};
    Vector3 moment{};
    std::array<double, 6> quad{};
    double moment_error = 0.0, moment_size = 0.0, quad_error = 0.0, quad_size = 0.0;
    double reach = 0.0;
    bool expansion = false;
    double reach4 = 0.0, second_fan = 0.0, second_moment = 0.0, second_quad = 0.0;
  };
  struct Triangle {
    Point3 a{}, b{}, c{};
    double multiplicity = 1.0;
  };
  /// A triangle's area and edge lengths (b - a, c - b, a - c), each from above: for F and
  /// the variation's near triangles, kept apart from the corners the angles read.
  struct Sizes {
    double area = 0.0;
    std::array<double, 3> lengths{};
  };
  struct Refined {
    double lower = 0.0, upper = 0.0;  // radians of half angle
  };
  std::uint32_t build_loops(std::span<const Point3> vertices,
                            const std::vector<std::vector<VertexIndex>>& loops,
                            std::span<std::pair<Point3, std::uint32_t>> centres);
  std::uint32_t build_range(std::span<const Point3> vertices, std::span<const VertexIndex> loop,
                            std::size_t i, std::size_t j);
  void add_triangle(std::span<const Point3> vertices, VertexIndex a, VertexIndex b, VertexIndex c);
  static std::optional<double> near_triangle_bound(const Point3& lower, const Point3& upper,
                                                   const Triangle& t, const Sizes& sizes) noexcept;
  void finish(Node& node) const;
  void set_expansions();
  template <class Done>
  std::optional<Refined> refine(const Point3& point, Refinement& r, const Done& done) const;

  std::vector<Triangle> triangles_;
  std::vector<Sizes> sizes_;      // one per triangle
  std::vector<CapTriangle> cap_;  // the same, as indices
  std::vector<Node> nodes_;
};

}  // namespace exactgeo
