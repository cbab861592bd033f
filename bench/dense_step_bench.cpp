// Mesh CCD on dense steps: peak memory and time per candidate against the candidate count
// (docs/ccd.md, "Steps of many candidates in bounded memory").
//
//   dense_step_bench MESH [--degrees D,D,...] [--threads T,T,...] [--scales K,K,...]
//                    [--list] [--write DIR]
//
// Each step turns MESH (quads split into two triangles) as a rigid body by D degrees about
// the vertical axis (exactgeo/testbed/turned_step.hpp: millions of candidate pairs, no
// collision), scaled by 2^K. Every row is a fresh MeshCcd's first step (exact method),
// so it builds its trees, on T threads; its peak resident memory is read from the moment
// before the step (the mesh and both frames already resident) to its end
// (exactgeo/testbed/resident_memory.hpp). With --list, each row also gives the peak of
// MeshCcd::candidates on the same step (a fresh MeshCcd, same threads): the candidate
// list that a step holding all its candidates would hold, as the library's step did before
// it decided them in batches. Prints a markdown table. With --write, also writes
// each angle's frames as DIR/turned-D-0.obj and DIR/turned-D-1.obj (scale 2^0) for
// `exactgeo ccd-mesh --json`, whose peak_memory_bytes is the same measure for a whole run.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/testbed/resident_memory.hpp"
#include "exactgeo/testbed/turned_step.hpp"

namespace {

using namespace exactgeo;

struct Options {
  std::string mesh;
  std::vector<double> degrees{0.5, 5, 10, 20, 40, 80};
  std::vector<unsigned> threads{1, 2};
  std::vector<int> scales{0, 1000, -1000};
  std::string write_dir;
  bool list = false;
};

template <class T>
std::vector<T> list_of(const std::string& text) {
  std::vector<T> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::stringstream one(item);
    T value{};
    if (!(one >> value) || !one.eof())
      throw std::invalid_argument("not a list of numbers: " + text);
    values.push_back(value);
  }
  return values;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--degrees") {
      o.degrees = list_of<double>(value());
    } else if (a == "--threads") {
      o.threads = list_of<unsigned>(value());
    } else if (a == "--scales") {
      o.scales = list_of<int>(value());
    } else if (a == "--list") {
      o.list = true;
    } else if (a == "--write") {
      o.write_dir = value();
    } else if (o.mesh.empty() && a.rfind("--", 0) != 0) {
      o.mesh = a;
    } else {
      throw std::invalid_argument("unknown argument " + a);
    }
  }
  if (o.mesh.empty()) throw std::invalid_argument("a mesh file is needed");
  return o;
}

void write_obj(const std::string& path, std::span<const double> xyz,
               std::span<const ccd::Triangle> faces) {
  std::ofstream out(path);
  char line[96];
  for (std::size_t v = 0; v < xyz.size() / 3; ++v) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", xyz[3 * v], xyz[3 * v + 1],
                  xyz[3 * v + 2]);
    out << line;
  }
  for (const ccd::Triangle& f : faces)
    out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string megabytes(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", static_cast<double>(bytes) / (1 << 20));
  return text;
}

}  // namespace

int main(int argc, char** argv) try {
  const Options options = parse(argc, argv);
  const mesh::LoadedMesh loaded = mesh::load_mesh(options.mesh);
  const std::vector<double> positions = ccd::flat_positions(loaded.mesh.vertices);
  const std::vector<ccd::Triangle> faces = mesh::triangle_surface_of(loaded.mesh).triangles;
  const std::size_t vertex_count = loaded.mesh.vertices.size();
  std::cout << "| triangles | degrees | scale | threads | candidates | collisions | step ms | "
               "ns / candidate | peak MB | resident before MB | peak MB, list held |\n"
            << "|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const double degrees : options.degrees) {
    if (!options.write_dir.empty()) {
      const testbed::TurnedStep step = testbed::turned_step(positions, degrees);
      const std::string stem = options.write_dir + "/turned-" + std::to_string(degrees);
      write_obj(stem + "-0.obj", step.t0, faces);
      write_obj(stem + "-1.obj", step.t1, faces);
    }
    for (const int scale : options.scales) {
      const testbed::TurnedStep step = testbed::turned_step(positions, degrees, scale);
      for (const unsigned threads : options.threads) {
        ccd::MeshCcdOptions o;
        o.threads = threads;
        const auto peak_of = [&](const auto& run) {
          if (!testbed::reset_peak_resident_memory())
            throw std::runtime_error("the peak resident memory cannot be reset here");
          const std::size_t before = testbed::peak_resident_memory().value_or(0);
          run();
          return std::pair{before, testbed::peak_resident_memory().value_or(0)};
        };
        ccd::MeshCcdResult r;
        const auto [before, peak] = peak_of([&] {
          r = ccd::MeshCcd(vertex_count, faces).step({step.t0, step.t1}, o);
        });
        std::string list_peak = "-";
        if (options.list) {
          list_peak =
              megabytes(peak_of([&] {
                          ccd::MeshCcd(vertex_count, faces).candidates({step.t0, step.t1}, o);
                        }).second);
        }
        const double seconds = r.broad_phase_seconds + r.narrow_phase_seconds;
        const std::size_t collisions = r.vertex_face.size() + r.edge_edge.size();
        char row[320];
        std::snprintf(
            row, sizeof row, "| %zu | %g | 2^%d | %u | %zu | %zu | %.1f | %.1f | %s | %s | %s |\n",
            faces.size(), degrees, scale, threads, r.candidates(), collisions, 1e3 * seconds,
            1e9 * seconds / static_cast<double>(std::max<std::size_t>(1, r.candidates())),
            megabytes(peak).c_str(), megabytes(before).c_str(), list_peak.c_str());
        std::cout << row << std::flush;
      }
    }
  }
  return 0;
} catch (const std::exception& e) {
  std::cerr << "dense_step_bench: " << e.what() << '\n';
  return 2;
}
