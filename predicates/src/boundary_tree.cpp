#include "exactgeo/predicates/boundary_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "boundary_term_filter.hpp"
#include "box_distance.hpp"
#include "double_interval.hpp"
#include "far_field.hpp"

// The identity, why a ray that misses a node's box makes it exact, and the bound:
// boundary_tree.hpp.

namespace exactgeo {
namespace {

using internal::area_above;
using internal::DoubleInterval;
using internal::up;

constexpr double kU = 0x1p-53;
constexpr double kTiny = 0x1p-1000;

// The per-point tests take a priori bounds instead of directed rounding (std::nextafter
// is a library call, and a point visits many nodes): a difference, product or quotient of
// doubles is within u = 2^-53 of its exact value relatively, or 2^-1075 absolutely where
// it underflows (a difference that underflows is exact).

/// A lower bound on the squared distance from p to the box (0 when p may be in it).
double distance2_below(const Point3& p, const Point3& lower, const Point3& upper) noexcept {
  return internal::box_distance2_below(p, p, lower, upper);
}

/// Does the ray p + t r (t >= 0) certainly miss the closed box? From the slabs: it meets
/// the box exactly when max(0, entries) <= min(exits), the entry and exit parameters
/// (lower - p) / r and (upper - p) / r (ordered by r's sign), computed as
/// (lower - p) times `inverse`, 1 / r rounded. Each computed t is within 3u |t| + 2^-1075
/// of its exact value (a difference, a reciprocal and a product; the reciprocal of a
/// component between 2^-1000 and 2^1000 in magnitude neither underflows nor overflows,
/// which refine checks); the largest entry moved down and the smallest exit moved up by
/// 2^-50 |t| + kTiny (more than that, their own rounding included) bound the exact
/// entry of the same slab, hence the exact largest, from below, and the exact exit of the
/// same slab, hence the exact smallest, from above: a miss found with them is a miss. (Only
/// the two extremes take a margin.) A difference that overflows makes a t infinite: an
/// infinite largest entry or smallest exit then gives NaN, which finds no miss.
[[gnu::always_inline]] inline bool ray_misses(const Point3& p, const Vector3& r,
                                              const Vector3& inverse, const Point3& lower,
                                              const Point3& upper) noexcept {
  double enter = 0.0, exit = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (r[i] == 0.0) {
      if (p[i] < lower[i] || p[i] > upper[i]) return true;  // parallel to the slab, outside
      continue;
    }
    const double t0 = (lower[i] - p[i]) * inverse[i], t1 = (upper[i] - p[i]) * inverse[i];
    enter = std::max(enter, std::min(t0, t1));
    exit = std::min(exit, std::max(t0, t1));
  }
  enter -= std::abs(enter) * 0x1p-50 + kTiny;
  exit += std::abs(exit) * 0x1p-50 + kTiny;
  return enter > exit;
}

/// Each edge's piece of trail (a walk along edges that share vertices, cut into pieces of
/// at most kPiece consecutive edges), its place in it, and the key the halving sorts by:
/// the piece's mean midpoint, which keeps it together where the halving allows. A node
/// then holds whole pieces, each with at most two ends (none for a small closed loop),
/// where edges sorted by their own midpoints left a winding rim entering and leaving
/// every box many times, two ends each time (docs/inside.md measures the pieces' length).
/// A cost only: any grouping gives the same bounds' guarantee.
std::vector<BoundaryTree::TrailPlace> trail_places(std::span<const BoundaryEdge> edges,
                                                   std::span<const Point3> vertices) {
  constexpr std::uint32_t kPiece = 64;
  std::vector<std::vector<std::uint32_t>> leaving(vertices.size());
  for (std::uint32_t i = 0; i < edges.size(); ++i)
    leaving[edges[i].from].push_back(i);
  std::vector<BoundaryTree::TrailPlace> places(edges.size());
  std::vector<bool> used(edges.size(), false);
  std::uint32_t trail = 0;
  std::vector<std::uint32_t> walk;
  for (std::uint32_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    walk.clear();
    for (std::uint32_t e = start;;) {
      used[e] = true;
      walk.push_back(e);
      auto& next = leaving[edges[e].to];
      while (!next.empty() && used[next.back()])
        next.pop_back();
      if (next.empty()) break;
      e = next.back();
    }
    for (std::size_t first = 0; first < walk.size(); first += kPiece) {
      const std::size_t count = std::min<std::size_t>(kPiece, walk.size() - first);
      Point3 mean{0.0, 0.0, 0.0};
      for (std::size_t k = first; k < first + count; ++k) {
        const BoundaryEdge& e = edges[walk[k]];
        for (int i = 0; i < 3; ++i)
          mean[i] +=
              (0.5 * vertices[e.from][i] + 0.5 * vertices[e.to][i]) / static_cast<double>(count);
      }
      for (std::size_t k = first; k < first + count; ++k)
        places[walk[k]] = {mean, trail, static_cast<std::uint32_t>(k)};
      ++trail;
    }
  }
  return places;
}

}  // namespace

/// M = (1/2) sum m (a - c) x (b - c) and Q = sum m (1/6) ((a - c) x (b - c))
/// ((a - c) + (b - c))^T (boundary_tree.hpp, "Second order") of the fan of `edges` about
/// c, in outward-rounded intervals.
internal::Moments BoundaryTree::fan_moments(const Point3& c,
                                            std::span<const BoundaryEdge> edges) const {
  internal::Moments moments;
  auto& [m, q] = moments;
  const DoubleInterval sixth = DoubleInterval{1.0, 1.0} / DoubleInterval::exact(6.0);
  const DoubleInterval half = DoubleInterval::exact(0.5);
  for (const BoundaryEdge& e : edges) {
    std::array<DoubleInterval, 3> u, v, x, s;
    for (int i = 0; i < 3; ++i) {
      u[i] = DoubleInterval::difference(vertices_[e.from][i], c[i]);
      v[i] = DoubleInterval::difference(vertices_[e.to][i], c[i]);
      s[i] = u[i] + v[i];
    }
    const DoubleInterval times = DoubleInterval::exact(e.multiplicity);
    x[0] = (u[1] * v[2] - u[2] * v[1]) * times;
    x[1] = (u[2] * v[0] - u[0] * v[2]) * times;
    x[2] = (u[0] * v[1] - u[1] * v[0]) * times;
    for (int i = 0; i < 3; ++i) {
      m[i] = m[i] + x[i] * half;
      for (int j = 0; j < 3; ++j)
        q[i][j] = q[i][j] + x[i] * s[j] * sixth;
    }
  }
  return moments;
}

BoundaryTree::BoundaryTree(std::span<const Point3> vertices, std::span<const BoundaryEdge> edges) {
  if (edges.empty()) return;
  // The edges' vertices, renumbered in order of first use.
  std::unordered_map<VertexIndex, VertexIndex> renumbered;
  const auto own = [&](VertexIndex v) {
    const auto [it, added] = renumbered.try_emplace(v, static_cast<VertexIndex>(vertices_.size()));
    if (added) vertices_.push_back(vertices[v]);
    return it->second;
  };
  edges_.reserve(edges.size());
  for (const BoundaryEdge& e : edges)
    edges_.push_back({own(e.from), own(e.to), e.multiplicity});
  places_ = trail_places(edges_, vertices_);
  nodes_.reserve(2 * (edges_.size() / kBoundaryTreeLeafEdges + 1));
  build(0, static_cast<std::uint32_t>(edges_.size()));
  places_ = {};
}

/// Chords from `starts` to `finishes` (vertices with the flow they lack and carry in
/// excess, equal in total) onto chords_: each start joined to the nearest finish with flow
/// left, as often as both allow; a chord whose two vertices coincide in space has no
/// cone term (its triangles have no area) and is left out. Nearest, not optimal: any
/// joining closes the node's edges (boundary_tree.hpp, "Chords"), and shorter chords
/// only make the bounds
/// smaller (a cost); past kChordSearch pairs the finishes are taken in order.
void BoundaryTree::join_chords(std::vector<std::pair<VertexIndex, std::int64_t>>& starts,
                               std::vector<std::pair<VertexIndex, std::int64_t>>& finishes) {
  constexpr std::size_t kChordSearch = 4096;
  const bool nearest = starts.size() * finishes.size() <= kChordSearch;
  std::size_t next = 0;  // finishes before it are spent (in order)
  for (auto& [s, left] : starts) {
    while (left > 0) {
      std::size_t best = next;
      if (nearest) {
        double best_d2 = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < finishes.size(); ++k) {
          if (finishes[k].second == 0) continue;
          double d2 = 0.0;
          for (int i = 0; i < 3; ++i) {
            const double d = vertices_[finishes[k].first][i] - vertices_[s][i];
            d2 += d * d;
          }
          if (d2 < best_d2 || best_d2 == std::numeric_limits<double>::infinity()) {
            best_d2 = d2;
            best = k;
          }
        }
      } else {
        while (finishes[next].second == 0)
          ++next;
        best = next;
      }
      auto& [f, carried] = finishes[best];
      const std::int64_t m = std::min(left, carried);
      left -= m;
      carried -= m;
      if (vertices_[s] != vertices_[f]) {
        chords_.push_back({s, f, static_cast<std::int32_t>(m)});
      }
    }
  }
}

std::uint32_t BoundaryTree::build(std::uint32_t first, std::uint32_t count) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.first = first;
  node.count = count;
  const std::span<BoundaryEdge> own(edges_.data() + first, count);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  node.lower = {kInf, kInf, kInf};
  node.upper = {-kInf, -kInf, -kInf};
  for (const BoundaryEdge& e : own) {
    for (const VertexIndex v : {e.from, e.to}) {
      for (int i = 0; i < 3; ++i) {
        node.lower[i] = std::min(node.lower[i], vertices_[v][i]);
        node.upper[i] = std::max(node.upper[i], vertices_[v][i]);
      }
    }
  }
  // The centre, clamped into the box (a rounded midpoint lies in it anyway; the clamp makes
  // that obvious).
  Point3 centre;
  for (int i = 0; i < 3; ++i) {
    centre[i] = std::clamp(0.5 * node.lower[i] + 0.5 * node.upper[i], node.lower[i], node.upper[i]);
  }
  node.centre = centre;
  // The chords (boundary_tree.hpp, "Chords"): delta(x) = what enters x minus what leaves
  // it; each start (delta < 0) joined to ends (delta > 0), the nearest first, until its
  // flow is spent. The node's edges with its chords reversed are a closed chain Z.
  std::vector<std::pair<VertexIndex, std::int64_t>> flow;
  flow.reserve(2 * count);
  for (const BoundaryEdge& e : own) {
    flow.emplace_back(e.to, e.multiplicity);
    flow.emplace_back(e.from, -std::int64_t{e.multiplicity});
  }
  std::sort(flow.begin(), flow.end());
  std::vector<std::pair<VertexIndex, std::int64_t>> starts, finishes;
  for (std::size_t i = 0; i < flow.size();) {
    std::int64_t delta = 0;
    std::size_t j = i;
    for (; j < flow.size() && flow[j].first == flow[i].first; ++j)
      delta += flow[j].second;
    if (delta < 0) starts.emplace_back(flow[i].first, -delta);
    if (delta > 0) finishes.emplace_back(flow[i].first, delta);
    i = j;
  }
  node.chords_first = static_cast<std::uint32_t>(chords_.size());
  join_chords(starts, finishes);
  node.chords_count = static_cast<std::uint32_t>(chords_.size()) - node.chords_first;
  const std::span<const BoundaryEdge> chords(chords_.data() + node.chords_first, node.chords_count);
  std::vector<BoundaryEdge> closed(own.begin(), own.end());
  for (const BoundaryEdge& e : chords)
    closed.push_back({e.to, e.from, e.multiplicity});
  const internal::Moments moments = fan_moments(centre, closed);
  // F = sum |m| area(a, b, c) over Z, rounded up (the children may give a smaller one,
  // below).
  const auto fan_of = [&](std::span<const BoundaryEdge> edges) {
    double fan = 0.0;
    for (const BoundaryEdge& e : edges) {
      const double area = area_above(vertices_[e.from], vertices_[e.to], centre);
      fan = up(fan + up(area * std::abs(static_cast<double>(e.multiplicity))));
    }
    return fan;
  };
  node.fan = fan_of(closed);
  if (count > kBoundaryTreeLeafEdges) {
    // Halves by the edges' midpoints along the box's longest axis.
    int axis = 0;
    for (int i = 1; i < 3; ++i) {
      if (node.upper[i] - node.lower[i] > node.upper[axis] - node.lower[axis]) axis = i;
    }
    // Pieces of trail (small holes whole) stay whole where the halves allow: a node
    // holding a closed loop entirely has no end for it.
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), first);
    const auto key = [&](std::uint32_t i) {
      const TrailPlace& t = places_[i];
      return std::tuple(t.key[axis], t.trail, t.position);
    };
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    std::vector<BoundaryEdge> sorted_edges(count);
    std::vector<TrailPlace> sorted_places(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      sorted_edges[i] = edges_[order[i]];
      sorted_places[i] = places_[order[i]];
    }
    std::copy(sorted_edges.begin(), sorted_edges.end(), edges_.begin() + first);
    std::copy(sorted_places.begin(), sorted_places.end(), places_.begin() + first);
    const auto same_piece = [&](std::uint32_t i) {  // edges i - 1 and i, of this node
      const TrailPlace& a = places_[first + i - 1];
      const TrailPlace& b = places_[first + i];
      return a.trail == b.trail;
    };
    std::uint32_t half = count / 2;
    std::uint32_t forward = half, backward = half;
    while (forward < count && same_piece(forward))
      ++forward;
    while (backward > 0 && same_piece(backward))
      --backward;
    if (forward < count) {
      half = forward - half <= half - backward || backward == 0 ? forward : backward;
    } else if (backward > 0) {
      half = backward;
    }
    node.left = build(first, half);
    node.right = build(first + half, count - half);
    // The children's bounds and the fan of their and this node's chords about this centre
    // (boundary_tree.hpp, "Nested bounds"): far smaller than the direct F where the
    // edges form small closed loops, whose fans about a distant centre are long and thin.
    double nested = up(up(nodes_[node.left].fan + nodes_[node.right].fan) +
                       fan_of(std::span(chords_).subspan(node.chords_first, node.chords_count)));
    for (const std::uint32_t child : {node.left, node.right}) {
      const Node& n = nodes_[child];
      nested = up(nested + fan_of(std::span(chords_).subspan(n.chords_first, n.chords_count)));
    }
    node.fan = std::min(node.fan, nested);
  }
  // (A node of more chords costs nearly what its edges cost, and is opened.)
  node.far_pays = 2 * node.chords_count < node.count && std::isfinite(node.fan);
  internal::set_far_field(node, moments);
  nodes_[index] = node;
  return index;
}

/// What every far node of one point's refinement is measured against.
struct BoundaryTree::Query {
  Point3 point;
  Vector3 ray;
  Vector3 apex;     // -ray
  Vector3 inverse;  // 1 / ray, per component
  Vector3 d;        // apex, scaled for the filter
  double ld = 0.0;  // its length
};

/// The node as a far node, where its bound is at most `limit` and the ray misses its
/// box (known already where `misses`); nullopt otherwise, or where an end's angle cannot
/// be bounded. Inlined into the refinement, which calls it for every node it visits (the
/// call's cost measured: docs/inside.md, "Many boundary edges near most points").
[[gnu::always_inline]] inline std::optional<BoundaryTree::FarValue> BoundaryTree::far_value(
    const Node& node, const Query& q, double limit, bool misses) const {
  if (!node.far_pays) return std::nullopt;
  const Point3& p = q.point;
  const double d2 = distance2_below(p, node.lower, node.upper);
  const auto [bound, expanded] = internal::far_bound(node, d2);  // far_field.hpp
  if (!(bound <= limit) || !(misses || ray_misses(p, q.ray, q.inverse, node.lower, node.upper))) {
    return std::nullopt;
  }
  const double expansion = expanded ? internal::expansion_value(node, p) : 0.0;
  double value = expansion, magnitudes = std::abs(expansion), errors = 0.0;
  for (std::uint32_t i = 0; i < node.chords_count; ++i) {
    const BoundaryEdge& e = chords_[node.chords_first + i];
    const auto angle =
        internal::half_angle(p, q.d, q.ld, vertices_[e.from], vertices_[e.to], q.apex);
    // (The ray misses the box, which holds the chords: never ray_on_edge.)
    if (!angle || angle->kind != BoundaryTermKind::enclosed) return std::nullopt;
    const double m = e.multiplicity;
    value += m * angle->theta;
    magnitudes += std::abs(m * angle->theta);
    errors += std::abs(m) * angle->error;
  }
  // The sum of chords + 1 terms rounds within (chords + 1) u of their magnitudes, and
  // each product by a multiplicity within u of its own: (chords + 3) u covers both.
  errors += (static_cast<double>(node.chords_count) + 3) * kU * magnitudes;
  return FarValue{value, errors, bound, expanded};
}

template <class Done>
std::optional<BoundaryTree::Refined> BoundaryTree::refine(const Point3& point, const Vector3& ray,
                                                          Refinement& r, std::size_t most_angles,
                                                          double first_cut,
                                                          const Done& done) const {
  r.heap.clear();
  r.stack.clear();
  r.angles = r.far_nodes = r.expansions = 0;
  r.slack = 0.0;
  r.opened = false;
  if (nodes_.empty()) return Refined{};
  // Each component 0 or between 2^-1000 and 2^1000 in magnitude (ray_misses' reciprocals).
  constexpr double kLargeComponent = 0x1p1000, kSmallComponent = 0x1p-1000;
  for (int i = 0; i < 3; ++i) {
    const double c = std::abs(ray[i]);
    if (!(c < kLargeComponent && (c == 0.0 || c > kSmallComponent))) {
      return std::nullopt;  // (not reached for the rays in use)
    }
  }
  const Vector3 apex{-ray[0], -ray[1], -ray[2]};
  const std::optional<Vector3> d = internal::normalized_apex(apex);
  if (!d) return std::nullopt;
  // The reciprocals of the ray's components (below 2^1000 in magnitude, which
  // ray_directions.hpp's and open_label.hpp's are by far: no reciprocal underflows).
  const Query q{point, ray,
                apex,  {1.0 / ray[0], 1.0 / ray[1], 1.0 / ray[2]},
                *d,    std::sqrt((*d)[0] * (*d)[0] + (*d)[1] * (*d)[1] + (*d)[2] * (*d)[2])};
  // The running sums (boundary_tree.hpp, "Refinement"): the angles' and far values' sum
  // with the magnitudes of all it was given or had taken away and their count; the far
  // bounds' sum likewise; the errors' (never taken away).
  double sum = 0.0, magnitudes = 0.0, bounds = 0.0, bound_magnitudes = 0.0, errors = 0.0;
  std::size_t terms = 0, bound_terms = 0, error_terms = 0;
  // A node's edges into the sum; false where an angle cannot be bounded (kind says
  // whether the ray meets the edge).
  BoundaryTermKind kind = BoundaryTermKind::enclosed;
  const auto add_edges = [&](const Node& node) {
    for (std::uint32_t i = 0; i < node.count; ++i) {
      const BoundaryEdge& e = edges_[node.first + i];
      const auto angle =
          internal::half_angle(point, q.d, q.ld, vertices_[e.from], vertices_[e.to], apex);
      if (!angle) return false;
      if (angle->kind != BoundaryTermKind::enclosed) {
        kind = angle->kind;
        return false;
      }
      const double m = e.multiplicity;
      sum += m * angle->theta;
      magnitudes += std::abs(m * angle->theta);
      errors += std::abs(m) * angle->error;
      ++terms;
      ++error_terms;
    }
    r.angles += node.count;
    return true;
  };
  // The nodes on the stack into the sum: far ones onto the heap, leaves' edges, the rest
  // opened.
  double limit = first_cut;  // the largest bound a far node may enter with
  bool opened = false;       // whether the first cut left the point unsettled
  // The far nodes become a heap only when the first cut does not settle the point (most
  // points are settled there).
  bool heaped = false;
  const auto by_bound = [](const Refinement::Far& a, const Refinement::Far& b) {
    return a.bound < b.bound;
  };
  const auto descend = [&]() {
    while (!r.stack.empty()) {
      const auto [n, misses] = r.stack.back();
      r.stack.pop_back();
      const Node& node = nodes_[n];
      if (const auto far = far_value(node, q, limit, misses)) {
        sum += far->value;
        magnitudes += std::abs(far->value);
        ++terms;
        errors += far->error;
        ++error_terms;
        bounds += far->bound;
        bound_magnitudes += far->bound;
        ++bound_terms;
        r.angles += node.chords_count;
        r.heap.push_back({far->bound, far->value, n, far->expanded});
        if (heaped) std::push_heap(r.heap.begin(), r.heap.end(), by_bound);
        continue;
      }
      if (node.left == 0) {
        if (!add_edges(node)) return false;
        continue;
      }
      r.stack.push_back({node.right, misses});
      r.stack.push_back({node.left, misses});
    }
    return true;
  };
  r.stack.push_back({0, false});
  while (true) {
    if (!descend()) {
      if (kind == BoundaryTermKind::ray_on_edge) return Refined{kind, 0.0, 0.0};
      return std::nullopt;
    }
    // Recursive summation of k terms errs by at most (k - 1) u times their magnitudes;
    // the factor covers these products' and sums' own rounding.
    const double error = (errors + bounds +
                          kU * (static_cast<double>(terms + 2) * magnitudes +
                                static_cast<double>(bound_terms + 2) * bound_magnitudes +
                                static_cast<double>(error_terms + 2) * errors)) *
                             (1 + 8 * kU) +
                         kTiny;
    const double lower = sum - error, upper = sum + error;
    if (done(lower, upper) || r.heap.empty()) {
      r.opened = opened;
      r.far_nodes = r.heap.size();
      for (const Refinement::Far& far : r.heap) {
        r.expansions += far.expanded;
        r.slack += far.bound;
      }
      return Refined{BoundaryTermKind::enclosed, lower, upper};
    }
    if (r.angles > most_angles) return std::nullopt;
    opened = true;
    // The far node of largest bound opened; its children enter as far nodes only with
    // at most kBoundaryTreeOpening times less (else they are opened before their ends
    // are computed).
    if (!heaped) std::make_heap(r.heap.begin(), r.heap.end(), by_bound);
    heaped = true;
    limit = std::min(limit, r.heap.front().bound / kBoundaryTreeOpening);
    std::pop_heap(r.heap.begin(), r.heap.end(), by_bound);
    const Refinement::Far top = r.heap.back();
    r.heap.pop_back();
    sum -= top.value;
    magnitudes += std::abs(top.value);
    ++terms;
    bounds -= top.bound;
    bound_magnitudes += top.bound;
    ++bound_terms;
    const Node& node = nodes_[top.node];
    if (node.left == 0) {
      if (!add_edges(node)) {
        if (kind == BoundaryTermKind::ray_on_edge) return Refined{kind, 0.0, 0.0};
        return std::nullopt;
      }
    } else {
      // A far node's box the ray missed; so it misses its children's, which lie in it.
      r.stack.push_back({node.right, true});
      r.stack.push_back({node.left, true});
    }
  }
}

std::optional<BoundaryTerm> BoundaryTree::term(const Point3& point, const Vector3& ray,
                                               std::array<double, 2> levels,
                                               Refinement& scratch) const {
  std::optional<BoundaryTerm> settled;  // the last enclosure's verdict
  // Past as many angles as there are edges, the term over every edge is the better next
  // step.
  const auto sum = refine(
      point, ray, scratch, edges_.size(), scratch.first_cut, [&](double lower, double upper) {
        settled = internal::settled({BoundaryTermKind::enclosed, lower, upper}, levels);
        return settled.has_value();
      });
  // The next point's first cut (a cost, carried in the scratch): down to the scratch's
  // floor (kBoundaryTreeFinestFirstCut, or kBoundaryTreeSpatialFirstCut) while points need
  // opening, back up to kBoundaryTreeFirstCut, doubling, while the first cut settles them.
  scratch.first_cut = !sum || scratch.opened
                          ? std::max(scratch.finest_first_cut, scratch.first_cut / 2)
                          : std::min(kBoundaryTreeFirstCut, scratch.first_cut * 2);
  if (!sum || sum->kind != BoundaryTermKind::enclosed) return std::nullopt;
  return settled;
}

std::optional<Enclosure> BoundaryTree::enclosure(const Point3& point, const Vector3& ray,
                                                 double width, Refinement& scratch) const {
  const double radians = width * 2 * std::numbers::pi;
  const auto sum =
      refine(point, ray, scratch, std::numeric_limits<std::size_t>::max(), kBoundaryTreeFirstCut,
             [&](double lower, double upper) { return upper - lower <= radians; });
  if (!sum || sum->kind != BoundaryTermKind::enclosed) return std::nullopt;
  return internal::turns_of({BoundaryTermKind::enclosed, sum->lower, sum->upper});
}

}  // namespace exactgeo
