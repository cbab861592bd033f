// `exactgeo inside MESHES POINTS --output-dir DIR` (run_inside_batch, as the binary calls
// it): one labels file per mesh, the labels `exactgeo inside MESH POINTS` prints; a folder
// walked with its relative paths kept, a list, a per-mesh points pattern; a mesh that
// fails is named and leaves no file while the others are written; what cannot run at all
// (names that collide, no mesh, points on standard input) is refused before anything.

#include "cli/inside_batch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/hexahedron.hpp"
#include "support/scratch_dir.hpp"

namespace exactgeo::cli {
namespace {

namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The unit cube as an OBJ of quads, moved by `offset` along x; without its face x = 1
/// when `open`.
std::string cube_obj(double offset, bool open = false) {
  std::string obj;
  for (const Point3& c : testing::unit_cube_corners())
    obj += "v " + std::to_string(c[0] + offset) + " " + std::to_string(c[1]) + " " +
           std::to_string(c[2]) + "\n";
  for (std::size_t f = 0; f < testing::kHexahedronFaces.size() - (open ? 1 : 0); ++f) {
    const auto& q = testing::kHexahedronFaces[f];
    obj += "f " + std::to_string(q[0] + 1) + " " + std::to_string(q[1] + 1) + " " +
           std::to_string(q[2] + 1) + " " + std::to_string(q[3] + 1) + "\n";
  }
  return obj;
}

struct Outcome {
  ExitCode code;
  std::string out, err;
};

class InsideBatch : public ::testing::Test {
 protected:
  const testing::ScratchDir scratch_{"exactgeo_inside_batch"};
  const fs::path& dir_ = scratch_.path;

  Outcome run(const std::string& meshes, const std::string& points, bool json = false,
              BatchLabelsFormat format = BatchLabelsFormat::text) {
    InsideCommandOptions options;
    options.labels_format = format;
    options.mesh.path = meshes;
    options.points = points;
    options.output_dir = (dir_ / "labels").string();
    options.mesh.threads = 2;
    options.json = json;
    std::ostringstream out, err;
    const ExitCode code = run_inside_batch(options, out, err);
    return {code, out.str(), err.str()};
  }

  /// What `exactgeo inside MESH POINTS` prints.
  std::string single(const fs::path& mesh, const fs::path& points) {
    InsideCommandOptions options;
    options.mesh.path = mesh.string();
    options.points = points.string();
    std::ifstream in(points, std::ios::binary);
    std::ostringstream out, err;
    EXPECT_EQ(run_inside(options, in, options.points, out, err), ExitCode::success) << err.str();
    return out.str();
  }
};

TEST_F(InsideBatch, AFolderGetsOneLabelsFilePerMeshUnderItsRelativePath) {
  const fs::path shapes = dir_ / "shapes";
  write_file(shapes / "a" / "model.obj", cube_obj(0));
  write_file(shapes / "b" / "model.obj", cube_obj(0.5));
  write_file(shapes / "open.obj", cube_obj(0, true));
  write_file(shapes / "notes.md", "not a mesh\n");
  write_file(dir_ / "points.txt", "0.25 0.5 0.5\n0.75 0.5 0.5\n1.25 0.5 0.5\n0 0.5 0.5\n");
  const Outcome outcome = run(shapes.string(), (dir_ / "points.txt").string());
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  const fs::path labels = dir_ / "labels";
  EXPECT_EQ(read_file(labels / "a" / "model.labels.txt"), "inside\ninside\noutside\nboundary\n");
  EXPECT_EQ(read_file(labels / "b" / "model.labels.txt"), "outside\ninside\ninside\noutside\n");
  for (const auto& [mesh, file] : {std::pair{"a/model.obj", "a/model.labels.txt"},
                                   {"b/model.obj", "b/model.labels.txt"},
                                   {"open.obj", "open.labels.txt"}}) {
    EXPECT_EQ(read_file(labels / file), single(shapes / mesh, dir_ / "points.txt")) << mesh;
  }
  EXPECT_EQ(outcome.out, (shapes / "a" / "model.obj").string() +
                             ": 4 points, 2 inside, 1 outside, 1 boundary, 0 undecided -> " +
                             (labels / "a" / "model.labels.txt").string() + "\n" +
                             (shapes / "b" / "model.obj").string() +
                             ": 4 points, 2 inside, 2 outside, 0 boundary, 0 undecided -> " +
                             (labels / "b" / "model.labels.txt").string() + "\n" +
                             (shapes / "open.obj").string() +
                             ": 4 points, 2 inside, 1 outside, 1 boundary, 0 undecided -> " +
                             (labels / "open.labels.txt").string() + "\n");
  // --json: an object per line.
  const Outcome json = run(shapes.string(), (dir_ / "points.txt").string(), true);
  ASSERT_EQ(json.code, ExitCode::success) << json.err;
  EXPECT_EQ(json.out.substr(0, json.out.find('\n')),
            "{\"mesh\": \"" + (shapes / "a" / "model.obj").string() + "\", \"labels_file\": \"" +
                (labels / "a" / "model.labels.txt").string() +
                "\", \"points\": 4, \"inside\": 2, \"outside\": 1, \"boundary\": 1, "
                "\"undecided\": 0}");
}

TEST_F(InsideBatch, AMeshThatFailsIsNamedAndTheOthersAreWritten) {
  const fs::path shapes = dir_ / "shapes";
  write_file(shapes / "a.obj", cube_obj(0));
  write_file(shapes / "broken.off", "OFF\n3 1 0\n0 0 0\n");
  write_file(shapes / "c.obj", cube_obj(2));
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n");
  const Outcome outcome = run(shapes.string(), (dir_ / "points.txt").string());
  EXPECT_EQ(outcome.code, ExitCode::input_error);
  EXPECT_NE(outcome.err.find("exactgeo inside: " + (shapes / "broken.off").string() + ":"),
            std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("1 of 3 meshes failed"), std::string::npos) << outcome.err;
  EXPECT_EQ(read_file(dir_ / "labels" / "a.labels.txt"), "inside\n");
  EXPECT_EQ(read_file(dir_ / "labels" / "c.labels.txt"), "outside\n");
  EXPECT_FALSE(fs::exists(dir_ / "labels" / "broken.labels.txt"));
  std::vector<std::string> written;
  for (const auto& entry : fs::directory_iterator(dir_ / "labels"))
    written.push_back(entry.path().filename().string());
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written, (std::vector<std::string>{"a.labels.txt", "c.labels.txt"}));  // no temporary
  EXPECT_EQ(outcome.out, "");  // an error: nothing on standard output, the files say it
}

TEST_F(InsideBatch, AListAndAPointsPatternPerMesh) {
  write_file(dir_ / "set" / "one.obj", cube_obj(0));
  write_file(dir_ / "set" / "one.points.txt", "0.5 0.5 0.5\n");
  write_file(dir_ / "set" / "sub" / "two.obj", cube_obj(0.5));
  write_file(dir_ / "set" / "sub" / "two.points.txt", "0.25 0.5 0.5\n1.25 0.5 0.5\n");
  write_file(dir_ / "set" / "meshes.txt", "# the training split\none.obj\n\n  sub/two.obj  \n");
  const Outcome outcome = run((dir_ / "set" / "meshes.txt").string(), "{mesh}.points.txt");
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  EXPECT_EQ(read_file(dir_ / "labels" / "one.labels.txt"), "inside\n");
  EXPECT_EQ(read_file(dir_ / "labels" / "sub" / "two.labels.txt"), "outside\ninside\n");
  EXPECT_EQ(batch_points("{mesh}.npy", "data/chair.obj"), "data/chair.npy");
  EXPECT_EQ(batch_points("grid.npy", "data/chair.obj"), "grid.npy");
}

// --labels-format npy: NAME.labels.npy, version 1.0 of the format: a header that says int8,
// one dimension of the points' count, padded so that the data starts at a multiple of 64
// bytes; then one code a point, inside::Location's values (the Python module's constants).
TEST_F(InsideBatch, NpyLabelsAreTheCodesOfTheTextLabels) {
  write_file(dir_ / "set" / "cube.obj", cube_obj(0));
  write_file(dir_ / "set" / "open.obj", cube_obj(0, true));
  std::string points;
  for (int k = 0; k < 40; ++k)
    points += std::to_string(-0.5 + 0.05 * k) + " 0.5 0.5\n";  // out, boundary, in, out
  write_file(dir_ / "points.txt", points);
  const Outcome outcome =
      run((dir_ / "set").string(), (dir_ / "points.txt").string(), false, BatchLabelsFormat::npy);
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  for (const std::string name : {"cube", "open"}) {
    const std::string npy = read_file(dir_ / "labels" / (name + ".labels.npy"));
    const std::string text = single(dir_ / "set" / (name + ".obj"), dir_ / "points.txt");
    ASSERT_GT(npy.size(), 10u);
    EXPECT_EQ(npy.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
    const std::size_t header = static_cast<unsigned char>(npy[8]) +
                               256 * static_cast<std::size_t>(static_cast<unsigned char>(npy[9]));
    EXPECT_EQ((10 + header) % 64, 0u);
    EXPECT_EQ(npy[10 + header - 1], '\n');
    EXPECT_EQ(npy.substr(10, 58), "{'descr': '|i1', 'fortran_order': False, 'shape': (40,), }");
    std::string codes;
    std::istringstream lines(text);
    for (std::string word; std::getline(lines, word);) {
      const std::vector<std::string> words{"outside", "inside", "boundary", "undecided"};
      const auto found = std::find(words.begin(), words.end(), word);
      ASSERT_NE(found, words.end()) << word;
      codes.push_back(static_cast<char>(found - words.begin()));
    }
    EXPECT_EQ(codes.size(), 40u);
    EXPECT_EQ(npy.substr(10 + header), codes) << name;
    EXPECT_NE(codes.find('\2'), std::string::npos) << name;  // each kind is there
    EXPECT_NE(codes.find('\1'), std::string::npos) << name;
  }
  EXPECT_NE(outcome.out.find("cube.labels.npy"), std::string::npos) << outcome.out;
}

TEST_F(InsideBatch, WhatCannotRunIsRefusedBeforeAnything) {
  write_file(dir_ / "x" / "model.obj", cube_obj(0));
  write_file(dir_ / "y" / "model.obj", cube_obj(0));
  // Paths that leave the list's folder keep only their file name: these two collide.
  write_file(dir_ / "lists" / "list.txt", "../x/model.obj\n../y/model.obj\n");
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n");
  Outcome outcome = run((dir_ / "lists" / "list.txt").string(), (dir_ / "points.txt").string());
  EXPECT_EQ(outcome.code, ExitCode::input_error);
  EXPECT_NE(outcome.err.find("would both write " + (dir_ / "labels" / "model.labels.txt").string()),
            std::string::npos)
      << outcome.err;
  fs::create_directories(dir_ / "empty");
  outcome = run((dir_ / "empty").string(), (dir_ / "points.txt").string());
  EXPECT_EQ(outcome.code, ExitCode::input_error);
  EXPECT_NE(outcome.err.find("empty: no mesh file in this folder"), std::string::npos)
      << outcome.err;
  outcome = run((dir_ / "x").string(), "-");
  EXPECT_EQ(outcome.code, ExitCode::input_error);
  EXPECT_NE(outcome.err.find("--output-dir needs POINTS as a file"), std::string::npos)
      << outcome.err;
  EXPECT_FALSE(fs::exists(dir_ / "labels"));
  EXPECT_EQ(outcome.out, "");
}

}  // namespace
}  // namespace exactgeo::cli
