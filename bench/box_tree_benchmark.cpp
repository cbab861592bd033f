// Building a box tree against refitting it, per primitive, on one thread (docs/ccd.md):
// the vertex, edge and face trees of a Spot mesh under a small random motion, as the mesh
// broad phase makes them on a step's first call (build) and on the next ones (refit).
//
//   build-bench/bin/box_tree_benchmark [--benchmark_filter=Spot]
//
// Reads Spot cc2 (93,696 triangles) from the shared data next to the checkout; without it,
// the bundled Spot cc1 (23,424). Each benchmark reports its time per primitive; builds also report
// the tree's looseness (box_tree.hpp), the walk's work per primitive, roughly.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/boxes/box_tree.hpp"
#include "exactgeo/ccd/mesh/internal/swept_box.hpp"
#include "exactgeo/mesh/load.hpp"

namespace {

using namespace exactgeo;

struct Scene {
  boxes::VertexBoxes vertices;
  std::vector<std::array<VertexIndex, 1>> points;
  std::vector<std::array<VertexIndex, 2>> edges;
  std::vector<std::array<VertexIndex, 3>> faces;
};

const Scene& spot() {
  static const Scene scene = [] {
    std::string path = EXACTGEO_SHARED_DATA_DIR "/meshes/spot/spot_quad_cc2.ply";
    if (!std::filesystem::exists(path))
      path = EXACTGEO_TEST_DATA_DIR "/meshes/spot/spot_quad_cc1.ply";
    const mesh::LoadedMesh loaded = mesh::load_mesh(path);
    Scene s;
    std::vector<double> t0, t1;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> motion(-0.002, 0.002);
    double largest = 0.0;
    for (const Point3& p : loaded.mesh.vertices) {
      for (const double x : p) {
        t0.push_back(x);
        t1.push_back(x + motion(rng));
        largest = std::max({largest, std::abs(t0.back()), std::abs(t1.back())});
      }
    }
    const boxes::Scale scale(largest);
    std::vector<boxes::FloatBox> swept(loaded.mesh.vertices.size());
    for (std::size_t v = 0; v < swept.size(); ++v)
      swept[v] = ccd::internal::vertex_swept_box(t0.data(), t1.data(), v, scale);
    s.vertices = boxes::VertexBoxes::at_rest(std::move(swept));
    for (std::size_t v = 0; v < loaded.mesh.vertices.size(); ++v)
      s.points.push_back({static_cast<VertexIndex>(v)});
    for (const mesh::Face& f : loaded.mesh.faces) {
      s.faces.push_back({f.corners[0], f.corners[1], f.corners[2]});
      if (!f.is_triangle()) s.faces.push_back({f.corners[0], f.corners[2], f.corners[3]});
    }
    for (const auto& f : s.faces) {
      for (int i = 0; i < 3; ++i)
        s.edges.push_back({std::min(f[i], f[(i + 1) % 3]), std::max(f[i], f[(i + 1) % 3])});
    }
    std::sort(s.edges.begin(), s.edges.end());
    s.edges.erase(std::unique(s.edges.begin(), s.edges.end()), s.edges.end());
    return s;
  }();
  return scene;
}

template <std::size_t N>
const std::vector<std::array<VertexIndex, N>>& primitives(const Scene& s) {
  if constexpr (N == 1) return s.points;
  if constexpr (N == 2) return s.edges;
  if constexpr (N == 3) return s.faces;
}

/// The time per primitive, as a counter (seconds, shown with an SI prefix: 120n is 120 ns).
void per_primitive(benchmark::State& state, std::size_t primitives) {
  state.counters["per_primitive"] = benchmark::Counter(
      static_cast<double>(primitives),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <std::size_t N>
void Build(benchmark::State& state) {
  const Scene& s = spot();
  const auto& p = primitives<N>(s);
  double looseness = 0.0;
  for (auto _ : state) {
    boxes::BoxTree<N> tree(p, s.vertices);
    looseness = tree.looseness();
    benchmark::DoNotOptimize(tree);
  }
  per_primitive(state, p.size());
  // The walk's work per primitive, roughly (box_tree.hpp): how good the tree is.
  state.counters["looseness"] = looseness;
}

template <std::size_t N>
void Refit(benchmark::State& state) {
  const Scene& s = spot();
  const auto& p = primitives<N>(s);
  boxes::BoxTree<N> tree(p, s.vertices);
  for (auto _ : state) {
    tree.refit(s.vertices);
    benchmark::DoNotOptimize(tree);
  }
  per_primitive(state, p.size());
}

BENCHMARK(Build<1>)->Name("SpotBuild/vertices")->Unit(benchmark::kMillisecond);
BENCHMARK(Build<2>)->Name("SpotBuild/edges")->Unit(benchmark::kMillisecond);
BENCHMARK(Build<3>)->Name("SpotBuild/faces")->Unit(benchmark::kMillisecond);
BENCHMARK(Refit<1>)->Name("SpotRefit/vertices")->Unit(benchmark::kMillisecond);
BENCHMARK(Refit<2>)->Name("SpotRefit/edges")->Unit(benchmark::kMillisecond);
BENCHMARK(Refit<3>)->Name("SpotRefit/faces")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
