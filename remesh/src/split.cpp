// split_edge and split_edges: edge ab split at a new vertex m, each of its triangles x y c
// (walking x -> y along the edge) replaced by x m c and m y c. A point exactly inside the
// edge moves nothing; any other point sweeps, for each triangle, the hull of a, b, c and
// m (swept_region.hpp, with the other side's triangle as the region's partner), and the
// two sides' new triangles are checked against each other.
//
// A pass plans in the order flip.cpp's does: topology (the edge's triangles), no shared
// vertex with an earlier split going ahead, geometry (where m is, no zero area or
// turn-over, the two sides apart), regions apart from the earlier ones'; then the regions
// against the surface in one walk.

#include <algorithm>
#include <array>
#include <cstdint>
#include <variant>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "exactgeo/predicates/orient3d.hpp"
#include "exactgeo/predicates/segment_triangle.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "operation_checks.hpp"
#include "pass_plans.hpp"
#include "pass_schedule.hpp"
#include "pass_workspace.hpp"

namespace exactgeo::remesh {

using namespace internal;  // operation_checks.hpp, pass_plans.hpp, pass_schedule.hpp

namespace {

std::string splitting(VertexIndex a, VertexIndex b) {
  return operation_name("splitting", a, b);
}

/// The triangles x m c and m y c that replace each triangle x y c of the edge (walking
/// x -> y along it), for a new vertex numbered m.
std::vector<Triangle> split_triangles(const Surface& surface, const EdgeTrianglesOfOne& on_edge,
                                      VertexIndex a, VertexIndex b, VertexIndex m) {
  std::vector<Triangle> made;
  for (const std::size_t t : on_edge) {
    const Triangle& old = surface.triangles[t];
    const VertexIndex x = walks(old, a, b) ? a : b;
    const VertexIndex y = x == a ? b : a;
    const VertexIndex c = third_corner(old, a, b);
    made.push_back({x, m, c});
    made.push_back({m, y, c});
  }
  return made;
}

/// Whether a new triangle of one side of an inner edge meets one of the other side's
/// outside their shared corners (exactly, mesh::face_contact, a flat overlap counting):
/// the two sides are not each other's obstacles in their regions (the partner), so they
/// are checked against each other here. The halves of one side tile their region (they
/// face as the old triangle: split_geometry), so only pairs across the edge are tested.
bool sides_meet(const Surface& surface, const std::vector<Triangle>& made, const Point3& at) {
  // A small mesh of their corners only: the new vertex last.
  mesh::Mesh m;
  std::array<VertexIndex, 4> corners{};  // the surface's vertices among them
  std::size_t n = 0;
  const auto local = [&](VertexIndex v) -> VertexIndex {
    if (v >= surface.vertices.size()) return 4;  // the new vertex
    for (std::size_t k = 0; k < n; ++k) {
      if (corners[k] == v) return static_cast<VertexIndex>(k);
    }
    corners[n] = v;
    return static_cast<VertexIndex>(n++);
  };
  std::vector<mesh::Face> faces;
  for (const Triangle& t : made)
    faces.push_back(mesh::make_triangle(local(t[0]), local(t[1]), local(t[2])));
  for (std::size_t k = 0; k < n; ++k)
    m.vertices.push_back(surface.vertices[corners[k]]);
  m.vertices.resize(4, at);  // unused slots, then
  m.vertices.push_back(at);  // the new vertex, at index 4
  m.faces = std::move(faces);
  for (const std::size_t i : {0, 1}) {
    for (const std::size_t j : {2, 3}) {
      if (mesh::face_contact(m, i, j, mesh::CoplanarOverlap::intersecting) !=
          mesh::FaceContact::apart) {
        return true;
      }
    }
  }
  return false;
}

/// Whether the two sides' new triangles of an inner edge ab split at m (off the line ab)
/// are apart, by one of two arguments (docs/remesh.md, "Split"), where sides_meet builds
/// the four triangles' contacts:
///  - the opposite corners c and d lie strictly on opposite sides of the plane of a, b and
///    m: each side's new triangles (x m c, m y c, and x m d, m y d) lie on its closed side
///    and meet that plane only in their edge am or mb, so a new triangle of one side meets
///    one of the other only in am, mb or m, which they share (am and mb meet only at m);
///  - c and d lie in that plane, and the four new triangles (`made`, the new vertex
///    numbered after the surface's) turn the same way in its shadow: they are a fan of
///    four angles around m, each below a half turn, going round once (their sum is a
///    whole number of turns, below two), so they tile without overlap.
/// `off`: orient3d(a, b, c, m) and orient3d(a, b, d, m), which split_geometry has asked
/// (the sides of the plane of a, b and m that c and d lie on, both the other way round: a
/// swap of two points turns an exact determinant's sign, so which is which is the same).
bool sides_apart(const Surface& surface, const SplitPlan& plan, const std::vector<Triangle>& made,
                 const std::array<Sign, 2>& off) {
  const auto& p = surface.vertices;
  const VertexIndex c = third_corner(surface.triangles[plan.on_edge[0]], plan.a, plan.b);
  const Sign sc = off[0], sd = off[1];
  if (sc != Sign::zero || sd != Sign::zero) return sc != Sign::zero && sd == -sc;
  const int axis = *shadow_axis(p[plan.a], p[plan.b], p[c]);
  const auto point = [&](VertexIndex v) -> const Point3& { return v < p.size() ? p[v] : plan.at; };
  const auto turn = [&](const Triangle& t) {
    return orient2d_along(axis, point(t[0]), point(t[1]), point(t[2]));
  };
  const Sign first = turn(made[0]);
  return first != Sign::zero &&
         std::all_of(made.begin(), made.end(), [&](const Triangle& t) { return turn(t) == first; });
}

std::variant<Outcome, SplitPlan> split_topology(const Surface& surface, VertexIndex a,
                                                VertexIndex b, const Point3& at,
                                                std::vector<std::size_t>& on_edge) {
  if (auto why = edge_problem(surface, a, b, on_edge)) return topology(*why);
  SplitPlan plan;
  plan.a = a;
  plan.b = b;
  plan.at = at;
  plan.on_edge = EdgeTrianglesOfOne(on_edge);
  return plan;
}

/// The geometry of a planned split: nullopt with its regions filled in, or why it is
/// refused.
std::optional<Outcome> split_geometry(const Surface& surface, SplitPlan& plan) {
  const VertexIndex a = plan.a, b = plan.b;
  const Point3& at = plan.at;
  if (!finite(at)) return topology("the new position is not finite");
  const auto& p = surface.vertices;
  // On the edge's line: only strictly between its ends, where nothing moves.
  bool between = false;
  if (collinear(p[a], p[b], at)) {
    between = at != p[a] && at != p[b];
    for (int k = 0; k < 3; ++k)
      between =
          between && std::min(p[a][k], p[b][k]) <= at[k] && at[k] <= std::max(p[a][k], p[b][k]);
    if (!between) return topology("the new vertex lies on the edge's line, outside the edge");
  }
  const auto m = static_cast<VertexIndex>(surface.vertices.size());  // the new vertex
  const std::vector<Triangle> made = split_triangles(surface, plan.on_edge, a, b, m);
  const auto point = [&](VertexIndex v) { return v == m ? at : p[v]; };
  std::array<Sign, 2> off{};  // per triangle x y c of the edge: orient3d(a, b, c, m)
  for (std::size_t i = 0; i < plan.on_edge.size(); ++i) {
    const Triangle& old = surface.triangles[plan.on_edge[i]];
    const VertexIndex c = third_corner(old, a, b);
    if (collinear(p[a], p[c], at) || collinear(p[b], p[c], at)) {
      return topology("a triangle of the split would have zero area");
    }
    // At a point of the old triangle's plane off the edge, outside the triangle's angle
    // at c, a half would face the other way (lying flat over the other, or the two
    // turned over together). turns_over_in_plane for both halves, with the plane's side
    // of m asked once: m is each half's only corner that is not one of the old
    // triangle's (at is none of them here: the zero-area checks above refuse that), so
    // off the plane neither half turns over, and in it a half turns over when its shadow
    // turns the other way.
    off[i] = orient3d(p[a], p[b], p[c], at);
    if (off[i] == Sign::zero) {
      const int axis = *shadow_axis(p[old[0]], p[old[1]], p[old[2]]);
      const Sign old_turn = orient2d_along(axis, p[old[0]], p[old[1]], p[old[2]]);
      for (const Triangle& t : {made[2 * i], made[2 * i + 1]}) {
        if (orient2d_along(axis, point(t[0]), point(t[1]), point(t[2])) != old_turn) {
          return turns_over(splitting(a, b), t, c);
        }
      }
    }
  }
  plan.sweeps = !between;
  plan.volume = off;
  if (!between && plan.on_edge.size() == 2 && !sides_apart(surface, plan, made, off) &&
      sides_meet(surface, made, at)) {
    return Outcome{Verdict::refused_collision,
                   splitting(a, b) + " off the edge would fold its two sides into each other",
                   Blocker{Blocker::Kind::triangle, surface.triangles[plan.on_edge[1]]},
                   {}};
  }
  return std::nullopt;
}

/// Makes the planned split: a new vertex, and each triangle x y c (walking x -> y along
/// the edge) replaced by x m c and m y c.
Outcome apply_split(Surface& surface, const SplitPlan& plan) {
  const auto m = static_cast<VertexIndex>(surface.vertices.size());
  const std::vector<Triangle> made = split_triangles(surface, plan.on_edge, plan.a, plan.b, m);
  surface.vertices.push_back(plan.at);
  if (!surface.fixed.empty()) surface.fixed.push_back(false);
  for (std::size_t i = 0; i < plan.on_edge.size(); ++i) {
    surface.triangles[plan.on_edge[i]] = made[2 * i];
    surface.triangles.push_back(made[2 * i + 1]);
  }
  Outcome done;
  done.new_vertex = m;
  return done;
}

}  // namespace

Outcome split_edge(Surface& surface, VertexIndex a, VertexIndex b, const Point3& at) {
  std::vector<std::size_t> on_edge;
  auto planned = split_topology(surface, a, b, at, on_edge);
  if (const auto* refused = std::get_if<Outcome>(&planned)) return *refused;
  SplitPlan& plan = std::get<SplitPlan>(planned);
  if (auto refused = split_geometry(surface, plan)) return *refused;
  for (std::size_t r = 0; r < plan.region_count(); ++r) {
    if (auto hit = first_in_region(surface, plan.region(surface, r), plan.partner(surface, r))) {
      return collision(*hit, splitting(a, b));
    }
  }
  return apply_split(surface, plan);
}

std::vector<Outcome> split_edges(Surface& surface, std::span<const Split> splits,
                                 PassWorkspace* workspace, TriangleChanges* changes) {
  if (changes != nullptr) changes->reset(surface.triangles.size());
  PassWorkspace own;  // used when the caller keeps none
  PassWorkspace::Arrays& kept = arrays_of(workspace, own);
  // The triangles on the proposed edges, from a table of the triangles around their ends
  // only (every triangle on edge ab has corner a), not of the whole surface: a remesher's
  // pass proposes a few edges of many.
  EdgeTriangles& table = kept.edges;
  std::vector<std::uint8_t>& marked = kept.marked;
  marked.assign(surface.vertices.size(), 0);
  for (const Split& s : splits) {
    for (const VertexIndex v : {s.a, s.b})
      if (v < marked.size()) marked[v] = 1;  // an index out of range finds no triangles
  }
  table.assign_marked(surface.triangles, surface.vertices.size(), marked);
  std::vector<Outcome> outcomes(splits.size());
  // 1. Topology.
  std::vector<SplitPlan>& plans = kept.split_plans;
  std::vector<std::size_t>& split_of_plan = kept.operation_of_plan;
  plans.clear();
  split_of_plan.clear();
  plans.reserve(splits.size());  // one allocation, not a chain of growing copies
  split_of_plan.reserve(splits.size());
  std::vector<std::size_t> on_edge;  // reused from split to split
  for (std::size_t i = 0; i < splits.size(); ++i) {
    const Split& s = splits[i];
    table.on(s.a, s.b, on_edge);
    auto planned = split_topology(surface, s.a, s.b, s.at, on_edge);
    if (auto* refused = std::get_if<Outcome>(&planned)) {
      outcomes[i] = std::move(*refused);
      continue;
    }
    plans.push_back(std::get<SplitPlan>(std::move(planned)));
    split_of_plan.push_back(i);
  }
  // 2. No shared vertex with an earlier split that goes ahead.
  // (Its vertices: the edge's ends and its triangles' opposite corners, one or two.)
  std::vector<std::array<VertexIndex, 4>>& by_vertices = kept.by_vertices;
  by_vertices.resize(plans.size());
  for (std::size_t k = 0; k < plans.size(); ++k) {
    const SplitPlan& plan = plans[k];
    by_vertices[k] = {plan.a, plan.b, kNoVertex, kNoVertex};
    for (std::size_t i = 0; i < plan.on_edge.size(); ++i)
      by_vertices[k][2 + i] = third_corner(surface.triangles[plan.on_edge[i]], plan.a, plan.b);
  }
  const std::vector<bool> apart = internal::share_no_vertex(by_vertices, surface.vertices.size());
  // 3. Geometry, and 4. regions apart from the earlier ones'.
  std::vector<std::size_t>& candidates = kept.candidates;
  candidates.clear();
  std::vector<internal::Footprint> by_regions;
  for (std::size_t k = 0; k < plans.size(); ++k) {
    const std::size_t i = split_of_plan[k];
    if (!apart[k]) {
      outcomes[i] = deferred("splitting", plans[k].a, plans[k].b,
                             "shares a vertex with another split of the pass");
    } else if (auto refused = split_geometry(surface, plans[k])) {
      outcomes[i] = std::move(*refused);
    } else {
      candidates.push_back(k);
      internal::Footprint footprint;
      for (std::size_t r = 0; r < plans[k].region_count(); ++r)
        footprint.regions.push_back(plans[k].region(surface, r));
      by_regions.push_back(std::move(footprint));
    }
  }
  const std::vector<bool> ahead = internal::go_ahead(by_regions, surface.vertices);
  std::vector<std::array<RegionCorner, 4>>& regions = kept.regions;
  std::vector<VertexIndex>& partners = kept.partners;
  std::vector<Sign>& volumes = kept.volumes;
  std::vector<std::size_t>& checked = kept.checked;
  regions.clear();
  partners.clear();
  volumes.clear();
  checked.clear();
  for (std::size_t n = 0; n < candidates.size(); ++n) {
    const SplitPlan& plan = plans[candidates[n]];
    if (!ahead[n]) {
      outcomes[split_of_plan[candidates[n]]] = deferred(
          "splitting", plan.a, plan.b, "sweeps a region that meets another split's of the pass");
      continue;
    }
    for (std::size_t r = 0; r < plan.region_count(); ++r) {
      regions.push_back(plan.region(surface, r));
      partners.push_back(plan.partner(surface, r));
      volumes.push_back(plan.volume[r]);
    }
    checked.push_back(candidates[n]);
  }
  // As for flips: the splits that go ahead meet nothing another one makes.
  const std::vector<std::optional<Blocker>> hits =
      internal::first_in_regions(surface, regions, partners, kept.region_query, volumes);
  std::size_t next_region = 0;
  for (const std::size_t k : checked) {
    std::optional<Blocker> hit;
    for (std::size_t r = 0; r < plans[k].region_count(); ++r, ++next_region) {
      if (!hit) hit = hits[next_region];
    }
    const SplitPlan& plan = plans[k];
    if (hit) {
      outcomes[split_of_plan[k]] = collision(*hit, splitting(plan.a, plan.b));
      continue;
    }
    if (changes != nullptr) record_rewrites(surface, plan.on_edge, *changes);
    outcomes[split_of_plan[k]] = apply_split(surface, plan);
  }
  if (changes != nullptr) sort_rewrites(*changes);
  return outcomes;
}

}  // namespace exactgeo::remesh
