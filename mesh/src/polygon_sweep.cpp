#include "polygon_sweep.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "polygon_status.hpp"
#include "scratch_vector.hpp"

namespace exactgeo::mesh::internal {

namespace {

/// An edge of the walk in the sweep, as the status holds it: the (u, v) coordinates of
/// its endpoints in sweep order, its index in walk.edges, the winding number above it
/// minus the one below it (-1, 0 or 1), and the winding number just above it once
/// inserted (-2 to 2 before the sweep refuses anything but -1 to 1).
struct Segment {
  double left_u;
  double left_v;
  double right_u;
  double right_v;
  std::uint32_t edge;
  std::int8_t weight;
  std::int8_t above;

  Point3 left() const { return {left_u, left_v, 0.0}; }
  Point3 right() const { return {right_u, right_v, 0.0}; }
};

bool meet_improperly(const Segment& s, const Segment& t, const Projection& plane) {
  return segments_meet_improperly(s.left(), s.right(), t.left(), t.right(), plane);
}

/// The status order, bottom to top, of two segments across the sweep line at the point
/// where one of them is inserted: the other is already there (its left end is not later)
/// and has not left (its right end is later). A pair this order cannot separate (the new
/// one's left end on the other's line, or both from one point in one direction) meets
/// improperly: `degenerate` is set and the sweep stops.
class BottomToTop {
 public:
  explicit BottomToTop(bool& degenerate) : degenerate_(&degenerate) {}

  bool operator()(const Segment& s, const Segment& t) const {
    const Point3 s0 = s.left();
    const Point3 t0 = t.left();
    if (kFlat.same(s0, t0)) return decided(kFlat.orientation(s0, s.right(), t.right()));
    if (kFlat.before(s0, t0)) return decided(kFlat.orientation(s0, s.right(), t0));
    return decided(-kFlat.orientation(t0, t.right(), s0));
  }

 private:
  static constexpr Projection kFlat{2};

  /// s below t when `t_above_s` is positive.
  bool decided(Sign t_above_s) const {
    if (t_above_s == Sign::zero) *degenerate_ = true;  // the sweep stops
    return t_above_s == Sign::positive;
  }

  bool* degenerate_;
};

// Small enough that a status node, with its links, is one cache line of 64 bytes.
static_assert(sizeof(Segment) <= 40);

}  // namespace

bool segments_meet_improperly(const Point3& a0, const Point3& a1, const Point3& b0,
                              const Point3& b1, const Projection& plane) {
  // A shared endpoint (neighbours in a walk, mostly) makes one of the four orientations
  // below an exact zero, a filter's slowest answer; its cases are short. Such segments
  // share more than that point only when they lie on one line and leave it the same way:
  // from a common left end, or into a common right end; a common point that is the left
  // end of one and the right end of the other lies between them on any line.
  if (plane.same(a0, b0)) return plane.orientation(a0, a1, b1) == Sign::zero;
  if (plane.same(a1, b1)) return plane.orientation(a0, a1, b0) == Sign::zero;
  if (plane.same(a1, b0) || plane.same(a0, b1)) return false;
  const Sign o1 = plane.orientation(a0, a1, b0);
  const Sign o2 = plane.orientation(a0, a1, b1);
  if (o1 != Sign::zero && o1 == o2) return false;  // t on one side of s's line
  const Sign o3 = plane.orientation(b0, b1, a0);
  const Sign o4 = plane.orientation(b0, b1, a1);
  if (o3 != Sign::zero && o3 == o4) return false;
  if (o1 == Sign::zero && o2 == Sign::zero) {
    // One line, on which sweep order is the order along it: the segments share more
    // than a point when the later of their left ends comes before the earlier right end.
    const Point3& later_left = plane.before(a0, b0) ? b0 : a0;
    const Point3& earlier_right = plane.before(a1, b1) ? a1 : b1;
    return plane.before(later_left, earlier_right);
  }
  if (o1 != Sign::zero && o2 != Sign::zero && o3 != Sign::zero && o4 != Sign::zero) {
    return true;  // each straddles the other's line: a proper crossing
  }
  // Two lines, and an endpoint of one on the other's line: the segments can share only
  // that point, improperly when it lies strictly inside the other segment.
  const auto strictly_inside = [&](const Point3& p, const Point3& left, const Point3& right) {
    return plane.before(left, p) && plane.before(p, right);
  };
  if (o1 == Sign::zero) return strictly_inside(b0, a0, a1);
  if (o2 == Sign::zero) return strictly_inside(b1, a0, a1);
  if (o3 == Sign::zero) return strictly_inside(a0, b0, b1);
  return strictly_inside(a1, b0, b1);
}

std::optional<Sign> region_turn(const PolygonWalk& walk, std::span<const std::uint32_t> order,
                                std::span<const Point3> vertices, const Projection& plane,
                                ScratchVector<std::uint32_t>* below) {
  // Everything by rank in sweep order: the flat points side by side, the segments in the
  // order they are inserted (by their left ends' ranks), so that those starting at rank
  // r are segments[first[r], first[r + 1]), and those ending there ending[last[r],
  // last[r + 1]).
  const Projection flat(2);
  const std::size_t m = order.size();
  ScratchVector<std::uint32_t> rank(m);
  ScratchVector<Point3> point(m);
  for (std::size_t r = 0; r < m; ++r) {
    rank[order[r]] = static_cast<std::uint32_t>(r);
    point[r] = plane.flat(vertices[walk.vertices[order[r]]]);
  }
  ScratchVector<std::uint32_t> first(m + 1, 0);
  ScratchVector<std::uint32_t> last(m + 1, 0);
  for (const ChainEdge& e : walk.edges) {
    const std::uint32_t a = rank[e.low];
    const std::uint32_t b = rank[e.high];
    if (flat.same(point[a], point[b])) return std::nullopt;  // zero length
    // Off every other edge (else the sweep refuses), the winding numbers just above and
    // just below an edge differ by its coefficient, and two of 0 and one sign's 1 differ
    // by at most 1.
    if (e.coefficient < -1 || e.coefficient > 1) return std::nullopt;
    ++first[std::min(a, b) + 1];
    ++last[std::max(a, b) + 1];
  }
  for (std::size_t r = 0; r < m; ++r) {
    first[r + 1] += first[r];
    last[r + 1] += last[r];
  }
  ScratchVector<Segment> segments(walk.edges.size());
  ScratchVector<std::uint32_t> ending(walk.edges.size());
  ScratchVector<std::uint32_t> right_rank(walk.edges.size());
  {
    ScratchVector<std::uint32_t> fill_first(first.begin(), first.end() - 1);
    ScratchVector<std::uint32_t> fill_last(last.begin(), last.end() - 1);
    for (std::uint32_t k = 0; k < walk.edges.size(); ++k) {
      const ChainEdge& e = walk.edges[k];
      const std::uint32_t a = rank[e.low];
      const std::uint32_t b = rank[e.high];
      const Point3& l = point[std::min(a, b)];
      const Point3& r = point[std::max(a, b)];
      const std::uint32_t s = fill_first[std::min(a, b)]++;
      const auto weight = static_cast<std::int8_t>(a < b ? e.coefficient : -e.coefficient);
      segments[s] = {l[0], l[1], r[0], r[1], k, weight, 0};
      right_rank[s] = std::max(a, b);
      ending[fill_last[std::max(a, b)]++] = s;
    }
  }

  bool degenerate = false;
  using Status = SweepStatus<Segment, BottomToTop>;
  Status status{BottomToTop(degenerate)};
  ScratchVector<Status::Handle> place(segments.size(), Status::kNone);
  bool positive = false;
  bool negative = false;
  ScratchVector<std::uint32_t> inserted;
  if (below) below->assign(walk.vertices.size(), kNoEdge);
  // The edge just below a point, from the status item just above it (kNone: the top).
  const auto record = [&](std::size_t g, std::size_t h, Status::Handle above_point) {
    std::uint32_t edge = kNoEdge;
    Status::Handle at = above_point == Status::kNone ? status.last() : status.previous(above_point);
    for (int bridges = 0; at != Status::kNone; ++bridges, at = status.previous(at)) {
      if (status[at].weight != 0) {
        edge = status[at].edge;
        break;
      }
      if (bridges == 8) {
        edge = kUnknownEdge;
        break;
      }
    }
    for (std::size_t r = g; r < h; ++r)
      (*below)[order[r]] = edge;
  };
  // A corner with both edges leaving (no edge ended there to take the place of): its
  // lowest edge is tried just below and just above an edge that ends where it ends,
  // already in the status (the corners of a polygon's walk are near their neighbours',
  // so mostly that is its place: two comparisons each, where a search from the root
  // costs a few dozen), and searched for otherwise.
  const auto insert_beside_a_neighbour = [&](std::uint32_t s) {
    const std::uint32_t r = right_rank[s];
    for (std::uint32_t e = last[r]; e < last[r + 1]; ++e) {
      const Status::Handle neighbour = place[ending[e]];
      if (ending[e] == s || neighbour == Status::kNone) continue;
      for (const Status::Handle above : {neighbour, status.next(neighbour)}) {
        if (const Status::Handle it = status.try_insert_below(segments[s], above);
            it != Status::kNone || degenerate) {
          return it;
        }
      }
      break;
    }
    return status.insert(segments[s]);
  };
  for (std::size_t g = 0; g < m;) {
    // The ranks [g, h) at one projected point.
    const Point3& at = point[g];
    std::size_t h = g + 1;
    while (h < m && flat.same(at, point[h]))
      ++h;
    // Where the last segment left: most corners have one edge in and one out, and the
    // one out goes there (a place the status checks with two comparisons, else ignores).
    bool removed = false;
    Status::Handle hint = Status::kNone;
    for (std::uint32_t e = last[g]; e < last[h]; ++e) {
      const Status::Handle it = place[ending[e]];
      const Status::Handle under = status.previous(it);
      const Status::Handle over = status.next(it);
      if (under != Status::kNone && over != Status::kNone &&
          meet_improperly(status[under], status[over], flat)) {
        return std::nullopt;
      }
      hint = status.erase(it);
      place[ending[e]] = Status::kNone;
      removed = true;
    }
    if (below && removed) record(g, h, hint);
    // Lowest first, so that each finds the winding number below it already set.
    inserted.resize(first[h] - first[g]);
    std::iota(inserted.begin(), inserted.end(), first[g]);
    if (inserted.size() > 1) {
      std::sort(inserted.begin(), inserted.end(), [&](std::uint32_t a, std::uint32_t b) {
        return flat.orientation(at, segments[a].right(), segments[b].right()) == Sign::positive;
      });
    }
    bool placed = removed;
    for (const std::uint32_t s : inserted) {
      const Status::Handle it =
          placed ? status.insert_below(segments[s], hint) : insert_beside_a_neighbour(s);
      if (degenerate) return std::nullopt;
      if (below && !placed) record(g, h, it);
      placed = true;
      hint = status.next(it);  // the next one from this point goes just above
      place[s] = it;
      std::int32_t winding_below = 0;
      if (const Status::Handle under = status.previous(it); under != Status::kNone) {
        if (meet_improperly(status[under], status[it], flat)) return std::nullopt;
        winding_below = status[under].above;
      }
      if (hint != Status::kNone && meet_improperly(status[it], status[hint], flat)) {
        return std::nullopt;
      }
      Segment& inserted_segment = status[it];
      inserted_segment.above = static_cast<std::int8_t>(winding_below + inserted_segment.weight);
      positive = positive || inserted_segment.above == 1;
      negative = negative || inserted_segment.above == -1;
      if (inserted_segment.above > 1 || inserted_segment.above < -1 || (positive && negative)) {
        return std::nullopt;
      }
    }
    g = h;
  }
  if (positive) return Sign::positive;
  if (negative) return Sign::negative;
  return std::nullopt;  // the walk bounds nothing
}

}  // namespace exactgeo::mesh::internal
