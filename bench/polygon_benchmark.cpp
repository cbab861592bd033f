// Loading one OBJ polygon of n corners (docs/inside.md, "polygons"): convex, star-shaped
// and comb-shaped, n = 10 to 10^6, with mesh::read_obj from text in memory, against the
// same vertices written as n - 2 plain triangles, measured in the same run, interleaved.
//
//   build-bench/bin/polygon_benchmark [--benchmark_filter=Convex]
//
// Each benchmark's time is the polygon's load (manual time); it reports the time per
// corner of both loads and their ratio (polygon / triangles). The polygons are the test
// suite's generators (exactgeo/testbed/polygons.hpp) with a fixed seed.

#include <benchmark/benchmark.h>

#include <charconv>
#include <chrono>
#include <functional>
#include <random>
#include <string>

#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/testbed/polygons.hpp"

namespace {

using namespace exactgeo;
using testbed::Polygon2;

void append_number(std::string& text, double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;  // shortest, exact
  text.append(buffer, end);
}

/// The polygon's points as OBJ vertices at z = 0, then one face of all its corners, or
/// n - 2 triangles (the fan from its first corner) with `as_triangles`.
std::string obj_text(const Polygon2& polygon, bool as_triangles) {
  std::string text;
  for (const auto& [x, y] : polygon.points) {
    text.append("v ");
    append_number(text, x);
    text.append(" ");
    append_number(text, y);
    text.append(" 0\n");
  }
  const auto corner = [&](std::size_t k) { return std::to_string(polygon.cycle[k] + 1); };
  if (as_triangles) {
    for (std::size_t k = 1; k + 1 < polygon.cycle.size(); ++k)
      text.append("f " + corner(0) + " " + corner(k) + " " + corner(k + 1) + "\n");
  } else {
    text.append("f");
    for (std::size_t k = 0; k < polygon.cycle.size(); ++k)
      text.append(" ").append(corner(k));
    text.append("\n");
  }
  return text;
}

double seconds_to_load(const std::string& text) {
  const auto start = std::chrono::steady_clock::now();
  const mesh::LoadedMesh loaded = mesh::read_obj(text, "polygon.obj", {});
  benchmark::DoNotOptimize(loaded.mesh.faces.data());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void load_polygon(benchmark::State& state,
                  const std::function<Polygon2(std::mt19937_64&, int)>& make) {
  std::mt19937_64 rng(20261121);
  const Polygon2 polygon = make(rng, static_cast<int>(state.range(0)));
  const std::string as_polygon = obj_text(polygon, false);
  const std::string as_triangles = obj_text(polygon, true);
  double polygon_seconds = 0;
  double triangle_seconds = 0;
  for (auto _ : state) {
    const double seconds = seconds_to_load(as_polygon);
    state.SetIterationTime(seconds);
    polygon_seconds += seconds;
    triangle_seconds += seconds_to_load(as_triangles);
  }
  const double corners = static_cast<double>(polygon.cycle.size());
  const double iterations = static_cast<double>(state.iterations());
  state.counters["corners"] = corners;
  state.counters["ns_per_corner"] = 1e9 * polygon_seconds / iterations / corners;
  state.counters["triangles_ns_per_corner"] = 1e9 * triangle_seconds / iterations / corners;
  state.counters["ratio"] = polygon_seconds / triangle_seconds;
}

void Convex(benchmark::State& state) {
  load_polygon(state, [](std::mt19937_64& rng, int n) { return testbed::convex_polygon(rng, n); });
}
void Star(benchmark::State& state) {
  load_polygon(state,
               [](std::mt19937_64& rng, int n) { return testbed::star_polygon(rng, n, false); });
}
void Comb(benchmark::State& state) {
  load_polygon(state,
               [](std::mt19937_64& rng, int n) { return testbed::comb_polygon(rng, n / 4); });
}

BENCHMARK(Convex)
    ->RangeMultiplier(10)
    ->Range(10, 1000000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(Star)
    ->RangeMultiplier(10)
    ->Range(10, 1000000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(Comb)
    ->RangeMultiplier(10)
    ->Range(12, 1000000)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
