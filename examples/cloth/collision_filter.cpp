#include "collision_filter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace exactgeo::cloth {

namespace {

/// TOI variant: the earliest root is bracketed to this width (a fraction of the step).
constexpr double kTimeOfImpactWidth = 1e-3;
/// TOI variant: the fraction of the time of impact's start that the step is scaled to.
constexpr double kTimeOfImpactFraction = 0.8;
/// TOI variant: scaled rounds before falling back to freezing.
constexpr std::size_t kMaxTimeOfImpactRounds = 4;

}  // namespace

CollisionFilter::CollisionFilter(std::size_t vertex_count, std::span<const ccd::Triangle> faces,
                                 std::size_t cloth_vertices, const FilterOptions& options)
    : ccd_(vertex_count, faces),
      cloth_vertices_(cloth_vertices),
      options_(options),
      look_ahead_(3 * vertex_count),
      marked_(cloth_vertices, 0) {}

std::span<const double> CollisionFilter::round_end(std::span<const double> x0,
                                                   std::span<const double> x1, bool look_ahead) {
  if (!look_ahead) return x1;
  std::copy(x1.begin(), x1.end(), look_ahead_.begin());
  for (std::size_t v = 0; v < cloth_vertices_; ++v) {
    const double dx = x1[3 * v] - x0[3 * v];
    const double dy = x1[3 * v + 1] - x0[3 * v + 1];
    const double dz = x1[3 * v + 2] - x0[3 * v + 2];
    const double len = std::hypot(dx, dy, dz);
    if (len == 0.0) continue;  // standing: x1, bit for bit x0
    const double further = options_.separation / len;
    look_ahead_[3 * v] = x1[3 * v] + further * dx;
    look_ahead_[3 * v + 1] = x1[3 * v + 1] + further * dy;
    look_ahead_[3 * v + 2] = x1[3 * v + 2] + further * dz;
  }
  return look_ahead_;
}

void CollisionFilter::count(const ccd::MeshCcdResult& result, FilterStats& stats) const {
  const std::span<const ccd::Triangle> faces = ccd_.faces();
  const auto cloth = [&](ccd::VertexIndex v) { return v < cloth_vertices_; };
  for (const ccd::VertexFacePair& pair : result.vertex_face) {
    const ccd::Triangle& f = faces[pair.face];
    const bool self = cloth(pair.vertex) && cloth(f[0]) && cloth(f[1]) && cloth(f[2]);
    ++(self ? stats.self_pairs : stats.obstacle_pairs);
  }
  for (const ccd::EdgeEdgePair& pair : result.edge_edge) {
    const bool self = cloth(pair.a[0]) && cloth(pair.a[1]) && cloth(pair.b[0]) && cloth(pair.b[1]);
    ++(self ? stats.self_pairs : stats.obstacle_pairs);
  }
  stats.vertex_face += result.vertex_face.size();
  stats.edge_edge += result.edge_edge.size();
  stats.candidates += result.candidates();
}

void CollisionFilter::mark_colliding(const ccd::MeshCcdResult& result) {
  const auto mark = [&](ccd::VertexIndex v) {
    if (v < cloth_vertices_ && marked_[v] == 0) {
      marked_[v] = 1;
      marked_list_.push_back(v);
    }
  };
  const std::span<const ccd::Triangle> faces = ccd_.faces();
  for (const ccd::VertexFacePair& pair : result.vertex_face) {
    mark(pair.vertex);
    for (const ccd::VertexIndex v : faces[pair.face])
      mark(v);
  }
  for (const ccd::EdgeEdgePair& pair : result.edge_edge) {
    for (const ccd::VertexIndex v : {pair.a[0], pair.a[1], pair.b[0], pair.b[1]})
      mark(v);
  }
}

FilterStats CollisionFilter::filter(std::span<const double> x0, std::span<double> x1,
                                    std::span<double> velocity, std::vector<double>* first_t1) {
  using Clock = std::chrono::steady_clock;
  FilterStats stats;
  bool look_ahead = options_.kind == FilterKind::freeze && options_.separation > 0.0;
  std::size_t stopped_before = 0;  // marked_list_ entries already stopped
  for (;;) {
    const bool toi =
        options_.kind == FilterKind::time_of_impact && stats.scaled < kMaxTimeOfImpactRounds;
    const std::span<const double> end = round_end(x0, x1, look_ahead);
    ccd::MeshCcdOptions ccd_options;
    ccd_options.method = ccd::Method::exact;
    if (toi) ccd_options.time_of_impact_width = kTimeOfImpactWidth;
    ccd_options.threads = options_.threads;

    const Clock::time_point start = Clock::now();
    const ccd::MeshCcdResult result = ccd_.step({x0, end}, ccd_options);
    stats.seconds += std::chrono::duration<double>(Clock::now() - start).count();
    stats.broad_phase_seconds += result.broad_phase_seconds;
    stats.narrow_phase_seconds += result.narrow_phase_seconds;
    ++stats.rounds;
    if (result.trees_rebuilt) ++stats.trees_rebuilt;
    if (options_.timing != nullptr) {
      options_.timing->add({x0, end}, ccd_.faces(), ccd_.candidates({x0, end}, ccd_options));
    }
    if (first_t1 != nullptr && stats.rounds == 1) first_t1->assign(end.begin(), end.end());
    count(result, stats);

    if (!result.collision()) {
      if (look_ahead) {  // the look-ahead is clean: now make sure of the real step
        look_ahead = false;
        continue;
      }
      break;
    }
    mark_colliding(result);
    for (std::size_t i = stopped_before; i < marked_list_.size(); ++i) {
      const std::size_t v = marked_list_[i];
      for (std::size_t k = 0; k < 3; ++k)
        velocity[3 * v + k] = 0.0;
    }
    stopped_before = marked_list_.size();

    if (toi && result.time_of_impact) {
      // Line search: every moving vertex keeps the same fraction of its step; standing
      // vertices (and every vertex when the fraction is 0) stay bit for bit at x0.
      ++stats.scaled;
      const double s = kTimeOfImpactFraction * result.time_of_impact->start;
      for (std::size_t i = 0; i < 3 * cloth_vertices_; ++i) {
        x1[i] = s == 0.0 || x1[i] == x0[i] ? x0[i] : x0[i] + s * (x1[i] - x0[i]);
      }
      continue;
    }
    // Freeze: the sheet vertices of the colliding pairs stand still for this step. At
    // least one of them moved (pairs of standing primitives are never reported).
    bool froze_one = false;
    for (std::size_t v : marked_list_) {
      const auto from = x0.begin() + static_cast<std::ptrdiff_t>(3 * v);
      const auto to = x1.begin() + static_cast<std::ptrdiff_t>(3 * v);
      if (std::equal(from, from + 3, to)) continue;
      std::copy_n(from, 3, to);
      froze_one = true;
    }
    if (!froze_one && stats.obstacle_held == 0) {
      // Only the obstacle moves in the colliding pairs: hold it for this step.
      const auto obstacle = static_cast<std::ptrdiff_t>(3 * cloth_vertices_);
      if (!std::equal(x0.begin() + obstacle, x0.end(), x1.begin() + obstacle)) {
        std::copy(x0.begin() + obstacle, x0.end(), x1.begin() + obstacle);
        stats.obstacle_held = 1;
        froze_one = true;
      }
    }
    if (!froze_one) {
      throw std::logic_error(
          "MeshCcd reported a colliding pair whose corners all stand still: the filter "
          "cannot make progress");
    }
  }
  stats.frozen = marked_list_.size();
  frozen_.assign(cloth_vertices_, 0);
  for (std::size_t v : marked_list_) {
    frozen_[v] = 1;
    marked_[v] = 0;
  }
  marked_list_.clear();
  return stats;
}

}  // namespace exactgeo::cloth
