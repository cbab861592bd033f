// Throughput of the exact predicates against the plain double evaluation of the same
// formulas, measured in the same run, on three kinds of input:
//   random      uniform in [-1, 1]^3: the filter should decide nearly everything;
//   near        degenerate up to rounding (computed on a plane / through a patch edge);
//   degenerate  exactly degenerate small dyadic integers.
// After the timings it prints, per predicate and input kind, the exact/double time ratio
// and the fraction of signs decided by each stage (filter, expansions, rationals).
//
//   build/bench/predicates_benchmark [--benchmark_min_time=0.5]

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/crossing_parity.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"
#include "exactgeo/predicates/orient3d.hpp"

namespace {

using exactgeo::Arithmetic;
using exactgeo::BilinearPatch;
using exactgeo::Point3;
using exactgeo::Sign;
using Rng = std::mt19937_64;

constexpr std::size_t kBatch = 4096;
constexpr std::uint64_t kSeed = 20261121;

Point3 random_point(Rng& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  return {u(rng), u(rng), u(rng)};
}
Point3 integer_point(Rng& rng, int range) {
  std::uniform_int_distribution<int> i(-range, range);
  return {double(i(rng)), double(i(rng)), double(i(rng))};
}
Point3 affine(const Point3& a, const Point3& b, const Point3& c, double s, double t) {
  Point3 p;
  for (int k = 0; k < 3; ++k)
    p[k] = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]);
  return p;
}

enum class Kind { random, near, degenerate };
const char* name(Kind k) {
  return k == Kind::random ? "random" : k == Kind::near ? "near" : "degenerate";
}

// --- orient3d ---------------------------------------------------------------------------

struct OrientCase {
  Point3 a, b, c, d;
};

std::vector<OrientCase> orient_cases(Kind kind) {
  Rng rng(kSeed + static_cast<int>(kind));
  std::uniform_real_distribution<double> st(-2, 2);
  std::uniform_int_distribution<int> small(-3, 3);
  std::vector<OrientCase> cases(kBatch);
  for (auto& c : cases) {
    if (kind == Kind::degenerate) {
      c.a = integer_point(rng, 1000), c.b = integer_point(rng, 1000),
      c.c = integer_point(rng, 1000);
      c.d = affine(c.a, c.b, c.c, small(rng), small(rng));
    } else {
      c.a = random_point(rng), c.b = random_point(rng), c.c = random_point(rng);
      c.d = kind == Kind::random ? random_point(rng) : affine(c.a, c.b, c.c, st(rng), st(rng));
    }
  }
  return cases;
}

/// The plain double predicate: the sign of the determinant evaluated in double, out of line
/// like the library call it is compared with.
[[gnu::noinline]] Sign orient3d_plain(const Point3& a, const Point3& b, const Point3& c,
                                      const Point3& d) {
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  return exactgeo::sign_of(bx * (cy * dz - cz * dy) + by * (cz * dx - cx * dz) +
                           bz * (cx * dy - cy * dx));
}

void BM_orient3d_exact(benchmark::State& state, Kind kind) {
  const auto cases = orient_cases(kind);
  for (auto _ : state) {
    for (const auto& c : cases)
      benchmark::DoNotOptimize(exactgeo::orient3d(c.a, c.b, c.c, c.d));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(cases.size()));
}

void BM_orient3d_double(benchmark::State& state, Kind kind) {
  const auto cases = orient_cases(kind);
  for (auto _ : state) {
    for (const auto& c : cases)
      benchmark::DoNotOptimize(orient3d_plain(c.a, c.b, c.c, c.d));
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(cases.size()));
}

exactgeo::kernel::StageCounts orient_stages(Kind kind) {
  using exactgeo::kernel::Offset;
  exactgeo::kernel::StageCounts counts;
  const exactgeo::kernel::ExactSigns signs(&counts);
  for (const auto& c : orient_cases(kind)) {
    signs.det3_by_axis(Offset::between(c.a, c.b), Offset::between(c.a, c.c),
                       Offset::between(c.a, c.d));
  }
  return counts;
}

// --- ray vs bilinear patch --------------------------------------------------------------

struct RayPatchCase {
  Point3 origin;
  Point3 direction;
  BilinearPatch patch;
};

std::vector<RayPatchCase> ray_patch_cases(Kind kind) {
  Rng rng(kSeed + 10 + static_cast<int>(kind));
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<RayPatchCase> cases(kBatch);
  for (auto& c : cases) {
    if (kind == Kind::degenerate) {
      // Small integers: rays through corners and edges, flat and collapsed patches.
      c.patch = {integer_point(rng, 2), integer_point(rng, 2), integer_point(rng, 2),
                 integer_point(rng, 2)};
      c.origin = integer_point(rng, 2);
      do {
        c.direction = integer_point(rng, 2);
      } while (c.direction == Point3{0, 0, 0});
      continue;
    }
    c.patch = {random_point(rng), random_point(rng), random_point(rng), random_point(rng)};
    const Point3 target = affine(c.patch.p00, c.patch.p10, c.patch.p01, unit(rng), unit(rng));
    c.origin = random_point(rng);
    if (kind == Kind::near) {
      // Aim at a point of the edge p00 p10 (up to rounding): the ray grazes the boundary.
      const Point3 edge = affine(c.patch.p00, c.patch.p10, c.patch.p00, unit(rng), 0);
      for (int k = 0; k < 3; ++k)
        c.direction[k] = edge[k] - c.origin[k];
    } else {
      for (int k = 0; k < 3; ++k)
        c.direction[k] = target[k] - c.origin[k];
    }
  }
  return cases;
}

void BM_ray_patch(benchmark::State& state, Kind kind, Arithmetic arithmetic) {
  const auto cases = ray_patch_cases(kind);
  for (auto _ : state) {
    for (const auto& c : cases) {
      benchmark::DoNotOptimize(
          exactgeo::ray_patch_parity(c.origin, c.direction, c.patch, arithmetic));
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(cases.size()));
}

exactgeo::kernel::StageCounts ray_patch_stages(Kind kind) {
  using exactgeo::kernel::Offset;
  exactgeo::kernel::StageCounts counts;
  const exactgeo::kernel::ExactSigns signs(&counts);
  constexpr auto face = exactgeo::SurfaceFace::patch(0, 1, 2, 3);
  for (const auto& c : ray_patch_cases(kind)) {
    const std::array<exactgeo::Point3, 4> corners{c.patch.p00, c.patch.p10, c.patch.p11,
                                                  c.patch.p01};
    const auto corner = [&](exactgeo::VertexIndex i) {
      return Offset::between(c.origin, corners[i]);
    };
    exactgeo::cross_face(signs, face, exactgeo::span_of(signs, face, corners), corner,
                         Offset::vector(c.direction));
  }
  return counts;
}

// --- registration and the ratio table ---------------------------------------------------

/// Remembers each run's time per item, to print ratios after the usual table.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration) continue;
      const auto items = r.counters.find("items_per_second");
      if (items != r.counters.end() && items->second.value > 0) {
        ns_per_item[r.benchmark_name()] = 1e9 / items->second.value;
      }
    }
  }
  std::map<std::string, double> ns_per_item;
};

/// How often the plain double answer differs from the exact one: the other side of the trade.
int orient_double_errors(Kind kind) {
  int wrong = 0;
  for (const auto& c : orient_cases(kind)) {
    wrong += exactgeo::orient3d(c.a, c.b, c.c, c.d, Arithmetic::plain_double) !=
             exactgeo::orient3d(c.a, c.b, c.c, c.d);
  }
  return wrong;
}

int ray_patch_double_errors(Kind kind) {
  int wrong = 0;
  for (const auto& c : ray_patch_cases(kind)) {
    wrong += exactgeo::ray_patch_parity(c.origin, c.direction, c.patch, Arithmetic::plain_double) !=
             exactgeo::ray_patch_parity(c.origin, c.direction, c.patch);
  }
  return wrong;
}

void print_stages(const char* label, const exactgeo::kernel::StageCounts& c) {
  const double total = double(c.total());
  std::printf("  %-28s signs %8llu  filter %6.2f%%  expansion %6.2f%%  rational %6.2f%%\n", label,
              static_cast<unsigned long long>(c.total()), 100 * double(c.filter) / total,
              100 * double(c.expansion) / total, 100 * double(c.rational) / total);
}

}  // namespace

int main(int argc, char** argv) {
  for (const Kind kind : {Kind::random, Kind::near, Kind::degenerate}) {
    benchmark::RegisterBenchmark((std::string("orient3d/double/") + name(kind)).c_str(),
                                 BM_orient3d_double, kind);
    benchmark::RegisterBenchmark((std::string("orient3d/exact/") + name(kind)).c_str(),
                                 BM_orient3d_exact, kind);
  }
  for (const Kind kind : {Kind::random, Kind::near, Kind::degenerate}) {
    benchmark::RegisterBenchmark((std::string("ray_patch/double/") + name(kind)).c_str(),
                                 BM_ray_patch, kind, Arithmetic::plain_double);
    benchmark::RegisterBenchmark((std::string("ray_patch/exact/") + name(kind)).c_str(),
                                 BM_ray_patch, kind, Arithmetic::exact);
    benchmark::RegisterBenchmark((std::string("ray_patch/rational/") + name(kind)).c_str(),
                                 BM_ray_patch, kind, Arithmetic::rational);
  }
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  std::printf("\nexact / double time per call (same run):\n");
  for (const char* predicate : {"orient3d", "ray_patch"}) {
    for (const Kind kind : {Kind::random, Kind::near, Kind::degenerate}) {
      const std::string suffix = std::string("/") + name(kind);
      const auto exact = reporter.ns_per_item.find(predicate + std::string("/exact") + suffix);
      const auto plain = reporter.ns_per_item.find(predicate + std::string("/double") + suffix);
      if (exact == reporter.ns_per_item.end() || plain == reporter.ns_per_item.end()) continue;
      std::printf("  %-10s %-11s double %8.2f ns  exact %8.2f ns  ratio %5.2f\n", predicate,
                  name(kind), plain->second, exact->second, exact->second / plain->second);
    }
  }
  std::printf("\nplain double answers that differ from the exact ones (of %zu cases):\n", kBatch);
  for (const Kind kind : {Kind::random, Kind::near, Kind::degenerate}) {
    std::printf("  %-11s orient3d %5d   ray_patch %5d\n", name(kind), orient_double_errors(kind),
                ray_patch_double_errors(kind));
  }
  std::printf("\nwhich stage decided each sign:\n");
  for (const Kind kind : {Kind::random, Kind::near, Kind::degenerate}) {
    print_stages((std::string("orient3d/") + name(kind)).c_str(), orient_stages(kind));
  }
  for (const Kind kind : {Kind::random, Kind::near, Kind::degenerate}) {
    print_stages((std::string("ray_patch/") + name(kind)).c_str(), ray_patch_stages(kind));
  }
  benchmark::Shutdown();
  return 0;
}
