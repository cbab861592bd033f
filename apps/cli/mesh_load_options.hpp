#pragma once

// The options that say how a mesh file is read (mesh::LoadOptions), the same on every
// subcommand that reads meshes: --format, the format of a mesh read from standard input
// ("-") or from a file whose name has no (or a misleading) extension; --weld; and
// --split-polygons. Each registers its flag with the meaning every subcommand shares, and a
// subcommand may add what the flag means there.

#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace exactgeo::cli {

/// Registers `--format NAME` on `sub`; `format` (mesh::LoadOptions::format) must outlive
/// the parse.
void add_mesh_format_option(CLI::App& sub, std::string& format);

/// Registers `--weld` (mesh::LoadOptions::weld), described as merging vertices with exactly
/// equal coordinates, then `more`; `weld` must outlive the parse.
void add_weld_flag(CLI::App& sub, bool& weld, std::string_view more = {});

/// Registers `--split-polygons` (mesh::LoadOptions::split_polygons), described as splitting
/// a face of more than four corners whose edges cross into a triangle fan, then `more` (what
/// happens without it: " instead of refusing the file"), then that other such faces are
/// always split; `split_polygons` must outlive the parse.
void add_split_polygons_flag(CLI::App& sub, bool& split_polygons, std::string_view more = {});

}  // namespace exactgeo::cli
