// Root parity CCD, exact vs the same algorithm with plain double signs, per query, on the
// time-of-impact sample of the public benchmark (simulation queries). Uses
// ../shared/data/ccd/scalable-ccd-data when present next to the checkout, otherwise the
// bundled cloth-funnel slice in tests/data. Parsing is excluded from the timings. After the
// table it prints exact/double ratios measured in the same run.
//
//   build/bin/ccd_benchmark [--benchmark_min_time=0.5]

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include "cli/ccd_queries.hpp"
#include "exactgeo/ccd/root_parity.hpp"

namespace {

namespace fs = std::filesystem;
using exactgeo::Arithmetic;

struct Queries {
  std::vector<exactgeo::ccd::VertexFaceQuery> vertex_face;
  std::vector<exactgeo::ccd::EdgeEdgeQuery> edge_edge;
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
    const auto records = exactgeo::cli::read_ccd_records(in, entry.path().string());
    const bool edge_edge = entry.path().stem().string().ends_with("ee");
    for (const auto& r : records) {
      if (edge_edge) {
        q.edge_edge.push_back(exactgeo::cli::edge_edge_query(r));
      } else {
        q.vertex_face.push_back(exactgeo::cli::vertex_face_query(r));
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
void BM_parity(benchmark::State& state, const std::vector<Query>* queries, Arithmetic arithmetic) {
  for (auto _ : state) {
    for (const Query& q : *queries) {
      if constexpr (std::is_same_v<Query, exactgeo::ccd::VertexFaceQuery>) {
        benchmark::DoNotOptimize(exactgeo::ccd::vertex_face_root_parity(q, arithmetic));
      } else {
        benchmark::DoNotOptimize(exactgeo::ccd::edge_edge_root_parity(q, arithmetic));
      }
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(queries->size()));
}

class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const auto items = r.counters.find("items_per_second");
      if (r.run_type == Run::RT_Iteration && items != r.counters.end() && items->second.value > 0) {
        ns_per_query[r.benchmark_name()] = 1e9 / items->second.value;
      }
    }
  }
  std::map<std::string, double> ns_per_query;
};

}  // namespace

int main(int argc, char** argv) {
  std::printf("queries from %s: %zu vertex-face, %zu edge-edge\n", queries().source.c_str(),
              queries().vertex_face.size(), queries().edge_edge.size());
  for (const auto& [name, arithmetic] :
       {std::pair{"double", Arithmetic::plain_double}, std::pair{"exact", Arithmetic::exact}}) {
    benchmark::RegisterBenchmark((std::string("parity/vertex_face/") + name).c_str(),
                                 BM_parity<exactgeo::ccd::VertexFaceQuery>, &queries().vertex_face,
                                 arithmetic);
    benchmark::RegisterBenchmark((std::string("parity/edge_edge/") + name).c_str(),
                                 BM_parity<exactgeo::ccd::EdgeEdgeQuery>, &queries().edge_edge,
                                 arithmetic);
  }
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nroot parity, time per query (same run):\n");
  for (const char* type : {"vertex_face", "edge_edge"}) {
    const std::string base = std::string("parity/") + type + "/";
    const double plain = reporter.ns_per_query[base + "double"];
    const double exact = reporter.ns_per_query[base + "exact"];
    if (plain > 0) {
      std::printf("  %-12s double %7.1f ns  exact %7.1f ns  ratio %5.2f\n", type, plain, exact,
                  exact / plain);
    }
  }
  benchmark::Shutdown();
  return 0;
}
