#pragma once

// Polycubes: solids made of unit voxels of an n^3 grid, whose point-in-volume truth is
// known exactly. The surface is every unit square between a filled and an empty voxel
// (outside the grid counts as empty), as quads on the integer lattice with shared
// vertices. Voxels touching only along an edge give edges used by four faces; every edge
// is still used by an even number of faces.
//
// Variants with the same truth where it is known: every quad split into two triangles
// (the diagonal chosen per lattice square), every lattice vertex moved by a dyadic offset
// k/64, |k| <= 8 (skew patches, all within 1/8 of the original surface), or y scaled and
// every vertex moved along one direction (skew patches that keep the degenerate rays of
// that direction). Random
// choices are functions of a seed and the lattice position (not of the order in which
// faces are built), so removing voxels from a failing case keeps every other choice.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::inside::polycube {

using mesh::Face;
using mesh::make_quad;
using mesh::make_triangle;
using mesh::Mesh;

using Lattice = std::array<int, 3>;

/// The lattice point with coordinate `a_value` on axis a, and b_value, c_value on the two
/// following axes (cyclically), so that (e_a, e_b, e_c) is right-handed.
inline Lattice on_axes(int a, int a_value, int b_value, int c_value) {
  Lattice p{};
  p[static_cast<std::size_t>(a)] = a_value;
  p[static_cast<std::size_t>((a + 1) % 3)] = b_value;
  p[static_cast<std::size_t>((a + 2) % 3)] = c_value;
  return p;
}

/// Occupancy of an n^3 grid of unit voxels; voxel (x, y, z) is the cell [x, x+1] x ...
struct Voxels {
  int n = 0;
  std::vector<std::uint8_t> cells;  ///< index x + n (y + n z)

  explicit Voxels(int size = 0)
      : n(size),
        cells(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) *
              static_cast<std::size_t>(size)) {}

  bool in_grid(const Lattice& v) const {
    return v[0] >= 0 && v[0] < n && v[1] >= 0 && v[1] < n && v[2] >= 0 && v[2] < n;
  }
  std::size_t index(const Lattice& v) const {
    return static_cast<std::size_t>(v[0] + n * (v[1] + n * v[2]));
  }
  /// False outside the grid.
  bool filled(const Lattice& v) const { return in_grid(v) && cells[index(v)] != 0; }
  void set(const Lattice& v, bool value) { cells[index(v)] = value ? 1 : 0; }

  std::vector<Lattice> filled_list() const {
    std::vector<Lattice> out;
    for (int z = 0; z < n; ++z)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          if (filled({x, y, z})) out.push_back({x, y, z});
    return out;
  }
};

/// Each voxel filled with probability `density`; at least one voxel is filled.
inline Voxels random_voxels(std::mt19937_64& rng, int n, double density) {
  Voxels v(n);
  std::bernoulli_distribution fill(density);
  for (auto& c : v.cells)
    c = fill(rng) ? 1 : 0;
  if (v.filled_list().empty()) {
    std::uniform_int_distribution<int> any(0, n - 1);
    v.set({any(rng), any(rng), any(rng)}, true);
  }
  return v;
}

/// The truth for the point whose coordinates are twice[i] / 2: the voxels whose closed
/// cells contain it (1, 2, 4 or 8 of them) all filled -> inside, all empty -> outside,
/// mixed -> boundary.
inline Location truth_at_half_lattice(const Voxels& voxels, const Lattice& twice) {
  std::array<std::array<int, 2>, 3> range{};  // candidate voxel indices per axis
  std::array<int, 3> count{};
  for (std::size_t i = 0; i < 3; ++i) {
    const int t = twice[i];
    if (t % 2 == 0) {
      range[i] = {t / 2 - 1, t / 2};
      count[i] = 2;
    } else {
      range[i] = {(t - 1) / 2, 0};
      count[i] = 1;
    }
  }
  bool any_filled = false, any_empty = false;
  for (int a = 0; a < count[0]; ++a)
    for (int b = 0; b < count[1]; ++b)
      for (int c = 0; c < count[2]; ++c) {
        const bool f = voxels.filled({range[0][static_cast<std::size_t>(a)],
                                      range[1][static_cast<std::size_t>(b)],
                                      range[2][static_cast<std::size_t>(c)]});
        (f ? any_filled : any_empty) = true;
      }
  if (any_filled && any_empty) return Location::boundary;
  return any_filled ? Location::inside : Location::outside;
}

/// Lattice edges used by four faces: the four voxels around the edge alternate filled,
/// empty, filled, empty (two voxels touching only along the edge).
inline std::size_t count_non_manifold_edges(const Voxels& voxels) {
  std::size_t count = 0;
  for (int a = 0; a < 3; ++a)
    for (int la = 0; la < voxels.n; ++la)
      for (int lb = 0; lb <= voxels.n; ++lb)
        for (int lc = 0; lc <= voxels.n; ++lc) {
          // The voxels around the edge from (la, lb, lc) to (la + 1, lb, lc), in cyclic order.
          const std::array<bool, 4> ring{voxels.filled(on_axes(a, la, lb - 1, lc - 1)),
                                         voxels.filled(on_axes(a, la, lb, lc - 1)),
                                         voxels.filled(on_axes(a, la, lb, lc)),
                                         voxels.filled(on_axes(a, la, lb - 1, lc))};
          int changes = 0;
          for (std::size_t k = 0; k < 4; ++k)
            changes += ring[k] != ring[(k + 1) % 4] ? 1 : 0;
          if (changes == 4) ++count;
        }
  return count;
}

/// Where a face of a polycube mesh comes from: the lattice square it lies on.
struct FaceOrigin {
  int axis = 0;               ///< the square's normal axis a
  Lattice low{};              ///< its corner with the smallest coordinates
  bool filled_above = false;  ///< the voxel on its +a side is filled (the -a one is not)
  int triangle = -1;          ///< -1 for a quad, else which half (0 or 1) of the square
  friend bool operator==(const FaceOrigin&, const FaceOrigin&) = default;

  /// The voxel on the +a side (above) or the -a side.
  Lattice voxel(bool above) const {
    Lattice v = low;
    if (!above) --v[static_cast<std::size_t>(axis)];
    return v;
  }
};

struct Polycube {
  Mesh mesh;
  std::vector<Lattice> lattice;     ///< the lattice point of each vertex
  std::vector<FaceOrigin> origins;  ///< one per face
};

/// The surface of the voxel set as quads, oriented outwards, with shared vertices (only the
/// lattice points used by a face). Quad corners run c0 = low, c1 = low + e_b, c2 = low +
/// e_b + e_c, c3 = low + e_c (reversed when the outside is on the -a side).
inline Polycube build_polycube(const Voxels& voxels) {
  const int n = voxels.n;
  const auto side = static_cast<std::size_t>(n + 1);
  std::vector<VertexIndex> vertex_of(side * side * side, mesh::kNoVertex);
  Polycube out;
  const auto vertex = [&](const Lattice& p) {
    const std::size_t key =
        static_cast<std::size_t>(p[0]) +
        side * (static_cast<std::size_t>(p[1]) + side * static_cast<std::size_t>(p[2]));
    if (vertex_of[key] == mesh::kNoVertex) {
      vertex_of[key] = static_cast<VertexIndex>(out.mesh.vertices.size());
      out.mesh.vertices.push_back(
          {static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2])});
      out.lattice.push_back(p);
    }
    return vertex_of[key];
  };
  for (int a = 0; a < 3; ++a)
    for (int la = 0; la <= n; ++la)
      for (int lb = 0; lb < n; ++lb)
        for (int lc = 0; lc < n; ++lc) {
          const bool above = voxels.filled(on_axes(a, la, lb, lc));
          const bool below = voxels.filled(on_axes(a, la - 1, lb, lc));
          if (above == below) continue;
          const VertexIndex c0 = vertex(on_axes(a, la, lb, lc));
          const VertexIndex c1 = vertex(on_axes(a, la, lb + 1, lc));
          const VertexIndex c2 = vertex(on_axes(a, la, lb + 1, lc + 1));
          const VertexIndex c3 = vertex(on_axes(a, la, lb, lc + 1));
          // (c0, c1, c2, c3) turns counter-clockwise around +e_a.
          out.mesh.faces.push_back(below ? make_quad(c0, c1, c2, c3) : make_quad(c0, c3, c2, c1));
          out.origins.push_back({a, on_axes(a, la, lb, lc), above, -1});
        }
  return out;
}

/// A well-mixed 64-bit hash (splitmix64 finaliser), for choices keyed by lattice position.
inline std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

inline std::uint64_t lattice_key(std::uint64_t seed, const Lattice& p, int extra) {
  std::uint64_t h = mix(seed);
  for (const int c : p)
    h = mix(h ^ static_cast<std::uint64_t>(static_cast<std::uint32_t>(c)));
  return mix(h ^ static_cast<std::uint64_t>(extra));
}

/// Every quad split into two triangles with the same orientation, along the diagonal
/// c0-c2 or c1-c3 chosen from `seed` and the quad's lattice square.
inline Polycube split_quads(const Polycube& quads, std::uint64_t seed) {
  Polycube out;
  out.mesh.vertices = quads.mesh.vertices;
  out.lattice = quads.lattice;
  for (std::size_t f = 0; f < quads.mesh.faces.size(); ++f) {
    const auto& c = quads.mesh.faces[f].corners;
    FaceOrigin o = quads.origins[f];
    const bool first = (lattice_key(seed, o.low, o.axis) & 1) == 0;
    const std::array<Face, 2> halves =
        first
            ? std::array<Face, 2>{make_triangle(c[0], c[1], c[2]), make_triangle(c[0], c[2], c[3])}
            : std::array<Face, 2>{make_triangle(c[0], c[1], c[3]), make_triangle(c[1], c[2], c[3])};
    for (int h = 0; h < 2; ++h) {
      out.mesh.faces.push_back(halves[static_cast<std::size_t>(h)]);
      o.triangle = h;
      out.origins.push_back(o);
    }
  }
  return out;
}

inline constexpr int kOffsetDenominator = 64;  ///< offsets are k / 64
inline constexpr int kMaxOffset = 8;           ///< |k| <= 8: at most 1/8

/// The offset numerator k of lattice point p along `axis`, in [-kMaxOffset, kMaxOffset].
inline int offset_numerator(std::uint64_t seed, const Lattice& p, int axis) {
  constexpr std::uint64_t kChoices = 2 * kMaxOffset + 1;
  return static_cast<int>(lattice_key(seed, p, axis) % kChoices) - kMaxOffset;
}

/// Every vertex moved from its lattice point p by k / 64 along each axis, with k from
/// offset_numerator(seed, p, axis). Exact in double: the coordinates are multiples of 1/64.
inline Polycube perturbed(Polycube cube, std::uint64_t seed) {
  for (std::size_t i = 0; i < cube.lattice.size(); ++i)
    for (int a = 0; a < 3; ++a) {
      const auto ia = static_cast<std::size_t>(a);
      cube.mesh.vertices[i][ia] =
          static_cast<double>(cube.lattice[i][ia]) +
          static_cast<double>(offset_numerator(seed, cube.lattice[i], a)) / kOffsetDenominator;
    }
  return cube;
}

/// Every vertex mapped to (x, 2^y_exponent y, z) + (k / 64) d, with one k per lattice
/// point (offset_numerator(seed, p, 0)). Each vertex moves along the line through it in
/// direction d, and each edge within the plane through it parallel to d, so a ray with
/// direction d meets a moved vertex or edge exactly when it meets the unmoved one (the
/// classifier's degenerate cases stay degenerate) while the quads become skew. Exact when
/// d's coordinates are short dyadics.
inline Polycube sheared(Polycube cube, std::uint64_t seed, int y_exponent, const Vector3& d) {
  for (std::size_t i = 0; i < cube.lattice.size(); ++i) {
    const double k =
        static_cast<double>(offset_numerator(seed, cube.lattice[i], 0)) / kOffsetDenominator;
    Point3& v = cube.mesh.vertices[i];
    v[1] = std::ldexp(v[1], y_exponent);
    for (std::size_t a = 0; a < 3; ++a)
      v[a] += k * d[a];
  }
  return cube;
}

/// Every face's corner order reversed where `flip(face index)` says so (orientation must
/// not matter).
template <class Flip>
Mesh with_flipped_faces(Mesh mesh, Flip&& flip) {
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!flip(f)) continue;
    auto& c = mesh.faces[f].corners;
    if (mesh.faces[f].is_triangle()) {
      std::swap(c[1], c[2]);
    } else {
      std::swap(c[1], c[3]);
    }
  }
  return mesh;
}

/// Every vertex coordinate mapped by f.
template <class F>
Mesh mapped(Mesh mesh, F&& f) {
  for (Point3& p : mesh.vertices)
    for (double& x : p)
      x = f(x);
  return mesh;
}

}  // namespace exactgeo::inside::polycube
