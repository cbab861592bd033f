#include "remesher.hpp"

#include "flip_candidates.hpp"
#include "float_shortcuts.hpp"
#include "sheet_edges.hpp"
#include "unsuited_edges.hpp"
#include "vertex_sizes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace exactgeo::cloth {

namespace {

using remesh::Edge;
using remesh::Surface;
using remesh::VertexIndex;

/// Splits and collapses use these fractions of an edge's size (a split edge's halves and a
/// collapse's new edges then stay between them, so the two do not undo each other).
constexpr double kSplitAbove = 4.0 / 3.0;
constexpr double kCollapseBelow = 4.0 / 5.0;
/// A flip's two opposite angles (in the material) must exceed pi by this much (radians),
/// so that a cocircular quad, or one made so by rounding, is not flipped back and forth.
constexpr double kDelaunaySlack = 1e-6;

/// The surface being remeshed, with what the operations do not know about its vertices.
struct Work {
  Surface surface;
  std::vector<Material> material;           ///< per vertex (the obstacles' are unused)
  std::vector<Point3> velocity;             ///< per vertex (the obstacles' are unused)
  remesh::PassWorkspace* passes = nullptr;  ///< the passes' memory, the caller's (or none)
};

double material_length(const Work& w, VertexIndex a, VertexIndex b) {
  return std::hypot(w.material[b][0] - w.material[a][0], w.material[b][1] - w.material[a][1]);
}

/// material_length(w, a, b) > limit where the squares tell it (float_shortcuts.hpp).
std::optional<bool> clearly_longer_in_material(const Work& w, VertexIndex a, VertexIndex b,
                                               double limit) {
  return clearly_longer(w.material[b][0] - w.material[a][0], w.material[b][1] - w.material[a][1],
                        limit);
}

/// Twice the signed area of the triangle in the material.
double material_area(const Work& w, VertexIndex a, VertexIndex b, VertexIndex c) {
  const Material &p = w.material[a], &q = w.material[b], &r = w.material[c];
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

/// The angle at c of the triangle a b c in the material, as the absolute cross product and
/// the dot product of its sides (its atan2).
std::array<double, 2> material_corner(const Work& w, VertexIndex a, VertexIndex b, VertexIndex c) {
  const Material &p = w.material[a], &q = w.material[b], &r = w.material[c];
  const double ux = p[0] - r[0], uy = p[1] - r[1], vx = q[0] - r[0], vy = q[1] - r[1];
  return {std::abs(ux * vy - uy * vx), ux * vx + uy * vy};
}

/// Whether edge ab, with opposite corners c and d, is not Delaunay in the material: the
/// angles at c and d sum to more than pi + kDelaunaySlack (decided without atan2 where
/// clearly_beyond_half_turn can: float_shortcuts.hpp; `tan_slack` is tan(kDelaunaySlack)).
bool not_delaunay(const Work& w, VertexIndex a, VertexIndex b, VertexIndex c, VertexIndex d,
                  double tan_slack) {
  const auto [cross_c, dot_c] = material_corner(w, a, b, c);
  const auto [cross_d, dot_d] = material_corner(w, a, b, d);
  if (const auto clear = clearly_beyond_half_turn(cross_c, dot_c, cross_d, dot_d, tan_slack))
    return *clear;
  return std::atan2(cross_c, dot_c) + std::atan2(cross_d, dot_d) >
         std::numbers::pi + kDelaunaySlack;
}

double triangle_min_angle_to_floor(const Surface& s, const remesh::Triangle& t) {
  return world_min_angle_to_floor(s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
}

/// The guard: the new triangles' smallest angle stays at kMinAngle, or at the old ones'
/// (`old_worst()`, asked only when the new ones are below kMinAngle).
template <class OldWorst>
bool keeps_quality(const OldWorst& old_worst, double new_worst) {
  return new_worst >= kMinAngle || new_worst >= old_worst();
}

/// The sheets' edges and the sizes their vertices ask for, worked out when first asked and
/// kept while the surface stays as it was: a pass that applies nothing leaves it unchanged
/// (its triangles, their order, the vertices and their material), so the next pass, of
/// this kind or another, reads the same tables. A pass that changes the surface reports
/// what it changed (remesh::TriangleChanges, into changes()), and both tables are patched
/// there (SheetEdgeTable::update, update_vertex_sizes) when next asked for: the sizes of
/// the vertices whose edges changed are worked out again (a split's new vertex takes its
/// material coordinates before the next pass asks).
class SurfaceTables {
 public:
  const std::vector<SheetEdge>& edges(const Work& w) {
    if (!edges_) {
      edges_.emplace(w.surface);
    } else if (pending_) {
      pending_ = false;
      if (edges_->update(w.surface, changes_, touched_)) {
        sizes_touched_.insert(sizes_touched_.end(), touched_.begin(), touched_.end());
        sizes_moved_.insert(sizes_moved_.end(), changes_.moved.begin(), changes_.moved.end());
      } else {
        sizes_.reset();  // built again: which vertices' edges changed is not known
      }
    }
    return edges_->edges();
  }
  const std::vector<double>& sizes(const Work& w, const RemeshParameters& p) {
    const std::vector<SheetEdge>& edges = this->edges(w);
    if (sizes_ && !sizes_touched_.empty() &&
        !update_vertex_sizes(*sizes_, w.surface, w.material, edges, p, sizes_touched_, sizes_moved_,
                             marks_)) {
      sizes_.reset();
    }
    sizes_touched_.clear();
    sizes_moved_.clear();
    if (!sizes_) sizes_ = vertex_sizes(w.surface, w.material, edges, p);
    return *sizes_;
  }
  /// Where a pass on `w` reports its changes (a pending patch made first: the report is
  /// the last pass's).
  remesh::TriangleChanges* changes(const Work& w) {
    if (pending_) edges(w);
    return &changes_;
  }
  /// The last pass's report (valid after a pass that changed the surface).
  const remesh::TriangleChanges& last_changes() const noexcept { return changes_; }
  /// Takes `table` as the edges of the work's surface (it must be theirs).
  void adopt(SheetEdgeTable table) { edges_.emplace(std::move(table)); }
  /// The edges of the work's surface as it is (patched first when a pass left them to be),
  /// taken out.
  SheetEdgeTable release(const Work& w) {
    edges(w);
    SheetEdgeTable table = std::move(*edges_);
    edges_.reset();
    return table;
  }
  /// After a pass: the tables to be patched when it changed the surface.
  void pass_done(bool changed) {
    if (changed) pending_ = edges_.has_value();
  }

 private:
  std::optional<SheetEdgeTable> edges_;
  std::optional<std::vector<double>> sizes_;
  remesh::TriangleChanges changes_;   ///< the last pass's
  bool pending_ = false;              ///< the edges wait for the patch of changes_
  std::vector<VertexIndex> touched_;  ///< the edges' patch's
  /// The ends of the edges changed, and the vertices moved, since the sizes were patched.
  std::vector<VertexIndex> sizes_touched_;
  std::vector<VertexIndex> sizes_moved_;
  std::vector<char> marks_;  ///< update_vertex_sizes' storage
};

double edge_size(const std::vector<double>& size, VertexIndex a, VertexIndex b) {
  return std::min(size[a], size[b]);
}

/// The guard for a split of e at m: each triangle a b c becomes a m c and m b c.
bool split_keeps_quality(const Surface& s, const SheetEdge& e, const Point3& m) {
  for (const std::optional<std::size_t> t : {std::optional(e.left), e.right}) {
    if (!t) continue;
    const remesh::Triangle& tri = s.triangles[*t];
    const Point3& c = s.vertices[remesh::third_corner(tri, e.a, e.b)];
    const Point3 &a = s.vertices[e.a], &b = s.vertices[e.b];
    const double made =
        std::min(world_min_angle_to_floor(a, m, c), world_min_angle_to_floor(m, b, c));
    if (!keeps_quality([&] { return triangle_min_angle_to_floor(s, tri); }, made)) return false;
  }
  return true;
}

bool split_pass(Work& w, const RemeshParameters& p, SurfaceTables& tables, VerdictCounts& counts) {
  const std::vector<SheetEdge>& edges = tables.edges(w);
  const std::vector<double>& size = tables.sizes(w, p);
  std::vector<std::pair<double, remesh::Split>> wanted;  // (length / size, split)
  for (const SheetEdge& e : edges) {
    // A length clearly below kSplitAbove sizes has a ratio of at most kSplitAbove.
    if (clearly_longer_in_material(w, e.a, e.b, kSplitAbove * edge_size(size, e.a, e.b)) == false)
      continue;
    const double ratio = material_length(w, e.a, e.b) / edge_size(size, e.a, e.b);
    if (ratio <= kSplitAbove) continue;
    const Point3 &pa = w.surface.vertices[e.a], &pb = w.surface.vertices[e.b];
    const Point3 mid{0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])};
    if (!split_keeps_quality(w.surface, e, mid)) continue;
    wanted.push_back({ratio, remesh::Split{e.a, e.b, mid}});
  }
  std::stable_sort(wanted.begin(), wanted.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  std::vector<remesh::Split> splits;
  for (const auto& [ratio, split] : wanted)
    splits.push_back(split);
  const std::vector<remesh::Outcome> outcomes =
      remesh::split_edges(w.surface, splits, w.passes, tables.changes(w));
  bool any = false;
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    counts.add(outcomes[i].verdict);
    if (!outcomes[i].applied()) continue;
    any = true;
    const VertexIndex a = splits[i].a, b = splits[i].b;
    if (*outcomes[i].new_vertex != w.material.size()) {
      throw std::logic_error("split_edges numbered its new vertices out of order");
    }
    w.material.push_back(
        {0.5 * (w.material[a][0] + w.material[b][0]), 0.5 * (w.material[a][1] + w.material[b][1])});
    const Point3 &va = w.velocity[a], &vb = w.velocity[b];
    w.velocity.push_back({0.5 * (va[0] + vb[0]), 0.5 * (va[1] + vb[1]), 0.5 * (va[2] + vb[2])});
  }
  return any;
}

/// The corners of the triangles around v other than v, each once per triangle side, into
/// `sides` (sorted): a neighbour seen once is across a boundary edge.
void ring_sides(const remesh::Surface& s, std::span<const std::size_t> star, VertexIndex v,
                std::vector<VertexIndex>& sides) {
  sides.clear();
  for (const std::size_t t : star) {
    for (const VertexIndex c : s.triangles[t])
      if (c != v) sides.push_back(c);
  }
  std::sort(sides.begin(), sides.end());
}

/// The neighbours across boundary edges, into `once`: those seen once among the sides.
void boundary_neighbours(const std::vector<VertexIndex>& sides, std::vector<VertexIndex>& once) {
  once.clear();
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j] == sides[i])
      ++j;
    if (j - i == 1) once.push_back(sides[i]);
    i = j;
  }
}

/// What collapse_suits reuses from one call to the next.
struct RingScratch {
  std::vector<VertexIndex> sides;
  std::vector<VertexIndex> ends;
};

/// Whether removing `gone` into `kept` makes an edge longer than it may be (kept joined
/// to each other corner of the triangles around gone; a neighbour in two triangles is
/// asked twice). Most collapses a pass wants fail here; it needs no ring, and apart from
/// the rest of the shape check its calls save and restore few registers.
bool makes_too_long_edge(const Work& w, const std::vector<double>& size,
                         std::span<const std::size_t> star, VertexIndex kept, VertexIndex gone) {
  for (const std::size_t t : star) {
    for (const VertexIndex x : w.surface.triangles[t]) {
      if (x == kept || x == gone) continue;
      const double limit = kSplitAbove * edge_size(size, kept, x);
      const std::optional<bool> longer = clearly_longer_in_material(w, kept, x, limit);
      if (longer ? *longer : material_length(w, kept, x) > limit) return true;
    }
  }
  return false;
}

/// collapse_suits for a collapse that makes no edge too long: the rest of its conditions,
/// out of line (few candidates get this far).
[[gnu::noinline]] bool collapse_shape_suits(const Work& w, std::span<const std::size_t> star,
                                            VertexIndex kept, VertexIndex gone, bool boundary_edge,
                                            RingScratch& scratch) {
  std::vector<VertexIndex>& sides = scratch.sides;
  std::vector<VertexIndex>& ends = scratch.ends;
  ring_sides(w.surface, star, gone, sides);
  boundary_neighbours(sides, ends);
  if (ends.empty() == boundary_edge) return false;  // gone on the boundary, or not
  // A boundary end goes only where the outline is straight: its two boundary neighbours
  // on one line with it, up to the rounding of averaged material coordinates (a choice of
  // shape, not of safety: every collapse is still decided exactly by collapse_edges).
  if (boundary_edge) {
    if (ends.size() != 2) return false;
    const double area = material_area(w, ends[0], gone, ends[1]);
    const double scale = material_length(w, ends[0], gone) * material_length(w, gone, ends[1]);
    if (std::abs(area) > 1e-9 * scale) return false;
  }
  for (const std::size_t t : star) {
    remesh::Triangle tri = w.surface.triangles[t];
    if (std::find(tri.begin(), tri.end(), kept) != tri.end()) continue;  // removed
    const remesh::Triangle old = tri;
    const double before = material_area(w, tri[0], tri[1], tri[2]);
    for (VertexIndex& c : tri)
      if (c == gone) c = kept;
    const double after = material_area(w, tri[0], tri[1], tri[2]);
    if (!(before * after > 0.0)) return false;
    if (!keeps_quality([&] { return triangle_min_angle_to_floor(w.surface, old); },
                       triangle_min_angle_to_floor(w.surface, tri))) {
      return false;
    }
  }
  return true;
}

/// Whether removing `gone` into `kept` (gone moves to kept's place) suits the sheet: a
/// boundary end moves only along its boundary edge and is no corner of the outline, no
/// edge made is longer than it may be, and no triangle turns over in the material. The
/// edges made are asked first.
bool collapse_suits(const Work& w, const std::vector<double>& size,
                    std::span<const std::size_t> star, VertexIndex kept, VertexIndex gone,
                    bool boundary_edge, RingScratch& scratch) {
  return !makes_too_long_edge(w, size, star, kept, gone) &&
         collapse_shape_suits(w, star, kept, gone, boundary_edge, scratch);
}

/// What a remesh's collapse passes keep from one to the next (unsuited_edges.hpp).
struct CollapseMemory {
  UnsuitedEdges unsuited;
  std::vector<double> sizes;    ///< those the last pass read
  std::vector<char> unsettled;  ///< per vertex
  bool after_a_pass = false;    ///< the last pass was a collapse pass of this remesh
};

bool collapse_pass(Work& w, const RemeshParameters& p, SurfaceTables& tables,
                   CollapseMemory& memory, VerdictCounts& counts) {
  const std::vector<SheetEdge>& edges = tables.edges(w);
  const std::vector<double>& size = tables.sizes(w, p);
  remesh::CollapsePass pass(w.surface, w.passes);
  // The triangles around each vertex as the pass starts (the pass defers the collapses
  // whose surroundings another one of it changes): the pass's own table.
  const auto stars = [&pass](VertexIndex v) { return pass.triangles_around(v); };
  // An edge that suited neither way in the last collapse pass, both of its ends settled
  // since (unsuited_edges.hpp: everything its checks read is as it was), suits neither
  // way now; after a remesh's first collapse pass every vertex is unsettled.
  memory.unsuited.start_pass();
  if (memory.after_a_pass) {
    mark_unsettled(w.surface, tables.last_changes(), memory.sizes, size, stars, memory.unsettled);
  } else {
    memory.unsettled.assign(w.surface.vertices.size(), 1);
  }
  // The edges below their limit whose collapse suits the sheet one way (a first, then b),
  // in the order of the edges. collapse_suits reads the surface, the material and the
  // sizes, which proposals do not change (the pass makes its collapses in finish()), so
  // it is asked of every candidate before any is proposed; could_go_ahead reads only the
  // collapses proposed before, and only suited edges are proposed. So asking it of the
  // suited edges alone, in the order of lengths, proposes the same collapses in the same
  // order as asking both of every candidate in that order: the stable sort of the suited
  // ones keeps their order among themselves, ties by the order of the edges, as a stable
  // sort of all does. Most candidates do not suit (the stack: 1,045 proposed of 461,100
  // over 60 steps), so the sort and could_go_ahead see few.
  struct Suited {
    double length;
    const SheetEdge* edge;
    VertexIndex kept, gone;
  };
  std::vector<Suited> suited;
  RingScratch scratch;
  for (const SheetEdge& e : edges) {
    const double limit = kCollapseBelow * edge_size(size, e.a, e.b);
    // Clearly not longer is clearly shorter: the squares a relative 1e-9 apart put hypot
    // below the limit (FloatShortcuts.ClearlyLongerAnswersAsHypot), so the length, the
    // sort's key, is worked out for the suited edges only; hypot decides the others.
    const std::optional<bool> longer = clearly_longer_in_material(w, e.a, e.b, limit);
    if (longer == true) continue;
    if (!longer && !(material_length(w, e.a, e.b) < limit)) continue;
    const std::uint64_t key = UnsuitedEdges::key(e.a, e.b);
    if (memory.unsettled[e.a] == 0 && memory.unsettled[e.b] == 0 &&
        memory.unsuited.was_unsuited(key)) {
      memory.unsuited.add(key);
      continue;
    }
    const bool boundary = !e.right;
    VertexIndex kept = e.a, gone = e.b;
    if (!collapse_suits(w, size, stars(gone), kept, gone, boundary, scratch)) {
      std::swap(kept, gone);
      if (!collapse_suits(w, size, stars(gone), kept, gone, boundary, scratch)) {
        memory.unsuited.add(key);
        continue;
      }
    }
    suited.push_back({material_length(w, e.a, e.b), &e, kept, gone});
  }
  std::stable_sort(suited.begin(), suited.end(),
                   [](const Suited& x, const Suited& y) { return x.length < y.length; });
  for (const Suited& s : suited) {
    if (pass.could_go_ahead(s.edge->a, s.edge->b))
      pass.propose({s.kept, s.gone, w.surface.vertices[s.kept]});
  }
  memory.sizes.assign(size.begin(), size.end());
  memory.after_a_pass = true;
  bool any = false;
  for (const remesh::Outcome& o : pass.finish(w.surface, tables.changes(w))) {
    counts.add(o.verdict);
    any = any || o.applied();
  }
  return any;
}

/// What a remesh's flip passes keep from one to the next (flip_candidates.hpp).
struct FlipMemory {
  FlipCandidates candidates;
  bool after_a_pass = false;  ///< the last pass was a flip pass of this remesh
};

bool flip_pass(Work& w, SurfaceTables& tables, FlipMemory& memory, VerdictCounts& counts) {
  std::vector<Edge> flips;
  const double tan_slack = std::tan(kDelaunaySlack);  // once, not per edge
  const std::vector<SheetEdge>& edges = tables.edges(w);
  // An edge whose triangles the last flip pass of this remesh left as they were is a
  // candidate exactly when it was one then (flip_candidates.hpp): only the others are
  // asked. The candidates are proposed in the table's order either way.
  memory.candidates.start_pass(memory.after_a_pass ? &tables.last_changes() : nullptr,
                               w.surface.triangles.size());
  memory.after_a_pass = true;
  for (const SheetEdge& e : edges) {
    if (!e.right) continue;
    const std::uint64_t key = UnsuitedEdges::key(e.a, e.b);
    if (const std::optional<bool> known = memory.candidates.known(e, key)) {
      if (*known) {
        flips.push_back(remesh::edge_of(e.a, e.b));
        memory.candidates.add(key);
      }
      continue;
    }
    const VertexIndex c = remesh::third_corner(w.surface.triangles[e.left], e.a, e.b);
    const VertexIndex d = remesh::third_corner(w.surface.triangles[*e.right], e.a, e.b);
    if (!not_delaunay(w, e.a, e.b, c, d, tan_slack)) continue;
    // The new triangles c a d and d b c must turn as the old a b c does.
    const double old_turn = material_area(w, e.a, e.b, c);
    if (!(material_area(w, c, e.a, d) * old_turn > 0.0) ||
        !(material_area(w, d, e.b, c) * old_turn > 0.0)) {
      continue;
    }
    const auto old_worst = [&] {
      return std::min(triangle_min_angle_to_floor(w.surface, w.surface.triangles[e.left]),
                      triangle_min_angle_to_floor(w.surface, w.surface.triangles[*e.right]));
    };
    const double new_worst = std::min(triangle_min_angle_to_floor(w.surface, {c, e.a, d}),
                                      triangle_min_angle_to_floor(w.surface, {d, e.b, c}));
    if (!keeps_quality(old_worst, new_worst)) continue;
    flips.push_back(remesh::edge_of(e.a, e.b));
    memory.candidates.add(key);
  }
  bool any = false;
  for (const remesh::Outcome& o :
       remesh::flip_edges(w.surface, flips, w.passes, tables.changes(w))) {
    counts.add(o.verdict);
    any = any || o.applied();
  }
  return any;
}

Work work_of(const ClothMesh& mesh) {
  Work w;
  const std::size_t n = mesh.vertex_count(), sheet = mesh.sheet_vertices();
  w.surface.vertices.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    w.surface.vertices[v] = {mesh.positions[3 * v], mesh.positions[3 * v + 1],
                             mesh.positions[3 * v + 2]};
  }
  w.surface.triangles.assign(mesh.faces.begin(), mesh.faces.end());
  w.surface.fixed.assign(n, false);
  std::fill(w.surface.fixed.begin() + static_cast<std::ptrdiff_t>(sheet), w.surface.fixed.end(),
            true);
  w.material = mesh.material;
  w.material.resize(n);
  w.velocity.resize(n);
  for (std::size_t v = 0; v < sheet; ++v)
    w.velocity[v] = {mesh.velocity[3 * v], mesh.velocity[3 * v + 1], mesh.velocity[3 * v + 2]};
  return w;
}

/// How write_back numbered the work's vertices and sheet triangles in the mesh.
struct Numbering {
  std::vector<VertexIndex> vertex;      ///< per vertex: its index in the mesh (kNoVertex: gone)
  std::vector<std::size_t> sheet_face;  ///< per sheet triangle: its face in the mesh
};

/// The mesh back from the work: used sheet vertices first (in order), then the obstacle's,
/// sheet faces first; how each vertex and sheet triangle was numbered into `numbering`.
void write_back(const Work& w, ClothMesh& mesh, Numbering& numbering) {
  const Surface& s = w.surface;
  std::vector<char> used(s.vertices.size(), 0), fixed(s.vertices.size(), 0);  // bytes
  for (const remesh::Triangle& t : s.triangles) {
    for (const VertexIndex v : t)
      used[v] = 1;
  }
  for (VertexIndex v = 0; v < s.vertices.size(); ++v)
    fixed[v] = s.is_fixed(v) ? 1 : 0;
  std::vector<VertexIndex>& renumber = numbering.vertex;
  renumber.assign(s.vertices.size(), remesh::kNoVertex);
  numbering.sheet_face.assign(s.triangles.size(), 0);
  std::vector<VertexIndex> order;
  order.reserve(s.vertices.size());
  for (const bool obstacle : {false, true}) {
    for (VertexIndex v = 0; v < s.vertices.size(); ++v) {
      if ((fixed[v] != 0) != obstacle || (!obstacle && !used[v])) continue;
      renumber[v] = static_cast<VertexIndex>(order.size());
      order.push_back(v);
    }
  }
  mesh.positions.clear();
  mesh.velocity.clear();
  mesh.material.clear();
  mesh.positions.reserve(3 * order.size());
  mesh.velocity.reserve(3 * order.size());
  mesh.material.reserve(order.size());
  for (const VertexIndex v : order) {
    mesh.positions.insert(mesh.positions.end(), s.vertices[v].begin(), s.vertices[v].end());
    if (fixed[v]) continue;
    mesh.velocity.insert(mesh.velocity.end(), w.velocity[v].begin(), w.velocity[v].end());
    mesh.material.push_back(w.material[v]);
  }
  // Sheet faces (no corner fixed) first, then the obstacles'.
  const auto sheet = [&](const remesh::Triangle& t) {
    return (fixed[t[0]] | fixed[t[1]] | fixed[t[2]]) == 0;
  };
  mesh.faces.clear();
  mesh.faces.reserve(s.triangles.size());
  for (const bool obstacle : {false, true}) {
    for (std::size_t f = 0; f < s.triangles.size(); ++f) {
      const remesh::Triangle& t = s.triangles[f];
      if (sheet(t) == obstacle) continue;
      if (!obstacle) numbering.sheet_face[f] = mesh.faces.size();
      mesh.faces.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]]});
    }
    if (!obstacle) mesh.sheet_faces = mesh.faces.size();
  }
}

}  // namespace

void VerdictCounts::add(remesh::Verdict verdict) noexcept {
  switch (verdict) {
    case remesh::Verdict::applied:
      ++applied;
      break;
    case remesh::Verdict::refused_topology:
      ++refused_topology;
      break;
    case remesh::Verdict::refused_collision:
      ++refused_collision;
      break;
    case remesh::Verdict::deferred:
      ++deferred;
      break;
  }
}

VerdictCounts& VerdictCounts::operator+=(const VerdictCounts& c) noexcept {
  applied += c.applied;
  refused_topology += c.refused_topology;
  refused_collision += c.refused_collision;
  deferred += c.deferred;
  return *this;
}

RemeshCounts& RemeshCounts::operator+=(const RemeshCounts& c) noexcept {
  split += c.split;
  collapse += c.collapse;
  flip += c.flip;
  seconds += c.seconds;
  return *this;
}

std::optional<SheetEdgeTable> KeptSheetEdges::take_for(const ClothMesh& mesh) {
  std::optional<SheetEdgeTable> taken = std::move(table_);
  table_.reset();
  // The faces compared as bytes (three indices each, no padding: equal bytes are equal
  // faces), one memcmp instead of a comparison per index.
  static_assert(std::has_unique_object_representations_v<ccd::Triangle>);
  if (!taken || mesh.vertex_count() != vertices_ || mesh.sheet_vertices() != sheet_vertices_ ||
      mesh.faces.size() != faces_.size() ||
      std::memcmp(mesh.faces.data(), faces_.data(), faces_.size() * sizeof(ccd::Triangle)) != 0) {
    return std::nullopt;
  }
  return taken;
}

void KeptSheetEdges::keep(SheetEdgeTable table, const ClothMesh& mesh) {
  table_ = std::move(table);
  faces_ = mesh.faces;
  vertices_ = mesh.vertex_count();
  sheet_vertices_ = mesh.sheet_vertices();
}

RemeshCounts remesh(ClothMesh& mesh, const RemeshParameters& parameters,
                    remesh::PassWorkspace* workspace, KeptSheetEdges* kept) {
  const auto start = std::chrono::steady_clock::now();
  RemeshCounts counts;
  Work w = work_of(mesh);
  w.passes = workspace;
  // Split vertices come after the obstacle's (as split_edges appends them), and so do
  // their entries in the work's per-vertex arrays; write_back puts them with the sheets.
  SurfaceTables tables;
  if (kept != nullptr) {
    if (std::optional<SheetEdgeTable> table = kept->take_for(mesh)) tables.adopt(std::move(*table));
  }
  const auto run = [&](const auto& one_pass) {
    for (int pass = 0; pass < parameters.passes; ++pass) {
      const bool changed = one_pass();
      tables.pass_done(changed);
      if (!changed) break;
    }
  };
  run([&] { return split_pass(w, parameters, tables, counts.split); });
  CollapseMemory collapse_memory;
  run([&] { return collapse_pass(w, parameters, tables, collapse_memory, counts.collapse); });
  FlipMemory flip_memory;
  run([&] { return flip_pass(w, tables, flip_memory, counts.flip); });
  Numbering numbering;
  write_back(w, mesh, numbering);
  if (kept != nullptr) {
    // The work's table, numbered as the mesh written back: the sheets' vertices and
    // faces come first there, each in their order, so the entries keep theirs.
    SheetEdgeTable table = tables.release(w);
    table.renumber(numbering.vertex, numbering.sheet_face);
    kept->keep(std::move(table), mesh);
  }
  counts.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return counts;
}

}  // namespace exactgeo::cloth
