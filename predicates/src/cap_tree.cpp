#include "exactgeo/predicates/cap_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "arctan2.hpp"
#include "boundary_term_filter.hpp"
#include "box_distance.hpp"
#include "double_interval.hpp"
#include "exactgeo/predicates/orient3d.hpp"
#include "far_field.hpp"
#include "variation_bound.hpp"

// The cap, the identity and the bounds: cap_tree.hpp.

namespace exactgeo {
namespace {

using internal::area_above;
using internal::DoubleInterval;
using internal::up;

constexpr double kU = 0x1p-53;
constexpr double kTiny = 0x1p-1000;
// A triangle's half angle theta = atan2(N, D) (Van Oosterom and Strackee), N =
// det[A, B, C], D = |A||B||C| + (A.B)|C| + (A.C)|B| + (B.C)|A|, A, B, C = corners - p,
// in plain doubles, and its error bound. As boundary_term_filter.cpp's half_angle, whose
// derivation this follows, with the third vector a rounded difference too (there it is
// the exact direction -r); u = 2^-53, every vector scaled by a power of two so that its
// largest component is in [1, 2):
//
//  - Each of A, B, C is within u|X| + 2^-1074 per component of the exact difference
//    (scaled by the same power of two).
//  - N: the cross product and the dot round within gamma_5 P, P = sum_i |A_i| (|B_j||C_k|
//    + |B_k||C_j|); the three inputs' errors add, by trilinearity, (3u + 3u^2 + u^3) P:
//    8.02u P in all (the half angle's filter had two inexact inputs: 7.01u P). P <=
//    2 |A||B||C| (Cauchy-Schwarz, as there), and the computed L = fl(fl(|A||B|)|C|) is
//    within a factor 1 + 24u of |A||B||C| (each computed length within 7u, two products):
//    |N - N*| <= 16.04u (1 + 24u) L < 16.1u L; 20u L, rounded down by at most u, covers it.
//  - D: the half angle's 96u L stands. Its derivation already took every length within 7u
//    (three in L: 23u) and each dot's inputs within 2.01u of the exact ones with the
//    dot's own gamma_3 (13u per product term, 39u for three) and the three sums (12u):
//    74u L, whichever of the vectors was exact.
//  - Underflows lose at most 2^-1075 per operation on numbers of magnitude below 8,
//    far below the 2^-1000 added to both bounds.
//  - Then as there: the exact (N*, D*) lies within E = |dN| + |dD| of the computed point;
//    where E <= r / 4 (r = max(|N|, |D|), at most |(N, D)|) and the segment between them does not
//    cross the branch cut (|N| > |dN|, or D > |dD|), the half angles differ by at most
//    (4/3) E / r; where D < -|dD|, the exact sign of N* (orient3d(p, a, b, c)) is given to
//    N; kArctanError for the arctangent. The branch cut is where p lies on the triangle
//    (N* = 0 with D* < 0: p in the triangle's plane, inside it, where the half angle
//    jumps between -pi and pi): there the sign is 0 and the angle is not defined.
constexpr double kNumError = 20 * kU;
constexpr double kDenError = 96 * kU;

struct HalfAngle {
  double theta = 0.0;
  double error = 0.0;
};

/// Out of line: rare.
[[gnu::noinline]] double side_of(const Point3& p, const Point3& a, const Point3& b,
                                 const Point3& c) {
  const Sign s = orient3d(p, a, b, c);
  return s == Sign::zero ? 0.0 : s == Sign::positive ? 1.0 : -1.0;
}

/// The triangle's half angle seen from p within `error` radians; nullopt where the bound
/// cannot be made (p within rounding of the triangle's edges' lines or on it).
[[gnu::always_inline]] inline std::optional<HalfAngle> triangle_half_angle(const Point3& p,
                                                                           const Point3& pa,
                                                                           const Point3& pb,
                                                                           const Point3& pc) {
  const auto dot = [](const Vector3& x, const Vector3& y) {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
  };
  const auto a = internal::normalized({pa[0] - p[0], pa[1] - p[1], pa[2] - p[2]});
  const auto b = internal::normalized({pb[0] - p[0], pb[1] - p[1], pb[2] - p[2]});
  const auto c = internal::normalized({pc[0] - p[0], pc[1] - p[1], pc[2] - p[2]});
  if (!a || !b || !c) return std::nullopt;  // p on a corner, or an overflow
  const Vector3& A = *a;
  const Vector3& B = *b;
  const Vector3& C = *c;
  const Vector3 bxc{B[1] * C[2] - B[2] * C[1], B[2] * C[0] - B[0] * C[2],
                    B[0] * C[1] - B[1] * C[0]};
  double num = dot(A, bxc);
  const double la = std::sqrt(dot(A, A)), lb = std::sqrt(dot(B, B)), lc = std::sqrt(dot(C, C));
  const double length = la * lb * lc;
  const double den = length + dot(A, B) * lc + dot(A, C) * lb + dot(B, C) * la;
  const double num_error = kNumError * length + kTiny;
  const double den_error = kDenError * length + kTiny;
  // r = max(|N|, |D|), exact, at most |(N, D)|: any r at most the distance from the
  // origin serves (the segment then stays at least 3r/4 from it), and this one needs no
  // square root (half_angle's is at most sqrt 2 times larger).
  const double radius = std::max(std::abs(num), std::abs(den));
  const double e = num_error + den_error;
  if (!(e <= radius / 4)) return std::nullopt;
  if (!(std::abs(num) > num_error) && !(den > den_error)) {
    if (!(den < -den_error)) return std::nullopt;
    const double side = side_of(p, pa, pb, pc);
    if (side == 0.0) return std::nullopt;  // p on the triangle
    num = std::copysign(std::abs(num), side);
  }
  return HalfAngle{internal::arctan2(num, den), (4.0 / 3.0) * e / radius + internal::kArctanError};
}

/// The triangles of the loop's range [i, j] (recursive halving, cap_tree.hpp), in
/// pre-order (the range's own triangle, then its halves'); vertex n is vertex 0.
void halve(std::span<const VertexIndex> loop, std::size_t i, std::size_t j,
           std::vector<CapTriangle>& out) {
  if (j - i < 2) return;
  const std::size_t k = i + (j - i) / 2;
  const auto at = [&](std::size_t x) { return loop[x % loop.size()]; };
  out.push_back({at(i), at(j), at(k), 1});
  halve(loop, i, k, out);
  halve(loop, k, j, out);
}

/// The chain's closed loops, each as its vertices v_0, ..., v_{n-1} (the edge v_{n-1} ->
/// v_0 closing it): walk unused edges, cutting off each loop the walk closes.
std::vector<std::vector<VertexIndex>> loops_of(std::span<const Point3> vertices,
                                               std::span<const BoundaryEdge> edges) {
  std::vector<std::int64_t> remaining(edges.size()), delta(vertices.size(), 0);
  std::vector<std::vector<std::uint32_t>> leaving(vertices.size());
  std::vector<BoundaryEdge> oriented(edges.begin(), edges.end());
  for (std::uint32_t e = 0; e < oriented.size(); ++e) {
    BoundaryEdge& edge = oriented[e];
    if (edge.multiplicity < 0) {
      std::swap(edge.from, edge.to);
      edge.multiplicity = -edge.multiplicity;
    }
    if (edge.from == edge.to || edge.multiplicity == 0) continue;
    remaining[e] = edge.multiplicity;
    leaving[edge.from].push_back(e);
    delta[edge.to] += edge.multiplicity;
    delta[edge.from] -= edge.multiplicity;
  }
  if (std::any_of(delta.begin(), delta.end(), [](std::int64_t d) { return d != 0; })) {
    throw std::invalid_argument("cap_triangles: the boundary chain is not closed");
  }
  std::vector<std::vector<VertexIndex>> loops;
  std::vector<std::int64_t> position(vertices.size(), -1);
  std::vector<VertexIndex> path;
  for (VertexIndex start = 0; start < vertices.size(); ++start) {
    path.assign(1, start);
    position[start] = 0;
    for (VertexIndex at = start;;) {
      auto& out = leaving[at];
      while (!out.empty() && remaining[out.back()] == 0)
        out.pop_back();
      if (out.empty()) break;
      const std::uint32_t e = out.back();
      --remaining[e];
      const VertexIndex next = oriented[e].to;
      if (position[next] >= 0) {
        // The walk closed a loop: path[position[next]], ..., path.back(), next.
        const auto from = static_cast<std::size_t>(position[next]);
        loops.emplace_back(path.begin() + static_cast<std::ptrdiff_t>(from), path.end());
        for (std::size_t x = from + 1; x < path.size(); ++x)
          position[path[x]] = -1;
        path.resize(from + 1);
      } else {
        position[next] = static_cast<std::int64_t>(path.size());
        path.push_back(next);
      }
      at = next;
    }
    // A closed chain's walk stops only where it began.
    if (path.size() != 1) throw std::logic_error("cap_triangles: a walk did not close");
    position[start] = -1;
  }
  return loops;
}

}  // namespace

std::vector<CapTriangle> cap_triangles(std::span<const Point3> vertices,
                                       std::span<const BoundaryEdge> edges) {
  std::vector<CapTriangle> raw;
  for (const std::vector<VertexIndex>& loop : loops_of(vertices, edges))
    halve(loop, 0, loop.size(), raw);
  // Equal triangles merged (rotations alike; a reversed one counts negatively), those on
  // one line left out.
  for (CapTriangle& t : raw) {
    while (t.a > t.b || t.a > t.c)
      t = {t.b, t.c, t.a, t.multiplicity};
    if (t.b > t.c) t = {t.a, t.c, t.b, -t.multiplicity};
  }
  std::sort(raw.begin(), raw.end(), [](const CapTriangle& x, const CapTriangle& y) {
    return std::tie(x.a, x.b, x.c) < std::tie(y.a, y.b, y.c);
  });
  std::vector<CapTriangle> cap;
  for (std::size_t i = 0; i < raw.size();) {
    std::size_t j = i;
    std::int64_t m = 0;
    for (; j < raw.size() && raw[j].a == raw[i].a && raw[j].b == raw[i].b && raw[j].c == raw[i].c;
         ++j)
      m += raw[j].multiplicity;
    const CapTriangle& t = raw[i];
    if (m != 0 && t.a != t.b && t.b != t.c &&
        !collinear(vertices[t.a], vertices[t.b], vertices[t.c])) {
      cap.push_back({t.a, t.b, t.c, static_cast<std::int32_t>(m)});
    }
    i = j;
  }
  return cap;
}

CapTree::CapTree(std::span<const Point3> vertices, std::span<const BoundaryEdge> edges) {
  std::vector<std::vector<VertexIndex>> loops = loops_of(vertices, edges);
  std::erase_if(loops, [](const std::vector<VertexIndex>& loop) { return loop.size() < 3; });
  if (loops.empty()) return;
  // Each loop's centre (of its vertices' box), for the halving of the loops.
  std::vector<std::pair<Point3, std::uint32_t>> centres;
  for (std::uint32_t l = 0; l < loops.size(); ++l) {
    Point3 lower = vertices[loops[l][0]], upper = lower;
    for (const VertexIndex v : loops[l]) {
      for (int i = 0; i < 3; ++i) {
        lower[i] = std::min(lower[i], vertices[v][i]);
        upper[i] = std::max(upper[i], vertices[v][i]);
      }
    }
    centres.push_back({{0.5 * lower[0] + 0.5 * upper[0], 0.5 * lower[1] + 0.5 * upper[1],
                        0.5 * lower[2] + 0.5 * upper[2]},
                       l});
  }
  nodes_.reserve(4 * edges.size() / 3 + 2 * loops.size() + 2);
  build_loops(vertices, loops, centres);
  set_expansions();
  // A node without triangles (every one of its triangles on a line) is harmless: F = 0.
}

/// Every node's expansion (far_field.hpp) from M = sum m (vector area) and Q = sum m
/// (vector area) (centroid - c)^T about its centre c, in outward-rounded intervals
/// (cap_tree.hpp, "Far nodes"): its own triangles' summed, its children's taken over. M
/// does not depend on the centre, and Q about c is the child's Q about its own centre c'
/// plus M (c' - c)^T (the centroids' offsets shift by c' - c), so each triangle is summed
/// once instead of once per ancestor. A child's index is above its parent's (build_range
/// and build_loops place a node before its children), so the nodes taken from the last
/// to the first meet every child before its parent.
void CapTree::set_expansions() {
  std::vector<internal::Moments> moments(nodes_.size());
  const DoubleInterval third = DoubleInterval{1.0, 1.0} / DoubleInterval::exact(3.0);
  const DoubleInterval half = DoubleInterval::exact(0.5);
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    Node& node = nodes_[n];
    if (node.count == 0) continue;  // no triangle: M = Q = 0, no expansion
    const Point3& c = node.centre;
    auto& [m, q] = moments[n];
    for (std::uint32_t t = node.first; t < node.first + node.own; ++t) {
      const Triangle& tri = triangles_[t];
      std::array<DoubleInterval, 3> u, v, w, e, f, x, s;
      for (int i = 0; i < 3; ++i) {
        u[i] = DoubleInterval::difference(tri.a[i], c[i]);
        v[i] = DoubleInterval::difference(tri.b[i], c[i]);
        w[i] = DoubleInterval::difference(tri.c[i], c[i]);
        e[i] = v[i] - u[i];
        f[i] = w[i] - u[i];
        s[i] = (u[i] + v[i] + w[i]) * third;
      }
      const DoubleInterval times = DoubleInterval::exact(tri.multiplicity) * half;
      x[0] = (e[1] * f[2] - e[2] * f[1]) * times;
      x[1] = (e[2] * f[0] - e[0] * f[2]) * times;
      x[2] = (e[0] * f[1] - e[1] * f[0]) * times;
      for (int i = 0; i < 3; ++i) {
        m[i] = m[i] + x[i];
        for (int j = 0; j < 3; ++j)
          q[i][j] = q[i][j] + x[i] * s[j];
      }
    }
    for (const std::uint32_t child : {node.left, node.right}) {
      if (child == 0 || nodes_[child].count == 0) continue;
      const auto& [cm, cq] = moments[child];
      std::array<DoubleInterval, 3> shift;
      for (int j = 0; j < 3; ++j)
        shift[j] = DoubleInterval::difference(nodes_[child].centre[j], c[j]);
      for (int i = 0; i < 3; ++i) {
        m[i] = m[i] + cm[i];
        for (int j = 0; j < 3; ++j)
          q[i][j] = q[i][j] + cq[i][j] + cm[i] * shift[j];
      }
    }
    internal::set_far_field(node, moments[n]);
  }
}

/// The node's box, F and centre, from its triangles (its expansion: set_expansions).
void CapTree::finish(Node& node) const {
  // No triangle (every one on a line): F = 0 and the box a point, far with value 0.
  if (node.count == 0) return;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  node.lower = {kInf, kInf, kInf};
  node.upper = {-kInf, -kInf, -kInf};
  double fan = 0.0;
  for (std::uint32_t t = node.first; t < node.first + node.count; ++t) {
    const Triangle& tri = triangles_[t];
    for (const Point3* v : {&tri.a, &tri.b, &tri.c}) {
      for (int i = 0; i < 3; ++i) {
        node.lower[i] = std::min(node.lower[i], (*v)[i]);
        node.upper[i] = std::max(node.upper[i], (*v)[i]);
      }
    }
    fan = up(fan + up(sizes_[t].area * std::abs(tri.multiplicity)));
  }
  node.fan = fan;
  node.two_fan = 2 * fan;
  for (int i = 0; i < 3; ++i) {
    node.centre[i] =
        std::clamp(0.5 * node.lower[i] + 0.5 * node.upper[i], node.lower[i], node.upper[i]);
  }
}

/// The cap triangle (a, b, c) onto triangles_ unless its corners lie on one line.
void CapTree::add_triangle(std::span<const Point3> vertices, VertexIndex a, VertexIndex b,
                           VertexIndex c) {
  if (a == b || b == c || c == a || collinear(vertices[a], vertices[b], vertices[c])) return;
  triangles_.push_back({vertices[a], vertices[b], vertices[c], 1.0});
  sizes_.push_back({area_above(vertices[a], vertices[b], vertices[c]),
                    {internal::segment_length_above(vertices[a], vertices[b]),
                     internal::segment_length_above(vertices[b], vertices[c]),
                     internal::segment_length_above(vertices[c], vertices[a])}});
  cap_.push_back({a, b, c, 1});
}

/// The node of the loop's range [i, j]: its own triangle (v_i, v_j, v_k), then its halves'
/// nodes, or, for a short range, every triangle of the range as its own (a leaf). Its
/// triangles lie in the box of v_i, ..., v_j: compact where the rim is.
std::uint32_t CapTree::build_range(std::span<const Point3> vertices,
                                   std::span<const VertexIndex> loop, std::size_t i,
                                   std::size_t j) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.first = static_cast<std::uint32_t>(triangles_.size());
  const std::size_t k = i + (j - i) / 2;
  const auto at = [&](std::size_t x) { return loop[x % loop.size()]; };
  if (j - i <= kCapTreeLeafSpan) {
    std::vector<CapTriangle> leaf;
    halve(loop, i, j, leaf);
    for (const CapTriangle& t : leaf)
      add_triangle(vertices, t.a, t.b, t.c);
    node.own = static_cast<std::uint32_t>(triangles_.size()) - node.first;
  } else {
    add_triangle(vertices, at(i), at(j), at(k));
    node.own = static_cast<std::uint32_t>(triangles_.size()) - node.first;
    node.left = build_range(vertices, loop, i, k);
    node.right = build_range(vertices, loop, k, j);
  }
  node.count = static_cast<std::uint32_t>(triangles_.size()) - node.first;
  finish(node);
  nodes_[index] = node;
  return index;
}

/// The node of a set of loops: halved by their centres along the longest axis of the
/// centres' box, down to one loop's node.
std::uint32_t CapTree::build_loops(std::span<const Point3> vertices,
                                   const std::vector<std::vector<VertexIndex>>& loops,
                                   std::span<std::pair<Point3, std::uint32_t>> centres) {
  if (centres.size() == 1) {
    const std::vector<VertexIndex>& loop = loops[centres[0].second];
    return build_range(vertices, loop, 0, loop.size());
  }
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.first = static_cast<std::uint32_t>(triangles_.size());
  Point3 lower = centres[0].first, upper = lower;
  for (const auto& [c, l] : centres) {
    for (int i = 0; i < 3; ++i) {
      lower[i] = std::min(lower[i], c[i]);
      upper[i] = std::max(upper[i], c[i]);
    }
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (upper[i] - lower[i] > upper[axis] - lower[axis]) axis = i;
  }
  const std::size_t half = centres.size() / 2;
  std::nth_element(centres.begin(), centres.begin() + static_cast<std::ptrdiff_t>(half),
                   centres.end(), [axis](const auto& x, const auto& y) {
                     return std::tie(x.first[axis], x.second) < std::tie(y.first[axis], y.second);
                   });
  node.left = build_loops(vertices, loops, centres.subspan(0, half));
  node.right = build_loops(vertices, loops, centres.subspan(half));
  node.count = static_cast<std::uint32_t>(triangles_.size()) - node.first;
  finish(node);
  nodes_[index] = node;
  return index;
}

template <class Done>
std::optional<CapTree::Refined> CapTree::refine(const Point3& p, Refinement& r,
                                                const Done& done) const {
  r.heap.clear();
  r.stack.clear();
  r.tested = r.triangles = r.far_nodes = r.expansions = r.opened = 0;
  if (nodes_.empty()) return Refined{};
  // The running sums (as BoundaryTree::refine): the angles' and far values' sum with the
  // magnitudes of all it was given or had taken away and their count; the far bounds'
  // sum likewise; the errors' (never taken away).
  double sum = 0.0, magnitudes = 0.0, bounds = 0.0, bound_magnitudes = 0.0, errors = 0.0;
  std::size_t terms = 0, bound_terms = 0, error_terms = 0;
  // A node opened: its own triangles into the sum (a leaf's are all of them), its
  // children onto the stack.
  const auto open = [&](const Node& node) __attribute__((always_inline)) {
    if (node.left != 0) r.stack.push_back(node.left);
    if (node.right != 0) r.stack.push_back(node.right);
    for (std::uint32_t i = node.first; i < node.first + node.own; ++i) {
      const Triangle& t = triangles_[i];
      const auto angle = triangle_half_angle(p, t.a, t.b, t.c);
      if (!angle) return false;
      const double value = t.multiplicity * angle->theta;
      sum += value;
      magnitudes += std::abs(value);
      errors += std::abs(t.multiplicity) * angle->error;
      ++terms;
      ++error_terms;
    }
    r.triangles += node.own;
    return true;
  };
  double limit = r.first_cut;
  bool heaped = false;
  const auto by_bound = [](const Refinement::Far& a, const Refinement::Far& b) {
    return a.bound < b.bound;
  };
  // The node as a far node, where its bound is at most `limit`. First without divisions:
  // the zero-order bound F / (2 d^2) can be at most the limit only where F <= 2 limit d^2
  // (about: the test is a cost, the bound below the certificate), and the second-order
  // one only where d > 2 rho and (3/2) rho^2 F <= limit d^4.
  const auto far = [&](const Node& node) __attribute__((always_inline))->bool {
    ++r.tested;
    const double d2 = internal::box_distance2_below(p, p, node.lower, node.upper);
    if (!(node.two_fan <= limit * d2) &&
        !(node.expansion && d2 > node.reach4 && node.second_fan <= limit * d2 * d2)) {
      return false;
    }
    const auto [bound, expanded] = internal::far_bound(node, d2);  // far_field.hpp
    if (!(bound <= limit)) return false;
    double value = 0.0;
    if (expanded) {
      value = internal::expansion_value(node, p);
      ++r.expansions;
    }
    // The expansion's rounding is in its bound (kExpansionRounding).
    sum += value;
    magnitudes += std::abs(value);
    ++terms;
    bounds += bound;
    bound_magnitudes += bound;
    ++bound_terms;
    r.heap.push_back({bound, value, static_cast<std::uint32_t>(&node - nodes_.data()), expanded});
    if (heaped) std::push_heap(r.heap.begin(), r.heap.end(), by_bound);
    return true;
  };
  const auto descend = [&]() {
    while (!r.stack.empty()) {
      const std::uint32_t n = r.stack.back();
      r.stack.pop_back();
      const Node& node = nodes_[n];
      if (far(node)) continue;
      if (!open(node)) return false;
    }
    return true;
  };
  r.stack.push_back(0);
  while (true) {
    if (!descend()) return std::nullopt;
    // (As BoundaryTree::refine: recursive summation's (k - 1) u of the magnitudes, and the
    // factor for these products' and sums' own rounding.)
    const double error = (errors + bounds +
                          kU * (static_cast<double>(terms + 2) * magnitudes +
                                static_cast<double>(bound_terms + 2) * bound_magnitudes +
                                static_cast<double>(error_terms + 2) * errors)) *
                             (1 + 8 * kU) +
                         kTiny;
    const double lower = sum - error, upper = sum + error;
    if (done(lower, upper)) {
      r.far_nodes = r.heap.size();
      return Refined{lower, upper};
    }
    if (r.heap.empty()) return std::nullopt;
    if (!heaped) std::make_heap(r.heap.begin(), r.heap.end(), by_bound);
    heaped = true;
    limit = std::min(limit, r.heap.front().bound / 8);
    std::pop_heap(r.heap.begin(), r.heap.end(), by_bound);
    const Refinement::Far top = r.heap.back();
    r.heap.pop_back();
    ++r.opened;
    sum -= top.value;
    magnitudes += std::abs(top.value);
    ++terms;
    bounds -= top.bound;
    bound_magnitudes += top.bound;
    ++bound_terms;
    if (!open(nodes_[top.node])) return std::nullopt;
  }
}

namespace {

/// Radians of half angle to turns, rounded outward (internal::turns_of).
Enclosure turns(double lower, double upper) {
  return internal::turns_of({BoundaryTermKind::enclosed, lower, upper});
}

/// [lower - margin, upper + margin] between two consecutive half-integers, strictly:
/// k - 1/2 < lower - margin and upper + margin < k + 1/2 (k +- 1/2 exact for these
/// magnitudes, the widened ends rounded outward).
bool between_half_integers(const Enclosure& e, double margin) {
  if (!(std::abs(e.lower) < 0x1p50 && std::abs(e.upper) < 0x1p50)) return false;
  const double lower = margin == 0.0 ? e.lower : DoubleInterval::down(e.lower - margin);
  const double upper = margin == 0.0 ? e.upper : up(e.upper + margin);
  const double k = std::nearbyint(e.lower);
  return k - 0.5 < lower && upper < k + 0.5;
}

/// No x in [lower, upper] has [x - margin, x + margin] strictly between two consecutive
/// half-integers: every k's window (k - 1/2 + margin, k + 1/2 - margin) misses the
/// enclosure (margin at least 1/2 leaves no window). Only the k nearest the ends can
/// miss it: a k between them lies in the enclosure, and in its own window. Then no
/// refinement can settle the point.
bool apart_impossible(const Enclosure& e, double margin) {
  if (!(margin < 0.5)) return true;
  if (!(std::abs(e.lower) < 0x1p50 && std::abs(e.upper) < 0x1p50)) return false;
  const double first = std::nearbyint(e.lower), last = std::nearbyint(e.upper);
  if (last - first >= 2) return false;
  for (const double k : {first, last}) {
    // The window's ends rounded outward (a larger window): a miss is then certain.
    const double low = DoubleInterval::down(k - 0.5 + margin);
    const double high = up(k + 0.5 - margin);
    if (e.upper > low && e.lower < high) return false;
  }
  return true;
}

}  // namespace

std::optional<Enclosure> CapTree::enclosure_apart(const Point3& point, Refinement& scratch,
                                                  double margin) const {
  bool hopeless = false;
  const auto sum = refine(point, scratch, [&](double lower, double upper) {
    const Enclosure e = turns(lower, upper);
    if (between_half_integers(e, margin)) return true;
    hopeless = margin > 0.0 && apart_impossible(e, margin);
    return hopeless;
  });
  scratch.first_cut = !sum || hopeless || scratch.opened > 0
                          ? std::max(scratch.finest_first_cut, scratch.first_cut / 2)
                          : std::min(scratch.coarsest_first_cut, scratch.first_cut * 2);
  if (!sum || hopeless) return std::nullopt;
  return turns(sum->lower, sum->upper);
}

std::optional<Enclosure> CapTree::enclosure(const Point3& point, double width,
                                            Refinement& scratch) const {
  const double radians = width * 2 * std::numbers::pi;
  const auto sum = refine(point, scratch, [&](double lower, double upper) {
    return upper - lower <= radians || scratch.heap.empty();
  });
  if (!sum) return std::nullopt;
  return turns(sum->lower, sum->upper);
}

}  // namespace exactgeo
