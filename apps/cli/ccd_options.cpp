#include "cli/ccd_options.hpp"

#include <CLI/CLI.hpp>

#include <ostream>
#include <string>

#include "cli/ccd_method_option.hpp"
#include "cli/number_option.hpp"
#include "cli/progress_option.hpp"

namespace exactgeo::cli {

std::optional<ccd::Options> checked_ccd_options(const CcdCommandOptions& options,
                                                std::ostream& err) {
  ccd::Options checked = options.ccd;
  if (options.min_separation) {
    std::string error;
    const auto delta = parse_min_separation(*options.min_separation, error);
    if (!delta) {
      err << "exactgeo ccd: --min-separation must be a finite number >= 0: " << error << "\n";
      return std::nullopt;
    }
    const ccd::Method m = checked.method;
    if (*delta > 0.0 && m != ccd::Method::exact && m != ccd::Method::plain_double) {
      err << "exactgeo ccd: --min-separation needs --method exact (or double: the per-axis "
             "box test in plain doubles)\n";
      return std::nullopt;
    }
    checked.min_separation = *delta;
  }
  if (checked.time_of_impact_width && checked.method != ccd::Method::exact) {
    err << "exactgeo ccd: --toi-width needs --method exact (the other methods only say "
           "whether a query collides)\n";
    return std::nullopt;
  }
  return checked;
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
  add_progress_flag(*sub, options.progress_asked);
  add_ccd_method_option(*sub, options.ccd.method,
                        {ccd::Method::exact, ccd::Method::parity, ccd::Method::plain_double,
                         ccd::Method::rational, ccd::Method::cubic},
                        "exact (default: any root, exactly), parity (the 2012 root parity "
                        "algorithm), double (parity in plain doubles), rational (parity in GMP "
                        "rationals), cubic (coplanarity cubic with --tolerance)");
  sub->add_option_function<std::string>(
         "--type",
         [&options](const std::string& t) {
           options.type = t == "vf" ? ccd::QueryType::vertex_face : ccd::QueryType::edge_edge;
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
  add_number_option(
      *sub, "--tolerance",
      [&options](double t) -> std::optional<std::string> {
        if (!(t > 0.0)) return "expected a positive number";
        options.ccd.cubic_tolerance = t;
        return std::nullopt;
      },
      "cubic only: distance tolerance (default 1e-6)");
  add_number_option(
      *sub, "--toi-width",
      [&options](double w) -> std::optional<std::string> {
        if (!(w >= 0x1p-60 && w <= 1.0)) return "expected a width in [2^-60, 1]";
        options.ccd.time_of_impact_width = w;
        return std::nullopt;
      },
      "exact only: also bracket each colliding query's earliest contact to at most this "
      "width (--per-query writes the brackets)");
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
