#pragma once

// Collision-safe mesh operations on an intersection-free Surface: each is applied, leaving
// the surface intersection free, or refused with the reason and, for a geometric refusal,
// the element that would be met. Every geometric decision is exact.
//
//   relocate_vertex  the vertex moves on a straight line, checked by exact CCD through the
//                    mesh broad phase (a pass of one move: relocate_vertices);
//   collapse_edge    both ends move to the new point on straight lines, pairs that become
//                    adjacent excepted (the surface after it needs no check of its own:
//                    docs/remesh.md, "Collapse");
//   flip_edge        the surface sweeps the hull of the edge's two triangles' four corners;
//   split_edge       nothing moves when the new vertex lies exactly on the edge; otherwise
//                    the surface sweeps the hull of the edge's ends, the new vertex and
//                    each opposite corner (swept_region.hpp).
//
// Topology is checked first: an edge of one or two triangles, no fixed corner, a flip
// that would duplicate an edge, a collapse that breaks the link condition (the ends'
// common neighbours must be the opposite corners: otherwise it pinches the surface), or
// that would make a triangle of zero area or a duplicate triangle. Not covered here: how
// much a collapse or a relocation turns a neighbouring triangle (a quality matter; a
// triangle folding through another part of the surface is a contact, and refused).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "exactgeo/remesh/pseudo_motion.hpp"
#include "exactgeo/remesh/surface.hpp"
#include "exactgeo/remesh/swept_region.hpp"

namespace exactgeo::remesh {

enum class Verdict : std::uint8_t {
  applied,
  refused_topology,   ///< not an operation this surface allows there (reason says why)
  refused_collision,  ///< the motion or the swept region meets `blocker`
  deferred,           ///< a pass: left for a later pass, another operation of it comes near
};

std::string_view to_string(Verdict v) noexcept;

/// The working memory of the passes (split_edges, collapse_edges, flip_edges), kept from
/// one pass to the next by a caller that runs many (a remesher, a simulator; one
/// workspace serves every kind of pass): the arrays of one entry per proposed operation
/// (the plans, each plan's operation, a split's or flip's vertices, those whose geometry
/// passed, those checked), the regions checked together and their partners, the points,
/// corner groups and near pairs of the regions' box query, and the edge table of the
/// split and flip passes (the triangles on every edge). A pass clears what it uses and
/// keeps its storage, so that a later pass writes into memory already in place instead of
/// allocating, and faulting in, arrays of the same size again (at thousands of operations
/// a pass, the page faults of fresh allocations can cost more than the pass's exact
/// tests: docs/remesh.md, "What a remesh costs"). Not kept: the outcomes (the caller's),
/// the box trees of the regions' query, and the collapse pass's own (the surface's stars,
/// the reach of its motions, the mesh broad phase over it, the surface it makes).
///
/// It carries no state that changes answers: every array is cleared, or filled anew,
/// before it is read, so a pass with a used workspace returns the same outcomes and leaves
/// the same surface as with a fresh one, or with none (each pass then makes its own).
/// Caller-owned, movable, not copyable; one pass at a time (not shared between threads).
class PassWorkspace {
 public:
  PassWorkspace();
  ~PassWorkspace();
  PassWorkspace(PassWorkspace&&) noexcept;
  PassWorkspace& operator=(PassWorkspace&&) noexcept;
  PassWorkspace(const PassWorkspace&) = delete;
  PassWorkspace& operator=(const PassWorkspace&) = delete;

  /// The arrays (remesh/src/pass_workspace.hpp: the library's own), made on first use
  /// (a workspace no pass has used, or one moved from, holds none).
  struct Arrays;
  Arrays& arrays();

 private:
  std::unique_ptr<Arrays> arrays_;
};

struct Outcome {
  Verdict verdict = Verdict::applied;
  std::string reason{};                     ///< empty when applied
  std::optional<Blocker> blocker{};         ///< refused_collision: what would be met
  std::optional<VertexIndex> new_vertex{};  ///< split_edge, applied: the vertex made
  bool applied() const noexcept { return verdict == Verdict::applied; }
};

/// What a pass (split_edges, collapse_edges, CollapsePass::finish, flip_edges) did to the
/// surface's triangles, for a caller that keeps tables of them (the triangles on each edge,
/// around each vertex) and patches them where the pass changed the surface instead of
/// building them again. A pass removes triangles (a collapse: its edge's), gives triangles
/// new corners in place (a split's, a flip's and the others around a collapse's removed
/// end) and appends triangles (a split's second halves); every other triangle keeps its
/// corners and the order of the whole stays: triangle t of the surface before the pass,
/// not removed, is index_after(t) after it, and the appended triangles are those from
/// first_added() on. Vertices are only appended (a split's) or moved (`moved`).
/// Filled anew by each pass it is handed to (its vectors' storage kept).
struct TriangleChanges {
  /// A triangle of the surface before the pass: its index and its corners then.
  struct Was {
    std::size_t triangle = 0;
    Triangle corners{};
    bool operator==(const Was&) const = default;
  };
  std::size_t triangles_before = 0;  ///< the number of triangles before the pass
  std::vector<Was> removed;          ///< ascending by index
  /// Given new corners (their corners now: the surface's at index_after), ascending by
  /// index; none of them removed, none twice (a pass's operations share no triangle).
  std::vector<Was> rewritten;
  /// The vertices given a new position (a collapse's ends, when its new point is not
  /// where they were), ascending.
  std::vector<VertexIndex> moved;

  /// The index after the pass of triangle t before it: t less the removed triangles below
  /// t (a binary search of `removed`). Precondition: t was not removed.
  std::size_t index_after(std::size_t t) const noexcept;
  /// The index of the first appended triangle (there are none when it is the count).
  std::size_t first_added() const noexcept { return triangles_before - removed.size(); }
  /// Forgets the last pass's changes (storage kept): nothing changed in `triangles` triangles.
  void reset(std::size_t triangles) noexcept;
};

/// Moves vertex v to `to`. Refused for a fixed vertex or one no triangle uses.
Outcome relocate_vertex(Surface& surface, VertexIndex v, const Point3& to);

/// Many relocations at once (a smoothing pass): one pseudo-motion in which every vertex
/// moves to its target, checked by the mesh broad phase (ccd::MeshCcd, exact method), so
/// that the pass costs about one mesh CCD step instead of one check per vertex. The moves
/// of every colliding pair are refused (with the element they would meet) and the others
/// checked again, until a step has no collision; the applied moves are then made
/// together. One outcome per move, in order. A vertex moved twice is refused the second
/// time, and so is a move that would give a triangle zero area (with the others of that
/// triangle's corners).
std::vector<Outcome> relocate_vertices(Surface& surface, std::span<const Move> moves);

/// Merges a and b into a, at `to`; removes the edge's triangles (vertex b stays in the
/// vertex list, used by no triangle).
Outcome collapse_edge(Surface& surface, VertexIndex a, VertexIndex b, const Point3& to);

/// A collapse of edge ab: b merged into a, both at `to`.
struct Collapse {
  VertexIndex a = kNoVertex;
  VertexIndex b = kNoVertex;
  Point3 to{};
};

/// Many collapses at once (a coarsening pass): each is planned on the surface as it is
/// (the same topology checks as collapse_edge); a collapse whose box (the triangles around
/// its ends and the new point) meets an earlier one's is deferred; the others' motions are
/// checked together as one step of the mesh broad phase (ccd::MeshCcd, exact method), the
/// pairs that come to share the merged vertex excepted (they meet there at the end of the
/// step, which is the collapse itself), refusing the collapses of every colliding pair
/// until a step has no collision (the surface after it needs no check of its own:
/// docs/remesh.md, "Collapse"). One outcome per collapse, in
/// order; collapse_edge on each applied edge of the surface before the pass would have
/// applied it too. Removed triangles leave the list; the other triangles keep their order.
/// `workspace`: memory kept between passes (PassWorkspace), or none (a pass of its own).
/// `changes`: filled with what the pass changed (TriangleChanges), or none.
std::vector<Outcome> collapse_edges(Surface& surface, std::span<const Collapse> collapses,
                                    PassWorkspace* workspace = nullptr,
                                    TriangleChanges* changes = nullptr);

/// A pass of collapses proposed one at a time: collapse_edges for a caller that decides
/// what to propose as it goes. Each proposal is planned and scheduled when it is made, by
/// collapse_edges' rules, so that could_go_ahead can tell beforehand whether a collapse
/// of edge ab cannot go ahead for coming near one already going ahead (a vertex of the
/// triangles around a or b taken by one; proposed, it would be deferred, or refused for
/// its topology, which is checked first): a caller that checks each collapse's shape (a
/// remesher) skips those, and proposing only the others makes the same collapses, with
/// the same outcomes, as proposing all. finish() checks the motions of
/// those going ahead and makes them. The surface must stay as it is until then.
class CollapsePass {
 public:
  /// `workspace` as for collapse_edges.
  explicit CollapsePass(const Surface& surface, PassWorkspace* workspace = nullptr);
  ~CollapsePass();
  CollapsePass(CollapsePass&&) noexcept;
  CollapsePass& operator=(CollapsePass&&) noexcept;
  CollapsePass(const CollapsePass&) = delete;
  CollapsePass& operator=(const CollapsePass&) = delete;

  /// False when a collapse of edge ab cannot go ahead in this pass: a vertex of the
  /// triangles around a or b belongs to those around the ends of a collapse going ahead.
  /// (True does not promise that it goes ahead: its topology, and its moving triangles'
  /// boxes, decide.)
  bool could_go_ahead(VertexIndex a, VertexIndex b) const;
  /// The triangles around vertex v (indices, in triangle order) on the surface the pass
  /// was made for: the table the pass plans with, for a caller that reads the same (a
  /// remesher checking each collapse's shape), so that it builds none of its own.
  /// Precondition: v is a vertex of that surface.
  std::span<const std::size_t> triangles_around(VertexIndex v) const;
  /// Plans and schedules the collapse; its outcome is the next of finish()'s.
  void propose(const Collapse& collapse);
  /// One outcome per proposal, in order, with the collapses that go ahead and meet
  /// nothing made on `surface` (the one the pass was made for). Once: afterwards (or
  /// once moved from) every member throws std::logic_error. `changes` as for
  /// collapse_edges.
  std::vector<Outcome> finish(Surface& surface, TriangleChanges* changes = nullptr);

 private:
  struct State;
  State& state() const;
  std::unique_ptr<State> state_;
};

/// Replaces the triangles abc and bad on edge ab by cad and dbc.
Outcome flip_edge(Surface& surface, VertexIndex a, VertexIndex b);

/// Many flips at once (a pass): each is planned on the surface as it is; a flip whose
/// region's box meets the box of an earlier one of the pass is deferred, the others'
/// regions are checked in one pass over the surface (first_in_regions) and every flip
/// that meets nothing is made. One outcome per edge, in order; flip_edge on each applied
/// edge of the surface before the pass would have applied it too. `workspace` and
/// `changes` as for collapse_edges (a flip rewrites its edge's two triangles).
std::vector<Outcome> flip_edges(Surface& surface, std::span<const Edge> edges,
                                PassWorkspace* workspace = nullptr,
                                TriangleChanges* changes = nullptr);

/// Adds a vertex at `at` and splits edge ab and its triangles there.
Outcome split_edge(Surface& surface, VertexIndex a, VertexIndex b, const Point3& at);

/// A split of edge ab at `at`.
struct Split {
  VertexIndex a = kNoVertex;
  VertexIndex b = kNoVertex;
  Point3 at{};
};

/// Many splits at once (a refinement pass), as flip_edges: a split whose box (its
/// triangles and the new vertex) meets an earlier one's is deferred, the others' regions
/// are checked in one pass over the surface, and every split that meets nothing is made
/// (new vertices in the order of the splits). `workspace` and `changes` as for
/// collapse_edges (a split rewrites each triangle x y c of its edge as x m c and appends
/// m y c).
std::vector<Outcome> split_edges(Surface& surface, std::span<const Split> splits,
                                 PassWorkspace* workspace = nullptr,
                                 TriangleChanges* changes = nullptr);

}  // namespace exactgeo::remesh
