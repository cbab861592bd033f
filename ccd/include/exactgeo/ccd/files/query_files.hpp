#pragma once

// Reading CCD queries in the public benchmark's CSV format (Wang et al. 2021; Belgrod et
// al. 2023): 8 rows per query, each row `x_num,x_den,y_num,y_den,z_num,z_den[,gt]`.
// Numerators and denominators are integers of any size (read with GMP), and every
// coordinate must be exactly a double: the benchmark's denominators are powers of two. A
// coordinate that is not exactly representable is an error, never silently rounded.
//
// Row order, vertex-face: v_t0, f0_t0, f1_t0, f2_t0, v_t1, f0_t1, f1_t1, f2_t1;
// edge-edge: ea0_t0, ea1_t0, eb0_t0, eb1_t0, ea0_t1, ea1_t1, eb0_t1, eb1_t1.

#include <array>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "exactgeo/ccd/queries.hpp"
#include "exactgeo/io/input_error.hpp"

namespace exactgeo::ccd {

/// One query's eight points in file order, and its ground truth when the file has it.
struct QueryRecord {
  std::array<Point3, 8> points;
  std::optional<bool> truth;
};

/// num / den as a double, or nullopt with `error` set: not integers, zero denominator, or
/// a value that is not exactly a finite double.
std::optional<double> exact_ratio(std::string_view numerator, std::string_view denominator,
                                  std::string& error);

/// All queries of one file. Throws io::InputError naming source and line.
std::vector<QueryRecord> read_query_records(std::istream& in, const std::string& source);

/// A `[true, false, ...]` ground-truth array. Throws io::InputError.
std::vector<bool> read_truth_array(std::istream& in, const std::string& source);

enum class QueryType { vertex_face, edge_edge };

/// The query type named by a path: a component `vertex-face` / `edge-edge`, else a file
/// stem ending in `vf` / `ee`.
std::optional<QueryType> query_type_of(const std::string& path);

/// One query file, read and validated, with ground truth when any is known.
struct QueryFile {
  std::string path;
  QueryType type;
  std::vector<QueryRecord> records;
};

/// Every file of `paths`, and every `*.csv` under its directories (sorted), in order. The
/// type is what the path says, else `type`; a `type` that contradicts the path is an
/// error. Ground truth is the 7th column, else `truth_file` when given (an error for a
/// file with the 7th column), else the published layout
/// `<dir>/../mma_bool/<stem>_mma_bool.json` when it exists. Throws io::InputError.
std::vector<QueryFile> read_query_files(const std::vector<std::string>& paths,
                                        std::optional<QueryType> type = std::nullopt,
                                        const std::string& truth_file = {});

VertexFaceQuery vertex_face_query(const QueryRecord& record) noexcept;
EdgeEdgeQuery edge_edge_query(const QueryRecord& record) noexcept;

}  // namespace exactgeo::ccd
