#pragma once

// The narrow phase timed per call, as CCD papers report it: the mean time of one
// vertex-face or edge-edge call on the pairs the broad phase's boxes let through (box
// culling excluded; whatever culling the method does itself included), over all calls and
// over the calls that report a collision, for exactgeo's exact method and the cubic
// solver, on the same pairs. Each batch is timed as a whole on one thread (a clock read
// per call would cost a good part of a call). The colliding calls are few per round (tens),
// too few for a clock: they are kept and replayed in batches of many rounds' worth
// (kCollidingBatch calls, the rest at finish()), three times each, and each replay's mean
// is a sample of the spread reported.

#include <cstddef>
#include <span>
#include <vector>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::cloth {

/// One kind of call for one method.
struct CallTimes {
  std::size_t calls = 0;
  double seconds = 0.0;
  std::size_t colliding_calls = 0;
  /// Per replay of a batch of colliding calls: its mean, in nanoseconds per call.
  std::vector<double> colliding_samples{};
  double colliding_seconds = 0.0;      ///< every replay's time, summed
  std::size_t colliding_replayed = 0;  ///< every replay's calls, summed

  double nanoseconds_per_call() const noexcept;
  double nanoseconds_per_colliding_call() const noexcept;
  /// The smallest and largest replay means (0 when none was replayed).
  double colliding_min() const noexcept;
  double colliding_max() const noexcept;
};

struct MethodTimes {
  CallTimes vertex_face;
  CallTimes edge_edge;
};

class NarrowPhaseTiming {
 public:
  /// Colliding calls kept before they are replayed as one batch.
  static constexpr std::size_t kCollidingBatch = 1 << 14;

  /// Times both methods on every candidate pair of the step.
  void add(const ccd::StepPositions& positions, std::span<const ccd::Triangle> faces,
           const ccd::MeshCcdCandidates& candidates);

  /// Replays the colliding calls still kept; call before reading the times.
  void finish();

  const MethodTimes& exact() const noexcept { return exact_; }
  const MethodTimes& cubic() const noexcept { return cubic_; }

 private:
  /// The colliding calls of one method, kept for their replay.
  struct Kept {
    std::vector<ccd::VertexFaceQuery> vertex_face;
    std::vector<ccd::EdgeEdgeQuery> edge_edge;
  };

  MethodTimes exact_;
  MethodTimes cubic_;
  Kept kept_exact_;
  Kept kept_cubic_;
};

}  // namespace exactgeo::cloth
