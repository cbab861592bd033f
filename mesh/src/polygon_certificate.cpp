#include "polygon_certificate.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <optional>

#include "polygon_sweep.hpp"

namespace exactgeo::mesh::internal {

bool triangles_fit(const PolygonWalk& walk, std::span<const Face> triangles,
                   std::span<const Point3> vertices, const Projection& plane, Sign turn) {
  if (triangles.size() + 2 != walk.corners) return false;
  ScratchVector<ChainUse> uses;
  uses.reserve(3 * triangles.size());
  for (const Face& t : triangles) {
    if (!t.is_triangle()) return false;
    const std::array<VertexIndex, 3> c{t.corners[0], t.corners[1], t.corners[2]};
    if (plane.orientation(vertices[c[0]], vertices[c[1]], vertices[c[2]]) != turn) return false;
    std::array<std::uint32_t, 3> local{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::optional<std::uint32_t> number = local_number(walk, c[k]);
      if (!number) return false;  // not one of the polygon's corners
      local[k] = *number;
    }
    for (std::size_t k = 0; k < 3; ++k)
      uses.push_back({local[k], local[(k + 1) % 3]});
  }
  const ScratchVector<ChainEdge> boundary = chain_of(uses, walk.vertices.size());
  // The two chains' pairs of non-zero coefficient, side by side.
  const auto next_nonzero = [](const ScratchVector<ChainEdge>& chain, std::size_t k) {
    while (k < chain.size() && chain[k].coefficient == 0)
      ++k;
    return k;
  };
  std::size_t a = next_nonzero(walk.edges, 0);
  std::size_t b = next_nonzero(boundary, 0);
  for (; a < walk.edges.size() && b < boundary.size();
       a = next_nonzero(walk.edges, a + 1), b = next_nonzero(boundary, b + 1)) {
    if (!(walk.edges[a] == boundary[b])) return false;
  }
  return a == walk.edges.size() && b == boundary.size();
}

namespace {

/// An edge of a chain between vertex indices: low < high, +1 for a use from low to high.
struct Use {
  VertexIndex low;
  VertexIndex high;
  int way;
};

/// Each pair once, by (low, high), with its net coefficient (0 kept).
ScratchVector<Use> merged(ScratchVector<Use> uses) {
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) {
    return a.low < b.low || (a.low == b.low && a.high < b.high);
  });
  ScratchVector<Use> chain;
  for (const Use& use : uses) {
    if (!chain.empty() && chain.back().low == use.low && chain.back().high == use.high) {
      chain.back().way += use.way;
    } else {
      chain.push_back(use);
    }
  }
  return chain;
}

Use use_of(VertexIndex a, VertexIndex b) {
  return {std::min(a, b), std::max(a, b), a < b ? 1 : -1};
}

/// The interiors of triangles t and u (projections turning as `turn`) are disjoint: their
/// boxes meet at most on a line, or a line through an edge of one has the other on its
/// closed outer side.
bool interiors_disjoint(const std::array<const Point3*, 3>& t,
                        const std::array<const Point3*, 3>& u, const Projection& plane, Sign turn) {
  for (const auto coordinate : {&Projection::u, &Projection::v}) {
    const auto along = [&](const std::array<const Point3*, 3>& a) {
      return std::minmax(
          {(plane.*coordinate)(*a[0]), (plane.*coordinate)(*a[1]), (plane.*coordinate)(*a[2])});
    };
    const auto [t_low, t_high] = along(t);
    const auto [u_low, u_high] = along(u);
    if (t_high <= u_low || u_high <= t_low) return true;
  }
  const auto outside_an_edge = [&](const std::array<const Point3*, 3>& a,
                                   const std::array<const Point3*, 3>& b) {
    for (std::size_t e = 0; e < 3; ++e) {
      // A shared corner lies on the line: known without the (exact, zero) sign.
      if (std::all_of(b.begin(), b.end(), [&](const Point3* x) {
            return x == a[e] || x == a[(e + 1) % 3] ||
                   plane.orientation(*a[e], *a[(e + 1) % 3], *x) != turn;
          })) {
        return true;
      }
    }
    return false;
  };
  return outside_an_edge(t, u) || outside_an_edge(u, t);
}

}  // namespace

bool few_triangles_tile(std::span<const VertexIndex> corners, std::span<const Face> triangles,
                        std::span<const Point3> vertices, const Projection& plane, Sign turn) {
  const std::size_t n = corners.size();
  if (triangles.size() + 2 != n) return false;
  ScratchVector<Use> walk_uses;
  walk_uses.reserve(n);
  for (std::size_t k = 0; k < n; ++k)
    walk_uses.push_back(use_of(corners[k], corners[k + 1 == n ? 0 : k + 1]));
  ScratchVector<Use> triangle_uses;
  triangle_uses.reserve(3 * triangles.size());
  ScratchVector<std::array<const Point3*, 3>> points;
  points.reserve(triangles.size());
  for (const Face& t : triangles) {
    if (!t.is_triangle()) return false;
    const std::array<const Point3*, 3> c{&vertices[t.corners[0]], &vertices[t.corners[1]],
                                         &vertices[t.corners[2]]};
    if (plane.orientation(*c[0], *c[1], *c[2]) != turn) return false;
    points.push_back(c);
    for (std::size_t k = 0; k < 3; ++k)
      triangle_uses.push_back(use_of(t.corners[k], t.corners[(k + 1) % 3]));
  }
  const ScratchVector<Use> walk = merged(std::move(walk_uses));
  ScratchVector<Use> boundary = merged(std::move(triangle_uses));
  ScratchVector<Use> walk_boundary;
  std::copy_if(walk.begin(), walk.end(), std::back_inserter(walk_boundary),
               [](const Use& use) { return use.way != 0; });
  std::erase_if(boundary, [](const Use& use) { return use.way == 0; });
  if (!std::equal(walk_boundary.begin(), walk_boundary.end(), boundary.begin(), boundary.end(),
                  [](const Use& a, const Use& b) {
                    return a.low == b.low && a.high == b.high && a.way == b.way;
                  })) {
    return false;
  }
  // A bridge (a pair walked both ways, coefficient 0) bounds no triangle, so the tiling
  // says nothing of it: it must not have zero length nor meet another edge of the walk
  // other than at a common endpoint. (An edge that bounds triangles cannot cross another,
  // nor have a corner inside it, once the triangles tile: the triangles of that corner
  // would overlap the edge's.)
  const auto ends = [&](const Use& use) {
    const Point3& a = vertices[use.low];
    const Point3& b = vertices[use.high];
    return plane.before(a, b) ? std::array{&a, &b} : std::array{&b, &a};
  };
  for (const Use& bridge : walk) {
    if (bridge.way != 0) continue;
    const auto [a0, a1] = ends(bridge);
    if (plane.same(*a0, *a1)) return false;
    for (const Use& other : walk) {
      if (other.low == bridge.low && other.high == bridge.high) continue;
      const auto [b0, b1] = ends(other);
      if (plane.same(*b0, *b1) || segments_meet_improperly(*a0, *a1, *b0, *b1, plane)) {
        return false;
      }
    }
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      if (!interiors_disjoint(points[i], points[j], plane, turn)) return false;
    }
  }
  return true;
}

bool triangles_tile_polygon(std::span<const VertexIndex> corners, std::span<const Face> triangles,
                            std::span<const Point3> vertices, int axis) {
  const ScratchVector<VertexIndex> walked = without_repeats(corners);
  if (walked.size() < 3) return false;
  const PolygonWalk walk = walk_of(walked);
  const Projection plane(axis);
  const std::optional<Sign> turn =
      region_turn(walk, sweep_order(walk, vertices, plane), vertices, plane);
  return turn && triangles_fit(walk, triangles, vertices, plane, *turn);
}

}  // namespace exactgeo::mesh::internal
