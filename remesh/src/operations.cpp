#include "exactgeo/remesh/operations.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <variant>
#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"
#include "operation_checks.hpp"
#include "pass_schedule.hpp"

namespace exactgeo::remesh {

using namespace checks;  // operation_checks.hpp

std::string_view to_string(Verdict v) noexcept {
  switch (v) {
    case Verdict::applied:
      return "applied";
    case Verdict::refused_topology:
      return "refused (topology)";
    case Verdict::refused_collision:
      return "refused (collision)";
    case Verdict::deferred:
      return "deferred";
  }
  return "?";
}

Outcome relocate_vertex(Surface& surface, VertexIndex v, const Point3& to) {
  // A pass of one move: the same checks, one code path.
  const Move move{v, to};
  return relocate_vertices(surface, std::span(&move, 1)).front();
}

namespace {

std::string flipping(VertexIndex a, VertexIndex b) {
  return "flipping edge " + std::to_string(a) + "-" + std::to_string(b);
}

std::string splitting(VertexIndex a, VertexIndex b) {
  return "splitting edge " + std::to_string(a) + "-" + std::to_string(b);
}

/// The refusal of an operation whose new triangle `made` would turn over in the plane of
/// the triangle it replaces (turns_over_in_plane): a fold flat onto the surface around
/// `corner`, the operation's vertex where it folds.
Outcome turns_over(const std::string& operation, const Triangle& made, VertexIndex corner) {
  const Blocker blocker{Blocker::Kind::vertex, {corner, kNoVertex, kNoVertex}};
  return {Verdict::refused_collision,
          operation + " would turn new triangle " + std::to_string(made[0]) + " " +
              std::to_string(made[1]) + " " + std::to_string(made[2]) +
              " over, flat in the plane of the triangle it replaces, folding at " +
              to_string(blocker),
          blocker,
          {}};
}

/// A flip that passed its topology checks: its triangles, their replacements, the region
/// it sweeps.
struct FlipPlan {
  std::size_t t1 = 0;  ///< walks a -> b
  std::size_t t2 = 0;  ///< walks b -> a
  Triangle new1{};
  Triangle new2{};
  std::array<RegionCorner, 4> region{};
};

/// The flip of edge ab, whose triangles are `on_edge`, or the reason it is refused.
/// `edge_exists(c, d)` says whether the surface has edge cd.
template <class EdgeExists>
std::variant<Outcome, FlipPlan> plan_flip(const Surface& surface, VertexIndex a, VertexIndex b,
                                          std::vector<std::size_t> on_edge,
                                          const EdgeExists& edge_exists) {
  if (auto why = edge_problem(surface, a, b, on_edge)) return topology(*why);
  if (on_edge.size() != 2) return topology("a boundary edge cannot be flipped");
  FlipPlan plan{on_edge[0], on_edge[1], {}, {}, {}};
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
  if (has_zero_area(surface, plan.new1) || has_zero_area(surface, plan.new2)) {
    return topology("a flipped triangle would have zero area");
  }
  const auto& p = surface.vertices;
  // In a flat quadrilateral that is not convex, one new triangle would lie over the other:
  // cad turns over when a is the reflex corner (a then lies in dbc), dbc when b is.
  const std::array<Point3, 3> old{p[a], p[b], p[c]};
  for (const auto& [made, reflex] : {std::pair{plan.new1, a}, std::pair{plan.new2, b}}) {
    if (turns_over_in_plane(old, {p[made[0]], p[made[1]], p[made[2]]})) {
      return turns_over(flipping(a, b), made, reflex);
    }
  }
  plan.region = {RegionCorner{a, p[a]}, RegionCorner{b, p[b]}, RegionCorner{c, p[c]},
                 RegionCorner{d, p[d]}};
  return plan;
}

}  // namespace

Outcome flip_edge(Surface& surface, VertexIndex a, VertexIndex b) {
  const auto planned = plan_flip(surface, a, b, {}, [&](VertexIndex c, VertexIndex d) {
    return !surface.triangles_on_edge(c, d).empty();
  });
  if (const auto* refused = std::get_if<Outcome>(&planned)) return *refused;
  const FlipPlan& plan = std::get<FlipPlan>(planned);
  if (auto hit = first_in_region(surface, plan.region)) return collision(*hit, flipping(a, b));
  surface.triangles[plan.t1] = plan.new1;
  surface.triangles[plan.t2] = plan.new2;
  return {};
}

std::vector<Outcome> flip_edges(Surface& surface, std::span<const Edge> edges) {
  const EdgeTriangles table(surface);
  std::vector<Outcome> outcomes(edges.size());
  std::vector<FlipPlan> plans;
  std::vector<std::size_t> planned_edge;  // the edge of each plan
  std::vector<internal::Footprint> footprints;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    // An index out of range finds no triangles here, and plan_flip names it.
    auto planned = plan_flip(surface, a, b, table.on(a, b),
                             [&](VertexIndex c, VertexIndex d) { return !table.on(c, d).empty(); });
    if (auto* refused = std::get_if<Outcome>(&planned)) {
      outcomes[i] = std::move(*refused);
      continue;
    }
    FlipPlan& plan = std::get<FlipPlan>(planned);
    internal::Footprint footprint;
    for (const RegionCorner& corner : plan.region)
      footprint.vertices.push_back(corner.vertex);
    footprint.regions.push_back(plan.region);
    footprints.push_back(std::move(footprint));
    plans.push_back(plan);
    planned_edge.push_back(i);
  }
  // The flips that go ahead change the surface only inside their own regions, which no
  // other one's reaches (pass_schedule.hpp); the others wait for the next pass.
  const std::vector<bool> ahead = internal::go_ahead(footprints, surface.vertices);
  std::vector<std::array<RegionCorner, 4>> regions;
  std::vector<std::size_t> checked;  // the plans going ahead
  for (std::size_t k = 0; k < plans.size(); ++k) {
    if (ahead[k]) {
      regions.push_back(plans[k].region);
      checked.push_back(k);
      continue;
    }
    const Edge& e = edges[planned_edge[k]];
    outcomes[planned_edge[k]] = {
        Verdict::deferred,
        flipping(e[0], e[1]) + " shares a vertex or its region with another flip of the pass",
        {},
        {}};
  }
  const std::vector<std::optional<Blocker>> hits = first_in_regions(surface, regions);
  for (std::size_t n = 0; n < checked.size(); ++n) {
    const FlipPlan& plan = plans[checked[n]];
    const Edge& e = edges[planned_edge[checked[n]]];
    if (hits[n]) {
      outcomes[planned_edge[checked[n]]] = collision(*hits[n], flipping(e[0], e[1]));
      continue;
    }
    surface.triangles[plan.t1] = plan.new1;
    surface.triangles[plan.t2] = plan.new2;
  }
  return outcomes;
}

namespace {

/// A split that passed its topology checks: the edge's triangles, and the regions it
/// sweeps (none when the new vertex lies exactly on the edge).
struct SplitPlan {
  VertexIndex a = 0;
  VertexIndex b = 0;
  Point3 at{};
  std::vector<std::size_t> on_edge;
  std::vector<std::array<RegionCorner, 4>> regions;
  std::vector<VertexIndex> partners;  ///< per region: the other side's opposite corner
};

/// The triangles x m c and m y c that replace each triangle x y c of the edge (walking
/// x -> y along it), for a new vertex numbered m.
std::vector<Triangle> split_triangles(const Surface& surface,
                                      const std::vector<std::size_t>& on_edge, VertexIndex a,
                                      VertexIndex b, VertexIndex m) {
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

/// Whether two of a split's new triangles intersect (exactly, mesh::face_contact): the
/// two sides of an inner edge split off the edge are checked against each other here,
/// not by each other's regions (first_in_region's partner).
bool new_triangles_meet(const Surface& surface, const std::vector<Triangle>& made,
                        const Point3& at) {
  // A small mesh of their corners only (the new vertex is the one past the surface's).
  mesh::Mesh m;
  std::map<VertexIndex, VertexIndex> local;
  const auto corner = [&](VertexIndex v) {
    const auto [it, added] = local.emplace(v, static_cast<VertexIndex>(m.vertices.size()));
    if (added) m.vertices.push_back(v < surface.vertices.size() ? surface.vertices[v] : at);
    return it->second;
  };
  for (const Triangle& t : made)
    m.faces.push_back(mesh::make_triangle(corner(t[0]), corner(t[1]), corner(t[2])));
  for (std::size_t i = 0; i < made.size(); ++i) {
    for (std::size_t j = i + 1; j < made.size(); ++j) {
      if (mesh::face_contact(m, i, j, mesh::CoplanarOverlap::intersecting) !=
          mesh::FaceContact::apart)
        return true;
    }
  }
  return false;
}

std::variant<Outcome, SplitPlan> plan_split(const Surface& surface, VertexIndex a, VertexIndex b,
                                            const Point3& at, std::vector<std::size_t> on_edge) {
  if (auto why = edge_problem(surface, a, b, on_edge)) return topology(*why);
  if (!finite(at)) return topology("the new position is not finite");
  const auto& p = surface.vertices;
  // On the edge's line: only strictly between its ends, where nothing moves.
  bool between = false;
  if (zero_area(p[a], p[b], at)) {
    between = at != p[a] && at != p[b];
    for (int k = 0; k < 3; ++k)
      between =
          between && std::min(p[a][k], p[b][k]) <= at[k] && at[k] <= std::max(p[a][k], p[b][k]);
    if (!between) return topology("the new vertex lies on the edge's line, outside the edge");
  }
  SplitPlan plan{a, b, at, on_edge, {}, {}};
  const auto m = static_cast<VertexIndex>(surface.vertices.size());  // the new vertex
  const std::vector<Triangle> made = split_triangles(surface, on_edge, a, b, m);
  for (std::size_t i = 0; i < on_edge.size(); ++i) {
    const Triangle& old = surface.triangles[on_edge[i]];
    const VertexIndex c = third_corner(old, a, b);
    if (zero_area(p[a], p[c], at) || zero_area(p[b], p[c], at)) {
      return topology("a triangle of the split would have zero area");
    }
    // At a point of the old triangle's plane off the edge, outside the triangle's
    // angle at c, a half would face the other way (lying flat over the other, or the
    // two turned over together).
    const auto point = [&](VertexIndex v) { return v == m ? at : p[v]; };
    for (const Triangle& t : {made[2 * i], made[2 * i + 1]}) {
      if (turns_over_in_plane({p[old[0]], p[old[1]], p[old[2]]},
                              {point(t[0]), point(t[1]), point(t[2])})) {
        return turns_over(splitting(a, b), t, c);
      }
    }
    if (!between) {
      plan.regions.push_back({RegionCorner{a, p[a]}, RegionCorner{b, p[b]}, RegionCorner{c, p[c]},
                              RegionCorner{kNoVertex, at}});
      plan.partners.push_back(
          on_edge.size() == 2 ? third_corner(surface.triangles[on_edge[1 - i]], a, b) : kNoVertex);
    }
  }
  if (!between && on_edge.size() == 2) {
    if (new_triangles_meet(surface, made, at)) {
      return Outcome{Verdict::refused_collision,
                     splitting(a, b) + " off the edge would fold its two sides into each other",
                     Blocker{Blocker::Kind::triangle, surface.triangles[on_edge[1]]},
                     {}};
    }
  }
  return plan;
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
  const auto planned = plan_split(surface, a, b, at, {});
  if (const auto* refused = std::get_if<Outcome>(&planned)) return *refused;
  const SplitPlan& plan = std::get<SplitPlan>(planned);
  for (std::size_t r = 0; r < plan.regions.size(); ++r) {
    if (auto hit = first_in_region(surface, plan.regions[r], plan.partners[r])) {
      return collision(*hit, splitting(a, b));
    }
  }
  return apply_split(surface, plan);
}

std::vector<Outcome> split_edges(Surface& surface, std::span<const Split> splits) {
  const EdgeTriangles table(surface);
  std::vector<Outcome> outcomes(splits.size());
  std::vector<SplitPlan> plans;
  std::vector<std::size_t> planned;  // the split of each plan
  std::vector<internal::Footprint> footprints;
  for (std::size_t i = 0; i < splits.size(); ++i) {
    const Split& s = splits[i];
    auto plan_or = plan_split(surface, s.a, s.b, s.at, table.on(s.a, s.b));
    if (auto* refused = std::get_if<Outcome>(&plan_or)) {
      outcomes[i] = std::move(*refused);
      continue;
    }
    SplitPlan& plan = std::get<SplitPlan>(plan_or);
    internal::Footprint footprint;
    for (const std::size_t t : plan.on_edge) {
      for (const VertexIndex v : surface.triangles[t])
        footprint.vertices.push_back(v);
    }
    footprint.regions = plan.regions;
    footprints.push_back(std::move(footprint));
    plans.push_back(std::move(plan));
    planned.push_back(i);
  }
  // As for flips: the splits that go ahead meet nothing another one makes.
  const std::vector<bool> ahead = internal::go_ahead(footprints, surface.vertices);
  std::vector<std::array<RegionCorner, 4>> regions;
  std::vector<VertexIndex> partners;
  for (std::size_t k = 0; k < plans.size(); ++k) {
    if (!ahead[k]) {
      const Split& s = splits[planned[k]];
      outcomes[planned[k]] = {
          Verdict::deferred,
          splitting(s.a, s.b) + " shares a vertex or its region with another split of the pass",
          {},
          {}};
      continue;
    }
    regions.insert(regions.end(), plans[k].regions.begin(), plans[k].regions.end());
    partners.insert(partners.end(), plans[k].partners.begin(), plans[k].partners.end());
  }
  const std::vector<std::optional<Blocker>> hits = first_in_regions(surface, regions, partners);
  std::size_t next_region = 0;
  for (std::size_t k = 0; k < plans.size(); ++k) {
    if (!ahead[k]) continue;
    std::optional<Blocker> hit;
    for (std::size_t r = 0; r < plans[k].regions.size(); ++r, ++next_region) {
      if (!hit) hit = hits[next_region];
    }
    const Split& s = splits[planned[k]];
    outcomes[planned[k]] =
        hit ? collision(*hit, splitting(s.a, s.b)) : apply_split(surface, plans[k]);
  }
  return outcomes;
}

}  // namespace exactgeo::remesh
