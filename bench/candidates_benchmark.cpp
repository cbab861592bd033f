// The two candidate finders of exactgeo::inside against each other on one mesh, in the
// same run: exactgeo's box tree (internal/tree_candidates.hpp) and Embree
// (internal/candidates.hpp). Per face count, the cost of one ray (random origins in the
// mesh's box, the first direction of the sequence, as most of the classifier's rays are)
// and of the build, each finder timed in alternation within every iteration, and the
// ratio tree / Embree. The classifier's face-count threshold (kBoxTreeFaces, classifier.hpp)
// comes from these figures and from Embree's fixed cost at start (docs/inside.md, "End to
// end"). The mesh is a closed torus of quads with a little noise, `faces` quads.
//
//   build/bin/candidates_benchmark [--benchmark_filter=Rays]
//   EXACTGEO_BENCH_SEED=N picks other origins and noise (the seed is printed)

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/inside/internal/tree_candidates.hpp"

namespace exactgeo::inside {
namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t seed() {
  static const std::uint64_t value = [] {
    const char* text = std::getenv("EXACTGEO_BENCH_SEED");
    const std::uint64_t s = text != nullptr ? std::strtoull(text, nullptr, 10) : 7;
    std::printf("seed %llu (EXACTGEO_BENCH_SEED)\n", static_cast<unsigned long long>(s));
    return s;
  }();
  return value;
}

/// A torus of about `faces` quads, 4:1 around, each vertex moved by noise.
mesh::Mesh torus(std::int64_t faces) {
  const int nv =
      std::max(4, static_cast<int>(std::lround(std::sqrt(static_cast<double>(faces) / 4.0))));
  const int nu = std::max(4, static_cast<int>(faces / nv));
  std::mt19937_64 rng(seed());
  std::uniform_real_distribution<double> noise(-0.01, 0.01);
  mesh::Mesh mesh;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double a = 2 * M_PI * i / nu, b = 2 * M_PI * j / nv;
      mesh.vertices.push_back({(2 + std::cos(b)) * std::cos(a) + noise(rng),
                               (2 + std::cos(b)) * std::sin(a) + noise(rng),
                               std::sin(b) + noise(rng)});
    }
  }
  const auto index = [&](int i, int j) { return static_cast<VertexIndex>((i % nu) * nv + j % nv); };
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      mesh.faces.push_back(
          mesh::make_quad(index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)));
    }
  }
  return mesh;
}

std::vector<Point3> origins_in(const mesh::Box& box, std::size_t count) {
  std::mt19937_64 rng(seed() + 1);
  std::vector<Point3> points(count);
  for (Point3& p : points) {
    for (int i = 0; i < 3; ++i) {
      p[i] = std::uniform_real_distribution<double>(box.lower[i], box.upper[i])(rng);
    }
  }
  return points;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Nanoseconds per ray of each finder, and tree / Embree; the candidates per ray.
void Rays(benchmark::State& state) {
  const mesh::Mesh mesh = torus(state.range(0));
  const mesh::Box box = *internal::corner_box(mesh);
  const internal::TreeCandidates tree(mesh, box);
  const internal::EmbreeCandidates embree(mesh, box);
  const std::vector<Point3> origins = origins_in(box, 1000);
  std::vector<FaceIndex> out;
  double tree_s = 0, embree_s = 0;
  std::size_t candidates = 0, rays = 0;
  for (auto _ : state) {
    auto start = Clock::now();
    for (const Point3& p : origins) {
      tree.find(p, 0, out);
      candidates += out.size();
    }
    tree_s += seconds_since(start);
    start = Clock::now();
    for (const Point3& p : origins) {
      embree.find(p, 0, out);
      benchmark::DoNotOptimize(out.data());
    }
    embree_s += seconds_since(start);
    rays += origins.size();
  }
  const auto n = static_cast<double>(rays);
  state.counters["faces"] = static_cast<double>(mesh.faces.size());
  state.counters["tree_ns"] = tree_s / n * 1e9;
  state.counters["embree_ns"] = embree_s / n * 1e9;
  state.counters["tree/embree"] = tree_s / embree_s;
  state.counters["candidates"] = static_cast<double>(candidates) / n;
}

/// Microseconds to build each finder (Embree: a device, a scene and its BVH, as every
/// classifier makes; not the library's loading, once per process), and tree / Embree.
void Build(benchmark::State& state) {
  const mesh::Mesh mesh = torus(state.range(0));
  const mesh::Box box = *internal::corner_box(mesh);
  double tree_s = 0, embree_s = 0;
  std::size_t builds = 0;
  for (auto _ : state) {
    auto start = Clock::now();
    {
      const internal::TreeCandidates tree(mesh, box);
      benchmark::DoNotOptimize(&tree);
    }
    tree_s += seconds_since(start);
    start = Clock::now();
    {
      const internal::EmbreeCandidates embree(mesh, box);
      benchmark::DoNotOptimize(&embree);
    }
    embree_s += seconds_since(start);
    ++builds;
  }
  const auto n = static_cast<double>(builds);
  state.counters["faces"] = static_cast<double>(mesh.faces.size());
  state.counters["tree_us"] = tree_s / n * 1e6;
  state.counters["embree_us"] = embree_s / n * 1e6;
  state.counters["tree/embree"] = tree_s / embree_s;
}

BENCHMARK(Rays)->RangeMultiplier(4)->Range(64, 65536)->Unit(benchmark::kMillisecond);
BENCHMARK(Build)->RangeMultiplier(4)->Range(64, 65536)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace exactgeo::inside

BENCHMARK_MAIN();
