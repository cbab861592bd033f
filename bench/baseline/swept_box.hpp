#pragma once

// The baseline broad phase's boxes (baseline/mesh_broad_phase.hpp): a float box with the
// index of its primitive, made from the primitive's corners in one pass. The rounding is
// the library's (exactgeo/ccd/mesh/internal/swept_box.hpp), so both make the same boxes.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "exactgeo/ccd/mesh/internal/swept_box.hpp"

namespace exactgeo::ccd::bench::baseline {

using internal::float_above;
using internal::float_below;

struct SweptBox {
  std::array<float, 3> lo;
  std::array<float, 3> hi;
  std::uint32_t id;  ///< the vertex, edge or face the box belongs to
};

/// Closed boxes: touching counts as overlapping.
inline bool overlap(const SweptBox& a, const SweptBox& b) noexcept {
  for (int k = 0; k < 3; ++k) {
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  }
  return true;
}

/// The swept box of the corners `ids` (vertex indices) of one primitive, in the step's
/// scale; positions are 3 doubles per vertex at t0 and at t1.
template <std::size_t N>
SweptBox swept_box(const std::array<std::uint32_t, N>& ids, std::uint32_t id, const double* t0,
                   const double* t1, const boxes::Scale& scale = {}) noexcept {
  SweptBox box{};
  box.id = id;
  for (int k = 0; k < 3; ++k) {
    double lo = t0[3 * ids[0] + k];
    double hi = lo;
    for (const double* frame : {t0, t1}) {
      for (const std::uint32_t v : ids) {
        lo = std::min(lo, frame[3 * v + k]);
        hi = std::max(hi, frame[3 * v + k]);
      }
    }
    box.lo[k] = float_below(scale(lo));
    box.hi[k] = float_above(scale(hi));
  }
  return box;
}

}  // namespace exactgeo::ccd::bench::baseline
