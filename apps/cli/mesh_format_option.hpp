#pragma once

// `--format`, the same on every subcommand that reads meshes: the format of a mesh read
// from standard input ("-") or from a file whose name has no (or a misleading) extension.

#include <string>

namespace CLI {
class App;
}

namespace exactgeo::cli {

/// Registers `--format NAME` on `sub`; `format` (mesh::LoadOptions::format) must outlive
/// the parse.
void add_mesh_format_option(CLI::App& sub, std::string& format);

}  // namespace exactgeo::cli
