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
#include "double_interval.hpp"

// The identity, why a ray that misses a node's box makes it exact, and the bound:
// boundary_tree.hpp.

namespace exactgeo {
namespace {

using internal::DoubleInterval;

constexpr double kU = 0x1p-53;
constexpr double kTiny = 0x1p-1000;
/// A bound on the dipole term's rounding relative to |M| / |c - p|^2: c - p within u,
/// which moves (c - p) / |c - p|^3 by 2u relatively; the dot within 3u of |M| |c - p|;
/// |c - p|^3 within 6u; the quotient u: 12u, far below this.
constexpr double kDipoleRounding = 0x1p-40;

double up(double x) noexcept {
  return DoubleInterval::up(x);
}

/// area(a, b, c) (half the cross product's length), its upper end in outward-rounded
/// intervals; +inf when that overflows.
double area_above(const Point3& a, const Point3& b, const Point3& c) noexcept {
  std::array<DoubleInterval, 3> u, v;
  for (int i = 0; i < 3; ++i) {
    u[i] = DoubleInterval::difference(a[i], c[i]);
    v[i] = DoubleInterval::difference(b[i], c[i]);
  }
  const DoubleInterval x = u[1] * v[2] - u[2] * v[1];
  const DoubleInterval y = u[2] * v[0] - u[0] * v[2];
  const DoubleInterval z = u[0] * v[1] - u[1] * v[0];
  const double length = sqrt(x * x + y * y + z * z).hi;
  if (!std::isfinite(length)) return std::numeric_limits<double>::infinity();
  return up(0.5 * length);
}

// The per-point tests take a priori bounds instead of directed rounding (std::nextafter
// is a library call, and a point visits many nodes): a difference, product or quotient of
// doubles is within u = 2^-53 of its exact value relatively, or 2^-1075 absolutely where
// it underflows (a difference that underflows is exact).

/// A lower bound on the squared distance from p to the box (0 when p may be in it): each
/// gap and square within u relatively, the sum of three within 2u more, all within
/// 5u < 2^-50; underflows lose at most 3 2^-1075, far below kTiny.
double distance2_below(const Point3& p, const Point3& lower, const Point3& upper) noexcept {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double gap = p[i] < lower[i] ? lower[i] - p[i] : p[i] > upper[i] ? p[i] - upper[i] : 0.0;
    sum += gap * gap;
  }
  return std::max(0.0, sum * (1 - 0x1p-50) - kTiny);
}

/// Does the ray p + t r (t >= 0) certainly miss the closed box? From the slabs: it meets
/// the box exactly when max(0, entries) <= min(exits), the entry and exit parameters
/// (lower - p) / r and (upper - p) / r (ordered by r's sign), computed as
/// (lower - p) times `inverse`, 1 / r rounded. Each computed t is within 3u |t| + 2^-1075
/// of its exact value (a difference, a reciprocal and a product; the reciprocal of a
/// component below 2^1000 does not underflow); an entry moved down and an exit moved up by
/// 2^-50 |t| + kTiny (more than that, their own rounding included) bound the exact ones,
/// and a miss found with them is a miss. A t that is not finite (an overflow, or a
/// reciprocal that overflows) is left out, which can only hide a miss.
bool ray_misses(const Point3& p, const Vector3& r, const Vector3& inverse, const Point3& lower,
                const Point3& upper) noexcept {
  double enter = 0.0, exit = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (r[i] == 0.0) {
      if (p[i] < lower[i] || p[i] > upper[i]) return true;  // parallel to the slab, outside
      continue;
    }
    double t0 = (lower[i] - p[i]) * inverse[i], t1 = (upper[i] - p[i]) * inverse[i];
    if (r[i] < 0) std::swap(t0, t1);
    if (std::isfinite(t0)) enter = std::max(enter, t0 - (std::abs(t0) * 0x1p-50 + kTiny));
    if (std::isfinite(t1)) exit = std::min(exit, t1 + (std::abs(t1) * 0x1p-50 + kTiny));
  }
  return enter > exit;
}

/// Each edge's trail (a walk along edges that share vertices), its place in it, and the
/// key the halving sorts by: the trail's mean midpoint for a short trail, which keeps it
/// together, and the edge's midpoint otherwise.
std::vector<BoundaryTree::TrailPlace> trail_places(std::span<const BoundaryEdge> edges,
                                                   std::span<const Point3> vertices) {
  constexpr std::uint32_t kShortTrail = 16;
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
    Point3 mean{0.0, 0.0, 0.0};
    for (const std::uint32_t e : walk) {
      for (int i = 0; i < 3; ++i)
        mean[i] += (0.5 * vertices[edges[e].from][i] + 0.5 * vertices[edges[e].to][i]) /
                   static_cast<double>(walk.size());
    }
    const bool short_trail = walk.size() <= kShortTrail;
    for (std::uint32_t k = 0; k < walk.size(); ++k) {
      const BoundaryEdge& e = edges[walk[k]];
      Point3 key = mean;
      if (!short_trail) {
        for (int i = 0; i < 3; ++i)
          key[i] = 0.5 * vertices[e.from][i] + 0.5 * vertices[e.to][i];
      }
      places[walk[k]] = {key, trail, k, short_trail};
    }
    ++trail;
  }
  return places;
}

}  // namespace

/// M = (1/2) sum m (a - c) x (b - c) in outward-rounded intervals, its midpoint and
/// radius; the reach, the distance from c to the farthest corner of the box, rounded up.
void BoundaryTree::set_dipole(Node& node, std::span<const BoundaryEdge> edges) const {
  const Point3& c = node.centre;
  std::array<DoubleInterval, 3> m{};
  for (const BoundaryEdge& e : edges) {
    std::array<DoubleInterval, 3> u, v;
    for (int i = 0; i < 3; ++i) {
      u[i] = DoubleInterval::difference(vertices_[e.from][i], c[i]);
      v[i] = DoubleInterval::difference(vertices_[e.to][i], c[i]);
    }
    const DoubleInterval times = DoubleInterval::exact(e.multiplicity);
    m[0] = m[0] + (u[1] * v[2] - u[2] * v[1]) * times;
    m[1] = m[1] + (u[2] * v[0] - u[0] * v[2]) * times;
    m[2] = m[2] + (u[0] * v[1] - u[1] * v[0]) * times;
  }
  double error = 0.0, size2 = 0.0, reach2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const DoubleInterval half = m[i] * DoubleInterval::exact(0.5);
    node.moment[i] = std::clamp(0.5 * half.lo + 0.5 * half.hi, half.lo, half.hi);
    error = up(error + up(std::max(half.hi - node.moment[i], node.moment[i] - half.lo)));
    size2 = up(size2 + up(node.moment[i] * node.moment[i]));
    const double r = up(std::max(c[i] - node.lower[i], node.upper[i] - c[i]));
    reach2 = up(reach2 + up(r * r));
  }
  node.moment_error = error;
  node.moment_size = up(std::sqrt(size2));
  node.reach = up(std::sqrt(reach2));
  node.dipole =
      std::isfinite(error) && std::isfinite(node.moment_size) && std::isfinite(node.reach);
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
  const auto c = static_cast<VertexIndex>(vertices_.size());
  vertices_.push_back(centre);
  node.centre = centre;
  set_dipole(node, own);
  // F = sum |m| area(a, b, c), rounded up (the children may give a smaller one, below).
  const auto fan_of = [&](std::span<const BoundaryEdge> edges) {
    double fan = 0.0;
    for (const BoundaryEdge& e : edges) {
      const double area = area_above(vertices_[e.from], vertices_[e.to], centre);
      fan = up(fan + up(area * std::abs(static_cast<double>(e.multiplicity))));
    }
    return fan;
  };
  node.fan = fan_of(own);
  // The ends: delta(x) = what enters x minus what leaves it; an edge c -> x of multiplicity
  // delta(x) (x -> c of -delta(x) when negative). An end at c itself has no cone term.
  std::vector<std::pair<VertexIndex, std::int64_t>> flow;
  flow.reserve(2 * count);
  for (const BoundaryEdge& e : own) {
    flow.emplace_back(e.to, e.multiplicity);
    flow.emplace_back(e.from, -std::int64_t{e.multiplicity});
  }
  std::sort(flow.begin(), flow.end());
  node.ends_first = static_cast<std::uint32_t>(ends_.size());
  for (std::size_t i = 0; i < flow.size();) {
    std::int64_t delta = 0;
    std::size_t j = i;
    for (; j < flow.size() && flow[j].first == flow[i].first; ++j)
      delta += flow[j].second;
    const VertexIndex x = flow[i].first;
    if (delta != 0 && vertices_[x] != centre) {
      const auto m = static_cast<std::int32_t>(std::abs(delta));
      ends_.push_back(delta > 0 ? BoundaryEdge{c, x, m} : BoundaryEdge{x, c, m});
    }
    i = j;
  }
  node.ends_count = static_cast<std::uint32_t>(ends_.size()) - node.ends_first;
  if (count > kBoundaryTreeLeafEdges) {
    // Halves by the edges' midpoints along the box's longest axis.
    int axis = 0;
    for (int i = 1; i < 3; ++i) {
      if (node.upper[i] - node.lower[i] > node.upper[axis] - node.lower[axis]) axis = i;
    }
    // Short trails (small holes) stay whole where the halves allow: a node holding a
    // closed loop entirely has no end for it.
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
    const auto same_short_trail = [&](std::uint32_t i) {  // edges i - 1 and i, of this node
      const TrailPlace& a = places_[first + i - 1];
      const TrailPlace& b = places_[first + i];
      return a.short_trail && a.trail == b.trail;
    };
    std::uint32_t half = count / 2;
    std::uint32_t forward = half, backward = half;
    while (forward < count && same_short_trail(forward))
      ++forward;
    while (backward > 0 && same_short_trail(backward))
      --backward;
    if (forward < count) {
      half = forward - half <= half - backward || backward == 0 ? forward : backward;
    } else if (backward > 0) {
      half = backward;
    }
    node.left = build(first, half);
    node.right = build(first + half, count - half);
    // The children's bounds and the fan of their ends about this centre
    // (boundary_tree.hpp, "Nested bounds"): far smaller than the direct F where the
    // edges form small closed loops, whose fans about a distant centre are long and thin.
    double nested = up(nodes_[node.left].fan + nodes_[node.right].fan);
    for (const std::uint32_t child : {node.left, node.right}) {
      const Node& n = nodes_[child];
      nested = up(nested + fan_of(std::span(ends_).subspan(n.ends_first, n.ends_count)));
    }
    node.fan = std::min(node.fan, nested);
  }
  node.far_pays = node.ends_count < node.count && std::isfinite(node.fan);
  nodes_[index] = node;
  return index;
}

void BoundaryTree::select(const Point3& point, const Vector3& ray, double budget,
                          Selection& out) const {
  out.edges.clear();
  out.offset = 0.0;
  out.slack = 0.0;
  if (nodes_.empty()) return;
  constexpr double kLargeComponent = 0x1p1000;
  if (!(std::abs(ray[0]) < kLargeComponent && std::abs(ray[1]) < kLargeComponent &&
        std::abs(ray[2]) < kLargeComponent)) {
    out.edges = edges_;  // no far node: every edge (not reached for the rays in use)
    return;
  }
  std::array<std::uint32_t, 128> stack;  // depth <= log2(edges) + 1, far below
  std::size_t top = 0, far = 0, dipoles = 0;
  double offsets = 0.0;  // the sum of the dipole terms' magnitudes
  // The reciprocals of the ray's components (below 2^1000 in magnitude, which
  // ray_directions.hpp's and open_label.hpp's are by far: no reciprocal underflows).
  const Vector3 inverse{1.0 / ray[0], 1.0 / ray[1], 1.0 / ray[2]};
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.far_pays) {
      const double d2 = distance2_below(point, node.lower, node.upper);
      // F / (2 d^2), moved up past its two roundings (and an underflow); d2 = 0 gives inf
      // or NaN, neither accepted.
      double bound = 0.5 * (node.fan / d2) * (1 + 4 * kU) + kTiny;
      // The dipole term and its bound (boundary_tree.hpp, "First order"), where smaller.
      double dipole = 0.0;
      // (Below d = 2 rho the first-order bound is the larger: not worth its square roots.)
      if (node.dipole && d2 > 4 * node.reach * node.reach) {
        const Vector3 v{node.centre[0] - point[0], node.centre[1] - point[1],
                        node.centre[2] - point[2]};
        const double r2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (r2 > 0x1p-900 && r2 < 0x1p900) {
          // d from below (the root within u/2); the bound's own rounding within 10u.
          const double d = std::sqrt(d2) * (1 - 0x1p-50);
          const double first_order =
              (node.reach * node.fan / (d2 * d) +
               0.5 * (node.moment_error + kDipoleRounding * node.moment_size) / d2) *
                  (1 + 0x1p-48) +
              kTiny;
          if (first_order < bound) {
            bound = first_order;
            dipole = 0.5 * (node.moment[0] * v[0] + node.moment[1] * v[1] + node.moment[2] * v[2]) /
                     (r2 * std::sqrt(r2));
          }
        }
      }
      if (bound <= budget && ray_misses(point, ray, inverse, node.lower, node.upper)) {
        out.edges.insert(out.edges.end(), ends_.begin() + node.ends_first,
                         ends_.begin() + node.ends_first + node.ends_count);
        out.slack += bound;
        ++far;
        if (dipole != 0.0) {
          out.offset += dipole;
          offsets += std::abs(dipole);
          ++dipoles;
        }
        continue;
      }
    }
    if (node.left == 0) {
      out.edges.insert(out.edges.end(), edges_.begin() + node.first,
                       edges_.begin() + node.first + node.count);
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = node.left;
  }
  // The offset's additions round within dipoles u of the sum of magnitudes; the sum of
  // `far` positive terms, each addition within u of its partial sum, within far u of the
  // exact sum; the products round within u more.
  out.slack += offsets * (static_cast<double>(dipoles + 2) * 2 * kU);
  out.slack *= 1 + static_cast<double>(far + 3) * 2 * kU;
}

std::optional<BoundaryTerm> BoundaryTree::term(const Point3& point, const Vector3& ray,
                                               std::array<double, 2> levels,
                                               Selection& scratch) const {
  const Vector3 apex{-ray[0], -ray[1], -ray[2]};
  for (const double budget : kBoundaryTreeBudgets) {
    select(point, ray, budget, scratch);
    // Where the tree saves little, the term over every edge is the better next step.
    if (scratch.edges.size() > edges_.size() / 2) return std::nullopt;
    // The levels lie 2 pi apart in half angles: an enclosure 2 pi wide holds one.
    if (scratch.slack >= std::numbers::pi) continue;
    const auto sum = internal::filtered_sum(point, apex, vertices_, scratch.edges, scratch.offset,
                                            scratch.slack);
    if (!sum || sum->kind != BoundaryTermKind::enclosed) return std::nullopt;
    if (auto settled = internal::settled(*sum, levels)) return settled;
    if (scratch.slack == 0.0) return std::nullopt;  // a finer budget changes nothing
  }
  return std::nullopt;
}

std::optional<Enclosure> BoundaryTree::enclosure(const Point3& point, const Vector3& ray,
                                                 double budget, Selection& scratch) const {
  select(point, ray, budget, scratch);
  const Vector3 apex{-ray[0], -ray[1], -ray[2]};
  const auto sum =
      internal::filtered_sum(point, apex, vertices_, scratch.edges, scratch.offset, scratch.slack);
  if (!sum || sum->kind != BoundaryTermKind::enclosed) return std::nullopt;
  return internal::turns_of(*sum);
}

}  // namespace exactgeo
