// flip_edge and flip_edges: the triangles abc and bad on edge ab replaced by cad and dbc,
// applied when nothing meets the closed hull of a, b, c, d (swept_region.hpp) and neither
// new triangle turns over flat in the old ones' plane.
//
// A pass plans its flips in four steps, the cheap ones first, so that the exact work is
// spent on the flips that can go ahead: the topology of each (its two triangles, no edge
// cd yet); which flips share no vertex with an earlier one; the geometry of those (no
// zero area, no turn-over); which of those sweep regions apart from the earlier ones'
// (pass_schedule.hpp). Then the regions are checked against the surface in one walk.

#include <array>
#include <cstddef>
#include <cstdint>
#include <variant>
#include <vector>

#include "exactgeo/remesh/operations.hpp"
#include "operation_checks.hpp"
#include "pass_plans.hpp"
#include "pass_schedule.hpp"
#include "pass_workspace.hpp"

namespace exactgeo::remesh {

using namespace internal;  // operation_checks.hpp, pass_plans.hpp, pass_schedule.hpp

namespace {

std::string flipping(VertexIndex a, VertexIndex b) {
  return operation_name("flipping", a, b);
}

/// The topology of the flip of edge ab, whose triangles are `on_edge`: the plan, or the
/// reason it is refused. `edge_exists(c, d)` says whether the surface has edge cd.
template <class EdgeExists>
std::variant<Outcome, FlipPlan> flip_topology(const Surface& surface, VertexIndex a, VertexIndex b,
                                              std::vector<std::size_t>& on_edge,
                                              const EdgeExists& edge_exists) {
  if (auto why = edge_problem(surface, a, b, on_edge)) return topology(*why);
  if (on_edge.size() != 2) return topology("a boundary edge cannot be flipped");
  FlipPlan plan{a, b, on_edge[0], on_edge[1], {}, {}};
  if (!walks(surface.triangles[plan.t1], a, b)) std::swap(plan.t1, plan.t2);
  if (!walks(surface.triangles[plan.t1], a, b) || !walks(surface.triangles[plan.t2], b, a)) {
    return topology("the edge's triangles are not oriented alike");
  }
  const VertexIndex c = third_corner(surface.triangles[plan.t1], a, b);
  const VertexIndex d = third_corner(surface.triangles[plan.t2], a, b);
  if (c == d) return topology("the edge's triangles share their third corner");
  if (edge_exists(c, d)) {
    return topology("the flip would duplicate edge " + std::to_string(c) + "-" + std::to_string(d));
  }
  plan.new1 = {c, a, d};
  plan.new2 = {d, b, c};
  return plan;
}

/// The geometry of a planned flip: nullopt, or why it is refused (a new triangle of zero
/// area, or one turned over in a flat quadrilateral that is not convex: cad turns over
/// when a is the reflex corner, and then lies in dbc; dbc when b is).
std::optional<Outcome> flip_geometry(const Surface& surface, const FlipPlan& plan) {
  if (has_zero_area(surface, plan.new1) || has_zero_area(surface, plan.new2)) {
    return topology("a flipped triangle would have zero area");
  }
  const auto& p = surface.vertices;
  const VertexIndex c = plan.new1[0];
  const std::array<Point3, 3> old{p[plan.a], p[plan.b], p[c]};
  for (const auto& [made, reflex] : {std::pair{plan.new1, plan.a}, std::pair{plan.new2, plan.b}}) {
    if (turns_over_in_plane(old, {p[made[0]], p[made[1]], p[made[2]]})) {
      return turns_over(flipping(plan.a, plan.b), made, reflex);
    }
  }
  return std::nullopt;
}

void apply_flip(Surface& surface, const FlipPlan& plan) {
  surface.triangles[plan.t1] = plan.new1;
  surface.triangles[plan.t2] = plan.new2;
}

}  // namespace

Outcome flip_edge(Surface& surface, VertexIndex a, VertexIndex b) {
  std::vector<std::size_t> on_edge;
  const auto planned = flip_topology(surface, a, b, on_edge, [&](VertexIndex c, VertexIndex d) {
    return !surface.triangles_on_edge(c, d).empty();
  });
  if (const auto* refused = std::get_if<Outcome>(&planned)) return *refused;
  const FlipPlan& plan = std::get<FlipPlan>(planned);
  if (auto refused = flip_geometry(surface, plan)) return *refused;
  if (auto hit = first_in_region(surface, plan.region(surface)))
    return collision(*hit, flipping(a, b));
  apply_flip(surface, plan);
  return {};
}

std::vector<Outcome> flip_edges(Surface& surface, std::span<const Edge> edges,
                                PassWorkspace* workspace, TriangleChanges* changes) {
  if (changes != nullptr) changes->reset(surface.triangles.size());
  PassWorkspace own;  // used when the caller keeps none
  PassWorkspace::Arrays& kept = arrays_of(workspace, own);
  // The triangles on the proposed edges ab, and whether edge cd exists for their third
  // corners c and d, from a table of the triangles around a, b, c and d only, not of the
  // whole surface (a remesher's pass proposes a few edges of many): one of the triangles
  // around a and b finds c and d, a second one the triangles around all four. An edge
  // with a marked end has all its triangles in the table (each has that corner).
  EdgeTriangles& table = kept.edges;
  std::vector<std::uint8_t>& marked = kept.marked;
  marked.assign(surface.vertices.size(), 0);
  for (const Edge& e : edges) {
    for (const VertexIndex v : e)
      if (v < marked.size()) marked[v] = 1;  // an index out of range finds no triangles
  }
  table.assign_marked(surface.triangles, surface.vertices.size(), marked);
  std::vector<std::size_t> on_edge;  // reused from flip to flip
  for (const Edge& e : edges) {
    table.on(e[0], e[1], on_edge);
    for (const std::size_t t : on_edge) {
      for (const VertexIndex v : surface.triangles[t])
        marked[v] = 1;
    }
  }
  table.assign_marked(surface.triangles, surface.vertices.size(), marked);
  std::vector<Outcome> outcomes(edges.size());
  // 1. Topology.
  std::vector<FlipPlan>& plans = kept.flip_plans;
  std::vector<std::size_t>& edge_of_plan = kept.operation_of_plan;
  plans.clear();
  edge_of_plan.clear();
  plans.reserve(edges.size());  // one allocation, not a chain of growing copies
  edge_of_plan.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    // An index out of range finds no triangles here, and flip_topology names it.
    table.on(a, b, on_edge);
    auto planned = flip_topology(surface, a, b, on_edge,
                                 [&](VertexIndex c, VertexIndex d) { return table.has(c, d); });
    if (auto* refused = std::get_if<Outcome>(&planned)) {
      outcomes[i] = std::move(*refused);
      continue;
    }
    plans.push_back(std::get<FlipPlan>(planned));
    edge_of_plan.push_back(i);
  }
  // 2. No shared vertex with an earlier flip that goes ahead.
  std::vector<std::array<VertexIndex, 4>>& by_vertices = kept.by_vertices;
  by_vertices.resize(plans.size());
  for (std::size_t k = 0; k < plans.size(); ++k)
    by_vertices[k] = plans[k].corners();
  const std::vector<bool> apart = internal::share_no_vertex(by_vertices, surface.vertices.size());
  // 3. Geometry, and 4. regions apart from the earlier ones'.
  std::vector<std::size_t>& candidates = kept.candidates;
  candidates.clear();
  std::vector<internal::Footprint> by_regions;
  for (std::size_t k = 0; k < plans.size(); ++k) {
    const std::size_t i = edge_of_plan[k];
    const auto [a, b] = edges[i];
    if (!apart[k]) {
      outcomes[i] = deferred("flipping", a, b, "shares a vertex with another flip of the pass");
    } else if (auto refused = flip_geometry(surface, plans[k])) {
      outcomes[i] = std::move(*refused);
    } else {
      candidates.push_back(k);
      by_regions.push_back({{}, {plans[k].region(surface)}});
    }
  }
  const std::vector<bool> ahead = internal::go_ahead(by_regions, surface.vertices);
  std::vector<std::array<RegionCorner, 4>>& regions = kept.regions;
  std::vector<std::size_t>& checked = kept.checked;
  regions.clear();
  checked.clear();
  for (std::size_t n = 0; n < candidates.size(); ++n) {
    const std::size_t k = candidates[n];
    const auto [a, b] = edges[edge_of_plan[k]];
    if (!ahead[n]) {
      outcomes[edge_of_plan[k]] =
          deferred("flipping", a, b, "sweeps a region that meets another flip's of the pass");
      continue;
    }
    regions.push_back(plans[k].region(surface));
    checked.push_back(k);
  }
  // The flips that go ahead change the surface only inside their own regions, which no
  // other one's reaches (pass_schedule.hpp): each is checked on the surface before the pass.
  const std::vector<std::optional<Blocker>> hits =
      internal::first_in_regions(surface, regions, {}, kept.region_query);
  for (std::size_t n = 0; n < checked.size(); ++n) {
    const FlipPlan& plan = plans[checked[n]];
    if (hits[n]) {
      outcomes[edge_of_plan[checked[n]]] = collision(*hits[n], flipping(plan.a, plan.b));
      continue;
    }
    if (changes != nullptr)
      record_rewrites(surface, std::array<std::size_t, 2>{plan.t1, plan.t2}, *changes);
    apply_flip(surface, plan);
  }
  if (changes != nullptr) sort_rewrites(*changes);
  return outcomes;
}

}  // namespace exactgeo::remesh
