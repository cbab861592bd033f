// The CCD methods on the two halves of the public benchmark, per query: the simulation
// (time-of-impact) queries and the handcrafted degenerate ones. `double` (root parity in
// plain doubles), `parity` (exact root parity) and `exact` (any root), each through the
// public ccd::*_ccd entry points. Uses ../shared/data/ccd (scalable-ccd-data and
// sample-queries) when present next to the checkout, otherwise the bundled slices in
// tests/data. Parsing is excluded from the timings. After the table it prints, per set and
// query type, the ratios exact/double, parity/double and exact/parity measured in the same
// run, from the fastest of 7 repetitions run in random interleaving (unless
// --benchmark_repetitions is given), next to the targets the project works toward.
//
//   build/bin/ccd_benchmark [--benchmark_min_time=0.2] [--benchmark_repetitions=9]

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "exactgeo/ccd/ccd.hpp"
#include "exactgeo/ccd/files/query_files.hpp"

namespace {

namespace fs = std::filesystem;
namespace ccd = exactgeo::ccd;

struct Queries {
  std::vector<ccd::VertexFaceQuery> vertex_face;
  std::vector<ccd::EdgeEdgeQuery> edge_edge;
  std::string source;
};

/// Every query file under `set` (a folder of the public data), from the shared data when
/// present, else from the bundled slice. The type comes from the path, as for `exactgeo ccd`.
Queries load(const std::string& set) {
  Queries q;
  fs::path root = fs::path(EXACTGEO_SHARED_DATA_DIR) / "ccd" / set;
  if (!fs::exists(root)) root = fs::path(EXACTGEO_TEST_DATA_DIR) / "ccd" / set;
  q.source = root.string();
  for (const ccd::QueryFile& file : ccd::read_query_files({root.string()})) {
    for (const auto& r : file.records) {
      if (file.type == ccd::QueryType::edge_edge) {
        q.edge_edge.push_back(ccd::edge_edge_query(r));
      } else {
        q.vertex_face.push_back(ccd::vertex_face_query(r));
      }
    }
  }
  return q;
}

/// One half of the public data, by name and folder.
struct Set {
  const char* name;
  const char* folder;
  Queries queries;
};

template <class Query>
void BM_ccd(benchmark::State& state, const std::vector<Query>* queries, ccd::Method method) {
  ccd::Options options;
  options.method = method;
  for (auto _ : state) {
    for (const Query& q : *queries) {
      if constexpr (std::is_same_v<Query, ccd::VertexFaceQuery>) {
        benchmark::DoNotOptimize(ccd::vertex_face_ccd(q, options));
      } else {
        benchmark::DoNotOptimize(ccd::edge_edge_ccd(q, options));
      }
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(queries->size()));
}

/// Records the time per iteration of each benchmark: the fastest repetition when there
/// are several (on a shared machine the least disturbed one), else the single run.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const bool single = r.run_type == Run::RT_Iteration && r.repetitions <= 1;
      const bool fastest = r.run_type == Run::RT_Aggregate && r.aggregate_name == "min";
      if (single || fastest) {
        seconds_per_iteration[r.run_name.function_name] =
            r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
      }
    }
  }
  std::map<std::string, double> seconds_per_iteration;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<Set> sets{{"simulation", "scalable-ccd-data", {}},
                        {"handcrafted", "sample-queries", {}}};
  for (Set& set : sets) {
    set.queries = load(set.folder);
    std::printf("%s queries from %s: %zu vertex-face, %zu edge-edge\n", set.name,
                set.queries.source.c_str(), set.queries.vertex_face.size(),
                set.queries.edge_edge.size());
  }
  constexpr std::array<std::pair<const char*, ccd::Method>, 3> kMethods{
      {{"double", ccd::Method::plain_double},
       {"parity", ccd::Method::parity},
       {"exact", ccd::Method::exact}}};
  auto fastest = [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); };
  for (const Set& set : sets) {
    for (const auto& [name, method] : kMethods) {
      const std::string prefix = std::string(set.name) + "/";
      benchmark::RegisterBenchmark((prefix + "vertex_face/" + name).c_str(),
                                   BM_ccd<ccd::VertexFaceQuery>, &set.queries.vertex_face, method)
          ->ComputeStatistics("min", fastest);
      benchmark::RegisterBenchmark((prefix + "edge_edge/" + name).c_str(),
                                   BM_ccd<ccd::EdgeEdgeQuery>, &set.queries.edge_edge, method)
          ->ComputeStatistics("min", fastest);
    }
  }
  // Defaults: 7 repetitions in random interleaving, so that the methods share the
  // machine's disturbances, and aggregates only.
  std::vector<char*> args(argv, argv + argc);
  std::string repetitions = "--benchmark_repetitions=7";
  std::string interleaving = "--benchmark_enable_random_interleaving=true";
  std::string aggregates = "--benchmark_report_aggregates_only=true";
  if (std::none_of(argv + 1, argv + argc, [](const char* a) {
        return std::string_view(a).starts_with("--benchmark_repetitions");
      })) {
    args.insert(args.begin() + 1, {repetitions.data(), interleaving.data(), aggregates.data()});
  }
  int arg_count = static_cast<int>(args.size());
  benchmark::Initialize(&arg_count, args.data());
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  // The targets: on the handcrafted set `exact` at most 3.0x (vertex-face) and 4.4x
  // (edge-edge) `double`, where the 2022 exact root parity code stands, and `parity` at
  // most 2x `double`; on the simulation set `exact` within 1.3x of `parity`.
  std::printf("\ntime per query, fastest repetition (same run):\n");
  std::printf("  %-24s %9s %9s %9s %13s %13s %13s\n", "set/type", "double", "parity", "exact",
              "exact/double", "parity/double", "exact/parity");
  for (const Set& set : sets) {
    for (const char* type : {"vertex_face", "edge_edge"}) {
      const std::string base = std::string(set.name) + "/" + type + "/";
      const bool vf = std::string_view(type) == "vertex_face";
      const double count =
          static_cast<double>(vf ? set.queries.vertex_face.size() : set.queries.edge_edge.size());
      auto ns = [&](const char* method) {
        const auto it = reporter.seconds_per_iteration.find(base + method);
        return it == reporter.seconds_per_iteration.end() || count == 0 ? 0.0
                                                                        : 1e9 * it->second / count;
      };
      const double plain = ns("double"), parity = ns("parity"), exact = ns("exact");
      if (plain <= 0 || parity <= 0 || exact <= 0) continue;
      const bool handcrafted = std::string_view(set.name) == "handcrafted";
      char targets[96];
      if (handcrafted) {
        std::snprintf(targets, sizeof targets,
                      "  (targets: exact/double <= %.1f, parity/double <= 2.0)", vf ? 3.0 : 4.4);
      } else {
        std::snprintf(targets, sizeof targets, "  (target: exact/parity <= 1.3)");
      }
      std::printf("  %-24s %7.1f ns %7.1f ns %7.1f ns %13.2f %13.2f %13.2f%s\n",
                  (std::string(set.name) + "/" + type).c_str(), plain, parity, exact, exact / plain,
                  parity / plain, exact / parity, targets);
    }
  }
  benchmark::Shutdown();
  return 0;
}
