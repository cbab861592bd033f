#include "one_mover.hpp"

#include <array>
#include <cstddef>
#include <span>

#include "exactgeo/predicates/orient3d.hpp"

namespace exactgeo::remesh::internal {

namespace {

/// A plane through three points of `own` with the rest of `own` on one closed side and
/// every point of `other` strictly on the other side (when the rest of `own` lies on the
/// plane, strictly on either side, all on one).
bool plane_separates(std::span<const Point3> own, std::span<const Point3> other) noexcept {
  const std::size_t n = own.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        Sign own_side = Sign::zero;
        bool one_side = true;
        for (std::size_t l = 0; l < n && one_side; ++l) {
          if (l == i || l == j || l == k) continue;
          const Sign s = orient3d(own[i], own[j], own[k], own[l]);
          if (s == Sign::zero) continue;
          if (own_side == Sign::zero) own_side = s;
          one_side = s == own_side;
        }
        if (!one_side) continue;
        Sign far = Sign::zero;
        bool strictly = true;
        for (const Point3& x : other) {
          const Sign s = orient3d(own[i], own[j], own[k], x);
          strictly = s != Sign::zero && s != own_side && (far == Sign::zero || s == far);
          if (!strictly) break;
          far = s;
        }
        if (strictly) return true;
      }
    }
  }
  return false;
}

/// The pair as two point sets, the moving primitive's standing corners with both ends of
/// its moving corner's path, and the other primitive's corners; then plane_separates
/// both ways. `t0` and `t1` hold the pair's corners at the step's start and end; the
/// first `first_size` belong to the first primitive.
template <std::size_t N>
bool apart(const std::array<const Point3*, N>& t0, const std::array<const Point3*, N>& t1,
           std::size_t first_size) noexcept {
  std::size_t mover = N;
  for (std::size_t c = 0; c < N; ++c) {
    if (*t0[c] == *t1[c]) continue;
    if (mover != N) return false;  // two move
    mover = c;
  }
  if (mover == N) return false;  // none moves: the mesh broad phase skips such pairs
  const bool in_first = mover < first_size;
  std::array<Point3, N + 1> swept{};
  std::array<Point3, N> other{};
  std::size_t ns = 0, no = 0;
  for (std::size_t c = 0; c < N; ++c) {
    if ((c < first_size) == in_first) {
      swept[ns++] = *t0[c];
      if (c == mover) swept[ns++] = *t1[c];
    } else {
      other[no++] = *t0[c];
    }
  }
  const std::span<const Point3> s(swept.data(), ns), o(other.data(), no);
  return plane_separates(s, o) || plane_separates(o, s);
}

}  // namespace

bool one_mover_apart(const ccd::VertexFaceQuery& q) noexcept {
  return apart<4>({&q.v_t0, &q.f0_t0, &q.f1_t0, &q.f2_t0}, {&q.v_t1, &q.f0_t1, &q.f1_t1, &q.f2_t1},
                  1);
}

bool one_mover_apart(const ccd::EdgeEdgeQuery& q) noexcept {
  return apart<4>({&q.ea0_t0, &q.ea1_t0, &q.eb0_t0, &q.eb1_t0},
                  {&q.ea0_t1, &q.ea1_t1, &q.eb0_t1, &q.eb1_t1}, 2);
}

}  // namespace exactgeo::remesh::internal
