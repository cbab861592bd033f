#include "exactgeo/remesh/swept_region.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numeric>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "exactgeo/boxes/exact_grid.hpp"
#include "exactgeo/boxes/point_groups.hpp"
#include "exactgeo/predicates/orient3d.hpp"
#include "exactgeo/predicates/segment_triangle.hpp"
#include "region_points.hpp"

namespace exactgeo::remesh {

namespace {

/// A point with the vertex it is (kNoVertex for a new point).
struct Corner {
  VertexIndex vertex;
  const Point3* point;
};

/// The closed segment ab meets the closed triangle t outside their shared corners.
bool edge_meets_triangle(const std::array<Corner, 2>& ab, const std::array<Corner, 3>& t) {
  int shared = 0;  // how many corners of t the segment shares
  int k = -1;      // the last of them, in t
  int shared_in_ab = -1;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (ab[i].vertex != kNoVertex && ab[i].vertex == t[j].vertex) {
        ++shared;
        k = j;
        shared_in_ab = i;
      }
    }
  }
  if (shared >= 2) return false;  // an edge of the triangle
  if (shared == 0) {
    return segment_meets_triangle(*ab[0].point, *ab[1].point, *t[0].point, *t[1].point,
                                  *t[2].point);
  }
  return segment_meets_triangle_beyond(*t[k].point, *ab[1 - shared_in_ab].point,
                                       *t[(k + 1) % 3].point, *t[(k + 2) % 3].point);
}

/// The coordinate axis the plane of p, q, r is most turned toward, in floating point (a
/// choice, not a decision), when the shadow of p, q, r along it is a triangle; otherwise
/// the first axis along which it is (shadow_axis). Precondition: p, q, r not collinear.
int shadow_axis_of(const Point3& p, const Point3& q, const Point3& r) noexcept {
  const double ux = q[0] - p[0], uy = q[1] - p[1], uz = q[2] - p[2];
  const double vx = r[0] - p[0], vy = r[1] - p[1], vz = r[2] - p[2];
  const std::array<double, 3> n{std::fabs(uy * vz - uz * vy), std::fabs(uz * vx - ux * vz),
                                std::fabs(ux * vy - uy * vx)};
  const int axis = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
  if (orient2d_along(axis, p, q, r) != Sign::zero) return axis;
  return *shadow_axis(p, q, r);
}

class Region {
 public:
  /// `volume`: orient3d of the four corners in order, when the caller knows it.
  explicit Region(const std::array<RegionCorner, 4>& corners,
                  std::optional<Sign> volume = std::nullopt) {
    if (volume) set_volume(*volume);
    for (int i = 0; i < 4; ++i)
      corners_[i] = {corners[i].vertex, &corners[i].point};
    // The hull's shadow on a coordinate plane is a convex polygon, whose sides are the
    // corner pairs with the other two corners on one closed side of their line, not both
    // on it; the plane along the shadow axis through such a side has the whole hull on
    // that side. The axis: the one the first three corners' plane is most turned toward
    // (in floating point, a choice only; its shadow of those three is checked to be a
    // triangle, so that a flat hull's shadow is its polygon, one to one).
    axis_ = shadow_axis_of(*corners_[0].point, *corners_[1].point, *corners_[2].point);
    // Each three corners' turn in the shadow, asked once: orient2d_along is the exact sign
    // of a determinant, which changes sign when two of its points swap, so corners i, j, k
    // (i < j) turn as the three in increasing order do, the other way when k lies between
    // i and j. (A split's thin region has its new point all but on the edge's line: that
    // turn falls to exact arithmetic, and the sides below ask it three times.)
    std::array<Sign, 4> turn{};  // of the three corners other than l, in increasing order
    for (int l = 0; l < 4; ++l) {
      const auto t = face_opposite(l);
      turn[l] = orient2d_along(axis_, *t[0].point, *t[1].point, *t[2].point);
    }
    for (int e = 0; e < 6; ++e) {
      const auto [i, j] = kPairs[e];
      Sign inward = Sign::zero;
      bool side = true;
      unsigned on = (1u << i) | (1u << j);
      for (int k = 0; k < 4; ++k) {
        if (k == i || k == j) continue;
        const Sign turn_ijk = turn[6 - i - j - k];  // the corner left out is 6 - i - j - k
        const Sign s = i < k && k < j ? -turn_ijk : turn_ijk;
        if (s == Sign::zero) {
          on |= 1u << k;
        } else if (inward == Sign::zero) {
          inward = s;
        } else if (s != inward) {
          side = false;
        }
      }
      if (side && inward != Sign::zero) {
        inward_side_[e] = inward;
        on_side_[e] = on;
      }
    }
  }

  // The separating planes a point x lies strictly beyond, as bits, each a plane with the
  // whole region on its other closed side: bit l (0-3) for the face of a tetrahedron
  // opposite corner l; bit 4 + e for a side of the shadow (corner pair e, kPairs), x's
  // shadow strictly beyond its line; bits 10 and 11 for a flat region's plane, x strictly
  // off it on either side. An element whose corners all lie strictly beyond one of them is
  // apart from the region (and so, by on_faces and on_sides, when some of them are region corners
  // on it).

  /// The bits of the faces or of a flat region's plane (kPlaneBits).
  unsigned beyond_planes(const Point3& x) const noexcept {
    orient();
    unsigned mask = 0;
    if (volume_ != Sign::zero) {
      for (int l = 0; l < 4; ++l) {
        if (beyond_face(l, x)) mask |= 1u << l;
      }
      return mask;
    }
    const Sign off = orient3d(*corners_[0].point, *corners_[1].point, *corners_[2].point, x);
    if (off != Sign::zero) mask = off == Sign::positive ? 1u << 10 : 1u << 11;
    return mask;
  }

  /// Bit l of beyond_planes for a tetrahedron: x strictly beyond its face opposite corner
  /// l. Precondition: not flat.
  bool beyond_face(int l, const Point3& x) const noexcept {
    orient();
    const auto t = face_opposite(l);
    return orient3d(*t[0].point, *t[1].point, *t[2].point, x) == -inward_[l];
  }

  /// The bits of the shadow's sides (kSideBits).
  unsigned beyond_sides(const Point3& x) const noexcept {
    unsigned mask = 0;
    for (int e = 0; e < 6; ++e) {
      if (inward_side_[e] == Sign::zero) continue;
      const auto [i, j] = kPairs[e];
      if (orient2d_along(axis_, *corners_[i].point, *corners_[j].point, x) == -inward_side_[e])
        mask |= 1u << (4 + e);
    }
    return mask;
  }

  /// The side of the shadow line through x and y that every corner other than x and y (by
  /// vertex) lies strictly on, or zero when there is none (x and y with one shadow make
  /// every turn zero: no line, no side).
  Sign corners_side_of_line(const Point3& x, VertexIndex xv, const Point3& y,
                            VertexIndex yv) const noexcept {
    Sign side = Sign::zero;
    for (const Corner& c : corners_) {
      if (c.vertex != kNoVertex && (c.vertex == xv || c.vertex == yv)) continue;
      const Sign s = orient2d_along(axis_, x, y, *c.point);
      if (s == Sign::zero || (side != Sign::zero && s != side)) return Sign::zero;
      side = s;
    }
    return side;
  }

  /// The side of the plane of the triangle t (its corners' vertices tv) that every corner
  /// other than t's (by vertex) lies strictly on, or zero when there is none (a triangle of
  /// zero area makes every orientation zero).
  Sign corners_side_of_plane(const std::array<const Point3*, 3>& t,
                             const Triangle& tv) const noexcept {
    Sign side = Sign::zero;
    for (const Corner& c : corners_) {
      if (c.vertex != kNoVertex && (c.vertex == tv[0] || c.vertex == tv[1] || c.vertex == tv[2]))
        continue;
      const Sign off = orient3d(*t[0], *t[1], *t[2], *c.point);
      if (off == Sign::zero || (side != Sign::zero && off != side)) return Sign::zero;
      side = off;
    }
    return side;
  }

  int axis() const noexcept { return axis_; }

  static constexpr unsigned kPlaneBits = 0xFu | (1u << 10) | (1u << 11);
  static constexpr unsigned kSideBits = 0x3Fu << 4;

  /// The separating planes that region corner k lies on: a tetrahedron's faces
  /// through it, the sides' planes through it (its own sides, and a side whose line its
  /// shadow lies on), a flat region's plane. An element whose every corner is strictly
  /// beyond one such plane or a region corner (by vertex index) on it meets the plane only
  /// in the hull of those shared corners, and the region, on the plane's other closed
  /// side, nowhere else: apart, beyond what it shares. In two parts, as the bits of
  /// beyond_planes and beyond_sides: the faces or a flat region's plane (kPlaneBits), and
  /// the sides (kSideBits).
  unsigned on_faces(int k) const noexcept {
    orient();
    return volume_ != Sign::zero ? 0xFu & ~(1u << k) : (1u << 10) | (1u << 11);
  }
  unsigned on_sides(int k) const noexcept {
    unsigned mask = 0;
    for (int e = 0; e < 6; ++e) {
      if (inward_side_[e] != Sign::zero && (on_side_[e] >> k & 1u) != 0) mask |= 1u << (4 + e);
    }
    return mask;
  }

  /// Which corner vertex v is (by index), or -1.
  int corner_of(VertexIndex v) const noexcept {
    for (int k = 0; k < 4; ++k) {
      if (corners_[k].vertex != kNoVertex && corners_[k].vertex == v) return k;
    }
    return -1;
  }

  bool is_corner(VertexIndex v) const noexcept {
    return std::any_of(corners_.begin(), corners_.end(),
                       [v](const Corner& c) { return c.vertex == v; });
  }

  /// x in the closed hull.
  bool holds(const Point3& x) const noexcept {
    orient();
    if (volume_ == Sign::zero) {  // flat: the union of the four corner triangles
      for (const auto& t : triangles()) {
        if (orient3d(*t[0].point, *t[1].point, *t[2].point, x) != Sign::zero) return false;
        if (in_triangle_of_its_plane(*t[0].point, *t[1].point, *t[2].point, x)) return true;
      }
      return false;
    }
    // A tetrahedron: on no face's far side (the side away from the opposite corner).
    return beyond_planes(x) == 0;
  }

  bool flat() const noexcept {
    orient();
    return volume_ == Sign::zero;
  }

  /// The four corner triangles: the tetrahedron's faces, or the flat hull's cover.
  std::array<std::array<Corner, 3>, 4> triangles() const noexcept {
    return {face_opposite(0), face_opposite(1), face_opposite(2), face_opposite(3)};
  }

  std::array<std::array<Corner, 2>, 6> edges() const noexcept {
    const auto& c = corners_;
    return {{{c[0], c[1]}, {c[0], c[2]}, {c[0], c[3]}, {c[1], c[2]}, {c[1], c[3]}, {c[2], c[3]}}};
  }

 private:
  std::array<Corner, 3> face_opposite(int l) const noexcept {
    std::array<Corner, 3> t{};
    int n = 0;
    for (int i = 0; i < 4; ++i) {
      if (i != l) t[n++] = corners_[i];
    }
    return t;
  }

  static constexpr std::array<std::array<int, 2>, 6> kPairs{
      {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

  std::array<Corner, 4> corners_{};
  /// The hull's volume's sign and each face's inward side, worked out when first asked: a
  /// split's rounding-thin region leaves these orientations to exact arithmetic, and its
  /// shadow's sides usually decide without them.
  void orient() const noexcept {
    if (oriented_) return;
    set_volume(
        orient3d(*corners_[0].point, *corners_[1].point, *corners_[2].point, *corners_[3].point));
  }
  void set_volume(Sign volume) const noexcept {
    oriented_ = true;
    volume_ = volume;
    if (volume_ == Sign::zero) return;
    // orient3d(face opposite l, corner l) is the volume's sign times the parity of the
    // corners' order (an exact determinant's sign changes with every swap): (1 2 3 0) and
    // (0 1 3 2) are odd, (0 2 3 1) and (0 1 2 3) even. One orient3d, not five: a split's
    // thin region leaves each to exact arithmetic.
    for (int l = 0; l < 4; ++l)
      inward_[l] = l % 2 == 1 ? volume_ : -volume_;
  }

  mutable bool oriented_ = false;
  mutable Sign volume_ = Sign::zero;
  /// the side of face l (opposite corner l) that corner l is on
  mutable std::array<Sign, 4> inward_{};
  int axis_ = 0;  ///< the shadow's axis
  /// per corner pair, the side of its line the other two corners are on in the shadow, or
  /// zero when the pair is no side (they are on both sides, or all on the line)
  std::array<Sign, 6> inward_side_{};
  std::array<unsigned, 6> on_side_{};  ///< per side: the corners on its line, as bits
};

/// The face of a tetrahedral region that an edge need not be tested against (by the
/// corner it is opposite), or -1 to test all four: a flat region, or an edge with two
/// region corners. `preferred`: the corner whose opposite face is dearest to test (a
/// split's a b m, corner 2, whose orientations fall to exact arithmetic, as a, b and m
/// are all but collinear), left out unless the edge has that corner.
///
/// Why three faces decide (edge_meets' precondition: neither end of the edge that is no
/// region corner lies in the closed tetrahedron T, which first_in and regions_meet test
/// first). Let F be a face of T holding every corner the edge shares with T (at most one;
/// S, their hull, is that corner or empty). Suppose the edge meets T at a point y outside
/// S. Its part in T is a segment [s1, s2] (a point when s1 = s2), and an end of the edge
/// in T is a shared corner, so it is s1 or s2. (1) y inside T: s1 and s2 lie on T's
/// boundary on either side of y. Were both on F alone, or one the shared corner (on F)
/// and the other on F, the segment would lie in F's plane, which holds no inner point of
/// T; so one of them that is not in S lies on a face other than F. (2) The part in T in
/// T's boundary: it lies in one closed face (the supporting plane at its midpoint holds
/// it). On a face other than F, done. In F: if y lies on an edge of F, it lies on another
/// face too; otherwise y is inside F and not an end of the edge (an end in T is in S), so
/// the edge lies in F's plane through y, and its part in T is a segment of F whose two
/// ends lie on F's edges (an end of the edge there is a corner of T), one of them not in
/// S, and on another face. So the edge meets T outside S exactly when it meets one of the
/// other three faces outside S: the answer of all four. A face without the shared corner
/// cannot be left out: an edge from the opposite corner through T leaves it through that
/// face alone.
int face_left_out(const Region& region, const std::array<Corner, 2>& edge, int preferred) {
  if (region.flat()) return -1;  // the cover's triangles are no faces: all are needed
  const int k0 = region.corner_of(edge[0].vertex), k1 = region.corner_of(edge[1].vertex);
  if (k0 >= 0 && k1 >= 0) return -1;
  const int shared = k0 >= 0 ? k0 : k1;
  if (shared != preferred) return preferred;
  return preferred == 3 ? 2 : 3;
}

/// The corner face_left_out prefers: 2 for a split's region (corner 3 its new point), 3
/// otherwise (a flip's faces cost alike).
int preferred_corner(const std::array<RegionCorner, 4>& corners) {
  return corners[3].vertex == kNoVertex ? 2 : 3;
}

/// An edge of the surface crosses or touches the region outside their shared corners
/// (given that neither end that is no region corner lies in the region: face_left_out),
/// by the region's triangles.
bool edge_meets(const Region& region, const std::array<Corner, 2>& edge, int preferred) {
  const auto triangles = region.triangles();
  const int left_out = face_left_out(region, edge, preferred);
  for (int l = 0; l < 4; ++l) {
    if (l != left_out && edge_meets_triangle(edge, triangles[l])) return true;
  }
  return false;
}

/// An edge of the region crosses or touches a triangle of the surface outside their
/// shared corners.
bool pierces(const Region& region, const std::array<Corner, 3>& triangle) {
  const auto edges = region.edges();
  return std::any_of(edges.begin(), edges.end(),
                     [&](const auto& e) { return edge_meets_triangle(e, triangle); });
}

}  // namespace

bool turns_over_in_plane(const std::array<Point3, 3>& old, const std::array<Point3, 3>& made) {
  for (const Point3& q : made) {
    if (q == old[0] || q == old[1] || q == old[2]) continue;  // a corner: in the plane
    if (orient3d(old[0], old[1], old[2], q) != Sign::zero) return false;
  }
  const int axis = *shadow_axis(old[0], old[1], old[2]);
  return orient2d_along(axis, made[0], made[1], made[2]) !=
         orient2d_along(axis, old[0], old[1], old[2]);
}

std::string to_string(const Blocker& blocker) {
  std::string s = blocker.kind == Blocker::Kind::vertex ? "vertex"
                  : blocker.kind == Blocker::Kind::edge ? "edge"
                                                        : "triangle";
  for (const VertexIndex v : blocker.corners) {
    if (v != kNoVertex) s.append(" ").append(std::to_string(v));
  }
  return s;
}

namespace {

/// The elements of the surface near one region: the triangles whose exact boxes meet its
/// exact box (found by a grid of the pass's regions, boxes/exact_grid.hpp), their corners,
/// each once, and their edges (the triangles' sides). Every element that meets the region
/// has its box meeting the region's box, and so has a triangle of it; the others are
/// tested and pass. Only what is left after the
/// separating planes is sorted: first_in reports the least element meeting the region,
/// in the order first_in_region reports them (vertices by index, then edges by their
/// ends, then triangles by index).
struct NearbyElements {
  static constexpr std::uint32_t kAbsent = ~std::uint32_t{0};

  std::vector<VertexIndex> vertices;
  std::span<const std::size_t> triangles;
  /// Per vertex, for first_in: which region corner it is, and its separating planes.
  std::vector<int> corner;
  std::vector<unsigned> first, second;
  /// Per vertex, for a tetrahedron's faces asked one at a time: which are known, and of
  /// those, which it lies strictly beyond (bit l for the face opposite corner l).
  std::vector<unsigned> face_known, face_beyond;
  /// Per vertex of the surface: its place in `vertices`, or kAbsent.
  std::vector<std::uint32_t> slot;
  /// first_in's edges and triangles that no separating plane passes over, to be tested.
  std::vector<Edge> edges_to_test;
  std::vector<std::size_t> triangles_to_test;
  /// Per triangle of `triangles`, for first_in: whether the region lies beyond its plane
  /// (kPlaneUnknown until asked).
  std::vector<std::uint8_t> beyond_plane;
  static constexpr std::uint8_t kPlaneUnknown = 2;

  explicit NearbyElements(std::size_t vertex_count) : slot(vertex_count, kAbsent) {}

  /// Gathers the elements of the triangles `near` (reusing this object's storage from one
  /// region to the next).
  void gather(const Surface& surface, std::span<const std::size_t> near) {
    for (const VertexIndex v : vertices)
      slot[v] = kAbsent;
    vertices.clear();
    triangles = near;
    for (const std::size_t t : triangles) {
      for (const VertexIndex v : surface.triangles[t]) {
        if (slot[v] != kAbsent) continue;
        slot[v] = static_cast<std::uint32_t>(vertices.size());
        vertices.push_back(v);
      }
    }
  }
};

std::optional<Blocker> first_in(const Surface& surface, NearbyElements& near,
                                const std::array<RegionCorner, 4>& corners, VertexIndex partner,
                                std::optional<Sign> volume) {
  // By the argument at the top of the header: a vertex in the hull, an edge meeting one of
  // its triangles, or one of its edges meeting a triangle (the corners and edges of a
  // triangle are the surface's own vertices and edges, tested before it).
  const Region region(corners, volume);
  const auto& p = surface.vertices;
  // The operation's own elements: those of the region's corners only, and the partner's
  // triangle abd (a, b: the first two corners), which the split replaces. Not its corner d
  // or its edges ad and bd, which stay (in the new triangles amd and mbd): the region must
  // not hold them beyond the corners they share with it, nor must any triangle at d (a
  // triangle acd next to the split is not the operation's).
  const VertexIndex edge_a = corners[0].vertex, edge_b = corners[1].vertex;
  const auto on_other_side = [&](VertexIndex v) {  // a corner of triangle abd
    return v == edge_a || v == edge_b || v == partner;
  };
  const bool has_partner = partner != kNoVertex;
  // Each nearby vertex's separating planes (Region::beyond_planes, beyond_sides): those
  // it lies strictly beyond, and for a region corner those it lies on. An element whose
  // corners have one in common meets the region at most in the hull of its corners that
  // are the region's (Region::on_faces, on_sides): it is passed over, as the tests below would pass
  // it. One kind first, the other only for the elements the first leaves: the shadow's
  // sides for a flat region or a split's (orient3d against a flat region's plane is an
  // exact zero for a vertex of its sheet, and a face of a split's rounding-thin region
  // leaves its orientations to expansions), the faces for a flip's (a vertex on a side's
  // line, common on a grid, costs an exact zero in the shadow).
  const bool sides_first =
      std::any_of(corners.begin(), corners.end(),
                  [](const RegionCorner& c) { return c.vertex == kNoVertex; }) ||
      region.flat();
  constexpr unsigned kUnknown = ~0u;
  std::vector<int>& corner = near.corner;
  std::vector<unsigned>& first = near.first;
  std::vector<unsigned>& second = near.second;
  corner.resize(near.vertices.size());
  first.resize(near.vertices.size());
  second.assign(near.vertices.size(), kUnknown);
  const auto bits = [&](std::size_t i, bool sides) {
    if (corner[i] >= 0) return sides ? region.on_sides(corner[i]) : region.on_faces(corner[i]);
    const Point3& x = p[near.vertices[i]];
    return sides ? region.beyond_sides(x) : region.beyond_planes(x);
  };
  for (std::size_t i = 0; i < near.vertices.size(); ++i) {
    corner[i] = region.corner_of(near.vertices[i]);
    first[i] = bits(i, sides_first);
  }
  const auto second_of = [&](std::size_t i) {
    if (second[i] == kUnknown) second[i] = bits(i, !sides_first);
    return second[i];
  };
  // A tetrahedron's faces after the sides (a split's region) are asked one at a time,
  // when needed, the face opposite corner 2 last: a split's region is a, b, c, m, and a, b
  // and m are all but collinear, so that face's orientations fall to exact arithmetic,
  // where another face usually decides first. The answers are those of every face's bit
  // (second_of): an element is passed over when its corners all lie beyond one face, a
  // vertex is inside when it lies beyond none.
  const bool faces_one_at_a_time = sides_first && !region.flat();
  std::vector<unsigned>& face_known = near.face_known;
  std::vector<unsigned>& face_beyond = near.face_beyond;
  if (faces_one_at_a_time) {
    face_known.assign(near.vertices.size(), 0);
    face_beyond.assign(near.vertices.size(), 0);
  }
  constexpr std::array<int, 4> kFaceOrder{3, 0, 1, 2};
  const auto beyond_face = [&](std::size_t i, int l) {
    if (corner[i] >= 0) return (region.on_faces(corner[i]) >> l & 1u) != 0;
    if ((face_known[i] >> l & 1u) == 0) {
      face_known[i] |= 1u << l;
      if (region.beyond_face(l, p[near.vertices[i]])) face_beyond[i] |= 1u << l;
    }
    return (face_beyond[i] >> l & 1u) != 0;
  };
  const auto index_of = [&](VertexIndex v) -> std::size_t { return near.slot[v]; };
  // An element apart from the region by a line L of its own in the shadow (along the
  // region's axis): an edge's line, or a triangle's side with its third corner on L or on
  // the other side from the region's corners. Every corner of the region that is no
  // corner of the element (by vertex) lies strictly on one side of L, and the element's
  // shadow on the closed other side, so a common point of the two lies over L; the
  // region's points over L are the convex combinations of its corners on L (a corner
  // strictly off L has weight zero there), which are shared corners: the common points lie
  // in the hull of the shared corners, and the element is apart beyond what it shares.
  // Exact: orient2d_along signs; a zero proves nothing (an element whose shadow is a point
  // has none but zeros). Asked of a tetrahedron's elements only: its corners are
  // affinely independent, so an element apart beyond what it shares meets each of its
  // faces and edges only in their own shared corners, and the segment tests below would
  // pass it too (a flat region's tests may report more, tests/remesh/swept_region_test.cpp,
  // Deviations); the blocker reported, the least element that meets the region, is the
  // same.
  const auto element_apart_in_shadow = [&](std::initializer_list<std::size_t> at) {
    const std::size_t* c = at.begin();
    const auto vertex = [&](std::size_t k) { return near.vertices[c[k]]; };
    const int n = static_cast<int>(at.size());
    for (int k = 0; k < (n == 2 ? 1 : 3); ++k) {
      const VertexIndex x = vertex(k), y = vertex((k + 1) % n);
      const Sign side = region.corners_side_of_line(p[x], x, p[y], y);
      if (side == Sign::zero) continue;
      if (n == 2 || orient2d_along(region.axis(), p[x], p[y], p[vertex((k + 2) % 3)]) != side)
        return true;
    }
    return false;
  };
  // A triangle of the surface apart from the region by its own plane: every corner of the
  // region that is no corner of the triangle lies strictly on one side of it, so the
  // region meets the plane only in the hull of the shared corners (its points there are
  // the convex combinations of its corners on the plane), and the triangle and its edges,
  // which lie in the plane, meet the region only there: apart beyond what they share (an
  // edge's shared corners are the triangle's on it, whose hull the edge meets only in
  // them: a corner strictly off the plane makes the triangle's area non-zero). Exact:
  // orient3d signs. Asked of a tetrahedron's elements only, as element_apart_in_shadow;
  // once per triangle (by its place in near.triangles), for it and its edges.
  std::vector<std::uint8_t>& beyond_plane = near.beyond_plane;
  beyond_plane.assign(near.triangles.size(), NearbyElements::kPlaneUnknown);
  const auto apart_by_plane_of = [&](std::size_t j) {
    if (beyond_plane[j] == NearbyElements::kPlaneUnknown) {
      const Triangle& c = surface.triangles[near.triangles[j]];
      beyond_plane[j] =
          region.corners_side_of_plane({&p[c[0]], &p[c[1]], &p[c[2]]}, c) != Sign::zero;
    }
    return beyond_plane[j] != 0;
  };
  // Whether the corners (indices into near.vertices) are all beyond one separating plane:
  // the first kind's (cheap, asked first), then the others, with the plane of the
  // element's triangle (near.triangles[j]) before a split's thin face.
  const auto apart_by_first = [&](std::initializer_list<std::size_t> at) {
    unsigned common = ~0u;
    for (const std::size_t i : at)
      common &= first[i];
    return common != 0;
  };
  const auto beyond_all = [&](std::initializer_list<std::size_t> at, int l) {
    for (const std::size_t i : at) {
      if (!beyond_face(i, l)) return false;
    }
    return true;
  };
  const auto apart_by_second = [&](std::initializer_list<std::size_t> at, std::size_t j) {
    if (faces_one_at_a_time) {
      // The face opposite corner 2 (a b m, a split's rounding-thin face, whose
      // orientations fall to exact arithmetic) after the element's own lines in the
      // shadow: the elements the sides and the other faces leave are mostly edges and
      // triangles around a region corner (the link of its star), on both sides of it,
      // which a line of their own keeps apart, or elements of another layer close to the
      // region, which the plane of their triangle keeps apart.
      return beyond_all(at, 3) || beyond_all(at, 0) || beyond_all(at, 1) ||
             element_apart_in_shadow(at) || apart_by_plane_of(j) || beyond_all(at, 2);
    }
    unsigned common = ~0u;
    for (const std::size_t i : at)
      common &= second_of(i);
    return common != 0;
  };
  // The least of each kind that meets the region (NearbyElements is unsorted: the edges
  // and triangles left to test are sorted, each once, and tested from the least up to the
  // first that meets it; an edge of two nearby triangles is then tested once).
  std::optional<VertexIndex> vertex;
  for (std::size_t i = 0; i < near.vertices.size(); ++i) {
    const VertexIndex v = near.vertices[i];
    if (corner[i] >= 0 || (vertex && *vertex < v)) continue;
    // Strictly beyond a separating plane: outside (a tetrahedron's vertex is inside
    // exactly when it is beyond none of its faces; a flat region's, when it is on its
    // plane, beyond none of its sides, and in one of its corner triangles).
    const auto beyond_none = [&] {
      if (!faces_one_at_a_time) return second_of(i) == 0;
      return std::none_of(kFaceOrder.begin(), kFaceOrder.end(),
                          [&](int l) { return beyond_face(i, l); });
    };
    const bool inside = first[i] == 0 && beyond_none() && (!region.flat() || region.holds(p[v]));
    if (inside) vertex = v;
  }
  if (vertex) return Blocker{Blocker::Kind::vertex, {*vertex, kNoVertex, kNoVertex}};
  std::vector<Edge>& edges = near.edges_to_test;
  edges.clear();
  for (std::size_t j = 0; j < near.triangles.size(); ++j) {
    const Triangle& c = surface.triangles[near.triangles[j]];
    for (int k = 0; k < 3; ++k) {
      const Edge e = edge_of(c[k], c[(k + 1) % 3]);
      const std::initializer_list<std::size_t> at{index_of(e[0]), index_of(e[1])};
      if (apart_by_first(at)) continue;                                // beyond one plane
      if (region.is_corner(e[0]) && region.is_corner(e[1])) continue;  // own
      if (apart_by_second(at, j)) continue;                            // beyond one plane
      edges.push_back(e);
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  // No vertex that is no region corner lies in the region (above): edge_meets' precondition.
  const int preferred = preferred_corner(corners);
  for (const Edge& e : edges) {
    if (edge_meets(region, {Corner{e[0], &p[e[0]]}, Corner{e[1], &p[e[1]]}}, preferred))
      return Blocker{Blocker::Kind::edge, {e[0], e[1], kNoVertex}};
  }
  std::vector<std::size_t>& triangles = near.triangles_to_test;
  triangles.clear();
  for (std::size_t j = 0; j < near.triangles.size(); ++j) {
    const std::size_t t = near.triangles[j];
    const Triangle& c = surface.triangles[t];
    const std::initializer_list<std::size_t> at{index_of(c[0]), index_of(c[1]), index_of(c[2])};
    if (apart_by_first(at)) continue;  // beyond one plane
    if (region.is_corner(c[0]) && region.is_corner(c[1]) && region.is_corner(c[2])) continue;
    // abd (its corners are distinct)
    if (has_partner && on_other_side(c[0]) && on_other_side(c[1]) && on_other_side(c[2])) continue;
    if (apart_by_second(at, j)) continue;  // beyond one plane
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());  // each once: the query finds a pair once
  for (const std::size_t t : triangles) {
    const Triangle& c = surface.triangles[t];
    if (pierces(region, {Corner{c[0], &p[c[0]]}, Corner{c[1], &p[c[1]]}, Corner{c[2], &p[c[2]]}}))
      return Blocker{Blocker::Kind::triangle, c};
  }
  return std::nullopt;
}

}  // namespace

std::optional<Blocker> first_in_region(const Surface& surface,
                                       const std::array<RegionCorner, 4>& corners,
                                       VertexIndex partner) {
  return first_in_regions(surface, std::span(&corners, 1), std::span(&partner, 1)).front();
}

std::vector<std::optional<Blocker>> first_in_regions(
    const Surface& surface, std::span<const std::array<RegionCorner, 4>> regions,
    std::span<const VertexIndex> partners) {
  internal::RegionQuery query;
  return internal::first_in_regions(surface, regions, partners, query);
}

std::vector<std::optional<Blocker>> internal::first_in_regions(
    const Surface& surface, std::span<const std::array<RegionCorner, 4>> regions,
    std::span<const VertexIndex> partners, RegionQuery& query, std::span<const Sign> volumes) {
  query.boxed.assign(surface.vertices, regions);
  // The triangles near each region: those whose exact boxes meet its exact box
  // (boxes/exact_grid.hpp), every triangle first_in needs (an element that meets the
  // region has its exact box meeting the region's, and so has every triangle it is
  // part of).
  query.pairs.clear();
  boxes::overlapping_groups_by_grid<4, 3>(
      query.boxed.points, std::span<const std::array<VertexIndex, 4>>(query.boxed.groups),
      surface.vertices, std::span<const Triangle>(surface.triangles),
      [&](std::size_t r, std::size_t t) { query.pairs.emplace_back(r, t); }, query.grid);
  query.near.assign(regions.size(), query.pairs);
  std::vector<std::optional<Blocker>> found;
  found.reserve(regions.size());
  NearbyElements elements(surface.vertices.size());
  for (std::size_t r = 0; r < regions.size(); ++r) {
    elements.gather(surface, query.near.of(r));
    found.push_back(first_in(surface, elements, regions[r],
                             partners.empty() ? kNoVertex : partners[r],
                             volumes.empty() ? std::nullopt : std::optional<Sign>(volumes[r])));
  }
  return found;
}

bool regions_meet(const std::array<RegionCorner, 4>& x, const std::array<RegionCorner, 4>& y) {
  // Convex sets meet exactly when a corner of one lies in the other or an edge of one
  // meets a triangle of the other (the header's argument with no shared corner: the
  // corners are taken as points, so two at one place meet).
  const auto as_points = [](std::array<RegionCorner, 4> corners) {
    for (RegionCorner& c : corners)
      c.vertex = kNoVertex;
    return corners;
  };
  const std::array<RegionCorner, 4> px = as_points(x), py = as_points(y);
  const Region rx(px), ry(py);
  // Apart when one's corners all lie strictly beyond one separating plane of the other
  // (Region::beyond_planes, beyond_sides: the other lies on its other closed side). Most pairs a
  // pass asks about end here, before the segment-triangle tests.
  const auto apart_by = [&](bool sides) {
    for (const auto& [a, b_corners] : {std::pair{&rx, &py}, std::pair{&ry, &px}}) {
      unsigned common = ~0u;
      for (const RegionCorner& c : *b_corners)
        common &= sides ? a->beyond_sides(c.point) : a->beyond_planes(c.point);
      if (common != 0) return true;
    }
    return false;
  };
  // The sides first when a region has a new point (a split's, rounding-thin: its faces'
  // orientations fall to exact arithmetic), the faces first otherwise (on a grid, a
  // corner on a side's line costs an exact zero in the shadow).
  const auto is_new = [](const RegionCorner& c) { return c.vertex == kNoVertex; };
  const bool sides_first =
      std::any_of(x.begin(), x.end(), is_new) || std::any_of(y.begin(), y.end(), is_new);
  if (apart_by(sides_first) || apart_by(!sides_first)) return false;
  for (const auto& [a, b, a_corners] : {std::tuple{&rx, &ry, &px}, std::tuple{&ry, &rx, &py}}) {
    for (const RegionCorner& c : *a_corners) {
      if (b->holds(c.point)) return true;
    }
    // No corner of a lies in b (just tested), and the corners are points sharing nothing:
    // edge_meets' precondition.
    const int preferred = preferred_corner(b == &rx ? x : y);
    for (const auto& edge : a->edges()) {
      if (edge_meets(*b, edge, preferred)) return true;
    }
  }
  return false;
}

}  // namespace exactgeo::remesh
