#pragma once

// Sweep and prune over boxes sorted by their lower bound on one axis.
//
// Two boxes overlap on the sweep axis exactly when the one that starts later starts before
// the other ends. So the pairs are found by taking each box in turn (the "outer" box) and
// scanning the sorted list forward from where it starts, while the scanned boxes start
// no later than the outer box ends; the other two axes are then compared directly.
//
// Each pair must come out once:
//  * one list with itself: scan only the boxes after the outer one (Scan::after_self);
//  * two lists A and B: the outer box from A scans the B boxes starting at or after it
//    (Scan::from_equal), the outer box from B scans the A boxes starting strictly after
//    it (Scan::from_above). Every overlapping pair has one box starting first (ties go
//    to the A box), so it is found in exactly one of the two passes.
//
// Each pass is split into ranges of outer boxes, so threads can share it.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "baseline/swept_box.hpp"

namespace exactgeo::ccd::bench {

using baseline::overlap;
using baseline::SweptBox;

enum class Scan { after_self, from_equal, from_above };

/// Sorts boxes by their lower bound on `axis` (ties by id, so the order is deterministic).
inline void sort_for_sweep(std::vector<SweptBox>& boxes, int axis) {
  std::sort(boxes.begin(), boxes.end(), [axis](const SweptBox& a, const SweptBox& b) {
    return a.lo[axis] != b.lo[axis] ? a.lo[axis] < b.lo[axis] : a.id < b.id;
  });
}

/// Calls visit(outer.id, inner.id) for every overlapping pair whose outer box is
/// outer[begin, end). `inner` is `outer` itself for Scan::after_self.
template <class Visit>
void sweep(std::span<const SweptBox> outer, std::size_t begin, std::size_t end,
           std::span<const SweptBox> inner, Scan scan, int axis, Visit&& visit) {
  const auto starts_before = [axis](const SweptBox& box, float x) { return box.lo[axis] < x; };
  const auto starts_after = [axis](float x, const SweptBox& box) { return x < box.lo[axis]; };
  for (std::size_t i = begin; i < end; ++i) {
    const SweptBox& a = outer[i];
    std::size_t j = 0;
    switch (scan) {
      case Scan::after_self:
        j = i + 1;
        break;
      case Scan::from_equal:
        j = static_cast<std::size_t>(
            std::lower_bound(inner.begin(), inner.end(), a.lo[axis], starts_before) -
            inner.begin());
        break;
      case Scan::from_above:
        j = static_cast<std::size_t>(
            std::upper_bound(inner.begin(), inner.end(), a.lo[axis], starts_after) - inner.begin());
        break;
    }
    for (; j < inner.size() && inner[j].lo[axis] <= a.hi[axis]; ++j) {
      if (overlap(a, inner[j])) visit(a.id, inner[j].id);
    }
  }
}

}  // namespace exactgeo::ccd::bench
