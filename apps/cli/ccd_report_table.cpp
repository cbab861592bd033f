#include "cli/ccd_report.hpp"

#include <cstdint>
#include <iomanip>
#include <ostream>
#include <string>
#include <string_view>

#include "cli/json.hpp"

namespace exactgeo::cli {

void write_ccd_table(std::ostream& out, const ccd::Options& options, const CcdRun& run) {
  out << "method " << ccd::to_string(options.method);
  if (options.min_separation > 0.0) out << ", min separation " << shortest(options.min_separation);
  out << "\n";
  out << std::left << std::setw(12) << "type" << std::right << std::setw(10) << "queries"
      << std::setw(11) << "positives" << std::setw(11) << "truth_pos" << std::setw(11)
      << "false_pos" << std::setw(11) << "false_neg" << std::setw(12) << "ns/query"
      << "\n";
  auto row = [&](std::string_view name, const QueryTally& t) {
    auto n = [&](std::uint64_t x) {
      return t.with_truth == 0 ? std::string("-") : std::to_string(x);
    };
    out << std::left << std::setw(12) << name << std::right << std::setw(10) << t.queries
        << std::setw(11) << t.positives << std::setw(11) << n(t.truth_positives) << std::setw(11)
        << n(t.false_positives) << std::setw(11) << n(t.false_negatives) << std::setw(12)
        << std::fixed << std::setprecision(1) << t.ns_per_query() << std::defaultfloat << "\n";
  };
  row("vertex-face", run.vertex_face);
  row("edge-edge", run.edge_edge);
  row("total", run.total);
  out << "decided by:";
  for (const ccd::DecidedBy decided_by : kDecidedByOrder) {
    const std::uint64_t count = run.total.decided_by[static_cast<std::size_t>(decided_by)];
    if (count) out << " " << ccd::to_string(decided_by) << " " << count;
  }
  out << "\n";
}

}  // namespace exactgeo::cli
