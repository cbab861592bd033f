#include "cli/mesh_load_options.hpp"

#include <CLI/CLI.hpp>

namespace exactgeo::cli {

void add_mesh_format_option(CLI::App& sub, std::string& format) {
  sub.add_option("--format", format,
                 "the mesh format when the name does not tell it (standard input, no "
                 "extension): obj, off, ply, stl (read exactly) or a format assimp reads "
                 "(glb, 3ds, ...); overrides the extension")
      ->type_name("NAME");
}

void add_weld_flag(CLI::App& sub, bool& weld, std::string_view more) {
  sub.add_flag("--weld", weld, "merge vertices with exactly equal coordinates" + std::string(more));
}

void add_split_polygons_flag(CLI::App& sub, bool& split_polygons, std::string_view more) {
  sub.add_flag("--split-polygons", split_polygons,
               "split a face of more than four corners whose edges cross into the fan of "
               "triangles from its first corner" +
                   std::string(more) +
                   " (other faces of more than four corners are always split, exactly)");
}

}  // namespace exactgeo::cli
