// A smoothing pass over a stack of sheets: every vertex moved a little, once by
// relocate_vertex one vertex at a time (each check goes over the whole surface) and once
// by relocate_vertices (one pseudo-motion through the mesh broad phase), and, as the
// yardstick a pass should be close to, one mesh CCD step over the same motion
// (ccd::find_collisions). All start from the same surface with the same moves; compare
// their times in the same run:
//
//   build/bench/remesh_benchmark --benchmark_filter=Smoothing
//
// A coarsening pass likewise: edges far enough apart collapsed into one end, by
// collapse_edge one at a time, by collapse_edges, and as one mesh CCD step of the same
// motion (the removed ends moving onto the kept ones):
//
//   build/bench/remesh_benchmark --benchmark_filter=Coarsening
//
// A full remesh (a pass of splits, one of collapses, one of flips) against the same step:
//
//   build/bench/remesh_benchmark --benchmark_filter='FullRemesh|SmoothingAsOne'
//
// (docs/remesh.md quotes the ratios).

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cmath>
#include <random>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/remesh/operations.hpp"

namespace {

using exactgeo::Point3;
using exactgeo::remesh::Collapse;
using exactgeo::remesh::Move;
using exactgeo::remesh::Surface;
using exactgeo::remesh::VertexIndex;

/// `layers` wavy n x n sheets, 1/4 apart, and a move of at most 1/16 for every vertex.
struct Scene {
  Surface surface;
  std::vector<Move> moves;
};

Scene scene(int layers, int n) {
  Scene out;
  Surface& s = out.surface;
  const double h = 1.0 / n;
  for (int k = 0; k < layers; ++k) {
    const auto first = static_cast<VertexIndex>(s.vertices.size());
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        s.vertices.push_back({i * h, j * h, 0.25 * k + 0.05 * std::sin(7.0 * i * h + 3.0 * j * h)});
      }
    }
    const auto at = [&](int i, int j) { return first + static_cast<VertexIndex>(i + (n + 1) * j); };
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> d(-h / 4, h / 4);
  for (VertexIndex v = 0; v < s.vertices.size(); ++v) {
    const Point3& p = s.vertices[v];
    out.moves.push_back({v, {p[0] + d(rng), p[1] + d(rng), p[2] + d(rng)}});
  }
  return out;
}

void SmoothingOneByOne(benchmark::State& state) {
  const Scene start = scene(3, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Surface s = start.surface;
    std::size_t applied = 0;
    for (const Move& m : start.moves)
      applied += exactgeo::remesh::relocate_vertex(s, m.vertex, m.to).applied();
    benchmark::DoNotOptimize(applied);
  }
  state.counters["vertices"] = static_cast<double>(start.moves.size());
}

void SmoothingBatch(benchmark::State& state) {
  const Scene start = scene(3, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Surface s = start.surface;
    benchmark::DoNotOptimize(exactgeo::remesh::relocate_vertices(s, start.moves));
  }
  state.counters["vertices"] = static_cast<double>(start.moves.size());
}

void SmoothingAsOneMeshCcdStep(benchmark::State& state) {
  const Scene start = scene(3, static_cast<int>(state.range(0)));
  const std::vector<double> t0 = exactgeo::ccd::flat_positions(start.surface.vertices);
  std::vector<double> t1 = t0;
  for (const Move& m : start.moves) {
    for (int k = 0; k < 3; ++k)
      t1[3 * m.vertex + k] = m.to[k];
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        exactgeo::ccd::find_collisions(start.surface.triangles, {t0, t1}).collision());
  }
  state.counters["vertices"] = static_cast<double>(start.moves.size());
}

/// Collapses of the edges from (i, j) to (i + 1, j) for i = 1, 5, 9, ... and j = 1, 4, 7,
/// ... of every sheet (n >= 4), into (i, j): apart from each other, no end on the boundary.
std::vector<Collapse> coarsening(const Scene& scene, int layers, int n) {
  std::vector<Collapse> out;
  for (int k = 0; k < layers; ++k) {
    const auto first = static_cast<VertexIndex>(k * (n + 1) * (n + 1));
    for (int j = 1; j < n; j += 3) {
      for (int i = 1; i + 1 < n; i += 4) {
        const VertexIndex a = first + static_cast<VertexIndex>(i + (n + 1) * j);
        out.push_back({a, a + 1, scene.surface.vertices[a]});
      }
    }
  }
  return out;
}

void CoarseningOneByOne(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Scene start = scene(3, n);
  const std::vector<Collapse> collapses = coarsening(start, 3, n);
  for (auto _ : state) {
    Surface s = start.surface;
    std::size_t applied = 0;
    for (const Collapse& c : collapses)
      applied += exactgeo::remesh::collapse_edge(s, c.a, c.b, c.to).applied();
    benchmark::DoNotOptimize(applied);
  }
  state.counters["collapses"] = static_cast<double>(collapses.size());
}

void CoarseningPass(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Scene start = scene(3, n);
  const std::vector<Collapse> collapses = coarsening(start, 3, n);
  std::size_t applied = 0;
  for (auto _ : state) {
    Surface s = start.surface;
    applied = 0;
    for (const auto& o : exactgeo::remesh::collapse_edges(s, collapses))
      applied += o.applied();
    benchmark::DoNotOptimize(applied);
  }
  state.counters["collapses"] = static_cast<double>(collapses.size());
  state.counters["applied"] = static_cast<double>(applied);
}

void CoarseningAsOneMeshCcdStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Scene start = scene(3, n);
  const std::vector<double> t0 = exactgeo::ccd::flat_positions(start.surface.vertices);
  std::vector<double> t1 = t0;
  for (const Collapse& c : coarsening(start, 3, n)) {
    for (int k = 0; k < 3; ++k)
      t1[3 * c.b + k] = c.to[k];
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        exactgeo::ccd::find_collisions(start.surface.triangles, {t0, t1}).collision());
  }
}

/// A full remesh of the sheets: a pass of splits (every edge at its rounded midpoint), a
/// pass of collapses (coarsening()) and a pass of flips (every edge), one after the other
/// on the surface each leaves, as a remesher calls them; against one mesh CCD step of the
/// same mesh (the smoothing moves, a step from scratch), the yardstick a remesh should be
/// within.
std::vector<exactgeo::remesh::Split> midpoint_splits(const Surface& s) {
  std::vector<exactgeo::remesh::Split> out;
  for (const auto& e : s.edges()) {
    const Point3 &a = s.vertices[e[0]], &b = s.vertices[e[1]];
    out.push_back({e[0], e[1], {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}});
  }
  return out;
}

/// The page faults (minor: memory first touched) of this process so far.
double page_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_minflt);
}

void FullRemesh(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Scene start = scene(3, n);
  const std::vector<Collapse> collapses = coarsening(start, 3, n);
  const std::vector<exactgeo::remesh::Split> splits = midpoint_splits(start.surface);
  std::size_t applied = 0;
  // One workspace for the three passes and every iteration, as a simulator keeps one.
  exactgeo::remesh::PassWorkspace workspace;
  const double faults_before = page_faults();
  for (auto _ : state) {
    Surface s = start.surface;
    applied = 0;
    for (const auto& o : exactgeo::remesh::split_edges(s, splits, &workspace))
      applied += o.applied();
    // The collapses name the start's vertices, which the splits keep (new ones come after).
    for (const auto& o : exactgeo::remesh::collapse_edges(s, collapses, &workspace))
      applied += o.applied();
    const std::vector<exactgeo::remesh::Edge> edges = s.edges();
    for (const auto& o : exactgeo::remesh::flip_edges(s, edges, &workspace))
      applied += o.applied();
    benchmark::DoNotOptimize(applied);
  }
  state.counters["triangles"] = static_cast<double>(start.surface.triangles.size());
  state.counters["applied"] = static_cast<double>(applied);
  // Per iteration; the first (the workspace's arrays made) included.
  state.counters["page_faults"] =
      benchmark::Counter(page_faults() - faults_before, benchmark::Counter::kAvgIterations);
}

BENCHMARK(FullRemesh)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

BENCHMARK(CoarseningOneByOne)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(CoarseningPass)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(CoarseningAsOneMeshCcdStep)
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(SmoothingOneByOne)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(SmoothingBatch)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);
BENCHMARK(SmoothingAsOneMeshCcdStep)
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
