#pragma once

// The leaves of a box tree (box_tree.hpp) stored lane by lane: up to eight primitives'
// boxes coordinate by coordinate, and their corners, so that one box, or one primitive's
// corners, is compared with all eight at once.
//
// The comparisons use the GCC and Clang vector extensions, four 32-bit lanes per vector,
// which every target lowers to its own SIMD instructions (SSE on x86-64, NEON on ARM).
// They are comparisons of floats and integers only: exact, so the masks are the same as
// the scalar tests would give. The one target-specific piece, gathering lane results into
// bits (SSE2's movemask), has a portable form, which the tests compare with it.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "exactgeo/boxes/float_box.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::boxes {

inline constexpr std::size_t kPacketLanes = 8;

// A lane that holds no primitive has corners kNoVertex (predicates/point.hpp) and the
// box kNoBox, which overlaps nothing: its bounds are NaN, and every comparison with NaN is
// false. (An empty box, lo = +inf and hi = -inf, would overlap a box reaching from -inf
// to +inf, which a huge separation margin can make.)

/// The box of a lane without a primitive.
inline constexpr FloatBox kNoBox{{__builtin_nanf(""), __builtin_nanf(""), __builtin_nanf("")},
                                 {__builtin_nanf(""), __builtin_nanf(""), __builtin_nanf("")}};

/// Up to kPacketLanes primitives with N corners each.
template <std::size_t N>
struct Packet {
  std::array<std::array<float, kPacketLanes>, 3> lo;
  std::array<std::array<float, kPacketLanes>, 3> hi;
  std::array<std::array<VertexIndex, kPacketLanes>, N> corner;
  std::array<std::uint32_t, kPacketLanes> id;  ///< the primitive's index; kNoVertex if none
  /// The motion digest its corners share (VertexBoxes::motion, box_tree.hpp), or 0: two
  /// primitives can only move rigidly together when their digests are equal and nonzero.
  std::array<std::uint32_t, kPacketLanes> motion;
  unsigned moving = 0;  ///< bit j: the primitive in lane j may move (VertexBoxes::moving)

  FloatBox box(std::size_t j) const noexcept {
    return {{lo[0][j], lo[1][j], lo[2][j]}, {hi[0][j], hi[1][j], hi[2][j]}};
  }
  void set_box(std::size_t j, const FloatBox& b) noexcept {
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k][j] = b.lo[k];
      hi[k][j] = b.hi[k];
    }
  }
  std::array<VertexIndex, N> corners(std::size_t j) const noexcept {
    std::array<VertexIndex, N> c{};
    for (std::size_t k = 0; k < N; ++k)
      c[k] = corner[k][j];
    return c;
  }
};

namespace lanes {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Index4 = std::uint32_t __attribute__((vector_size(16)));

template <class Vector, class T>
Vector load(const T* four) noexcept {
  Vector v;
  std::memcpy(&v, four, sizeof v);
  return v;
}

/// Bit j set for each lane j whose comparison result is true (all ones), on any target.
inline unsigned portable_bits(Int4 in) noexcept {
  Int4 b = in & Int4{1, 2, 4, 8};
  b |= __builtin_shufflevector(b, b, 2, 3, 0, 1);
  b |= __builtin_shufflevector(b, b, 1, 0, 3, 2);
  return static_cast<unsigned>(b[0]);
}

/// portable_bits, in one instruction where SSE2 has it (movemask).
inline unsigned bits(Int4 in) noexcept {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(reinterpret_cast<__m128i>(in))));
#else
  return portable_bits(in);
#endif
}

}  // namespace lanes

/// Bit j set when `a` overlaps lane j's box (closed boxes: touching counts).
template <std::size_t N>
unsigned overlap_mask(const FloatBox& a, const Packet<N>& p) noexcept {
  using lanes::Float4, lanes::load;
  unsigned mask = 0;
  for (std::size_t q = 0; q < kPacketLanes; q += 4) {
    lanes::Int4 in =
        (a.lo[0] <= load<Float4>(&p.hi[0][q])) & (load<Float4>(&p.lo[0][q]) <= a.hi[0]);
    in &= (a.lo[1] <= load<Float4>(&p.hi[1][q])) & (load<Float4>(&p.lo[1][q]) <= a.hi[1]);
    in &= (a.lo[2] <= load<Float4>(&p.hi[2][q])) & (load<Float4>(&p.lo[2][q]) <= a.hi[2]);
    mask |= lanes::bits(in) << q;
  }
  return mask;
}

/// Bit j set when lane j's primitive has a corner among `corners`.
template <std::size_t M, std::size_t N>
unsigned shared_corner_mask(const std::array<VertexIndex, M>& corners,
                            const Packet<N>& p) noexcept {
  using lanes::Index4, lanes::load;
  unsigned mask = 0;
  for (std::size_t q = 0; q < kPacketLanes; q += 4) {
    lanes::Int4 shared{};
    for (std::size_t k = 0; k < N; ++k) {
      const Index4 c = load<Index4>(&p.corner[k][q]);
      for (const VertexIndex v : corners)
        shared |= (c == v);
    }
    mask |= lanes::bits(shared) << q;
  }
  return mask;
}

}  // namespace exactgeo::boxes
