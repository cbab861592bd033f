// collapse_edge and collapse_edges: an edge's ends merged at a new point, checked as a
// pseudo-motion (both ends move there on straight lines while everything else stands).
//
// collapse_edge decides one collapse by pair CCD on every pair with a moving corner
// (first_collision); collapse_edges decides a pass through a broad phase around the moving
// vertices (moving_pairs.hpp) that finds the mesh broad phase's pairs that can collide.
// Both are exact, and the pass agrees with the single collapse on every collapse it does
// not defer (tested). The surface after the collapse needs no check of its own: a pair of triangles
// that intersects there was in contact during the motion, through a vertex-face or an
// edge-edge pair the motion check decides (docs/remesh.md, "Collapse", has the argument;
// Collapses.AnEndStateThatIntersectsIsRefusedByTheMotion, the evidence).

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <utility>
#include <variant>
#include <vector>

#include "exactgeo/boxes/point_groups.hpp"
#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/predicates/orient3d.hpp"
#include "exactgeo/predicates/segment_triangle.hpp"
#include "exactgeo/remesh/operations.hpp"
#include "exactgeo/remesh/pseudo_motion.hpp"
#include "moving_pairs.hpp"
#include "one_mover.hpp"
#include "operation_checks.hpp"
#include "pair_order.hpp"
#include "pass_plans.hpp"
#include "pass_schedule.hpp"
#include "pass_workspace.hpp"
#include "region_points.hpp"

namespace exactgeo::remesh {

using namespace internal;  // one_mover.hpp, operation_checks.hpp, pass_plans.hpp,
                           // pass_schedule.hpp

namespace {

std::string collapsing(VertexIndex a, VertexIndex b) {
  return operation_name("collapsing", a, b);
}

/// What plan_collapse reuses from one collapse to the next (a pass plans thousands).
struct PlanScratch {
  std::vector<std::size_t> on_edge;
  std::vector<VertexIndex> opposite, ring_a, ring_b, common;
  std::vector<Triangle> seen;
};

/// The neighbours of v into `sides` (sorted, each once), and whether v is on the boundary
/// (an edge of one triangle: a neighbour seen once among the triangles' sides).
bool ring(const Surface& s, const VertexTriangles& stars, VertexIndex v,
          std::vector<VertexIndex>& sides) {
  sides.clear();
  for (const std::size_t t : stars[v]) {
    for (const VertexIndex c : s.triangles[t])
      if (c != v) sides.push_back(c);
  }
  std::sort(sides.begin(), sides.end());
  bool boundary = false;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j] == sides[i])
      ++j;
    boundary = boundary || j - i == 1;
    i = j;
  }
  sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
  return boundary;
}

std::variant<Outcome, CollapsePlan> plan_collapse(const Surface& s, const VertexTriangles& stars,
                                                  VertexIndex a, VertexIndex b, const Point3& to,
                                                  PlanScratch& scratch) {
  for (const VertexIndex v : {a, b}) {
    if (auto why = vertex_problem(s, v)) return topology(*why);
  }
  std::vector<std::size_t>& on_edge = scratch.on_edge;
  on_edge.clear();
  std::set_intersection(stars[a].begin(), stars[a].end(), stars[b].begin(), stars[b].end(),
                        std::back_inserter(on_edge));
  if (auto why = edge_problem(s, a, b, on_edge)) return topology(*why);
  if (!finite(to)) return topology("the new position is not finite");
  // The link condition: the ends' common neighbours are the opposite corners only.
  std::vector<VertexIndex>& opposite = scratch.opposite;
  opposite.clear();
  for (const std::size_t t : on_edge)
    opposite.push_back(third_corner(s.triangles[t], a, b));
  std::sort(opposite.begin(), opposite.end());
  opposite.erase(std::unique(opposite.begin(), opposite.end()), opposite.end());
  std::vector<VertexIndex>&na = scratch.ring_a, &nb = scratch.ring_b;
  const bool a_on_boundary = ring(s, stars, a, na);
  const bool b_on_boundary = ring(s, stars, b, nb);
  std::vector<VertexIndex>& common = scratch.common;
  common.clear();
  std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
  if (common != opposite) {
    return topology(collapsing(a, b) +
                    " would pinch the surface (the ends share a neighbour beyond its triangles)");
  }
  if (on_edge.size() == 2 && (a_on_boundary || b_on_boundary)) {
    return topology("collapsing an inner edge with an end on the boundary would pinch the surface");
  }
  // The triangles around the merged vertex: none twice, none of zero area.
  const auto at = [&](VertexIndex v) { return v == a || v == b ? to : s.vertices[v]; };
  std::vector<Triangle>& seen = scratch.seen;  // sorted corners
  seen.clear();
  for (const VertexIndex end : {a, b}) {
    for (const std::size_t t : stars[end]) {
      if (std::find(on_edge.begin(), on_edge.end(), t) != on_edge.end()) continue;
      Triangle tri = s.triangles[t];
      std::replace(tri.begin(), tri.end(), b, a);
      if (collinear(at(tri[0]), at(tri[1]), at(tri[2]))) {
        return topology("a triangle around the merged vertex would have zero area");
      }
      std::sort(tri.begin(), tri.end());
      if (std::find(seen.begin(), seen.end(), tri) != seen.end()) {
        return topology("the collapse would duplicate a triangle");
      }
      seen.push_back(tri);
    }
  }
  return CollapsePlan{a, b, to, EdgeTrianglesOfOne(on_edge)};
}

/// Makes the planned collapses on `surface` (the one they were planned on; `stars`, its
/// triangles around each vertex), in place: each edge's triangles gone (the others moved
/// down in order), b replaced by a, both at `to`; what changed into `changes` (when given:
/// TriangleChanges). Only a triangle around some b has a corner replaced, so only those
/// are rewritten, and the kept triangles between two removed ones move down as a run.
void collapse(Surface& surface, const VertexTriangles& stars,
              const std::vector<const CollapsePlan*>& plans, TriangleChanges* changes = nullptr) {
  const std::size_t count = surface.triangles.size();
  if (changes != nullptr) changes->reset(count);
  std::vector<VertexIndex> merged_into(surface.vertices.size(), kNoVertex);
  std::vector<std::size_t> removed, around;  // the edges' triangles; those around the b's
  for (const CollapsePlan* p : plans) {
    if (changes != nullptr) {
      for (const VertexIndex end : {p->a, p->b})
        if (surface.vertices[end] != p->to) changes->moved.push_back(end);
    }
    surface.vertices[p->a] = surface.vertices[p->b] = p->to;
    removed.insert(removed.end(), p->on_edge.begin(), p->on_edge.end());
    const std::span<const std::size_t> star = stars[p->b];
    around.insert(around.end(), star.begin(), star.end());
    merged_into[p->b] = p->a;
  }
  std::sort(removed.begin(), removed.end());
  removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  for (const std::size_t t : around) {
    if (std::binary_search(removed.begin(), removed.end(), t)) continue;
    Triangle tri = surface.triangles[t];
    for (VertexIndex& c : tri)
      if (merged_into[c] != kNoVertex) c = merged_into[c];
    if (changes != nullptr) changes->rewritten.push_back({t, surface.triangles[t]});
    surface.triangles[t] = tri;
  }
  if (changes != nullptr) {
    for (const std::size_t t : removed)
      changes->removed.push_back({t, surface.triangles[t]});
    std::sort(changes->moved.begin(), changes->moved.end());
  }
  // The runs between removed triangles, each moved down past those removed before it.
  auto& triangles = surface.triangles;
  std::size_t kept = removed.empty() ? count : removed[0];
  for (std::size_t i = 0; i < removed.size(); ++i) {
    const std::size_t from = removed[i] + 1;
    const std::size_t to = i + 1 < removed.size() ? removed[i + 1] : count;
    std::copy(triangles.begin() + static_cast<std::ptrdiff_t>(from),
              triangles.begin() + static_cast<std::ptrdiff_t>(to),
              triangles.begin() + static_cast<std::ptrdiff_t>(kept));
    kept += to - from;
  }
  triangles.resize(kept);
}

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
constexpr std::uint32_t kNoStar = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kUnreached = std::numeric_limits<std::uint32_t>::max();

/// The part of the surface the collapses' motions can reach: the triangles around their
/// ends, and every triangle whose box meets the box one of those sweeps (its corners and
/// its collapse's new point), found by box trees; as a small mesh of its own (triangles
/// in surface order, over `vertices`, which maps its indices to the surface's), with the
/// star of each moving end (moving_pairs.hpp) in its indices. Every vertex-face or
/// edge-edge pair with a moving corner whose swept boxes meet lies in it: a static
/// element lies in the box of each of its triangles.
struct Reach {
  std::vector<VertexIndex> vertices;
  std::vector<ccd::Triangle> triangles;
  std::vector<MovingStar> stars;

  /// `around`: the triangles around each vertex of `s`.
  Reach(const Surface& s, const VertexTriangles& around,
        const std::vector<const CollapsePlan*>& plans) {
    // The points of the moving triangles' groups: the surface's vertices, and after them
    // the collapses' new points that lie at neither end. A new point with the bits of an
    // end's position (a collapse into an end: the cloth's) is that end in its groups: the
    // same point, so the same float box, and the largest coordinate of all, which sets
    // the boxes' scale, is the same; so the scan finds the same pairs, and the surface's
    // vertices are not copied to append it.
    std::vector<Point3> elsewhere;
    const auto same_bits = [](const Point3& x, const Point3& y) {
      return std::memcmp(x.data(), y.data(), sizeof(Point3)) == 0;
    };
    std::vector<std::array<VertexIndex, 4>> swept;          // a moving triangle's corners and `to`
    std::vector<std::uint32_t> swept_triangle;              // its index in the surface
    std::vector<std::array<std::uint32_t, 2>> swept_stars;  // the stars of its moving ends
    // Per triangle: kUnreached, or (once reached) its index in the reach, made below.
    std::vector<std::uint32_t> local_triangle(s.triangles.size(), kUnreached);
    const auto reached = [&](std::size_t t) { return local_triangle[t] != kUnreached; };
    // The triangles around the collapses' ends, each once (around both ends: the edge's),
    // found from the stars, not by a walk of every triangle. A triangle has the ends of
    // one collapse only (those going ahead share no vertex around their ends).
    for (const CollapsePlan* p : plans) {
      VertexIndex to = p->a;
      if (same_bits(p->to, s.vertices[p->b])) to = p->b;
      if (!same_bits(p->to, s.vertices[to])) {
        to = static_cast<VertexIndex>(s.vertices.size() + elsewhere.size());
        elsewhere.push_back(p->to);
      }
      const std::size_t first_star = stars.size();
      for (const VertexIndex end : {p->a, p->b}) {
        if (s.vertices[end] != p->to) stars.push_back({end, {}, {}});
      }
      const std::size_t first_swept = swept.size();
      for (const VertexIndex end : {p->a, p->b}) {
        for (const std::size_t t : around[end]) {
          if (reached(t)) continue;
          const Triangle& tri = s.triangles[t];
          swept.push_back({tri[0], tri[1], tri[2], to});
          swept_triangle.push_back(static_cast<std::uint32_t>(t));
          std::array<std::uint32_t, 2> moving{kNoStar, kNoStar};
          for (std::size_t k = first_star; k < stars.size(); ++k) {
            if (std::find(tri.begin(), tri.end(), stars[k].vertex) != tri.end())
              moving[k - first_star] = static_cast<std::uint32_t>(k);
          }
          swept_stars.push_back(moving);
          local_triangle[t] = 0;
        }
      }
      // Near each moving end: every triangle of its collapse (their motions reach beyond
      // their boxes at rest, which the trees see; another collapse's are apart: plan).
      for (std::size_t k = first_star; k < stars.size(); ++k) {
        for (std::size_t g = first_swept; g < swept.size(); ++g)
          stars[k].near.push_back(swept_triangle[g]);
      }
    }
    // The moving triangles against every triangle (region_points.hpp). The scan meets a
    // triangle's groups one after another, so a star's repeat of it is mostly its last (the
    // two trees' walk leaves more repeats, which moving_pairs passes over).
    const auto near_moving = [&](std::size_t g, std::size_t t) {
      local_triangle[t] = 0;
      for (const std::uint32_t k : swept_stars[g]) {
        if (k == kNoStar) continue;
        std::vector<std::uint32_t>& near = stars[k].near;
        if (near.empty() || near.back() != t) near.push_back(static_cast<std::uint32_t>(t));
      }
    };
    std::vector<Point3> joined;
    std::span<const Point3> points = s.vertices;
    if (!elsewhere.empty()) {
      joined.reserve(s.vertices.size() + elsewhere.size());
      joined = s.vertices;
      joined.insert(joined.end(), elsewhere.begin(), elsewhere.end());
      points = joined;
    }
    internal::groups_near_triangles<4>(points, swept, s.triangles, near_moving);
    std::vector<VertexIndex> local(s.vertices.size(), kNoVertex);
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
      if (!reached(t)) continue;
      ccd::Triangle tri{};
      for (std::size_t k = 0; k < 3; ++k) {
        const VertexIndex v = s.triangles[t][k];
        if (local[v] == kNoVertex) {
          local[v] = static_cast<VertexIndex>(vertices.size());
          vertices.push_back(v);
        }
        tri[k] = local[v];
      }
      local_triangle[t] = static_cast<std::uint32_t>(triangles.size());
      triangles.push_back(tri);
    }
    for (MovingStar& star : stars) {
      for (const std::size_t t : around[star.vertex])
        star.around.push_back(local_triangle[t]);
      for (std::uint32_t& t : star.near)
        t = local_triangle[t];
      star.vertex = local[star.vertex];
    }
  }
};

}  // namespace

/// A pass of collapses (CollapsePass, collapse_edges): what its proposals made.
struct CollapsePass::State {
  State(const Surface& surface, PassWorkspace* workspace)
      : surface_(surface),
        kept_(arrays_of(workspace, own_)),
        stars_(kept_.around),
        plans_(kept_.collapse_plans),
        outcome_of_(kept_.operation_of_plan),
        schedule_(surface.vertices.size()) {
    stars_.assign(surface.triangles, surface.vertices.size());
    plans_.clear();
    outcome_of_.clear();
    owner_.assign(surface.vertices.size(), kNone);
  }

  std::span<const std::size_t> triangles_around(VertexIndex v) const { return stars_[v]; }

  /// Whether no vertex around a or b is taken by a collapse going ahead.
  bool could_go_ahead(VertexIndex a, VertexIndex b) const {
    for (const VertexIndex end : {a, b}) {
      if (end >= surface_.vertices.size()) return true;  // propose() refuses it
      for (const std::size_t t : stars_[end]) {
        for (const VertexIndex v : surface_.triangles[t])
          if (schedule_.taken(v)) return false;
      }
    }
    return true;
  }

  /// Plans the collapse and schedules it: one whose surroundings (the vertices of the
  /// triangles around its ends) share a vertex with those of an earlier one that goes
  /// ahead waits for the next pass (its plan read them: the link condition, the
  /// triangles it changes; the other changes them), and so does one whose moving
  /// triangles' boxes meet theirs. The motions of those going ahead are checked together
  /// (refuse_collisions).
  void propose(const Collapse& c) {
    const std::size_t i = outcomes_.size();
    outcomes_.emplace_back();
    auto plan_or = plan_collapse(surface_, stars_, c.a, c.b, c.to, scratch_);
    if (auto* refused = std::get_if<Outcome>(&plan_or)) {
      outcomes_[i] = std::move(*refused);
      return;
    }
    // The vertices around both ends, and the box each triangle with a moving end sweeps.
    footprint_.vertices.clear();
    footprint_.regions.clear();
    const auto moves = [&](VertexIndex v) {
      return (v == c.a || v == c.b) && surface_.vertices[v] != c.to;
    };
    for (const VertexIndex end : {c.a, c.b}) {
      for (const std::size_t t : stars_[end]) {
        const Triangle& tri = surface_.triangles[t];
        footprint_.vertices.insert(footprint_.vertices.end(), tri.begin(), tri.end());
        if (end == c.b && std::find(tri.begin(), tri.end(), c.a) != tri.end()) continue;  // once
        if (!moves(tri[0]) && !moves(tri[1]) && !moves(tri[2])) continue;
        const auto& p = surface_.vertices;
        footprint_.regions.push_back(
            {RegionCorner{tri[0], p[tri[0]]}, RegionCorner{tri[1], p[tri[1]]},
             RegionCorner{tri[2], p[tri[2]]}, RegionCorner{kNoVertex, c.to}});
      }
    }
    if (!schedule_.take(footprint_)) {
      outcomes_[i] = deferred("collapsing", c.a, c.b,
                              "comes near another collapse of the pass (a shared vertex around "
                              "their ends, or their moving triangles' boxes)");
      return;
    }
    const CollapsePlan& plan = std::get<CollapsePlan>(plan_or);
    owner_[plan.a] = owner_[plan.b] = plans_.size();
    plans_.push_back(plan);
    outcome_of_.push_back(i);
  }

  std::vector<Outcome> finish(Surface& surface, TriangleChanges* changes) {
    refuse_collisions();
    if (&surface != &surface_) surface = surface_;
    collapse(surface, stars_, live_plans(), changes);
    return std::move(outcomes_);
  }

 private:
  bool live(std::size_t k) const { return outcomes_[outcome_of_[k]].applied(); }

  std::vector<const CollapsePlan*> live_plans() const {
    std::vector<const CollapsePlan*> out;
    for (std::size_t k = 0; k < plans_.size(); ++k) {
      if (live(k)) out.push_back(&plans_[k]);
    }
    return out;
  }

  /// Refuses the live collapse that moves vertex v, if any; true if it did. (The end a
  /// collapse keeps in place moves nothing: a pair it is in collides by another's motion.)
  bool refuse(VertexIndex v, const Blocker& blocker) {
    const std::size_t k = owner_[v];
    if (k == kNone || !live(k) || surface_.vertices[v] == plans_[k].to) return false;
    outcomes_[outcome_of_[k]] = collision(blocker, collapsing(plans_[k].a, plans_[k].b));
    return true;
  }

  /// v as the pairs see it at the end of the step: a live collapse's b is its a.
  VertexIndex merged(VertexIndex v) const {
    const std::size_t k = owner_[v];
    return k != kNone && live(k) && plans_[k].b == v ? plans_[k].a : v;
  }

  /// The motions of the live collapses, checked together as one step of the part of the
  /// surface they can reach: every collision refuses the collapse whose
  /// motion makes it (no moving triangle of one comes near another's: plan), and the rest
  /// is checked again, until a step is clean.
  void refuse_collisions() {
    const Reach reach(surface_, stars_, live_plans());
    if (reach.triangles.empty()) return;
    std::vector<Point3> start(reach.vertices.size());
    for (std::size_t i = 0; i < start.size(); ++i)
      start[i] = surface_.vertices[reach.vertices[i]];
    const std::vector<double> t0 = ccd::flat_positions(start);
    // The broad phase's pairs, once, in the order step() reports its collisions: a later
    // round's motions are this one's with refused collapses standing still, whose swept
    // boxes lie in the first round's, so its colliding pairs are among these. They are
    // found around the moving ends (moving_pairs.hpp): the pairs of the mesh broad phase
    // of the reach (MeshCcd::candidates) whose swept boxes meet exactly, in its order
    // (the reach's indices); the others it finds (float boxes rounded outward) have boxes
    // apart, which exact CCD finds clear, and a clear pair decides nothing. The narrow
    // phase (exact, as step() runs it) on those that are not the collapse itself (pairs
    // that share a vertex once each live collapse's ends are merged meet at its new point
    // at the end of the step, by construction: a touch exact CCD spends the most on;
    // step() would decide them, and they would be passed over here); a pair's answer is
    // kept for the next round unless one of its corners' motions changed.
    // A pair with a single moving corner (a collapse into one end moves one vertex) is
    // clear without CCD when a plane keeps its swept hull apart (one_mover.hpp).
    ccd::MeshCcdCandidates candidates;
    enum Known : std::int8_t { unknown, clear, colliding };
    std::vector<Known> vf_known, ee_known;
    std::vector<Point3> end = start, previous_end;
    std::vector<bool> moved_differently(start.size(), false);
    std::vector<std::uint8_t> moves(start.size(), 0);  // in this round
    ccd::Options exact;
    exact.method = ccd::Method::exact;
    const auto& global = reach.vertices;  // a reached vertex's index in the surface
    for (bool changed = true, first_round = true; changed; first_round = false) {
      changed = false;
      previous_end = end;
      for (std::size_t i = 0; i < end.size(); ++i) {
        const std::size_t k = owner_[reach.vertices[i]];
        end[i] = k != kNone && live(k) ? plans_[k].to : start[i];
        moved_differently[i] = end[i] != previous_end[i];
        moves[i] = end[i] != start[i] ? 1 : 0;
      }
      // A pair none of whose corners moves in this round (a later round's pair of a refused
      // collapse) is clear here: whatever CCD found, refuse() would find no live collapse
      // moving one of its corners to refuse.
      const auto stands = [&](std::initializer_list<VertexIndex> corners) {
        for (const VertexIndex c : corners)
          if (moves[c] != 0) return false;
        return true;
      };
      const std::vector<double> t1 = ccd::flat_positions(end);
      const ccd::StepPositions positions{t0, t1};
      if (first_round) {
        candidates = moving_pairs(reach.triangles, start, end, reach.stars);
        vf_known.assign(candidates.vertex_face.size(), unknown);
        ee_known.assign(candidates.edge_edge.size(), unknown);
      }
      for (std::size_t n = 0; n < candidates.vertex_face.size(); ++n) {
        const ccd::VertexFacePair& pair = candidates.vertex_face[n];
        const ccd::Triangle& local = reach.triangles[pair.face];
        const Triangle t{global[local[0]], global[local[1]], global[local[2]]};
        const VertexIndex x = global[pair.vertex];
        const VertexIndex v = merged(x);
        if (v == merged(t[0]) || v == merged(t[1]) || v == merged(t[2]))
          continue;  // the collapse itself
        if (vf_known[n] == unknown || moved_differently[pair.vertex] ||
            moved_differently[local[0]] || moved_differently[local[1]] ||
            moved_differently[local[2]]) {
          vf_known[n] = clear;
          if (!stands({pair.vertex, local[0], local[1], local[2]})) {
            const ccd::VertexFaceQuery query =
                ccd::vertex_face_query(positions, reach.triangles, pair);
            if (!one_mover_apart(query) && ccd::vertex_face_ccd(query, exact).collision)
              vf_known[n] = colliding;
          }
        }
        if (vf_known[n] != colliding) continue;
        changed |= refuse(x, {Blocker::Kind::triangle, t});
        for (const VertexIndex c : t)
          changed |= refuse(c, {Blocker::Kind::vertex, {x, kNoVertex, kNoVertex}});
      }
      for (std::size_t n = 0; n < candidates.edge_edge.size(); ++n) {
        const ccd::EdgeEdgePair& pair = candidates.edge_edge[n];
        const std::array<VertexIndex, 2> ea{global[pair.a[0]], global[pair.a[1]]};
        const std::array<VertexIndex, 2> eb{global[pair.b[0]], global[pair.b[1]]};
        const VertexIndex a0 = merged(ea[0]), a1 = merged(ea[1]);
        const VertexIndex b0 = merged(eb[0]), b1 = merged(eb[1]);
        if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) continue;  // the collapse itself
        if (ee_known[n] == unknown || moved_differently[pair.a[0]] ||
            moved_differently[pair.a[1]] || moved_differently[pair.b[0]] ||
            moved_differently[pair.b[1]]) {
          ee_known[n] = clear;
          if (!stands({pair.a[0], pair.a[1], pair.b[0], pair.b[1]})) {
            const ccd::EdgeEdgeQuery query = ccd::edge_edge_query(positions, pair);
            if (!one_mover_apart(query) && ccd::edge_edge_ccd(query, exact).collision)
              ee_known[n] = colliding;
          }
        }
        if (ee_known[n] != colliding) continue;
        const Blocker a{Blocker::Kind::edge, {ea[0], ea[1], kNoVertex}};
        const Blocker b{Blocker::Kind::edge, {eb[0], eb[1], kNoVertex}};
        for (const VertexIndex v : ea)
          changed |= refuse(v, b);
        for (const VertexIndex v : eb)
          changed |= refuse(v, a);
      }
    }
  }

  const Surface& surface_;
  PassWorkspace own_;  ///< used when the caller keeps none
  PassWorkspace::Arrays& kept_;
  VertexTriangles& stars_;  ///< the triangles around each vertex
  std::vector<Outcome> outcomes_;
  std::vector<CollapsePlan>& plans_;      ///< those going ahead
  std::vector<std::size_t>& outcome_of_;  ///< per plan: its collapse's index
  std::vector<std::size_t> owner_;        ///< per vertex: the plan it is an end of, or kNone
  BoxSchedule schedule_;
  PlanScratch scratch_;
  Footprint footprint_;  ///< propose()'s
};

Outcome collapse_edge(Surface& surface, VertexIndex a, VertexIndex b, const Point3& to) {
  PlanScratch scratch;
  const VertexTriangles stars(surface.triangles, surface.vertices.size());
  const auto planned = plan_collapse(surface, stars, a, b, to, scratch);
  if (const auto* refused = std::get_if<Outcome>(&planned)) return *refused;
  const CollapsePlan& plan = std::get<CollapsePlan>(planned);
  const std::array<Move, 2> moves{Move{a, to}, Move{b, to}};
  if (auto hit = first_collision(surface, moves, edge_of(a, b))) {
    return collision(*hit, collapsing(a, b));
  }
  collapse(surface, stars, {&plan});
  return {};
}

CollapsePass::CollapsePass(const Surface& surface, PassWorkspace* workspace)
    : state_(std::make_unique<State>(surface, workspace)) {}
CollapsePass::~CollapsePass() = default;
CollapsePass::CollapsePass(CollapsePass&&) noexcept = default;
CollapsePass& CollapsePass::operator=(CollapsePass&&) noexcept = default;

CollapsePass::State& CollapsePass::state() const {
  if (!state_) throw std::logic_error("remesh::CollapsePass used after finish() or a move");
  return *state_;
}

bool CollapsePass::could_go_ahead(VertexIndex a, VertexIndex b) const {
  return state().could_go_ahead(a, b);
}

std::span<const std::size_t> CollapsePass::triangles_around(VertexIndex v) const {
  return state().triangles_around(v);
}

void CollapsePass::propose(const Collapse& collapse) {
  state().propose(collapse);
}

std::vector<Outcome> CollapsePass::finish(Surface& surface, TriangleChanges* changes) {
  std::vector<Outcome> outcomes = state().finish(surface, changes);
  state_.reset();
  return outcomes;
}

std::vector<Outcome> collapse_edges(Surface& surface, std::span<const Collapse> collapses,
                                    PassWorkspace* workspace, TriangleChanges* changes) {
  CollapsePass pass(surface, workspace);
  for (const Collapse& c : collapses)
    pass.propose(c);
  return pass.finish(surface, changes);
}

}  // namespace exactgeo::remesh
