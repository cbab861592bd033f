#include "cli/ccd_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <optional>
#include <ostream>
#include <sstream>
#include <vector>

#include "cli/json.hpp"
#include "cli/number_option.hpp"
#include "cli/output_file.hpp"
#include "cli/progress_line.hpp"
#include "cli/seconds.hpp"
#include "exactgeo/ccd/files/query_files.hpp"
#include "exactgeo/io/input_error.hpp"

namespace exactgeo::cli {

using ccd::edge_edge_query;
using ccd::QueryFile;
using ccd::QueryRecord;
using ccd::QueryType;
using ccd::read_query_files;
using ccd::vertex_face_query;
using io::InputError;

namespace {

/// Every stage, in the order of the reports. The tallies index by a stage's value: one
/// slot for each.
constexpr std::array kStages{
    ccd::DecidedBy::culled,      ccd::DecidedBy::parity,           ccd::DecidedBy::polynomials,
    ccd::DecidedBy::subdivision, ccd::DecidedBy::depth_limit,      ccd::DecidedBy::cubic,
    ccd::DecidedBy::separation,  ccd::DecidedBy::separation_roots, ccd::DecidedBy::box_test};
static_assert(static_cast<std::size_t>(ccd::DecidedBy::box_test) + 1 == kStages.size());

/// Counts for one query type, or for all.
struct Tally {
  std::uint64_t queries = 0;
  std::uint64_t positives = 0;
  std::uint64_t with_truth = 0;
  std::uint64_t truth_positives = 0;
  std::uint64_t false_positives = 0;
  std::uint64_t false_negatives = 0;
  double seconds = 0.0;
  std::array<std::uint64_t, kStages.size()> stages{};

  void add(const Tally& o) {
    queries += o.queries;
    positives += o.positives;
    with_truth += o.with_truth;
    truth_positives += o.truth_positives;
    false_positives += o.false_positives;
    false_negatives += o.false_negatives;
    seconds += o.seconds;
    for (std::size_t s = 0; s < stages.size(); ++s)
      stages[s] += o.stages[s];
  }
  double ns_per_query() const {
    return queries == 0 ? 0.0 : seconds * 1e9 / static_cast<double>(queries);
  }
};

std::string_view type_name(QueryType t) {
  return t == QueryType::vertex_face ? "vf" : "ee";
}

/// Runs every query of the file `repeat` times; `seconds` is the fastest pass (on a shared
/// machine the least disturbed one). The answers do not depend on the pass. With
/// `query_ns`, one more pass times each query on its own (each time then includes one
/// reading of the clock, about 20-30 ns here), for the distribution of query times.
template <class Query, class Make, class Run>
std::vector<ccd::Result> run_timed(const QueryFile& file, Make make, Run run, int repeat,
                                   double& seconds, std::vector<double>* query_ns) {
  std::vector<Query> queries;
  queries.reserve(file.records.size());
  for (const QueryRecord& r : file.records)
    queries.push_back(make(r));
  std::vector<ccd::Result> results(queries.size());
  for (int pass = 0; pass < repeat; ++pass) {
    const Clock::time_point start = Clock::now();
    for (std::size_t i = 0; i < queries.size(); ++i)
      results[i] = run(queries[i]);
    const double elapsed = seconds_since(start);
    seconds = pass == 0 ? elapsed : std::min(seconds, elapsed);
  }
  if (query_ns != nullptr) {
    query_ns->resize(queries.size());
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Clock::time_point start = Clock::now();
      results[i] = run(queries[i]);
      (*query_ns)[i] = 1e9 * seconds_since(start);
    }
  }
  return results;
}

std::vector<ccd::Result> run_file(const QueryFile& file, const ccd::Options& options, int repeat,
                                  double& seconds, std::vector<double>* query_ns) {
  if (file.type == QueryType::vertex_face) {
    return run_timed<ccd::VertexFaceQuery>(
        file, vertex_face_query,
        [&](const ccd::VertexFaceQuery& q) { return ccd::vertex_face_ccd(q, options); }, repeat,
        seconds, query_ns);
  }
  return run_timed<ccd::EdgeEdgeQuery>(
      file, edge_edge_query,
      [&](const ccd::EdgeEdgeQuery& q) { return ccd::edge_edge_ccd(q, options); }, repeat, seconds,
      query_ns);
}

Tally tally(const QueryFile& file, const std::vector<ccd::Result>& results, double seconds) {
  Tally t;
  t.queries = results.size();
  t.seconds = seconds;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const bool hit = results[i].collision;
    t.positives += hit;
    ++t.stages[static_cast<std::size_t>(results[i].decided_by)];
    if (const auto truth = file.records[i].truth) {
      ++t.with_truth;
      t.truth_positives += *truth;
      t.false_positives += hit && !*truth;
      t.false_negatives += !hit && *truth;
    }
  }
  return t;
}

/// The nearest-rank p-quantile of `sorted` (ascending, not empty).
double quantile(const std::vector<double>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[std::max<std::size_t>(rank, 1) - 1];
}

/// {"queries": n, "median": .., "p99": .., "max": ..} of the times (ns), or null.
void write_distribution(std::ostream& out, std::vector<double> ns) {
  if (ns.empty()) {
    out << "null";
    return;
  }
  std::sort(ns.begin(), ns.end());
  out << "{\"queries\": " << ns.size() << std::fixed << std::setprecision(0)
      << ", \"median\": " << quantile(ns, 0.5) << ", \"p99\": " << quantile(ns, 0.99)
      << ", \"max\": " << ns.back() << std::defaultfloat << "}";
}

/// What one run produced: per file, every query's result and own time (the per-query pass).
struct RunResults {
  const std::vector<QueryFile>& files;
  std::vector<std::vector<ccd::Result>> results;
  std::vector<std::vector<double>> query_ns;
};

/// The per-query times of the files of `type` (all files when none): all of them, and by
/// the stage that decided each query.
void write_query_times(std::ostream& out, const RunResults& run, std::optional<QueryType> type) {
  std::vector<double> all;
  std::array<std::vector<double>, kStages.size()> by_stage;
  for (std::size_t f = 0; f < run.files.size(); ++f) {
    if (type && run.files[f].type != *type) continue;
    for (std::size_t i = 0; i < run.query_ns[f].size(); ++i) {
      all.push_back(run.query_ns[f][i]);
      by_stage[static_cast<std::size_t>(run.results[f][i].decided_by)].push_back(
          run.query_ns[f][i]);
    }
  }
  out << ", \"query_ns\": {\"all\": ";
  write_distribution(out, std::move(all));
  for (const ccd::DecidedBy stage : kStages) {
    std::vector<double>& ns = by_stage[static_cast<std::size_t>(stage)];
    if (ns.empty()) continue;
    out << ", " << json_string(ccd::to_string(stage)) << ": ";
    write_distribution(out, std::move(ns));
  }
  out << "}";
}

void write_json_counts(std::ostream& out, const Tally& t, const RunResults& run,
                       std::optional<QueryType> type) {
  auto errors = [&](std::uint64_t n) {
    return t.with_truth == 0 ? std::string("null") : std::to_string(n);
  };
  out << "\"queries\": " << t.queries << ", \"positives\": " << t.positives
      << ", \"truth_positives\": " << errors(t.truth_positives)
      << ", \"false_positives\": " << errors(t.false_positives)
      << ", \"false_negatives\": " << errors(t.false_negatives)
      << ", \"ns_per_query\": " << std::fixed << std::setprecision(1) << t.ns_per_query()
      << std::defaultfloat << ", \"stages\": {";
  for (std::size_t s = 0; s < kStages.size(); ++s) {
    out << (s ? ", " : "") << json_string(ccd::to_string(kStages[s])) << ": "
        << t.stages[static_cast<std::size_t>(kStages[s])];
  }
  out << "}";
  write_query_times(out, run, type);
}

void write_json(std::ostream& out, const ccd::Options& options, const Tally& vf, const Tally& ee,
                const Tally& all, const RunResults& run) {
  out << "{\"method\": " << json_string(ccd::to_string(options.method))
      << ", \"min_separation\": " << shortest(options.min_separation) << ", ";
  write_json_counts(out, all, run, std::nullopt);
  out << ", \"vertex_face\": {";
  write_json_counts(out, vf, run, QueryType::vertex_face);
  out << "}, \"edge_edge\": {";
  write_json_counts(out, ee, run, QueryType::edge_edge);
  out << "}}\n";
}

void write_table(std::ostream& out, const ccd::Options& options, const Tally& vf, const Tally& ee,
                 const Tally& all) {
  out << "method " << ccd::to_string(options.method);
  if (options.min_separation > 0.0) out << ", min separation " << shortest(options.min_separation);
  out << "\n";
  out << std::left << std::setw(12) << "type" << std::right << std::setw(10) << "queries"
      << std::setw(11) << "positives" << std::setw(11) << "truth_pos" << std::setw(11)
      << "false_pos" << std::setw(11) << "false_neg" << std::setw(12) << "ns/query"
      << "\n";
  auto row = [&](std::string_view name, const Tally& t) {
    auto n = [&](std::uint64_t x) {
      return t.with_truth == 0 ? std::string("-") : std::to_string(x);
    };
    out << std::left << std::setw(12) << name << std::right << std::setw(10) << t.queries
        << std::setw(11) << t.positives << std::setw(11) << n(t.truth_positives) << std::setw(11)
        << n(t.false_positives) << std::setw(11) << n(t.false_negatives) << std::setw(12)
        << std::fixed << std::setprecision(1) << t.ns_per_query() << std::defaultfloat << "\n";
  };
  row("vertex-face", vf);
  row("edge-edge", ee);
  row("total", all);
  out << "decided by:";
  for (std::size_t s = 0; s < kStages.size(); ++s) {
    const std::uint64_t count = all.stages[static_cast<std::size_t>(kStages[s])];
    if (count) out << " " << ccd::to_string(kStages[s]) << " " << count;
  }
  out << "\n";
}

/// The per-query CSV: one line per query, in file order.
std::string per_query_csv(const RunResults& run) {
  const std::vector<QueryFile>& files = run.files;
  const auto& results = run.results;
  const auto& query_ns = run.query_ns;
  std::ostringstream out;
  out << "path,index,type,result,truth,decided_by,ns,toi_start,toi_end\n";
  for (std::size_t f = 0; f < files.size(); ++f) {
    for (std::size_t i = 0; i < results[f].size(); ++i) {
      const ccd::Result& r = results[f][i];
      const auto truth = files[f].records[i].truth;
      out << files[f].path << "," << i << "," << type_name(files[f].type) << "," << r.collision
          << "," << (truth ? (*truth ? "1" : "0") : "") << "," << ccd::to_string(r.decided_by)
          << "," << std::llround(query_ns[f][i]) << ",";
      if (r.time_of_impact) {
        out << shortest(r.time_of_impact->start) << "," << shortest(r.time_of_impact->end);
      } else {
        out << ",";
      }
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace

ExitCode run_ccd(const CcdCommandOptions& given, std::ostream& out, std::ostream& err) {
  CcdCommandOptions options = given;
  if (options.min_separation) {
    std::string error;
    const auto delta = parse_min_separation(*options.min_separation, error);
    if (!delta) {
      err << "exactgeo ccd: --min-separation must be a finite number >= 0: " << error << "\n";
      return ExitCode::input_error;
    }
    const ccd::Method m = options.ccd.method;
    if (*delta > 0.0 && m != ccd::Method::exact && m != ccd::Method::plain_double) {
      err << "exactgeo ccd: --min-separation needs --method exact (or double: the per-axis "
             "box test in plain doubles)\n";
      return ExitCode::input_error;
    }
    options.ccd.min_separation = *delta;
  }
  if (options.ccd.time_of_impact_width && options.ccd.method != ccd::Method::exact) {
    err << "exactgeo ccd: --toi-width needs --method exact (the other methods only say "
           "whether a query collides)\n";
    return ExitCode::input_error;
  }
  std::vector<QueryFile> files;
  try {
    files = read_query_files(options.paths, options.type, options.truth);
  } catch (const InputError& e) {
    err << "exactgeo ccd: " << e.what() << "\n";
    return ExitCode::input_error;
  }
  // The files' ground truth is about contact (δ = 0); at a larger δ it does not apply.
  if (options.ccd.min_separation > 0.0) {
    for (QueryFile& f : files) {
      for (QueryRecord& r : f.records)
        r.truth.reset();
    }
  }
  std::size_t total = 0;
  for (const QueryFile& f : files)
    total += f.records.size();
  if (total == 0) {
    err << "exactgeo ccd: no queries in the " << files.size()
        << (files.size() == 1 ? " file read\n" : " files read\n");
    return ExitCode::input_error;
  }

  // The CSV file is reserved before the run, so an unwritable path fails at once; it is
  // written whole or not at all.
  std::optional<OutputFile> per_query_file;
  try {
    if (!options.per_query.empty()) per_query_file.emplace(options.per_query);
  } catch (const OutputFileError& e) {
    err << "exactgeo ccd: --per-query: " << e.what() << "\n";
    return ExitCode::input_error;
  }

  Tally vf;
  Tally ee;
  RunResults run{files, {}, {}};
  const bool time_each = options.json || !options.per_query.empty();
  std::size_t done = 0;
  ProgressLine progress(err, options.progress, "queries");
  for (const QueryFile& file : files) {
    double seconds = 0.0;
    run.query_ns.emplace_back();
    run.results.push_back(run_file(file, options.ccd, options.repeat, seconds,
                                   time_each ? &run.query_ns.back() : nullptr));
    (file.type == QueryType::vertex_face ? vf : ee).add(tally(file, run.results.back(), seconds));
    done += file.records.size();
    progress.count(done, total);
  }
  progress.clear();
  if (per_query_file) {
    try {
      per_query_file->commit(per_query_csv(run));
    } catch (const OutputFileError& e) {
      err << "exactgeo ccd: --per-query: " << e.what() << "\n";
      return ExitCode::input_error;
    }
  }
  Tally all;
  all.add(vf);
  all.add(ee);
  if (options.json) {
    write_json(out, options.ccd, vf, ee, all, run);
  } else {
    write_table(out, options.ccd, vf, ee, all);
  }
  return all.false_negatives > 0 ? ExitCode::found : ExitCode::success;
}

CLI::App& add_ccd_command(CLI::App& app, CcdCommandOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "ccd",
      "Run CCD queries in the public benchmark CSV format (files, or directories searched "
      "for *.csv) and report results, false positives/negatives against ground truth and "
      "time per query (with --json also the median, 99th percentile and maximum of each "
      "query's own time, in all and by deciding stage). Exit code 1 when a false negative "
      "is found.");
  sub->add_option("paths", options.paths, "query files or directories")->required();
  sub->add_option_function<std::string>(
         "--method",
         [&options](const std::string& m) { options.ccd.method = *ccd::parse_method(m); },
         "exact (default: any root, exactly), parity (the 2012 root parity algorithm), double "
         "(parity in plain doubles), rational (parity in GMP rationals), cubic (coplanarity "
         "cubic with --tolerance)")
      ->check(CLI::IsMember({"exact", "parity", "double", "rational", "cubic"}));
  sub->add_option_function<std::string>(
         "--type",
         [&options](const std::string& t) {
           options.type = t == "vf" ? QueryType::vertex_face : QueryType::edge_edge;
         },
         "vf or ee: the query type of files whose path does not say it (a folder vertex-face or "
         "edge-edge, a stem ending in vf or ee); a type that contradicts the path is refused")
      ->check(CLI::IsMember({"vf", "ee"}));
  sub->add_option("--truth", options.truth,
                  "ground truth JSON array for 6-column files (default: "
                  "<dir>/../mma_bool/<stem>_mma_bool.json when present); refused for files "
                  "with their own truth column");
  sub->add_option("--per-query", options.per_query,
                  "write path,index,type,result,truth,decided_by,ns,toi_start,toi_end for "
                  "every query to this CSV file");
  sub->add_option("--tolerance", options.ccd.cubic_tolerance,
                  "cubic only: distance tolerance (default 1e-6)")
      ->check(CLI::Validator(
          [](std::string& text) {
            std::string error;
            const auto value = number_option(text, error);
            if (!value) return "expected a positive number: " + error;
            return *value > 0.0 ? std::string() : "expected a positive number, got '" + text + "'";
          },
          "POSITIVE"));
  sub->add_option_function<double>(
         "--toi-width", [&options](double w) { options.ccd.time_of_impact_width = w; },
         "exact only: also bracket each colliding query's earliest contact to at most this "
         "width (--per-query writes the brackets)")
      ->check(CLI::Range(0x1p-60, 1.0));
  sub->add_option("--min-separation", options.min_separation,
                  "a collision is a time at which the primitives' Euclidean distance is at "
                  "most this (default 0: contact), exactly; with --method double the per-axis "
                  "box test of Tight Inclusion's minimum-separation mode instead, in plain "
                  "doubles; the files' ground truth, about contact, is then not compared");
  sub->add_option("--max-depth", options.ccd.max_depth,
                  "exact only: most halvings of the time step (default 64)")
      ->check(CLI::Range(0, 200));
  sub->add_option("--repeat", options.repeat,
                  "time every file this many times and report the fastest pass (default 1)")
      ->check(CLI::Range(1, 1000));
  sub->add_flag("--json", options.json, "print one JSON object instead of the table");
  return *sub;
}

}  // namespace exactgeo::cli
