#include "exactgeo/ccd/files/query_files.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/predicates/kernel/rational.hpp"

namespace exactgeo::ccd {

using io::InputError;

namespace {

/// An optionally signed decimal integer of any length.
std::optional<mpz_class> parse_integer(std::string_view text) {
  std::string_view digits = text;
  if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.remove_prefix(1);
  if (digits.empty() || digits.size() > 100000) return std::nullopt;
  for (const char c : digits) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  }
  mpz_class z;
  if (z.set_str(std::string(digits), 10) != 0) return std::nullopt;
  if (text[0] == '-') z = -z;
  return z;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
    s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

/// "'num/den'" for messages, each part cut to 40 characters. (Built by appending: GCC 12
/// warns falsely about chained string concatenation here.)
std::string quoted_ratio(std::string_view numerator, std::string_view denominator) {
  std::string s = "'";
  s.append(numerator.substr(0, 40));
  s.append("/");
  s.append(denominator.substr(0, 40));
  s.append("'");
  return s;
}

}  // namespace

std::optional<double> exact_ratio(std::string_view numerator, std::string_view denominator,
                                  std::string& error) {
  const auto num = parse_integer(numerator);
  const auto den = parse_integer(denominator);
  if (!num || !den) {
    error = quoted_ratio(numerator, denominator) + " is not a ratio of integers";
    return std::nullopt;
  }
  if (sgn(*den) == 0) {
    error = "zero denominator";
    return std::nullopt;
  }
  const kernel::Rational q(mpq_class(*num, *den));
  // A zero keeps the sign of the quotient as written ("-0/1", "0/-1": -0), as a double
  // division would; the rational has none.
  if (q.is_zero()) return (numerator[0] == '-') != (denominator[0] == '-') ? -0.0 : 0.0;
  // The value is a double iff the double toward zero from it is the value.
  const double x = q.toward_zero();
  if (!std::isfinite(x) || kernel::Rational(x) != q) {
    error = quoted_ratio(numerator, denominator) + " is not exactly a finite double";
    return std::nullopt;
  }
  return x;
}

std::vector<QueryRecord> read_query_records(std::istream& in, const std::string& source) {
  std::vector<QueryRecord> records;
  std::string line;
  std::size_t line_number = 0;
  std::size_t row = 0;  // within the current query
  std::size_t columns = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (trim(line).empty()) continue;
    const std::vector<std::string_view> fields = split_commas(line);
    if (fields.size() != 6 && fields.size() != 7) {
      throw InputError(
          source, line_number,
          "expected 6 or 7 comma-separated fields, found " + std::to_string(fields.size()));
    }
    if (columns == 0) columns = fields.size();
    if (fields.size() != columns) {
      throw InputError(source, line_number,
                       "expected " + std::to_string(columns) +
                           " fields like the first row, found " + std::to_string(fields.size()));
    }
    if (row == 0) records.emplace_back();
    QueryRecord& record = records.back();
    for (int axis = 0; axis < 3; ++axis) {
      std::string error;
      const auto x = exact_ratio(fields[2 * axis], fields[2 * axis + 1], error);
      if (!x) throw InputError(source, line_number, error);
      record.points[row][axis] = *x;
    }
    if (columns == 7) {
      if (fields[6] != "0" && fields[6] != "1") {
        throw InputError(source, line_number, "ground truth must be 0 or 1");
      }
      const bool truth = fields[6] == "1";
      if (row == 0) {
        record.truth = truth;
      } else if (*record.truth != truth) {
        throw InputError(source, line_number, "ground truth differs between rows of one query");
      }
    }
    row = (row + 1) % 8;
  }
  if (in.bad()) throw InputError(source + ": read error");
  if (row != 0) {
    throw InputError(source, line_number,
                     "the last query has " + std::to_string(row) + " rows, not 8");
  }
  return records;
}

std::vector<bool> read_truth_array(std::istream& in, const std::string& source) {
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<bool> truth;
  std::size_t i = 0;
  auto skip_space = [&] {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
      ++i;
  };
  auto fail = [&](const std::string& what) {
    throw InputError(source + ": " + what + " at byte " + std::to_string(i));
  };
  skip_space();
  if (i >= text.size() || text[i] != '[') fail("expected '['");
  ++i;
  skip_space();
  if (i < text.size() && text[i] == ']') return truth;
  while (true) {
    skip_space();
    if (text.compare(i, 4, "true") == 0) {
      truth.push_back(true);
      i += 4;
    } else if (text.compare(i, 5, "false") == 0) {
      truth.push_back(false);
      i += 5;
    } else {
      fail("expected true or false");
    }
    skip_space();
    if (i < text.size() && text[i] == ',') {
      ++i;
      continue;
    }
    if (i < text.size() && text[i] == ']') break;
    fail("expected ',' or ']'");
  }
  ++i;
  skip_space();
  if (i != text.size()) fail("unexpected text after the array");
  return truth;
}

namespace {

namespace fs = std::filesystem;

std::vector<std::string> csv_files(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& p : paths) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::recursive_directory_iterator(p, ec)) {
        if (entry.is_regular_file() && entry.path().extension() == ".csv") {
          found.push_back(entry.path().string());
        }
      }
      if (ec) throw InputError("cannot read directory '" + p + "': " + ec.message());
      std::sort(found.begin(), found.end());  // deterministic order
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(p, ec)) {
      files.push_back(p);
    } else {
      throw InputError("'" + p + "' is neither a file nor a directory");
    }
  }
  if (files.empty()) throw InputError("no *.csv query files under the given paths");
  return files;
}

std::vector<bool> read_truth_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open ground truth '" + path + "'");
  return read_truth_array(in, path);
}

std::string type_description(QueryType t) {
  return t == QueryType::vertex_face ? "vertex-face" : "edge-edge";
}

QueryFile read_query_file(const std::string& path, std::optional<QueryType> forced_type,
                          const std::string& truth_file) {
  const std::optional<QueryType> path_type = query_type_of(path);
  if (forced_type && path_type && *forced_type != *path_type) {
    throw InputError("'" + path + "' holds " + type_description(*path_type) +
                     " queries by its path, not " + type_description(*forced_type) +
                     " ones as the type given says");
  }
  const std::optional<QueryType> type = forced_type ? forced_type : path_type;
  if (!type) {
    throw InputError("cannot tell the query type of '" + path +
                     "' (no vertex-face/edge-edge folder, no vf/ee stem): use --type");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open '" + path + "'");
  QueryFile file{path, *type, read_query_records(in, path)};
  const bool inline_truth = !file.records.empty() && file.records.front().truth.has_value();
  if (inline_truth && !truth_file.empty()) {
    throw InputError("'" + path + "' has its own truth column; a truth file ('" + truth_file +
                     "') is for 6-column files");
  }
  if (inline_truth || file.records.empty()) return file;
  std::string truth_path = truth_file;
  if (truth_path.empty()) {
    const fs::path p(path);
    const fs::path published =
        p.parent_path() / ".." / "mma_bool" / (p.stem().string() + "_mma_bool.json");
    std::error_code ec;
    if (fs::is_regular_file(published, ec)) truth_path = published.string();
  }
  if (truth_path.empty()) return file;
  const std::vector<bool> truth = read_truth_file(truth_path);
  if (truth.size() != file.records.size()) {
    throw InputError("'" + truth_path + "' has " + std::to_string(truth.size()) + " entries but '" +
                     path + "' has " + std::to_string(file.records.size()) + " queries");
  }
  for (std::size_t i = 0; i < truth.size(); ++i)
    file.records[i].truth = truth[i];
  return file;
}

}  // namespace

std::optional<QueryType> query_type_of(const std::string& path) {
  const fs::path p(path);
  for (const auto& component : p.parent_path()) {
    if (component == "vertex-face") return QueryType::vertex_face;
    if (component == "edge-edge") return QueryType::edge_edge;
  }
  const std::string stem = p.stem().string();
  auto ends_with = [&](std::string_view s) {
    return stem.size() >= s.size() && stem.compare(stem.size() - s.size(), s.size(), s) == 0;
  };
  if (ends_with("vf")) return QueryType::vertex_face;
  if (ends_with("ee")) return QueryType::edge_edge;
  return std::nullopt;
}

std::vector<QueryFile> read_query_files(const std::vector<std::string>& paths,
                                        std::optional<QueryType> type,
                                        const std::string& truth_file) {
  std::vector<QueryFile> files;
  for (const std::string& path : csv_files(paths))
    files.push_back(read_query_file(path, type, truth_file));
  return files;
}

VertexFaceQuery vertex_face_query(const QueryRecord& r) noexcept {
  const auto& p = r.points;
  return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
}

EdgeEdgeQuery edge_edge_query(const QueryRecord& r) noexcept {
  const auto& p = r.points;
  return {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7]};
}

}  // namespace exactgeo::ccd
