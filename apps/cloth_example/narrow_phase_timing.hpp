#pragma once

// The narrow phase timed per call, as CCD papers report it: the mean time of one
// vertex-face or edge-edge call on the pairs the broad phase's boxes let through (box
// culling excluded; whatever culling the method does itself included), over all calls and
// over the calls that report a collision, for exactgeo's exact method and the cubic
// solver, on the same pairs. Each batch is timed as a whole on one thread (a clock read
// per call would cost a good part of a call); the colliding calls are run again as a batch
// of their own after the first pass has found them.

#include <cstddef>
#include <span>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::cloth {

/// One kind of call for one method.
struct CallTimes {
  std::size_t calls = 0;
  double seconds = 0.0;
  std::size_t colliding_calls = 0;
  double colliding_seconds = 0.0;

  double nanoseconds_per_call() const noexcept;
  double nanoseconds_per_colliding_call() const noexcept;
};

struct MethodTimes {
  CallTimes vertex_face;
  CallTimes edge_edge;
};

class NarrowPhaseTiming {
 public:
  /// Times both methods on every candidate pair of the step.
  void add(const ccd::StepPositions& positions, std::span<const ccd::Triangle> faces,
           const ccd::MeshCcdCandidates& candidates);

  const MethodTimes& exact() const noexcept { return exact_; }
  const MethodTimes& cubic() const noexcept { return cubic_; }

 private:
  MethodTimes exact_;
  MethodTimes cubic_;
};

}  // namespace exactgeo::cloth
