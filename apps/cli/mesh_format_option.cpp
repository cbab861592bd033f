#include "cli/mesh_format_option.hpp"

#include <CLI/CLI.hpp>

namespace exactgeo::cli {

void add_mesh_format_option(CLI::App& sub, std::string& format) {
  sub.add_option("--format", format,
                 "the mesh format when the name does not tell it (standard input, no "
                 "extension): obj, off, ply (read exactly) or a format assimp reads (stl, "
                 "glb, ...); overrides the extension")
      ->type_name("NAME");
}

}  // namespace exactgeo::cli
