// The CCD methods on the time-of-impact sample of the public benchmark (simulation
// queries), per query: `double` (root parity in plain doubles), `parity` (exact root
// parity) and `exact` (any root), each through the public ccd::*_ccd entry points. Uses
// ../shared/data/ccd/scalable-ccd-data when present next to the checkout, otherwise the
// bundled cloth-funnel slice in tests/data. Parsing is excluded from the timings. After the
// table it prints the ratios parity/double and exact/parity measured in the same run, from
// the fastest of 7 repetitions run in random interleaving (unless --benchmark_repetitions
// is given).
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
#include "exactgeo/ccd/query_files.hpp"

namespace {

namespace fs = std::filesystem;
namespace ccd = exactgeo::ccd;

struct Queries {
  std::vector<ccd::VertexFaceQuery> vertex_face;
  std::vector<ccd::EdgeEdgeQuery> edge_edge;
  std::string source;
};

Queries load() {
  Queries q;
  fs::path root = fs::path(EXACTGEO_SHARED_DATA_DIR) / "ccd/scalable-ccd-data";
  if (!fs::exists(root)) root = fs::path(EXACTGEO_TEST_DATA_DIR) / "ccd/scalable-ccd-data";
  q.source = root.string();
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".csv") continue;
    std::ifstream in(entry.path());
    const auto records = exactgeo::ccd::read_query_records(in, entry.path().string());
    const bool edge_edge = entry.path().stem().string().ends_with("ee");
    for (const auto& r : records) {
      if (edge_edge) {
        q.edge_edge.push_back(exactgeo::ccd::edge_edge_query(r));
      } else {
        q.vertex_face.push_back(exactgeo::ccd::vertex_face_query(r));
      }
    }
  }
  return q;
}

const Queries& queries() {
  static const Queries q = load();
  return q;
}

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
  std::printf("queries from %s: %zu vertex-face, %zu edge-edge\n", queries().source.c_str(),
              queries().vertex_face.size(), queries().edge_edge.size());
  constexpr std::array<std::pair<const char*, ccd::Method>, 3> kMethods{
      {{"double", ccd::Method::plain_double},
       {"parity", ccd::Method::parity},
       {"exact", ccd::Method::exact}}};
  auto fastest = [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); };
  for (const auto& [name, method] : kMethods) {
    benchmark::RegisterBenchmark((std::string("vertex_face/") + name).c_str(),
                                 BM_ccd<ccd::VertexFaceQuery>, &queries().vertex_face, method)
        ->ComputeStatistics("min", fastest);
    benchmark::RegisterBenchmark((std::string("edge_edge/") + name).c_str(),
                                 BM_ccd<ccd::EdgeEdgeQuery>, &queries().edge_edge, method)
        ->ComputeStatistics("min", fastest);
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
  std::printf("\ntime per query, fastest repetition (same run):\n");
  for (const char* type : {"vertex_face", "edge_edge"}) {
    const std::string base = std::string(type) + "/";
    const double count =
        static_cast<double>(std::string(type) == "vertex_face" ? queries().vertex_face.size()
                                                               : queries().edge_edge.size());
    auto ns = [&](const char* method) {
      return 1e9 * reporter.seconds_per_iteration[base + method] / count;
    };
    const double plain = ns("double");
    const double parity = ns("parity");
    const double exact = ns("exact");
    if (plain > 0 && parity > 0) {
      std::printf(
          "  %-12s double %7.1f ns  parity %7.1f ns  exact %7.1f ns  "
          "parity/double %5.2f  exact/parity %5.2f\n",
          type, plain, parity, exact, parity / plain, exact / parity);
    }
  }
  benchmark::Shutdown();
  return 0;
}
