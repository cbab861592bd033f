#include "obj_output.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace exactgeo::cloth {

void write_obj(const std::filesystem::path& path, std::span<const double> positions,
               std::span<const ccd::Triangle> faces, std::size_t cloth_faces) {
  std::string text;
  text.reserve(64 * positions.size() / 3 + 24 * faces.size());
  char line[128];
  for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
    const int n = std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", positions[i],
                                positions[i + 1], positions[i + 2]);
    text.append(line, static_cast<std::size_t>(n));
  }
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (i == 0 && cloth_faces > 0) text.append("g cloth\n");
    if (i == cloth_faces) text.append("g obstacle\n");
    const ccd::Triangle& f = faces[i];
    const int n =
        std::snprintf(line, sizeof line, "f %lu %lu %lu\n", static_cast<unsigned long>(f[0]) + 1,
                      static_cast<unsigned long>(f[1]) + 1, static_cast<unsigned long>(f[2]) + 1);
    text.append(line, static_cast<std::size_t>(n));
  }
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + path.string() + "'");
}

}  // namespace exactgeo::cloth
