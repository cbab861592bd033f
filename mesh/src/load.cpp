#include "exactgeo/mesh/load.hpp"

#include <cctype>
#include <filesystem>

#include "assimp_reader.hpp"
#include "exactgeo/io/read_bytes.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "exactgeo/mesh/weld.hpp"

namespace exactgeo::mesh {

using io::read_file;

namespace {

// "stl" for "Model.STL"; empty when the file name has no extension.
std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  if (!extension.empty()) extension.erase(0, 1);  // the dot
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace

LoadedMesh load_mesh(const std::string& path, const LoadOptions& options) {
  const std::string extension = lowercase_extension(path);
  using Reader = LoadedMesh (*)(std::string_view, const std::string&, const LoadOptions&);
  Reader reader = nullptr;
  if (extension == "obj") reader = read_obj;
  if (extension == "off") reader = read_off;
  if (extension == "ply") reader = read_ply;
  if (reader == nullptr) return read_with_assimp(path, extension, options);  // always welds

  const std::string bytes = read_file(path);
  LoadedMesh loaded = reader(bytes, path, options);
  if (options.weld) loaded.welded_vertices = weld_vertices(loaded.mesh);
  return loaded;
}

}  // namespace exactgeo::mesh
