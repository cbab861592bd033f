#include "polygon_monotone.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory_resource>
#include <optional>
#include <set>
#include <utility>

#include "polygon_sweep.hpp"

namespace exactgeo::mesh::internal {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

using Triangle = std::array<std::uint32_t, 3>;  // ranks

/// The region's boundary as loops with the region on their left, every corner still
/// joined named by its rank in sweep order: next and previous corner, its point
/// (Projection::flat, side by side in sweep order) and its vertex index. A corner that
/// only bridges reach is left out.
struct Loops {
  ScratchVector<std::uint32_t> next;
  ScratchVector<std::uint32_t> previous;
  ScratchVector<Point3> point;
  ScratchVector<VertexIndex> vertex;
  ScratchVector<std::uint32_t> rank_of;  ///< local number -> rank (kNone: not joined)

  std::uint32_t size() const { return static_cast<std::uint32_t>(next.size()); }
};

/// The loops of the walk's chain, or false when it is not a set of loops through distinct
/// points (see triangulate_by_sweep).
bool loops_of(const PolygonWalk& walk, std::span<const std::uint32_t> order,
              std::span<const Point3> vertices, const Projection& plane, Sign turn, Loops& loops) {
  const std::size_t m = walk.vertices.size();
  ScratchVector<std::uint32_t> next(m, kNone);
  ScratchVector<std::uint32_t> previous(m, kNone);
  for (const ChainEdge& e : walk.edges) {
    if (e.coefficient == 0) continue;
    if (e.coefficient != 1 && e.coefficient != -1) return false;
    std::uint32_t from = e.coefficient > 0 ? e.low : e.high;
    std::uint32_t to = e.coefficient > 0 ? e.high : e.low;
    if (turn == Sign::negative) std::swap(from, to);  // the region on the left
    if (next[from] != kNone || previous[to] != kNone) return false;
    next[from] = to;
    previous[to] = from;
  }
  const Projection flat(2);
  ScratchVector<std::uint32_t> rank(m, kNone);
  ScratchVector<std::uint32_t> joined;  // local numbers by rank
  for (const std::uint32_t v : order) {
    if (next[v] == kNone && previous[v] == kNone) continue;
    if (next[v] == kNone || previous[v] == kNone) return false;
    const Point3 p = plane.flat(vertices[walk.vertices[v]]);
    if (!loops.point.empty() && flat.same(loops.point.back(), p)) return false;
    rank[v] = static_cast<std::uint32_t>(joined.size());
    joined.push_back(v);
    loops.point.push_back(p);
    loops.vertex.push_back(walk.vertices[v]);
  }
  loops.next.resize(joined.size());
  loops.previous.resize(joined.size());
  for (std::size_t r = 0; r < joined.size(); ++r) {
    loops.next[r] = rank[next[joined[r]]];
    loops.previous[r] = rank[previous[joined[r]]];
  }
  loops.rank_of = std::move(rank);
  return true;
}

/// Exact orientations of corners named by rank.
class Geometry {
 public:
  explicit Geometry(const Loops& loops) : loops_(&loops) {}

  const Point3& at(std::uint32_t r) const { return loops_->point[r]; }
  Sign orientation(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    return plane().orientation(at(a), at(b), at(c));
  }
  static constexpr Projection plane() { return Projection(2); }

 private:
  const Loops* loops_;
};

/// An edge of the status: from corner `left` (its name: one edge leaves each corner) to
/// loops.next[left], later in sweep order, with the points of both.
struct StatusEdge {
  std::uint32_t left;
  Point3 from;
  Point3 to;
};

/// A point looked up in the status: which edge lies just below it.
struct Probe {
  Point3 point;
};

/// The status of the monotone partition: the region's boundary edges with the region just
/// above them that cross the sweep line, bottom to top. Edges in the status never meet
/// (region_turn), so a zero orientation means the input broke the precondition: `broken`
/// is set.
class EdgesBottomToTop {
 public:
  using is_transparent = void;

  explicit EdgesBottomToTop(bool& broken) : broken_(&broken) {}

  bool operator()(const StatusEdge& a, const StatusEdge& b) const {
    if (a.left == b.left) return false;
    // The later of the two left ends is the one being inserted.
    if (a.left < b.left) return side(a, b.from) == Sign::positive;
    return side(b, a.from) == Sign::negative;
  }
  bool operator()(const StatusEdge& e, const Probe& p) const {
    return side(e, p.point) == Sign::positive;
  }
  bool operator()(const Probe& p, const StatusEdge& e) const {
    return side(e, p.point) == Sign::negative;
  }

 private:
  /// The side of edge e's line that point c lies on.
  Sign side(const StatusEdge& e, const Point3& c) const {
    const Sign s = Geometry::plane().orientation(e.from, e.to, c);
    if (s == Sign::zero) *broken_ = true;
    return s;
  }

  bool* broken_;
};

enum class CornerKind : std::uint8_t {
  start,  ///< both neighbours later, convex: a piece begins
  end,    ///< both neighbours earlier, convex: a piece ends
  split,  ///< both neighbours later, reflex: needs a diagonal back
  merge,  ///< both neighbours earlier, reflex: needs a diagonal forward
  lower,  ///< on a lower boundary: the region above it
  upper,  ///< on an upper boundary: the region below it
};

/// The status of the monotone partition as an ordered set of edges, searched for the edge
/// below a corner.
class SearchedStatus {
 public:
  explicit SearchedStatus(const Loops& loops)
      : loops_(&loops), set_(EdgesBottomToTop(broken_), &pool_), place_(loops.size()) {}

  void open(std::uint32_t e) { place_[e] = set_.insert(edge(e)).first; }
  void close(std::uint32_t e) { set_.erase(place_[e]); }
  /// Edge v takes the place of edge e, which ends where v begins (a hint std::set checks).
  void replace(std::uint32_t e, std::uint32_t v) {
    place_[v] = set_.insert(set_.erase(place_[e]), edge(v));
  }
  std::uint32_t below(std::uint32_t v) {
    const auto it = set_.lower_bound(Probe{loops_->point[v]});
    return it == set_.begin() ? kNone : std::prev(it)->left;
  }
  bool broken() const { return broken_; }
  bool empty() const { return set_.empty(); }

 private:
  StatusEdge edge(std::uint32_t e) const {
    return {e, loops_->point[e], loops_->point[loops_->next[e]]};
  }

  const Loops* loops_;
  bool broken_ = false;
  std::pmr::unsynchronized_pool_resource pool_;  // the nodes side by side, reused
  std::pmr::set<StatusEdge, EdgesBottomToTop> set_;
  ScratchVector<std::pmr::set<StatusEdge, EdgesBottomToTop>::iterator> place_;
};

/// The status of the monotone partition as the certificate's sweep recorded it
/// (region_turn's `below`): the edge below each corner, looked up.
class RecordedStatus {
 public:
  explicit RecordedStatus(ScratchVector<std::uint32_t> below) : below_(std::move(below)) {}

  void open(std::uint32_t) {}
  void close(std::uint32_t) {}
  void replace(std::uint32_t, std::uint32_t) {}
  std::uint32_t below(std::uint32_t v) const { return below_[v]; }
  bool broken() const { return false; }
  bool empty() const { return true; }

 private:
  ScratchVector<std::uint32_t> below_;  ///< by rank: the edge just below, or kNone
};

/// The edge just below each corner (by rank) from the certificate's record, or nullopt
/// when the record has a gap (bridges stacked below a corner). An edge that is not one
/// with the region above it is left out (kNone), and the partition, needing it, fails.
std::optional<ScratchVector<std::uint32_t>> recorded_below(const PolygonWalk& walk,
                                                           const Loops& loops,
                                                           std::span<const std::uint32_t> below) {
  ScratchVector<std::uint32_t> edges(loops.size(), kNone);
  for (std::size_t local = 0; local < below.size(); ++local) {
    const std::uint32_t v = loops.rank_of[local];
    if (v == kNone || below[local] == kNoEdge) continue;
    if (below[local] == kUnknownEdge) return std::nullopt;
    const ChainEdge& e = walk.edges[below[local]];
    const std::uint32_t a = loops.rank_of[e.low];
    const std::uint32_t b = loops.rank_of[e.high];
    // The edge below a corner whose region reaches down to it runs left to right with the
    // region above; for other corners it is never asked for.
    if (a != kNone && b != kNone && loops.next[std::min(a, b)] == std::max(a, b)) {
      edges[v] = std::min(a, b);
    }
  }
  return edges;
}

/// The diagonals that split the region into pieces monotone in sweep order (de Berg et
/// al., MAKEMONOTONE, with "left of" as "below" and "above" as "earlier"): appended to
/// `diagonals`; false when the precondition turns out broken.
template <class Status>
bool monotone_diagonals(const Geometry& geometry, const Loops& loops, Status& status,
                        ScratchVector<std::pair<std::uint32_t, std::uint32_t>>& diagonals) {
  const std::uint32_t n = loops.size();
  ScratchVector<std::uint32_t> helper(n, kNone);
  ScratchVector<char> is_merge(n, 0);
  const auto open = [&](std::uint32_t e) {
    status.open(e);
    helper[e] = e;
  };
  // The edge ending at v; a merge corner as its helper gets its diagonal.
  const auto reach_end = [&](std::uint32_t v, std::uint32_t e) {
    if (is_merge[helper[e]]) diagonals.emplace_back(v, helper[e]);
  };
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t p = loops.previous[v];
    const std::uint32_t q = loops.next[v];
    const bool p_earlier = p < v;
    const bool q_earlier = q < v;
    CornerKind kind = p_earlier ? CornerKind::lower : CornerKind::upper;
    if (p_earlier == q_earlier) {
      const Sign turn = geometry.orientation(p, v, q);
      if (turn == Sign::zero) return false;  // two edges along one ray: they overlap
      const bool convex = turn == Sign::positive;
      kind = p_earlier ? (convex ? CornerKind::end : CornerKind::merge)
                       : (convex ? CornerKind::start : CornerKind::split);
    }
    is_merge[v] = kind == CornerKind::merge;
    switch (kind) {
      case CornerKind::start:
        open(v);
        break;
      case CornerKind::end:
        reach_end(v, p);
        status.close(p);
        break;
      case CornerKind::split: {
        const std::uint32_t e = status.below(v);
        if (e == kNone) return false;
        diagonals.emplace_back(v, helper[e]);
        helper[e] = v;
        open(v);
        break;
      }
      case CornerKind::merge: {
        reach_end(v, p);
        status.close(p);
        const std::uint32_t e = status.below(v);
        if (e == kNone) return false;
        if (is_merge[helper[e]]) diagonals.emplace_back(v, helper[e]);
        helper[e] = v;
        break;
      }
      case CornerKind::lower: {
        reach_end(v, p);
        status.replace(p, v);
        helper[v] = v;
        break;
      }
      case CornerKind::upper: {
        const std::uint32_t e = status.below(v);
        if (e == kNone) return false;
        if (is_merge[helper[e]]) diagonals.emplace_back(v, helper[e]);
        helper[e] = v;
        break;
      }
    }
    if (status.broken()) return false;
  }
  return !status.broken() && status.empty();
}

/// The region's boundary and diagonals as a plane graph: each corner's neighbours
/// counter-clockwise around it, in compressed rows.
class PlaneGraph {
 public:
  /// False when two neighbours of one corner lie in one direction from it (a diagonal
  /// along an edge: the precondition is broken).
  bool build(const Geometry& geometry, const Loops& loops,
             std::span<const std::pair<std::uint32_t, std::uint32_t>> diagonals) {
    const std::uint32_t m = loops.size();
    offset_.assign(m + 1, 0);
    for (std::uint32_t v = 0; v < m; ++v)
      offset_[v + 1] = 2;
    for (const auto& [a, b] : diagonals) {
      ++offset_[a + 1];
      ++offset_[b + 1];
    }
    for (std::uint32_t v = 0; v < m; ++v)
      offset_[v + 1] += offset_[v];
    neighbour_.assign(offset_[m], kNone);
    ScratchVector<std::uint32_t> fill(offset_.begin(), offset_.end() - 1);
    for (std::uint32_t v = 0; v < m; ++v) {
      neighbour_[fill[v]++] = loops.next[v];
      neighbour_[fill[v]++] = loops.previous[v];
    }
    for (const auto& [a, b] : diagonals) {
      neighbour_[fill[a]++] = b;
      neighbour_[fill[b]++] = a;
    }
    bool broken = false;
    for (std::uint32_t v = 0; v < m; ++v) {
      if (offset_[v + 1] - offset_[v] == 2) continue;
      std::sort(neighbour_.begin() + offset_[v], neighbour_.begin() + offset_[v + 1],
                [&](std::uint32_t a, std::uint32_t b) {
                  return counter_clockwise(geometry, v, a, b, broken);
                });
      // A neighbour twice: a diagonal along an edge or another diagonal.
      if (std::adjacent_find(neighbour_.begin() + offset_[v],
                             neighbour_.begin() + offset_[v + 1]) !=
          neighbour_.begin() + offset_[v + 1]) {
        return false;
      }
    }
    return !broken;
  }

  std::size_t begin(std::uint32_t v) const { return offset_[v]; }
  std::size_t end(std::uint32_t v) const { return offset_[v + 1]; }
  std::size_t size() const { return neighbour_.size(); }
  std::uint32_t neighbour(std::size_t slot) const { return neighbour_[slot]; }

  /// The slot of neighbour `a` in b's row, or size() when a is none of b's neighbours.
  std::size_t slot_of(const Geometry& geometry, std::uint32_t b, std::uint32_t a) const {
    const auto first = neighbour_.begin() + offset_[b];
    const auto last = neighbour_.begin() + offset_[b + 1];
    if (last - first <= 8) {
      const auto found = std::find(first, last, a);
      return found == last ? size() : static_cast<std::size_t>(found - neighbour_.begin());
    }
    bool broken = false;
    const auto found = std::lower_bound(first, last, a, [&](std::uint32_t x, std::uint32_t y) {
      return counter_clockwise(geometry, b, x, y, broken);
    });
    if (broken || found == last || *found != a) return size();
    return static_cast<std::size_t>(found - neighbour_.begin());
  }

 private:
  /// The direction from c to a comes before the one from c to b, counter-clockwise from
  /// the direction of increasing u (exact: a half-plane by coordinate comparisons, then an
  /// orientation).
  static bool counter_clockwise(const Geometry& geometry, std::uint32_t c, std::uint32_t a,
                                std::uint32_t b, bool& broken) {
    constexpr Projection plane = Geometry::plane();
    const auto lower_half = [&](std::uint32_t x) {
      const Point3& o = geometry.at(c);
      const Point3& p = geometry.at(x);
      return plane.v(p) < plane.v(o) || (plane.v(p) == plane.v(o) && plane.u(p) < plane.u(o));
    };
    const bool a_lower = lower_half(a);
    const bool b_lower = lower_half(b);
    if (a_lower != b_lower) return b_lower;
    const Sign turn = geometry.orientation(c, a, b);
    if (turn == Sign::zero && a != b) broken = true;
    return turn == Sign::positive;
  }

  ScratchVector<std::size_t> offset_;
  ScratchVector<std::uint32_t> neighbour_;
};

/// The working lists of triangulate_piece, kept from one piece to the next (a polygon is
/// cut into a piece per split or merge corner, and more).
struct PieceLists {
  ScratchVector<std::uint32_t> lower;
  ScratchVector<std::uint32_t> upper;
  ScratchVector<std::pair<std::uint32_t, bool>> sorted;  ///< (corner, on the upper chain)
  ScratchVector<std::uint32_t> stack;
};

/// Triangles of one piece monotone in sweep order, given as its corners counter-clockwise
/// (de Berg et al., TRIANGULATEMONOTONEPOLYGON), appended counter-clockwise; false when
/// the piece is not monotone or a triangle would be degenerate (the precondition broken).
bool triangulate_piece(const Geometry& geometry, std::span<const std::uint32_t> piece,
                       PieceLists& lists, ScratchVector<Triangle>& triangles) {
  const std::size_t k = piece.size();
  if (k < 3) return false;
  const auto earlier = [](std::uint32_t a, std::uint32_t b) { return a < b; };
  std::size_t first = 0;
  std::size_t last = 0;
  for (std::size_t i = 1; i < k; ++i) {
    if (earlier(piece[i], piece[first])) first = i;
    if (earlier(piece[last], piece[i])) last = i;
  }
  // Counter-clockwise, from the first corner forward to the last is the lower chain (the
  // piece above it), and backward the upper chain; each must advance in sweep order.
  auto& [lower, upper, sorted, stack] = lists;
  lower.clear();
  upper.clear();
  for (std::size_t i = (first + 1) % k; i != last; i = (i + 1) % k)
    lower.push_back(piece[i]);
  for (std::size_t i = (first + k - 1) % k; i != last; i = (i + k - 1) % k)
    upper.push_back(piece[i]);
  const auto advancing = [&](const ScratchVector<std::uint32_t>& chain) {
    return std::is_sorted(chain.begin(), chain.end(), earlier);
  };
  if (!advancing(lower) || !advancing(upper)) return false;
  // All corners in sweep order, each marked with its chain.
  sorted.clear();
  sorted.emplace_back(piece[first], false);
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < lower.size() || j < upper.size()) {
    if (j == upper.size() || (i < lower.size() && earlier(lower[i], upper[j]))) {
      sorted.emplace_back(lower[i++], false);
    } else {
      sorted.emplace_back(upper[j++], true);
    }
  }
  sorted.emplace_back(piece[last], false);

  bool degenerate = false;
  const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const Sign turn = geometry.orientation(a, b, c);
    if (turn == Sign::zero) degenerate = true;
    triangles.push_back(turn == Sign::positive ? Triangle{a, b, c} : Triangle{a, c, b});
  };
  stack.assign({sorted[0].first, sorted[1].first});
  bool top_upper = sorted[1].second;
  for (std::size_t n = 2; n + 1 < k; ++n) {
    const auto [u, u_upper] = sorted[n];
    if (u_upper != top_upper) {
      // The stack's chain faces u across the piece: a fan from u over all of it.
      for (std::size_t t = stack.size() - 1; t > 0; --t)
        emit(u, stack[t], stack[t - 1]);
      const std::uint32_t previous = stack.back();
      stack.assign({previous, u});
    } else {
      // Same chain: cut off the corners that are convex seen from u.
      std::uint32_t popped = stack.back();
      stack.pop_back();
      while (!stack.empty()) {
        const Sign turn = geometry.orientation(stack.back(), popped, u);
        if (turn != (u_upper ? Sign::negative : Sign::positive)) break;
        emit(stack.back(), popped, u);
        popped = stack.back();
        stack.pop_back();
      }
      stack.push_back(popped);
      stack.push_back(u);
    }
    top_upper = u_upper;
  }
  const std::uint32_t end = sorted[k - 1].first;
  for (std::size_t t = stack.size() - 1; t > 0; --t)
    emit(end, stack[t], stack[t - 1]);
  return !degenerate;
}

/// The pieces the diagonals cut the region into (the faces of the plane graph on the
/// region's side), each triangulated.
bool triangulate_pieces(const Geometry& geometry, const Loops& loops, const PlaneGraph& graph,
                        ScratchVector<Triangle>& triangles) {
  // Slot s of corner v is the half-edge v -> neighbour(s); the piece on its left follows
  // it. The half-edges against the loops (v -> previous[v]) have the outside on their left.
  ScratchVector<char> used(graph.size(), 0);
  ScratchVector<std::uint32_t> piece;
  PieceLists lists;
  for (std::uint32_t v = 0; v < loops.size(); ++v) {
    for (std::size_t s = graph.begin(v); s < graph.end(v); ++s) {
      if (used[s] || graph.neighbour(s) == loops.previous[v]) continue;
      piece.clear();
      std::uint32_t a = v;
      std::size_t slot = s;
      do {
        if (used[slot] || piece.size() > loops.size()) return false;
        used[slot] = 1;
        piece.push_back(a);
        const std::uint32_t b = graph.neighbour(slot);
        if (b == loops.previous[a]) return false;  // the outside
        // At b, the neighbour just clockwise from a: the piece turns as far left as it can.
        const std::size_t back = graph.slot_of(geometry, b, a);
        if (back == graph.size()) return false;
        slot = back == graph.begin(b) ? graph.end(b) - 1 : back - 1;
        a = b;
      } while (slot != s);
      if (!triangulate_piece(geometry, piece, lists, triangles)) return false;
    }
  }
  return true;
}

}  // namespace

bool triangulate_by_sweep(const PolygonWalk& walk, std::span<const std::uint32_t> order,
                          std::span<const Point3> vertices, const Projection& plane, Sign turn,
                          std::span<const std::uint32_t> below, std::vector<Face>& out) {
  Loops loops;
  if (!loops_of(walk, order, vertices, plane, turn, loops)) return false;
  const Geometry geometry(loops);
  ScratchVector<std::pair<std::uint32_t, std::uint32_t>> diagonals;
  std::optional<ScratchVector<std::uint32_t>> recorded;
  if (!below.empty()) recorded = recorded_below(walk, loops, below);
  bool partitioned = false;
  if (recorded) {
    RecordedStatus status(std::move(*recorded));
    partitioned = monotone_diagonals(geometry, loops, status, diagonals);
  }
  if (!partitioned) {  // no record, or one the partition could not use: search
    diagonals.clear();
    SearchedStatus status(loops);
    if (!monotone_diagonals(geometry, loops, status, diagonals)) return false;
  }
  PlaneGraph graph;
  if (!graph.build(geometry, loops, diagonals)) return false;
  ScratchVector<Triangle> triangles;
  triangles.reserve(walk.corners);
  if (!triangulate_pieces(geometry, loops, graph, triangles)) return false;
  // Counter-clockwise in the projection; the loops were reversed for a clockwise walk.
  for (const Triangle& t : triangles) {
    const VertexIndex a = loops.vertex[t[0]];
    const VertexIndex b = loops.vertex[t[1]];
    const VertexIndex c = loops.vertex[t[2]];
    out.push_back(turn == Sign::positive ? make_triangle(a, b, c) : make_triangle(a, c, b));
  }
  return true;
}

}  // namespace exactgeo::mesh::internal
