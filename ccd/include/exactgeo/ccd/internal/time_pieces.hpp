#pragma once

// Pieces of the time step, for the exact (any-root) method.
//
// Restricted to [t_a, t_b], a CCD query is again a CCD query: its corner images are the
// original ones at t_a and t_b, c(t) = (1 - t) c(0) + t c(1). At a dyadic split the new
// corners are midpoints, c((t_a + t_b) / 2) = (c(t_a) + c(t_b)) / 2. Every predicate is a
// homogeneous polynomial in the corners (the origin is 0), so the corners of one piece may
// all be multiplied by the same positive number without changing any sign. A piece
// therefore stores 2^s c(t) for its own s, and the children of (L, R) are
//
//   left = (2 L, L + R),   right = (L + R, 2 R),
//
// exact sums of expansions and doublings, never a division. A child whose components
// drift out of [2^-32, 2^32] is rescaled by a power of two so that its largest component
// lies in [1, 2) (well inside every filter's guard): exact as long as no
// component leaves the double range, which only inputs spanning about 2000 binades
// could force (then the split reports "cannot").
//
// Every coordinate is a dyadic combination of at most four input doubles, so it fits in
// a few components; a coordinate that would need more than ExactVector::kCapacity also
// makes the split report "cannot".

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

#include "exactgeo/predicates/kernel/error_free.hpp"
#include "exactgeo/predicates/kernel/exact_vector.hpp"
#include "exactgeo/predicates/kernel/offset.hpp"

namespace exactgeo::ccd::internal {

using exactgeo::kernel::ExactVector;
using exactgeo::kernel::Offset;
using exactgeo::kernel::Offsets;
using Coordinate = ExactVector::Coordinate;

template <std::size_t C>
struct TimePiece {
  /// Corners 0 .. C/2 - 1 at t_start, the others at t_end, all scaled alike.
  std::array<ExactVector, C> corners;
  double t_start = 0.0;
  double t_end = 1.0;
  int depth = 0;

  /// Views; the piece must outlive them.
  Offsets<C> offsets() const noexcept {
    return [&]<std::size_t... i>(std::index_sequence<i...>) {
      return Offsets<C>{Offset::exact(corners[i])...};
    }
    (std::make_index_sequence<C>{});
  }
  /// The filter may be used on every corner (exact_vector.hpp).
  bool filterable() const noexcept {
    for (const ExactVector& v : corners) {
      if (!v.filterable) return false;
    }
    return true;
  }
};

/// The exponent of a nonzero finite double: floor(log2 |c|) for normal numbers, -1023 for
/// subnormals (above their true exponent; their last bit, 2^-1074, is the lowest anyway).
/// Read from the bits: this runs for every component of every piece.
inline int component_exponent(double c) noexcept {
  return static_cast<int>((std::bit_cast<std::uint64_t>(c) >> 52) & 0x7ff) - 1023;
}

/// The exponent range of the components: the largest exponent (exact for normal numbers,
/// an overestimate for subnormals) and the lowest possible last bit (exponent - 52, at
/// least 2^-1074). Components are never zero (expansions drop zeros).
struct ComponentRange {
  int top = -2000;
  int grain = 2000;
  void include(double c) noexcept {
    const int e = component_exponent(c);
    top = std::max(top, e);
    grain = std::min(grain, std::max(e - 52, -1074));
  }
};

inline Coordinate scaled_coordinate(const Coordinate& x, int s) noexcept {
  Coordinate r = x;
  if (s == 0) return r;
  for (int i = 0; i < r.size(); ++i)
    r.mutable_data()[i] = std::ldexp(r.data()[i], s);
  return r;
}

/// 2 x: exact (pieces keep their components far below overflow).
inline Coordinate doubled_coordinate(const Coordinate& x) noexcept {
  Coordinate r = x;
  for (int i = 0; i < r.size(); ++i)
    r.mutable_data()[i] = 2.0 * r.data()[i];
  return r;
}

/// Completes corners whose exact coordinates are set, in place: rescales every component
/// by the same power of two so that the largest lies in [1, 2) (or as close as exactness
/// allows), then sets the rounded values. False when the corners cannot be stored.
template <std::size_t C>
bool complete_corners(std::array<ExactVector, C>& corners) noexcept {
  ComponentRange range;
  for (const ExactVector& corner : corners) {
    for (const Coordinate& c : corner.exact) {
      for (int i = 0; i < c.size(); ++i)
        range.include(c.data()[i]);
    }
  }
  // Largest component into [1, 2), unless a last bit would fall below 2^-1074. Pieces
  // whose largest component is already within [2^-32, 2^32] are left as they are (each
  // split doubles the scale; rescaling every time would cost more than it saves); so is
  // a piece whose corners are all the origin.
  if (range.top != -2000 && (range.top < -32 || range.top > 32)) {
    const int s = std::max(-range.top, -1074 - range.grain);
    if (range.top + s > 1000) return false;
    for (ExactVector& corner : corners) {
      for (Coordinate& c : corner.exact)
        c = scaled_coordinate(c, s);
    }
  }
  for (ExactVector& corner : corners)
    exactgeo::kernel::complete_exact_vector(corner);
  return true;
}

/// The whole step [0, 1] as a piece, from the query's corners (differences of doubles).
template <std::size_t C>
std::optional<TimePiece<C>> whole_step(const Offsets<C>& corners) noexcept {
  // head - tail is exact unless it overflows; below 2^1022 it cannot. Larger inputs are
  // first scaled by 1/4, exact when no nonzero input is below 2^-1020.
  double largest = 0.0;
  double smallest = INFINITY;
  for (const Offset& o : corners) {
    for (int axis = 0; axis < 3; ++axis) {
      for (const double x : {std::fabs(o.head(axis)), std::fabs(o.tail(axis))}) {
        largest = std::max(largest, x);
        if (x != 0.0) smallest = std::min(smallest, x);
      }
    }
  }
  int s = 0;
  if (largest >= 0x1p1022) {
    if (smallest < 0x1p-1020) return std::nullopt;
    s = -2;
  }
  std::optional<TimePiece<C>> piece(std::in_place);
  for (std::size_t k = 0; k < C; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      const double head = corners[k].head(axis);
      const double tail = corners[k].tail(axis);
      piece->corners[k].exact[axis] = s == 0
                                          ? exactgeo::kernel::Expansion<2>::difference(head, tail)
                                          : exactgeo::kernel::Expansion<2>::difference(
                                                std::ldexp(head, s), std::ldexp(tail, s));
    }
  }
  if (!complete_corners(piece->corners)) return std::nullopt;
  return piece;
}

/// Whether the piece's midpoint time is a double. Times are dyadic, and a split stores its
/// corners at the exact midpoint: once the midpoint needs a bit more than a double has (a
/// piece one double spacing wide), the halves' times would round and no longer be the
/// times of their corners. Such a piece is as narrow as a time of impact can be stated.
template <std::size_t C>
bool splittable(const TimePiece<C>& p) noexcept {
  const auto [sum, error] = exactgeo::kernel::two_sum(p.t_start, p.t_end);
  const double mid = 0.5 * sum;
  return error == 0.0 && mid + mid == sum && p.t_start < mid && mid < p.t_end;
}

enum class Half { left, right };

/// One half of a piece, split at its midpoint time, or nullopt when the midpoint corners
/// cannot be stored exactly (see above). Precondition: splittable(p).
template <std::size_t C>
std::optional<TimePiece<C>> half(const TimePiece<C>& p, Half which) noexcept {
  constexpr std::size_t H = C / 2;
  std::optional<TimePiece<C>> piece(std::in_place);
  auto& x = piece->corners;
  for (std::size_t k = 0; k < H; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      const Coordinate& start = p.corners[k].exact[axis];
      const Coordinate& end = p.corners[H + k].exact[axis];
      auto mid = (start + end).compress().template narrow<ExactVector::kCapacity>();
      if (!mid) return std::nullopt;
      if (which == Half::left) {
        x[k].exact[axis] = doubled_coordinate(start);
        x[H + k].exact[axis] = *mid;
      } else {
        x[k].exact[axis] = *mid;
        x[H + k].exact[axis] = doubled_coordinate(end);
      }
    }
  }
  if (!complete_corners(x)) return std::nullopt;
  const double t_mid = 0.5 * (p.t_start + p.t_end);  // exact: splittable(p)
  piece->t_start = which == Half::left ? p.t_start : t_mid;
  piece->t_end = which == Half::left ? t_mid : p.t_end;
  piece->depth = p.depth + 1;
  return piece;
}

}  // namespace exactgeo::ccd::internal
