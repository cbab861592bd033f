#include "cli/inside_batch.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <system_error>

#include "cli/json.hpp"
#include "cli/npy_labels.hpp"
#include "cli/output_file.hpp"
#include "exactgeo/inside/location.hpp"

namespace exactgeo::cli {

namespace fs = std::filesystem;

const std::vector<std::string> kBatchMeshExtensions{".obj", ".off", ".ply", ".stl", ".glb", ".gltf",
                                                    ".fbx", ".dae", ".3ds", ".amf", ".3mf"};

namespace {

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_mesh_file(const fs::path& path) {
  const std::string extension = lowercase(path.extension().string());
  return std::find(kBatchMeshExtensions.begin(), kBatchMeshExtensions.end(), extension) !=
         kBatchMeshExtensions.end();
}

/// `relative` (a mesh's path below the folder or list) with its extension replaced.
std::string labels_file(const fs::path& output_dir, fs::path relative, BatchLabelsFormat format) {
  relative.replace_extension();
  return (output_dir / relative).string() +
         (format == BatchLabelsFormat::npy ? ".labels.npy" : ".labels.txt");
}

/// The labels run_inside printed, one word a line (labels only: it printed nothing else).
std::vector<inside::Location> labels_of(const std::string& text) {
  std::vector<inside::Location> labels;
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string::npos;
       start = end + 1, end = text.find('\n', start)) {
    labels.push_back(
        inside::location_named(std::string_view(text).substr(start, end - start)).value());
  }
  return labels;
}

}  // namespace

std::optional<std::vector<BatchMesh>> batch_meshes(const std::string& given,
                                                   const std::string& output_dir,
                                                   BatchLabelsFormat format, std::string& error) {
  std::vector<BatchMesh> meshes;
  std::error_code failed;
  if (fs::is_directory(given, failed)) {
    std::vector<fs::path> found;
    for (auto it = fs::recursive_directory_iterator(given, failed);
         !failed && it != fs::recursive_directory_iterator(); it.increment(failed)) {
      if (it->is_regular_file(failed) && is_mesh_file(it->path())) found.push_back(it->path());
    }
    if (failed) {
      error = given + ": cannot read this folder: " + failed.message();
      return std::nullopt;
    }
    std::sort(found.begin(), found.end());
    for (const fs::path& path : found)
      meshes.push_back(
          {path.string(), labels_file(output_dir, path.lexically_relative(given), format)});
    if (meshes.empty()) {
      error = given + ": no mesh file in this folder or below it (extensions:";
      for (const std::string& e : kBatchMeshExtensions)
        error += " " + e;
      error += ")";
      return std::nullopt;
    }
  } else if (lowercase(fs::path(given).extension().string()) == ".txt") {
    std::ifstream list(given);
    if (!list) {
      error = given + ": cannot open this list of meshes";
      return std::nullopt;
    }
    const fs::path folder = fs::path(given).parent_path();
    std::string line;
    while (std::getline(list, line)) {
      line.erase(0, line.find_first_not_of(" \t\r"));
      line.erase(line.find_last_not_of(" \t\r") + 1);
      if (line.empty() || line[0] == '#') continue;
      const fs::path written = fs::path(line).lexically_normal();
      const fs::path path = written.is_absolute() ? written : folder / written;
      // Labels keep the list's relative path, unless it leaves the list's folder.
      const bool below = !written.is_absolute() && !written.empty() && *written.begin() != "..";
      meshes.push_back(
          {path.string(), labels_file(output_dir, below ? written : written.filename(), format)});
    }
    if (meshes.empty()) {
      error = given + ": the list names no mesh";
      return std::nullopt;
    }
  } else {
    meshes.push_back({given, labels_file(output_dir, fs::path(given).filename(), format)});
  }
  std::map<std::string, std::string> writers;
  for (const BatchMesh& m : meshes) {
    const auto [at, added] = writers.emplace(m.labels, m.mesh);
    if (!added) {
      error = at->second + " and " + m.mesh + " would both write " + m.labels +
              ": give their folder instead (labels files then keep the folders' relative "
              "paths)";
      return std::nullopt;
    }
  }
  return meshes;
}

std::string batch_points(const std::string& points, const std::string& mesh) {
  static const std::string kPlaceholder = "{mesh}";
  std::string stem = fs::path(mesh).replace_extension().string();
  std::string result = points;
  for (std::size_t at = result.find(kPlaceholder); at != std::string::npos;
       at = result.find(kPlaceholder, at + stem.size())) {
    result.replace(at, kPlaceholder.size(), stem);
  }
  return result;
}

ExitCode run_inside_batch(const InsideCommandOptions& options, std::ostream& out,
                          std::ostream& err) {
  std::string error;
  const auto meshes =
      batch_meshes(options.mesh.path, options.output_dir, options.labels_format, error);
  if (!meshes) {
    err << "exactgeo inside: " << error << "\n";
    return ExitCode::input_error;
  }
  if (options.points == "-") {
    err << "exactgeo inside: --output-dir needs POINTS as a file (or a pattern such as "
           "{mesh}.points.npy): standard input cannot be read once for every mesh\n";
    return ExitCode::input_error;
  }
  // The lines are printed once every mesh has succeeded: on an error standard output
  // stays empty, as for every command, and the files written say what was done.
  std::ostringstream report;
  std::size_t failures = 0;
  for (const BatchMesh& m : *meshes) {
    InsideCommandOptions one = options;
    one.mesh.path = m.mesh;
    one.points = batch_points(options.points, m.mesh);
    one.json = false;
    const auto fail = [&](const std::string& why) {
      ++failures;
      if (!why.empty()) err << "exactgeo inside: " << why << "\n";
    };
    std::error_code made;
    fs::create_directories(fs::path(m.labels).parent_path(), made);
    std::optional<OutputFile> file;
    try {
      file.emplace(m.labels);
    } catch (const OutputFileError& e) {
      fail(e.what());
      continue;
    }
    std::ifstream in(one.points, std::ios::binary);
    if (!in) {
      fail(m.mesh + ": cannot open its points file '" + one.points + "'");
      continue;
    }
    std::ostringstream labels;
    if (run_inside(one, in, one.points, labels, err) != ExitCode::success) {
      fail("");  // run_inside said why, naming the file
      continue;
    }
    const std::string text = labels.str();
    const std::vector<inside::Location> read = labels_of(text);
    try {
      file->commit(options.labels_format == BatchLabelsFormat::npy ? npy_labels(read) : text);
    } catch (const OutputFileError& e) {
      fail(e.what());
      continue;
    }
    inside::LocationCounts c;
    for (const inside::Location l : read)
      c.add(l);
    using inside::Location;
    const std::size_t points = read.size();
    if (options.json) {
      report << "{\"mesh\": " << json_string(m.mesh)
             << ", \"labels_file\": " << json_string(m.labels) << ", \"points\": " << points
             << ", \"inside\": " << c[Location::inside] << ", \"outside\": " << c[Location::outside]
             << ", \"boundary\": " << c[Location::boundary]
             << ", \"undecided\": " << c[Location::undecided] << "}\n";
    } else {
      report << m.mesh << ": " << points << " points, " << c[Location::inside] << " inside, "
             << c[Location::outside] << " outside, " << c[Location::boundary] << " boundary, "
             << c[Location::undecided] << " undecided -> " << m.labels << "\n";
    }
  }
  if (failures > 0) {
    err << "exactgeo inside: " << failures << " of " << meshes->size()
        << (meshes->size() == 1 ? " mesh" : " meshes") << " failed; the others' labels are in "
        << options.output_dir << "\n";
    return ExitCode::input_error;
  }
  out << report.str() << std::flush;
  return ExitCode::success;
}

}  // namespace exactgeo::cli
