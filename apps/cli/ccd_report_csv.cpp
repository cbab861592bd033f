#include "cli/ccd_report.hpp"

#include <cmath>
#include <sstream>
#include <string_view>

#include "cli/json.hpp"

namespace exactgeo::cli {

namespace {

std::string_view type_name(ccd::QueryType t) {
  return t == ccd::QueryType::vertex_face ? "vf" : "ee";
}

}  // namespace

std::string ccd_per_query_csv(const std::vector<ccd::QueryFile>& files, const CcdRun& run) {
  std::ostringstream out;
  out << "path,index,type,result,truth,decided_by,ns,toi_start,toi_end\n";
  for (std::size_t f = 0; f < files.size(); ++f) {
    for (std::size_t i = 0; i < run.results[f].size(); ++i) {
      const ccd::Result& r = run.results[f][i];
      const auto truth = files[f].records[i].truth;
      out << files[f].path << "," << i << "," << type_name(files[f].type) << "," << r.collision
          << "," << (truth ? (*truth ? "1" : "0") : "") << "," << ccd::to_string(r.decided_by)
          << "," << std::llround(run.query_ns[f][i]) << ",";
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

}  // namespace exactgeo::cli
