// Steps of millions of candidate pairs: mesh CCD decides them in batches where the broad
// phase finds them, so a step's peak memory does not grow with its candidate count.
//
// The steps turn the bundled Spot mesh (23,424 triangles) as a rigid body about the
// vertical axis (exactgeo/testbed/turned_step.hpp): the candidates grow with the angle (the
// tests ask for fewer than 100 thousand at half a degree, more than 5 million at 80 degrees),
// and there is no collision, by an argument independent of the code (the motion is an
// invertible linear map at every time), which the exact method must confirm on every pair.

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/testbed/resident_memory.hpp"
#include "exactgeo/testbed/turned_step.hpp"

namespace exactgeo::ccd {
namespace {

struct Spot {
  std::vector<double> positions;
  std::vector<Triangle> faces;
};

Spot spot_cc1() {
  const mesh::LoadedMesh loaded =
      mesh::load_mesh(std::string(EXACTGEO_TEST_DATA_DIR) + "/meshes/spot/spot_quad_cc1.ply");
  Spot spot;
  for (const Point3& p : loaded.mesh.vertices)
    spot.positions.insert(spot.positions.end(), p.begin(), p.end());
  for (const mesh::Face& f : loaded.mesh.faces) {
    spot.faces.push_back({f.corners[0], f.corners[1], f.corners[2]});
    if (!f.is_triangle()) spot.faces.push_back({f.corners[0], f.corners[2], f.corners[3]});
  }
  return spot;
}

struct MeasuredStep {
  MeshCcdResult result;
  std::size_t peak_bytes = 0;
};

/// A fresh MeshCcd's first step on Spot turned by `degrees`, at 2^scale_exponent, on two
/// threads, with the peak resident memory from just before the step to its end.
MeasuredStep turned_spot(const Spot& spot, double degrees, int scale_exponent = 0) {
  const testbed::TurnedStep step = testbed::turned_step(spot.positions, degrees, scale_exponent);
  MeshCcd ccd(spot.positions.size() / 3, spot.faces);
  MeshCcdOptions options;
  options.threads = 2;
  MeasuredStep measured;
  EXPECT_TRUE(testbed::reset_peak_resident_memory()) << "/proc/self/clear_refs is not writable";
  measured.result = ccd.step({step.t0, step.t1}, options);
  measured.peak_bytes = testbed::peak_resident_memory().value_or(0);
  return measured;
}

TEST(DenseSteps, PeakMemoryDoesNotGrowWithTheCandidates) {
  const Spot spot = spot_cc1();
  const MeasuredStep few = turned_spot(spot, 0.5);
  const MeasuredStep many = turned_spot(spot, 80.0);
  // A list of 5 million pairs (8 bytes each) alone would be 40 MB, several times the peak
  // of the step with few candidates.
  ASSERT_LT(few.result.candidates(), 100'000u);
  ASSERT_GT(many.result.candidates(), 5'000'000u);
  EXPECT_FALSE(few.result.collision());
  EXPECT_FALSE(many.result.collision());
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "peak memory is the sanitizer allocator's here; candidates checked only";
#else
  ASSERT_GT(few.peak_bytes, 0u);
  EXPECT_LE(many.peak_bytes, 2 * few.peak_bytes)
      << few.result.candidates() << " candidates: " << few.peak_bytes << " bytes at peak; "
      << many.result.candidates() << " candidates: " << many.peak_bytes << " bytes";
#endif
}

TEST(DenseSteps, CandidatesAreTheSameAtEveryMagnitude) {
  const Spot spot = spot_cc1();
  const MeasuredStep at_one = turned_spot(spot, 20.0);
  ASSERT_GT(at_one.result.candidates(), 1'000'000u);
  EXPECT_FALSE(at_one.result.collision());
  for (const int exponent : {1000, -1000}) {
    const MeasuredStep scaled = turned_spot(spot, 20.0, exponent);
    EXPECT_EQ(scaled.result.vertex_face_candidates, at_one.result.vertex_face_candidates)
        << "2^" << exponent;
    EXPECT_EQ(scaled.result.edge_edge_candidates, at_one.result.edge_edge_candidates)
        << "2^" << exponent;
    EXPECT_FALSE(scaled.result.collision()) << "2^" << exponent;
#if !defined(__SANITIZE_ADDRESS__)
    EXPECT_LE(scaled.peak_bytes, 2 * at_one.peak_bytes) << "2^" << exponent;
#endif
  }
  // Every candidate is handed to the narrow phase once: the counts are those of the
  // collected list. Last, as that list is the memory the steps above never hold.
  const testbed::TurnedStep step = testbed::turned_step(spot.positions, 20.0);
  MeshCcd ccd(spot.positions.size() / 3, spot.faces);
  const MeshCcdCandidates listed = ccd.candidates({step.t0, step.t1});
  EXPECT_EQ(listed.vertex_face.size(), at_one.result.vertex_face_candidates);
  EXPECT_EQ(listed.edge_edge.size(), at_one.result.edge_edge_candidates);
}

}  // namespace
}  // namespace exactgeo::ccd
