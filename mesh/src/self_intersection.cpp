#include "exactgeo/mesh/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <utility>

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/crossing_parity.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::mesh {

namespace {

using kernel::Offset;

// ---------------------------------------------------------------------------------------
// One face as the pair test sees it.

/// The shape classes that decide which method a pair gets.
enum class Shape : std::uint8_t {
  degenerate,  ///< a repeated corner index, or zero area: skipped
  triangle,    ///< three corners, not collinear
  convex,      ///< planar quad whose boundary is strictly convex: the patch is that polygon
  skew,        ///< corners not coplanar (the patch is injective on [0, 1]^2)
  other_flat,  ///< planar quad that is not strictly convex: concave, butterfly, or with a
               ///< straight corner (its patch may fold over itself)
};

bool repeated_corner(const Face& face) noexcept {
  const std::size_t n = face.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (face.corners[i] == face.corners[j]) return true;
  return false;
}

Shape shape_of(const Mesh& mesh, const Face& face) noexcept {
  if (repeated_corner(face)) return Shape::degenerate;
  switch (classify_patch(patch_of(mesh, face))) {
    case PatchShape::segment:
    case PatchShape::point:
      return Shape::degenerate;
    case PatchShape::skew:
      return Shape::skew;
    case PatchShape::convex:
      return face.is_triangle() ? Shape::triangle : Shape::convex;
    case PatchShape::concave:
    case PatchShape::butterfly:
    case PatchShape::degenerate_planar:
      break;
  }
  // The patch {a, b, c, c} of a non-collinear triangle has a repeated corner, so it is
  // degenerate_planar (or convex); any other flat quad is not strictly convex.
  return face.is_triangle() ? Shape::triangle : Shape::other_flat;
}

struct FaceGeometry {
  std::array<Point3, 4> p{};  ///< corners in boundary order (p00, p10, p11, p01)
  std::size_t n = 0;          ///< 3 or 4
  Shape shape = Shape::degenerate;

  /// A triangle or a convex quad: the face is a convex polygon, open face = its interior.
  bool convex_polygon() const noexcept {
    return shape == Shape::triangle || shape == Shape::convex;
  }
  /// Distinct points of the face map to distinct parameters: a triangle, a convex quad,
  /// a skew quad. Then the open face and its boundary edges are disjoint.
  bool injective() const noexcept { return shape != Shape::other_flat; }
  const Point3& corner(std::size_t i) const noexcept { return p[i % n]; }
};

FaceGeometry geometry_of(const Mesh& mesh, const Face& face, Shape shape) noexcept {
  FaceGeometry g;
  g.n = face.size();
  for (std::size_t i = 0; i < g.n; ++i)
    g.p[i] = mesh.vertices[face.corners[i]];
  g.shape = shape;
  return g;
}

// ---------------------------------------------------------------------------------------
// Separating planes.
//
// Every relative-interior point of a face is a combination of all its corners with
// positive weights: barycentric for a triangle, (1-u)(1-v), u(1-v), uv, (1-u)v with
// u, v in (0, 1) for a quad. So if a plane has the corners of one face on its closed
// positive side and those of the other on its closed negative side, and some corner
// strictly off it, the face owning that corner has its whole interior strictly on one
// side while the other face lies on the other closed side: the interiors cannot meet.

/// Which open sides of a plane a set of points reaches.
struct Sides {
  bool positive = false;
  bool negative = false;

  void add(Sign s) noexcept {
    positive = positive || s == Sign::positive;
    negative = negative || s == Sign::negative;
  }
  bool both() const noexcept { return positive && negative; }
  bool any() const noexcept { return positive || negative; }
};

/// The rule above, from the sides reached by each face's corners.
bool separated(const Sides& a, const Sides& b) noexcept {
  if (a.both() || b.both() || (!a.any() && !b.any())) return false;
  return !(a.positive && b.positive) && !(a.negative && b.negative);
}

constexpr std::array<std::array<std::size_t, 3>, 4> kQuadTriples{
    {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};

/// The planes through three corners of `f` (the faces of its corners' convex hull; for a
/// flat face, its plane once), tried against the corners of `f` and `g`.
bool separated_by_corner_plane(const FaceGeometry& f, const FaceGeometry& g) noexcept {
  const std::size_t planes = f.shape == Shape::skew || f.shape == Shape::other_flat ? 4 : 1;
  for (std::size_t t = 0; t < planes; ++t) {
    const auto& [i, j, k] = kQuadTriples[t];
    const auto side = [&](const Point3& x) {
      // A shared corner is on the plane: skip the exact stages that would prove it.
      if (x == f.p[i] || x == f.p[j] || x == f.p[k]) return Sign::zero;
      return orient3d(f.p[i], f.p[j], f.p[k], x);
    };
    Sides of_f;  // a flat face's own corners are all on its plane
    if (f.shape == Shape::skew) of_f.add(side(f.p[3 - t]));  // the corner not in the triple
    if (of_f.both()) continue;
    Sides of_g;
    for (std::size_t c = 0; c < g.n && !of_g.both(); ++c)
      of_g.add(side(g.p[c]));
    if (separated(of_f, of_g)) return true;
  }
  return false;
}

/// The separating axis test along n = (f_j - f_i) x (g_l - g_k) for every pair of corners
/// of each face (the cross products of the hulls' edges). Along n each face's corners
/// project to an interval; the faces are separated when one interval ends where or
/// before the other begins and not all corners project to one value. Projections are
/// compared exactly: n . (x - y) = det[f_j - f_i, g_l - g_k, x - y]. Symmetric in f, g.
class EdgePairAxis {
 public:
  EdgePairAxis(const Point3& fi, const Point3& fj, const Point3& gk, const Point3& gl) noexcept
      : e_(Offset::between(fi, fj)), h_(Offset::between(gk, gl)) {}

  /// sign(n . (x - y)).
  Sign compare(const Point3& x, const Point3& y) const noexcept {
    // x - y = 0 or +-e or +-h: zero without the exact stages (shared corners make these
    // common, and a zero is the filter's most expensive answer).
    if (x == y || along(e_, x, y) || along(h_, x, y)) return Sign::zero;
    return kernel::ExactSigns{}.det3_by_axis(e_, h_, Offset::between(y, x));
  }

  /// Index of a corner with the largest (sense = positive) or smallest projection.
  std::size_t extreme(const FaceGeometry& f, Sign sense) const noexcept {
    std::size_t best = 0;
    for (std::size_t c = 1; c < f.n; ++c)
      if (compare(f.p[c], f.p[best]) == sense) best = c;
    return best;
  }

  bool separates(const FaceGeometry& f, const FaceGeometry& g) const noexcept {
    const std::size_t f_max = extreme(f, Sign::positive), g_min = extreme(g, Sign::negative);
    const Sign f_before_g = compare(f.p[f_max], g.p[g_min]);  // max f - min g
    if (f_before_g == Sign::negative) return true;
    const std::size_t f_min = extreme(f, Sign::negative), g_max = extreme(g, Sign::positive);
    const Sign g_before_f = compare(g.p[g_max], f.p[f_min]);  // max g - min f
    if (g_before_f == Sign::negative) return true;
    if (f_before_g != Sign::zero && g_before_f != Sign::zero) return false;
    // One interval ends exactly where the other begins: separated unless every corner
    // projects to that one value.
    return compare(f.p[f_max], f.p[f_min]) != Sign::zero ||
           compare(g.p[g_max], g.p[g_min]) != Sign::zero;
  }

 private:
  /// {x, y} are the two ends of v.
  static bool along(const Offset& v, const Point3& x, const Point3& y) noexcept {
    const Point3& a = v.head_point();
    const Point3& b = v.tail_point();
    return (x == a && y == b) || (x == b && y == a);
  }

  Offset e_;
  Offset h_;
};

bool separated_by_edge_pair_axis(const FaceGeometry& f, const FaceGeometry& g) noexcept {
  for (std::size_t i = 0; i < f.n; ++i)
    for (std::size_t j = i + 1; j < f.n; ++j)
      for (std::size_t k = 0; k < g.n; ++k)
        for (std::size_t l = k + 1; l < g.n; ++l)
          if (EdgePairAxis(f.p[i], f.p[j], g.p[k], g.p[l]).separates(f, g)) return true;
  return false;
}

// ---------------------------------------------------------------------------------------
// Two convex polygons (triangles, convex quads): exact and complete.

/// orient2d of the projections that drop coordinate `axis`, as orient3d of the points
/// flattened onto that coordinate plane and the unit point on the axis (the determinant
/// reduces to the 2D one, up to a sign fixed by `axis`).
Sign orient2d(const Point3& a, const Point3& b, const Point3& c, std::size_t axis) noexcept {
  const auto flat = [axis](Point3 p) {
    p[axis] = 0.0;
    return p;
  };
  Point3 up{0.0, 0.0, 0.0};
  up[axis] = 1.0;
  return orient3d(flat(a), flat(b), flat(c), up);
}

/// An edge line of convex polygon f (in the common plane, projected along `axis`) with
/// every corner of g on its closed outer side. `inward`: f's orientation in the projection.
bool edge_line_separates(const FaceGeometry& f, const FaceGeometry& g, std::size_t axis,
                         Sign inward) noexcept {
  for (std::size_t i = 0; i < f.n; ++i) {
    bool all_outside = true;
    for (std::size_t c = 0; c < g.n && all_outside; ++c)
      all_outside = orient2d(f.corner(i), f.corner(i + 1), g.p[c], axis) != inward;
    if (all_outside) return true;
  }
  return false;
}

/// Coplanar convex polygons. Facing opposite ways they only touch, by the rule, whether
/// or not they overlap. Facing the same way, their interiors are disjoint exactly when a
/// line weakly separates them, and then one through an edge of either does (the Minkowski
/// difference of two convex polygons has edges parallel to theirs; the origin lies
/// outside its interior exactly when it is on the closed outer side of one of its edge
/// lines).
///
/// Facing: the normals by corner order, n = (p1 - p0) x (p2 - p0) for each, are parallel
/// and nonzero (one plane, first three corners not collinear), so they point the same way
/// exactly when their components on `axis` (nonzero for a, hence for b) have one sign.
/// orient2d(p0, p1, p2, axis) is that sign times a constant: the flattened points lie in
/// the plane x_axis = 0, `up` one unit above it, and the cross product of the flattened
/// differences is (0, .., n[axis], .., 0), the other coordinates dropping out. For a
/// strictly convex quad every three corners in boundary order have the polygon's
/// orientation, so its first three corners give its facing.
FaceContact coplanar_contact(const FaceGeometry& a, const FaceGeometry& b) noexcept {
  // Dropping a coordinate on which the plane's normal is nonzero keeps the configuration.
  std::size_t axis = 0;
  Sign a_facing = orient2d(a.p[0], a.p[1], a.p[2], axis);
  while (axis < 2 && a_facing == Sign::zero)
    a_facing = orient2d(a.p[0], a.p[1], a.p[2], ++axis);
  // Nonzero too: b lies in a's plane and its first three corners are not collinear.
  const Sign b_facing = orient2d(b.p[0], b.p[1], b.p[2], axis);
  if (a_facing != b_facing) return FaceContact::apart;  // the two sides of the surface
  if (edge_line_separates(a, b, axis, a_facing) || edge_line_separates(b, a, axis, b_facing))
    return FaceContact::apart;
  return FaceContact::intersecting;
}

/// One end of the chord in which a plane cuts a convex polygon that has corners strictly
/// on both sides: the crossing point of edge (p, q), p strictly on side `side`, q on the
/// other closed side (q itself when it lies on the plane).
struct ChordEnd {
  const Point3* p;
  const Point3* q;
  Sign side;
};

/// The two chord ends. Precondition: `sides` (of f's corners against the plane) has a
/// positive and a negative entry, and f is a convex polygon, so its boundary crosses the
/// plane exactly twice and the chord's open segment lies in the open polygon.
std::array<ChordEnd, 2> chord_ends(const FaceGeometry& f,
                                   const std::array<Sign, 4>& sides) noexcept {
  std::array<ChordEnd, 2> ends{};
  std::size_t found = 0;
  for (std::size_t i = 0; i < f.n && found < 2; ++i) {
    const Sign s = sides[i], t = sides[(i + 1) % f.n];
    if (s != Sign::zero && t != s) ends[found++] = {&f.p[i], &f.corner(i + 1), s};
  }
  return ends;
}

/// Convex polygons in planes that cross: each cuts the other's plane in a chord, and the
/// open polygons meet exactly when the open chords overlap on the planes' common line L.
///
/// The order of two chord ends along L is one orient3d: for ends k on edge (p, q) of a
/// and m on edge (p', q') of b, with s = side of p against b's plane and s' = side of p'
/// against a's plane, sign(orient3d(p, q, p', q')) = s s' sign(t(m) - t(k)), where t is
/// the coordinate along d = n_a x n_b (write q - p and q' - p' as multiples of k - p and
/// m - p' and expand the determinant in a frame of d and the two normals). Zero means
/// k = m. The chords are disjoint exactly when every end of one is at or before every
/// end of the other.
FaceContact crossing_planes_contact(const FaceGeometry& a, const std::array<Sign, 4>& a_sides,
                                    const FaceGeometry& b,
                                    const std::array<Sign, 4>& b_sides) noexcept {
  Sides order;
  for (const ChordEnd& k : chord_ends(a, a_sides))
    for (const ChordEnd& m : chord_ends(b, b_sides))
      order.add(orient3d(*k.p, *k.q, *m.p, *m.q) * k.side * m.side);
  return order.both() ? FaceContact::intersecting : FaceContact::apart;
}

/// The sides of f's corners against the plane of convex polygon g (its first three
/// corners are not collinear).
std::array<Sign, 4> sides_against(const FaceGeometry& f, const FaceGeometry& g) noexcept {
  std::array<Sign, 4> sides{};
  for (std::size_t c = 0; c < f.n; ++c)
    sides[c] = orient3d(g.p[0], g.p[1], g.p[2], f.p[c]);
  return sides;
}

Sides sides_reached(const std::array<Sign, 4>& sides, std::size_t n) noexcept {
  Sides s;
  for (std::size_t c = 0; c < n; ++c)
    s.add(sides[c]);
  return s;
}

FaceContact convex_polygons_contact(const FaceGeometry& a, const FaceGeometry& b) noexcept {
  const std::array<Sign, 4> a_sides = sides_against(a, b);
  const std::array<Sign, 4> b_sides = sides_against(b, a);
  const Sides a_reach = sides_reached(a_sides, a.n), b_reach = sides_reached(b_sides, b.n);
  if (!b_reach.any()) return coplanar_contact(a, b);
  // Not both sides: the polygon's interior is off the other plane (or the two are
  // coplanar, handled above).
  if (!a_reach.both() || !b_reach.both()) return FaceContact::apart;
  return crossing_planes_contact(a, a_sides, b, b_sides);
}

// ---------------------------------------------------------------------------------------
// The edge method: every edge of one face against the other face.

/// The other face as the ray tests read it: corners 0..n-1 of `geometry`.
struct RayTarget {
  const FaceGeometry* geometry;
  SurfaceFace face;
  PatchFrame frame;

  explicit RayTarget(const FaceGeometry& g) noexcept
      : geometry(&g),
        face(g.n == 3 ? SurfaceFace::triangle(0, 1, 2) : SurfaceFace::patch(0, 1, 2, 3)),
        frame(frame_of(kernel::ExactSigns{}, face, std::span<const Point3>(g.p.data(), g.n))) {}

  /// How the ray {origin + s (to - from) : s > 0} crosses the face. The direction is
  /// the exact difference of the two points, so rays from both ends of an edge run along
  /// one line.
  Crossing ray(const Point3& origin, const Offset& direction) const noexcept {
    const auto corner = [&](VertexIndex i) { return Offset::between(origin, geometry->p[i]); };
    return cross_face(kernel::ExactSigns{}, face, frame, corner, direction);
  }

  bool has_edge(const Point3& x, const Point3& y) const noexcept {
    for (std::size_t i = 0; i < geometry->n; ++i) {
      const Point3& u = geometry->corner(i);
      const Point3& v = geometry->corner(i + 1);
      if ((u == x && v == y) || (u == y && v == x)) return true;
    }
    return false;
  }
};

enum class EdgeCrossing : std::uint8_t { even, odd, undecided };

/// Parity of the crossings of the open segment (from, to) with the face: the crossings
/// of the ray from `from` through `to`, minus those of the ray from `to` onward (`to`
/// itself is not on the face when both rays are decided). nullopt when either ray starts
/// on the face or meets its boundary (or lies in a flat face's plane).
std::optional<bool> segment_parity(const Point3& from, const Point3& to,
                                   const RayTarget& target) noexcept {
  const Offset direction = Offset::between(from, to);
  const Crossing near = target.ray(from, direction);
  if (near == Crossing::origin_on || near == Crossing::degenerate) return std::nullopt;
  const Crossing far = target.ray(to, direction);
  if (far == Crossing::origin_on || far == Crossing::degenerate) return std::nullopt;
  return (near == Crossing::crossed) != (far == Crossing::crossed);
}

EdgeCrossing edge_crossing(const Point3& x, const Point3& y, const RayTarget& target) noexcept {
  if (x == y) return EdgeCrossing::even;  // an empty open segment
  // A shared edge lies on the boundary of an injective face, off its interior.
  if (target.has_edge(x, y))
    return target.geometry->injective() ? EdgeCrossing::even : EdgeCrossing::undecided;
  // A ray that meets the boundary beyond one end may miss it beyond the other.
  std::optional<bool> odd = segment_parity(x, y, target);
  if (!odd) odd = segment_parity(y, x, target);
  if (!odd) return EdgeCrossing::undecided;
  return *odd ? EdgeCrossing::odd : EdgeCrossing::even;
}

/// An edge of one face crossing the other's interior an odd number of times crosses it
/// transversally at some interior point z (multiplicities are 1 or 2, a tangency counts
/// 2), so nearby points of the first face's interior lie on both sides of the second
/// face near z, and the interiors meet.
FaceContact edge_method(const FaceGeometry& a, const FaceGeometry& b) noexcept {
  bool undecided = false;
  for (const auto& [f, g] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
    const RayTarget target(*g);
    for (std::size_t i = 0; i < f->n; ++i) {
      switch (edge_crossing(f->corner(i), f->corner(i + 1), target)) {
        case EdgeCrossing::odd:
          return FaceContact::intersecting;
        case EdgeCrossing::undecided:
          undecided = true;
          break;
        case EdgeCrossing::even:
          break;
      }
    }
  }
  return undecided ? FaceContact::undecided : FaceContact::apart;
}

/// The filters first (cheapest and most often decisive first: on a smooth quad mesh a
/// corner plane of one face settles most neighbours), then the exact method of the pair.
FaceContact contact(const FaceGeometry& a, const FaceGeometry& b) noexcept {
  if (a.shape == Shape::degenerate || b.shape == Shape::degenerate) return FaceContact::apart;
  if (separated_by_corner_plane(a, b) || separated_by_corner_plane(b, a)) return FaceContact::apart;
  if (a.convex_polygon() && b.convex_polygon()) return convex_polygons_contact(a, b);
  if (separated_by_edge_pair_axis(a, b)) return FaceContact::apart;
  // A coplanar pair gets here only with an other-flat quad (a skew quad lies in no plane).
  // Every edge then lies in the other face's plane, so each ray either misses the face or
  // is degenerate: undecided or apart, never intersecting, whichever way the faces face.
  // (A concave or butterfly patch folds over itself, so parts of it face each way.)
  return edge_method(a, b);
}

// ---------------------------------------------------------------------------------------
// Broad phase: a box tree over the faces, traversed against itself.

struct Aabb {
  Point3 lower;
  Point3 upper;
};

/// Closed boxes: touching counts as overlapping.
bool overlap(const Aabb& a, const Aabb& b) noexcept {
  for (std::size_t k = 0; k < 3; ++k)
    if (a.upper[k] < b.lower[k] || b.upper[k] < a.lower[k]) return false;
  return true;
}

Aabb box_of(const Mesh& mesh, const Face& face) noexcept {
  Aabb box{mesh.vertices[face.corners[0]], mesh.vertices[face.corners[0]]};
  for (std::size_t i = 1; i < face.size(); ++i) {
    const Point3& p = mesh.vertices[face.corners[i]];
    for (std::size_t k = 0; k < 3; ++k) {
      box.lower[k] = std::min(box.lower[k], p[k]);
      box.upper[k] = std::max(box.upper[k], p[k]);
    }
  }
  return box;
}

Aabb merged(const Aabb& a, const Aabb& b) noexcept {
  Aabb m = a;
  for (std::size_t k = 0; k < 3; ++k) {
    m.lower[k] = std::min(m.lower[k], b.lower[k]);
    m.upper[k] = std::max(m.upper[k], b.upper[k]);
  }
  return m;
}

/// A binary tree of boxes, split at the median of the box centres along their widest
/// axis; leaves hold at most kLeafSize items.
class BoxTree {
 public:
  explicit BoxTree(std::vector<std::size_t> items, const std::vector<Aabb>& boxes)
      : items_(std::move(items)), boxes_(boxes) {
    if (!items_.empty()) build(0, items_.size());
  }

  /// Calls report(i, j) once for every unordered pair of items with overlapping boxes.
  template <class Report>
  void overlapping_pairs(Report&& report) const {
    if (!nodes_.empty()) self_pairs(0, report);
  }

 private:
  static constexpr std::size_t kLeafSize = 4;

  struct Node {
    Aabb box;
    std::size_t begin = 0, end = 0;   ///< items_[begin, end)
    std::size_t left = 0, right = 0;  ///< children; 0 (the root's index) for a leaf
    bool leaf() const noexcept { return left == 0; }
  };

  std::size_t build(std::size_t begin, std::size_t end) {
    const std::size_t index = nodes_.size();
    nodes_.push_back({boxes_[items_[begin]], begin, end});
    Aabb centres{centre(items_[begin]), centre(items_[begin])};
    for (std::size_t i = begin + 1; i < end; ++i) {
      nodes_[index].box = merged(nodes_[index].box, boxes_[items_[i]]);
      centres = merged(centres, Aabb{centre(items_[i]), centre(items_[i])});
    }
    if (end - begin <= kLeafSize) return index;
    std::size_t axis = 0;
    for (std::size_t k = 1; k < 3; ++k)
      if (centres.upper[k] - centres.lower[k] > centres.upper[axis] - centres.lower[axis]) axis = k;
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(
        items_.begin() + static_cast<std::ptrdiff_t>(begin),
        items_.begin() + static_cast<std::ptrdiff_t>(middle),
        items_.begin() + static_cast<std::ptrdiff_t>(end),
        [&](std::size_t x, std::size_t y) { return centre(x)[axis] < centre(y)[axis]; });
    const std::size_t left = build(begin, middle);
    const std::size_t right = build(middle, end);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
  }

  /// Twice the centre (no rounding of the halving, and only used to split).
  Point3 centre(std::size_t item) const noexcept {
    const Aabb& b = boxes_[item];
    return {b.lower[0] + b.upper[0], b.lower[1] + b.upper[1], b.lower[2] + b.upper[2]};
  }

  template <class Report>
  void self_pairs(std::size_t n, Report& report) const {
    const Node& node = nodes_[n];
    if (node.leaf()) {
      for (std::size_t i = node.begin; i < node.end; ++i)
        for (std::size_t j = i + 1; j < node.end; ++j)
          if (overlap(boxes_[items_[i]], boxes_[items_[j]])) report(items_[i], items_[j]);
      return;
    }
    self_pairs(node.left, report);
    self_pairs(node.right, report);
    cross_pairs(node.left, node.right, report);
  }

  template <class Report>
  void cross_pairs(std::size_t a, std::size_t b, Report& report) const {
    const Node& x = nodes_[a];
    const Node& y = nodes_[b];
    if (!overlap(x.box, y.box)) return;
    if (x.leaf() && y.leaf()) {
      for (std::size_t i = x.begin; i < x.end; ++i)
        for (std::size_t j = y.begin; j < y.end; ++j)
          if (overlap(boxes_[items_[i]], boxes_[items_[j]])) report(items_[i], items_[j]);
      return;
    }
    // Descend into the node with more items (a leaf never splits).
    if (y.leaf() || (!x.leaf() && x.end - x.begin >= y.end - y.begin)) {
      cross_pairs(x.left, b, report);
      cross_pairs(x.right, b, report);
    } else {
      cross_pairs(a, y.left, report);
      cross_pairs(a, y.right, report);
    }
  }

  std::vector<std::size_t> items_;
  const std::vector<Aabb>& boxes_;
  std::vector<Node> nodes_;
};

}  // namespace

std::string_view to_string(FaceContact contact) noexcept {
  switch (contact) {
    case FaceContact::apart:
      return "apart";
    case FaceContact::intersecting:
      return "intersecting";
    case FaceContact::undecided:
      return "undecided";
  }
  return "?";
}

FaceContact face_contact(const Mesh& mesh, std::size_t a, std::size_t b) {
  if (a == b) return FaceContact::apart;
  const Face& fa = mesh.faces[a];
  const Face& fb = mesh.faces[b];
  return contact(geometry_of(mesh, fa, shape_of(mesh, fa)),
                 geometry_of(mesh, fb, shape_of(mesh, fb)));
}

SelfIntersections find_self_intersections(const Mesh& mesh) {
  const std::size_t n = mesh.faces.size();
  std::vector<Shape> shapes(n);
  std::vector<Aabb> boxes(n);
  std::vector<std::size_t> items;
  items.reserve(n);
  for (std::size_t f = 0; f < n; ++f) {
    shapes[f] = shape_of(mesh, mesh.faces[f]);
    boxes[f] = box_of(mesh, mesh.faces[f]);
    if (shapes[f] != Shape::degenerate) items.push_back(f);
  }

  SelfIntersections result;
  const BoxTree tree(std::move(items), boxes);
  tree.overlapping_pairs([&](std::size_t i, std::size_t j) {
    ++result.candidate_pairs;
    const FacePair pair{std::min(i, j), std::max(i, j)};
    switch (contact(geometry_of(mesh, mesh.faces[pair.first], shapes[pair.first]),
                    geometry_of(mesh, mesh.faces[pair.second], shapes[pair.second]))) {
      case FaceContact::intersecting:
        result.intersecting.push_back(pair);
        break;
      case FaceContact::undecided:
        result.undecided.push_back(pair);
        break;
      case FaceContact::apart:
        break;
    }
  });
  std::sort(result.intersecting.begin(), result.intersecting.end());
  std::sort(result.undecided.begin(), result.undecided.end());
  return result;
}

}  // namespace exactgeo::mesh
