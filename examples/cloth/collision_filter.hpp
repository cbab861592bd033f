#pragma once

// Makes a predicted step collision free with the mesh-level exact CCD ("simple velocity
// filtering"): the step x0 -> x1 of the whole mesh (sheet and static obstacle) is checked
// with MeshCcd::step, and every sheet vertex of a colliding pair is frozen for the step
// (x1 = x0, velocity zero); the CCD runs again on the new x1 until nothing collides.
//
// Why the loop ends: MeshCcd never reports a pair whose primitives both stand still (every
// corner with p_t0 == p_t1, bit for bit; a standing obstacle's x1 is a copy of its x0, and
// so is a frozen vertex's). So every reported pair has a moving corner; freezing the
// pair's sheet vertices freezes at least one vertex that moved, unless the only moving
// corners are an obstacle's (a spinning ball pushing into a sheet vertex that stands): then
// the whole obstacle is held for the step (its x1 becomes its x0). After at most (sheet
// vertices + 2) rounds nothing that could collide moves (one round more with the
// look-ahead below).
//
// Why the result is collision free: by induction over the steps, x0 is free of contact (the
// sheet starts above the obstacle, and each step ends at a collision-free x1). A pair of
// standing primitives keeps its x0 distance, which is positive; every other pair was just
// checked over the whole step. This relies on the CCD being exact: a missed root (the
// floating-point CCD methods' false negatives, e.g. two roots in one step) would let a
// vertex pass through a face, the next step would start tangled, and the induction would
// be gone for good. exactgeo's exact method never misses a root; it may report a
// tangential near miss as a collision (decided_by == depth_limit), which only freezes a
// vertex too many.
//
// Separation (freeze filter only): the first rounds check a look-ahead step in which every
// moving sheet vertex goes `separation` metres further along its motion, so vertices stop
// about that far in front of what they would hit instead of creeping to touching distance.
// The look-ahead motion is not the real one (each vertex is stretched by a different
// factor), so the rounds after it check the real x0 -> x1 until clean: the guarantee above
// holds for the real step whatever the look-ahead did.
//
// The TOI variant (line search) scales the moving vertices' whole step by 0.8 times the
// start of the earliest time of impact instead of freezing, and zeroes the velocities of
// the colliding pairs' sheet vertices. In exact arithmetic the scaled step is a collision
// free prefix of the old one; rounding may break that, so a collision after a scaled step
// is scaled again, and after a few rounds the filter falls back to freezing (which ends).
// Its weakness shows in resting contact: each step keeps a fifth of the gap, the gaps
// shrink geometrically, the time of impact reaches 0 and the whole sheet stops.

#include <cstddef>
#include <span>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "narrow_phase_timing.hpp"

namespace exactgeo::cloth {

enum class FilterKind { freeze, time_of_impact };

struct FilterOptions {
  FilterKind kind = FilterKind::freeze;
  double separation = 0.0;  ///< metres; freeze filter only
  unsigned threads = 0;     ///< MeshCcdOptions::threads
  /// When set, every round's candidates are also timed by it (exact and cubic).
  NarrowPhaseTiming* timing = nullptr;
};

struct FilterStats {
  std::size_t rounds = 0;       ///< MeshCcd::step calls
  std::size_t candidates = 0;   ///< broad-phase pairs, summed over the rounds
  std::size_t vertex_face = 0;  ///< colliding pairs, summed over the rounds
  std::size_t edge_edge = 0;
  std::size_t self_pairs = 0;      ///< of those: every corner a sheet vertex
  std::size_t obstacle_pairs = 0;  ///< ... some corner an obstacle vertex
  std::size_t frozen = 0;          ///< sheet vertices of colliding pairs: frozen, or (TOI) stopped
  std::size_t scaled = 0;          ///< TOI rounds that scaled the step
  std::size_t trees_rebuilt = 0;   ///< rounds that built a broad-phase tree anew
  std::size_t obstacle_held = 0;   ///< steps whose moving obstacle was held back
  double seconds = 0.0;            ///< wall time in MeshCcd::step
  double broad_phase_seconds = 0.0;
  double narrow_phase_seconds = 0.0;

  std::size_t collisions() const noexcept { return vertex_face + edge_edge; }

  FilterStats& operator+=(const FilterStats& s) noexcept {
    rounds += s.rounds;
    candidates += s.candidates;
    vertex_face += s.vertex_face;
    edge_edge += s.edge_edge;
    self_pairs += s.self_pairs;
    obstacle_pairs += s.obstacle_pairs;
    frozen += s.frozen;
    scaled += s.scaled;
    trees_rebuilt += s.trees_rebuilt;
    obstacle_held += s.obstacle_held;
    seconds += s.seconds;
    broad_phase_seconds += s.broad_phase_seconds;
    narrow_phase_seconds += s.narrow_phase_seconds;
    return *this;
  }
};

class CollisionFilter {
 public:
  /// The sheet's vertices are [0, cloth_vertices); the rest never move.
  CollisionFilter(std::size_t vertex_count, std::span<const ccd::Triangle> faces,
                  std::size_t cloth_vertices, const FilterOptions& options);

  /// Changes x1 (3 per mesh vertex) and velocity (3 per sheet vertex) until the step
  /// x0 -> x1 is collision free; x0 must be free of contact. When first_t1 is given, it
  /// receives the end frame of the first CCD call (the look-ahead frame when separation > 0).
  FilterStats filter(std::span<const double> x0, std::span<double> x1, std::span<double> velocity,
                     std::vector<double>* first_t1 = nullptr);

  /// Per sheet vertex, whether the last filter() froze (or stopped) it.
  std::span<const unsigned char> frozen() const noexcept { return frozen_; }

 private:
  /// The frame the next round checks: x1, or its look-ahead.
  std::span<const double> round_end(std::span<const double> x0, std::span<const double> x1,
                                    bool look_ahead);
  void count(const ccd::MeshCcdResult& result, FilterStats& stats) const;
  /// Marks the sheet vertices of every colliding pair.
  void mark_colliding(const ccd::MeshCcdResult& result);

  ccd::MeshCcd ccd_;
  std::size_t cloth_vertices_;
  FilterOptions options_;
  std::vector<double> look_ahead_;
  std::vector<unsigned char> marked_;
  std::vector<std::size_t> marked_list_;
  std::vector<unsigned char> frozen_;
};

}  // namespace exactgeo::cloth
