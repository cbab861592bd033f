#include "separating_planes.hpp"

#include <array>
#include <cstddef>

#include "exactgeo/predicates/kernel/offset.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::mesh::internal {

namespace {

using kernel::Offset;

/// The rule of separating_planes.hpp, from the sides reached by each face's corners.
bool separated(const Sides& a, const Sides& b) noexcept {
  if (a.both() || b.both() || (!a.any() && !b.any())) return false;
  return !(a.positive && b.positive) && !(a.negative && b.negative);
}

constexpr std::array<std::array<std::size_t, 3>, 4> kQuadTriples{
    {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}}};

/// The separating axis test along n = (f_j - f_i) x (g_l - g_k) for every pair of corners
/// of each face (the cross products of the hulls' edges). Along n each face's corners
/// project to an interval; the faces are separated when one interval ends where or
/// before the other begins and not all corners project to one value. Projections are
/// compared exactly: n . (x - y) = det[f_j - f_i, g_l - g_k, x - y]. Symmetric in f, g.
class EdgePairAxis {
 public:
  EdgePairAxis(const Point3& fi, const Point3& fj, const Point3& gk, const Point3& gl) noexcept
      : e_(Offset::between(fi, fj)), h_(Offset::between(gk, gl)) {}

  /// sign(n . (x - y)).
  Sign compare(const Point3& x, const Point3& y) const noexcept {
    // x - y = 0 or +-e or +-h: zero without the exact stages (shared corners make these
    // common, and a zero is the filter's most expensive answer).
    if (x == y || along(e_, x, y) || along(h_, x, y)) return Sign::zero;
    return kernel::ExactSigns{}.det3_by_axis(e_, h_, Offset::between(y, x));
  }

  /// Index of a corner with the largest (sense = positive) or smallest projection.
  std::size_t extreme(const FaceGeometry& f, Sign sense) const noexcept {
    std::size_t best = 0;
    for (std::size_t c = 1; c < f.n; ++c)
      if (compare(f.p[c], f.p[best]) == sense) best = c;
    return best;
  }

  bool separates(const FaceGeometry& f, const FaceGeometry& g) const noexcept {
    const std::size_t f_max = extreme(f, Sign::positive), g_min = extreme(g, Sign::negative);
    const Sign f_before_g = compare(f.p[f_max], g.p[g_min]);  // max f - min g
    if (f_before_g == Sign::negative) return true;
    const std::size_t f_min = extreme(f, Sign::negative), g_max = extreme(g, Sign::positive);
    const Sign g_before_f = compare(g.p[g_max], f.p[f_min]);  // max g - min f
    if (g_before_f == Sign::negative) return true;
    if (f_before_g != Sign::zero && g_before_f != Sign::zero) return false;
    // One interval ends exactly where the other begins: separated unless every corner
    // projects to that one value.
    return compare(f.p[f_max], f.p[f_min]) != Sign::zero ||
           compare(g.p[g_max], g.p[g_min]) != Sign::zero;
  }

 private:
  /// {x, y} are the two ends of v.
  static bool along(const Offset& v, const Point3& x, const Point3& y) noexcept {
    const Point3& a = v.head_point();
    const Point3& b = v.tail_point();
    return (x == a && y == b) || (x == b && y == a);
  }

  Offset e_;
  Offset h_;
};

}  // namespace

bool separated_by_corner_plane(const FaceGeometry& f, const FaceGeometry& g) noexcept {
  const std::size_t planes = f.shape == Shape::skew || f.shape == Shape::other_flat ? 4 : 1;
  for (std::size_t t = 0; t < planes; ++t) {
    // Plain copies, not a structured binding: a lambda may not capture one in clang 14.
    const std::size_t i = kQuadTriples[t][0], j = kQuadTriples[t][1], k = kQuadTriples[t][2];
    const auto side = [&](const Point3& x) {
      // A shared corner is on the plane: skip the exact stages that would prove it.
      if (x == f.p[i] || x == f.p[j] || x == f.p[k]) return Sign::zero;
      return orient3d(f.p[i], f.p[j], f.p[k], x);
    };
    Sides of_f;  // a flat face's own corners are all on its plane
    if (f.shape == Shape::skew) of_f.add(side(f.p[3 - t]));  // the corner not in the triple
    if (of_f.both()) continue;
    Sides of_g;
    for (std::size_t c = 0; c < g.n && !of_g.both(); ++c)
      of_g.add(side(g.p[c]));
    if (separated(of_f, of_g)) return true;
  }
  return false;
}

bool separated_by_edge_pair_axis(const FaceGeometry& f, const FaceGeometry& g) noexcept {
  for (std::size_t i = 0; i < f.n; ++i)
    for (std::size_t j = i + 1; j < f.n; ++j)
      for (std::size_t k = 0; k < g.n; ++k)
        for (std::size_t l = k + 1; l < g.n; ++l)
          if (EdgePairAxis(f.p[i], f.p[j], g.p[k], g.p[l]).separates(f, g)) return true;
  return false;
}

}  // namespace exactgeo::mesh::internal
