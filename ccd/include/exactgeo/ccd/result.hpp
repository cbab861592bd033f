#pragma once

// What every method answers for one pair over one step: whether there is a collision,
// what decided it (DecidedBy), and the time of impact where it was asked for. The rooms
// of ccd/ that decide queries (pair, separation, baselines) all answer in these words, so
// they live below all of them (docs/architecture.md, "ccd/"); ccd.hpp, which chooses the
// method, includes this header, and its callers need no other.

#include <cstdint>
#include <optional>
#include <string_view>

namespace exactgeo::ccd {

/// What decided a query.
enum class DecidedBy : std::uint8_t {
  culled,            ///< exact, parity: the corner images provably do not surround the origin
  parity,            ///< the root parity count (for exact: a boundary root or odd parity)
  subdivision,       ///< exact: even parity, decided by splitting time
  depth_limit,       ///< exact: even parity, a piece left undecided at the depth limit (reported
                     ///< as a collision)
  cubic,             ///< the cubic baseline
  polynomials,       ///< exact: the coplanarity cubic and the slice's side quartics, split in
                     ///< time, proved a root or its absence (no parity computed)
  separation,        ///< exact with min_separation > 0: the distance's polynomial conditions in
                     ///< bounded doubles on pieces of the step
  separation_roots,  ///< exact with min_separation > 0: exact roots of those conditions
  box_test,          ///< double with min_separation > 0: the per-axis box test, plain doubles
                     ///< (baselines/separation_box.hpp)
};

std::string_view to_string(DecidedBy s) noexcept;

/// A closed time interval within the step [0, 1].
struct TimeInterval {
  double start = 0.0;
  double end = 1.0;
};

struct Result {
  bool collision = false;
  DecidedBy decided_by = DecidedBy::parity;
  /// exact: the deepest split visited (0 when no splitting was needed).
  std::uint8_t depth = 0;
  /// exact with time_of_impact_width set and a collision: the earliest root's interval.
  std::optional<TimeInterval> time_of_impact;
};

}  // namespace exactgeo::ccd
