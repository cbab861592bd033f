#pragma once

// `exactgeo info`'s report of what it found in a mesh file, as a table (the default) or
// as one JSON object (--json); both end with the legend of the --mark file when there is
// one.

#include <iosfwd>
#include <optional>
#include <string>

#include "cli/marked_ply.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/loaded_mesh.hpp"
#include "exactgeo/mesh/self_intersection.hpp"

namespace exactgeo::cli {

/// Everything info found, for either form of the report.
struct InfoFindings {
  const mesh::LoadedMesh& loaded;
  const mesh::MeshCheck& check;
  std::optional<std::string> problem;  ///< why `inside` refuses the mesh
  /// nullopt when the check could not run (a corner out of range, a non-finite coordinate).
  std::optional<mesh::SelfIntersections> self;
  std::optional<MarkedMesh> marks;  ///< with --mark
};

/// The table for the mesh file `file` ("-": standard input); `mark_path` names the --mark
/// file when f.marks is set.
void write_info_table(std::ostream& out, const std::string& file, const InfoFindings& f,
                      const std::string& mark_path);

/// The JSON object (and a newline); the arguments as for write_info_table.
void write_info_json(std::ostream& out, const std::string& file, const InfoFindings& f,
                     const std::string& mark_path);

}  // namespace exactgeo::cli
