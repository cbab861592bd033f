// `exactgeo inside` end to end (run_inside on files, as the binary opens them): the same
// random points as text, f64 and npy (versions 1 to 3, either byte order) give identical
// labels; --json --labels carries them in input order; every malformed binary input gives
// exit code 2, a message naming the file and the place, and nothing on stdout.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "cli/inside_command.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/mesh/load.hpp"
#include "support/generators.hpp"
#include "support/hexahedron.hpp"
#include "support/npy_bytes.hpp"
#include "support/scratch_dir.hpp"
#include "support/seed.hpp"

namespace exactgeo::cli {
namespace {

namespace fs = std::filesystem;
using testing::float64_bytes;
using testing::npy_file;
using testing::npy_header;
using testing::npy_points_dict;

const std::string kMeshes = std::string(EXACTGEO_TEST_DATA_DIR) + "/meshes/";

struct Outcome {
  ExitCode code;
  std::string out, err;
};

/// Runs on the file `points` the way the binary does (opened in binary mode, named by its path).
Outcome run_file(InsideCommandOptions options, const fs::path& points) {
  options.points = points.string();
  options.mesh.threads = 2;
  std::ifstream in(points, std::ios::binary);
  std::ostringstream out, err;
  const ExitCode code = run_inside(options, in, options.points, out, err);
  return {code, out.str(), err.str()};
}

Outcome run_stdin(InsideCommandOptions options, const std::string& bytes) {
  std::istringstream in(bytes);
  std::ostringstream out, err;
  const ExitCode code = run_inside(options, in, "<stdin>", out, err);
  return {code, out.str(), err.str()};
}

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

/// Two unit cubes as OBJ, the second moved by 1/2 along every axis (six pairs of faces
/// cross), after `before` (lines of vertices and faces of `vertices_before` vertices); with
/// `turn_one_face`, the second cube's first face turned (the faces not oriented alike).
std::string two_crossing_cubes_obj(const std::string& before = "", int vertices_before = 0,
                                   bool turn_one_face = false) {
  std::string obj = before;
  for (const double offset : {0.0, 0.5})
    for (int c = 0; c < 8; ++c)
      obj += "v " + std::to_string((c & 1) + offset) + " " +
             std::to_string(((c >> 1) & 1) + offset) + " " +
             std::to_string(((c >> 2) & 1) + offset) + "\n";
  for (const int first : {vertices_before + 1, vertices_before + 9})
    for (std::size_t f = 0; f < testing::kHexahedronFaces.size(); ++f) {
      std::array<VertexIndex, 4> q = testing::kHexahedronFaces[f];
      if (turn_one_face && first == vertices_before + 9 && f == 0) std::reverse(q.begin(), q.end());
      obj += "f " + std::to_string(q[0] + first) + " " + std::to_string(q[1] + first) + " " +
             std::to_string(q[2] + first) + " " + std::to_string(q[3] + first) + "\n";
    }
  return obj;
}

std::string as_text(const std::vector<Point3>& points) {
  std::string text;
  char line[96];
  for (const Point3& p : points) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", p[0], p[1], p[2]);
    text += line;
  }
  return text;
}

/// The strings of the JSON array "labels" in `json` (one empty string if it is missing).
std::vector<std::string> json_labels(const std::string& json) {
  const std::size_t start = json.find("\"labels\": [");
  if (start == std::string::npos) return {""};
  const std::size_t end = json.find(']', start);
  std::vector<std::string> labels;
  for (std::size_t at = json.find('"', start + 10); at < end; at = json.find('"', at + 1)) {
    const std::size_t close = json.find('"', at + 1);
    labels.push_back(json.substr(at + 1, close - at - 1));
    at = close;
  }
  return labels;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

class InsideCommand : public ::testing::Test {
 protected:
  const testing::ScratchDir scratch_{"exactgeo_inside"};
  const fs::path& dir_ = scratch_.path;
};

TEST_F(InsideCommand, EveryPointFormatGivesTheSameLabels) {
  const std::string mesh = kMeshes + "spot/spot_quadrangulated.obj";
  const auto loaded = mesh::load_mesh(mesh);
  // Uniform in the mesh's box grown by 5% per side, then every vertex (boundary): more
  // than one block of the command's 65,536 points.
  auto rng = testing::seeded_engine("InsideCommand.formats");
  Point3 lo = loaded.mesh.vertices[0], hi = lo;
  for (const Point3& v : loaded.mesh.vertices) {
    for (std::size_t c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], v[c]);
      hi[c] = std::max(hi[c], v[c]);
    }
  }
  std::vector<Point3> points;
  for (int i = 0; i < 70000; ++i) {
    Point3 p;
    for (std::size_t c = 0; c < 3; ++c) {
      const double grow = 0.05 * (hi[c] - lo[c]);
      p[c] = testing::uniform(rng, lo[c] - grow, hi[c] + grow);
    }
    points.push_back(p);
  }
  points.insert(points.end(), loaded.mesh.vertices.begin(), loaded.mesh.vertices.end());

  InsideCommandOptions options;
  options.mesh.path = mesh;
  write_file(dir_ / "points.txt", as_text(points));
  const Outcome text = run_file(options, dir_ / "points.txt");
  ASSERT_EQ(text.code, ExitCode::success) << text.err;
  const std::vector<std::string> labels = lines_of(text.out);
  ASSERT_EQ(labels.size(), points.size());
  for (const char* label : {"inside", "outside", "boundary"}) {
    EXPECT_NE(std::find(labels.begin(), labels.end(), label), labels.end()) << label;
  }

  struct Case {
    std::string file;
    std::string bytes;
    std::optional<io::PointFormat> format;  // nullopt: by the file name
  };
  const std::vector<Case> cases = {
      {"points.f64", float64_bytes(points), io::PointFormat::f64},
      {"points.npy", npy_file(points, 1, false), std::nullopt},
      {"points_v2_big_endian.NPY", npy_file(points, 2, true), std::nullopt},
      {"points_v3.npy", npy_file(points, 3, false), io::PointFormat::npy},
      {"points_v1_big_endian.bin", npy_file(points, 1, true), io::PointFormat::npy},
  };
  for (const Case& c : cases) {
    write_file(dir_ / c.file, c.bytes);
    options.points_format = c.format;
    const Outcome binary = run_file(options, dir_ / c.file);
    ASSERT_EQ(binary.code, ExitCode::success) << c.file << ": " << binary.err;
    EXPECT_TRUE(binary.out == text.out) << c.file << ": labels differ from the text input's";
    EXPECT_EQ(binary.err, "") << c.file;
  }

  // --json --labels: the same labels, in input order, in one JSON object.
  options.points_format = std::nullopt;
  options.json = true;
  options.labels = true;
  const Outcome json = run_file(options, dir_ / "points.npy");
  ASSERT_EQ(json.code, ExitCode::success) << json.err;
  EXPECT_TRUE(json_labels(json.out) == labels) << "--json --labels differs from the labels";
  for (const std::string& key :
       {"{\"points\": " + std::to_string(points.size()) + ", ", std::string("\"build_seconds\": "),
        std::string("\"read_seconds\": "), std::string("\"seconds\": ")}) {
    EXPECT_NE(json.out.find(key), std::string::npos) << key;
  }
  EXPECT_EQ(json.out.substr(json.out.size() - 4), "\"]}\n");
  EXPECT_EQ(std::count(json.out.begin(), json.out.end(), '\n'), 1);
  options.labels = false;
  const Outcome counts = run_file(options, dir_ / "points.npy");
  EXPECT_EQ(counts.out.find("labels"), std::string::npos) << counts.out;
  EXPECT_NE(counts.out.find("\"read_seconds\": "), std::string::npos) << counts.out;
}

TEST_F(InsideCommand, MalformedBinaryInputIsRefusedNamingFileAndPlace) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Point3> two = {{0.5, 0.5, 0.5}, {3, 3, 3}};
  const std::string f64 = float64_bytes(two);
  const std::string npy = npy_file(two);  // 128 bytes of header, 48 of data
  const auto header = [](const std::string& descr, const std::string& fortran,
                         const std::string& shape) {
    return npy_header("{'descr': '" + descr + "', 'fortran_order': " + fortran +
                      ", 'shape': " + shape + ", }");
  };
  struct Case {
    std::string file;
    std::string bytes;
    std::string place;  // the message after "exactgeo inside: <file>: "
    std::optional<io::PointFormat> format = std::nullopt;
  };
  const std::vector<Case> cases = {
      {"bad_magic.npy", "\x92NUMPY" + npy.substr(6), "header: not an .npy file"},
      {"zip.npy", "PK\x03\x04", "header: not an .npy file"},
      {"empty.npy", "", "header: the input is empty, not an .npy file"},
      {"short_header.npy", npy.substr(0, 9), "header: the file ends within the header length"},
      {"header_past_end.npy", npy.substr(0, 100),
       "header: the header is 128 bytes long but the file ends at byte 100"},
      {"bad_dict.npy", npy_header("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3)"),
       "header: expected ',' or '}' after a value (at byte 128)"},
      {"float32.npy", header("<f4", "False", "(2, 3)") + std::string(24, '\0'),
       "header: descr is '<f4'; accepted: '<f8' or '>f8' (float64"},
      {"int64.npy", header("<i8", "False", "(2, 3)") + f64, "header: descr is '<i8'"},
      {"object.npy", header("|O", "False", "(2, 3)"), "header: descr is '|O'"},
      {"fortran.npy", header("<f8", "True", "(2, 3)") + f64,
       "header: fortran_order is True (the array is stored column by column); save a C-ordered "
       "copy: np.save(path, np.ascontiguousarray(points))"},
      {"one_d.npy", header("<f8", "False", "(6,)") + f64,
       "header: shape is (6,); accepted: (n, 3), one row per point"},
      {"four_columns.npy", header("<f8", "False", "(2, 4)") + f64 + std::string(16, '\0'),
       "header: shape is (2, 4)"},
      {"transposed.npy", header("<f8", "False", "(3, 2)") + f64, "header: shape is (3, 2)"},
      {"truncated.npy", npy.substr(0, npy.size() - 8),
       "point 1 (byte 152): the data ends 16 bytes into this point; the header's shape "
       "declares 2 points"},
      {"extra.npy", npy + std::string(8, '\0'),
       "byte 176: data continues after the 2 points the header's shape declares"},
      {"nan.npy", npy_file({{0, 0, 0}, {0, nan, 0}}, 2, true),
       "point 1 (byte 152): y is nan; coordinates must be finite"},
      {"nan.f64", float64_bytes({{0, 0, 0}, {0, 0, 0}, {nan, 0, 0}}),
       "point 2 (byte 48): x is nan; coordinates must be finite", io::PointFormat::f64},
      {"23.f64", f64.substr(0, 23), "point 0 (byte 0): the input ends 23 bytes into this point",
       io::PointFormat::f64},
      {"25.f64", f64.substr(0, 25), "point 1 (byte 24): the input ends 1 byte into this point",
       io::PointFormat::f64},
      {"text.txt", "0 0 0\n", "header: not an .npy file", io::PointFormat::npy},
  };
  for (const bool json : {false, true}) {
    for (const Case& c : cases) {
      InsideCommandOptions options;
      options.mesh.path = kMeshes + "cgal/cube_quad.off";
      options.points_format = c.format;
      options.json = json;
      options.labels = json;
      write_file(dir_ / c.file, c.bytes);
      const Outcome run = run_file(options, dir_ / c.file);
      const std::string expected = "exactgeo inside: " + (dir_ / c.file).string() + ": " + c.place;
      EXPECT_EQ(run.code, ExitCode::input_error) << c.file;
      EXPECT_EQ(run.out, "") << c.file;
      EXPECT_EQ(run.err.rfind(expected, 0), 0u) << run.err << "\nshould start with\n" << expected;
      EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    }
  }
}

TEST_F(InsideCommand, F64FromStandardInput) {
  InsideCommandOptions options;
  options.mesh.path = kMeshes + "cgal/cube_quad.off";
  options.points_format = io::PointFormat::f64;
  const std::string f64 = float64_bytes({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}});
  const Outcome labels = run_stdin(options, f64);
  EXPECT_EQ(labels.code, ExitCode::success) << labels.err;
  EXPECT_EQ(labels.out, "inside\noutside\nboundary\n");
  const Outcome empty = run_stdin(options, "");
  EXPECT_EQ(empty.code, ExitCode::success) << empty.err;
  EXPECT_EQ(empty.out, "");
  const Outcome truncated = run_stdin(options, f64.substr(0, 71));
  EXPECT_EQ(truncated.code, ExitCode::input_error);
  EXPECT_EQ(truncated.out, "");
  EXPECT_EQ(truncated.err,
            "exactgeo inside: <stdin>: point 2 (byte 48): the input ends 23 bytes into this point "
            "(f64 input is 24 bytes per point: x, y, z)\n");
  options.json = true;
  options.labels = true;
  const Outcome json = run_stdin(options, "");
  EXPECT_EQ(json.out.rfind("{\"points\": 0, \"inside\": 0, ", 0), 0u) << json.out;
  EXPECT_NE(json.out.find("\"labels\": []}"), std::string::npos) << json.out;
}

// On a terminal, one progress line shows the mesh being read and built, then the points
// with the share of the file read; it is erased before the command ends, and the labels
// on stdout are the same as without it.
TEST_F(InsideCommand, ProgressShowsTheBuildAndTheShareReadThenVanishes) {
  InsideCommandOptions options;
  options.mesh.path = kMeshes + "cgal/cube_quad.off";
  options.mesh.self_intersection_check = SelfIntersectionCheck::always;  // a stage of its own
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n2 0 0\n");
  const Outcome quiet = run_file(options, dir_ / "points.txt");
  options.progress = ProgressMode::terminal;
  const Outcome shown = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(shown.code, ExitCode::success) << shown.err;
  EXPECT_EQ(shown.out, quiet.out);
  EXPECT_EQ(quiet.err, "");
  const std::string& err = shown.err;
  const std::size_t reading = err.find("reading " + options.mesh.path + "...");
  const std::size_t building =
      err.find("building the search structure (6 faces) and looking for faces that intersect...");
  const std::size_t counted = err.find("2 points (100.0%)");
  EXPECT_NE(reading, std::string::npos) << err;
  EXPECT_NE(building, std::string::npos) << err;
  EXPECT_NE(counted, std::string::npos) << err;
  EXPECT_LT(reading, building);
  EXPECT_LT(building, counted);
  EXPECT_EQ(err.substr(err.size() - 4), "\r\033[K");  // the line is erased at the end
  EXPECT_EQ(err.find('\n'), std::string::npos);
  // From standard input the share is unknown: a count without a percentage.
  const Outcome piped = run_stdin(options, "0.5 0.5 0.5\n");
  EXPECT_NE(piped.err.find("1 points"), std::string::npos) << piped.err;
  EXPECT_EQ(piped.err.find('%'), std::string::npos) << piped.err;
  // --progress off a terminal (a log, a notebook): the same stages and count, a line each,
  // nothing erased.
  options.progress = ProgressMode::lines;
  const Outcome logged = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(logged.out, quiet.out);
  EXPECT_EQ(logged.err.rfind("reading " + options.mesh.path +
                                 "...\nbuilding the search "
                                 "structure (6 faces) and looking for faces that intersect...\n"
                                 "classifying...\n2 points (100.0%)",
                             0),
            0u)
      << logged.err;
  EXPECT_EQ(logged.err.back(), '\n');
  EXPECT_EQ(logged.err.find('\r'), std::string::npos) << logged.err;
  EXPECT_EQ(logged.err.find('\033'), std::string::npos) << logged.err;
}

// Two unit cubes, the second moved by 1/2 along every axis: six pairs of faces cross. By
// the default rule (nonzero) the overlap is inside, and nothing is said. By parity the
// labels are the parity solid's (the overlap is outside), and the command says so on
// standard error, in the file's numbering, whether the check runs beside the build or
// after it; without the check it says nothing.
TEST_F(InsideCommand, WarnsThatTheLabelsAreTheParitySolidsWhenFacesIntersect) {
  write_file(dir_ / "two_cubes.obj", two_crossing_cubes_obj());
  write_file(dir_ / "points.txt", "0.25 0.25 0.25\n0.75 0.75 0.75\n1.25 1.25 1.25\n");
  InsideCommandOptions options;
  options.mesh.path = (dir_ / "two_cubes.obj").string();
  const Outcome union_of_parts = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(union_of_parts.code, ExitCode::success) << union_of_parts.err;
  EXPECT_EQ(union_of_parts.out, "inside\ninside\ninside\n");
  EXPECT_EQ(union_of_parts.err, "");
  options.mesh.rule = inside::FillRule::parity;
  for (const unsigned threads : {2u, 1u}) {
    options.mesh.threads = threads;
    options.points = (dir_ / "points.txt").string();
    std::ifstream in(options.points, std::ios::binary);
    std::ostringstream out, err;
    ASSERT_EQ(run_inside(options, in, options.points, out, err), ExitCode::success) << err.str();
    EXPECT_EQ(out.str(), "inside\noutside\ninside\n");
    EXPECT_EQ(err.str().rfind("exactgeo inside: warning: " + options.mesh.path +
                                  ": 6 pairs of faces intersect (first: 2-9, ",
                              0),
              0u)
        << err.str();
    EXPECT_NE(err.str().find("(faces numbered from 1, as in the file): the labels are those of "
                             "the parity solid"),
              std::string::npos)
        << err.str();
    EXPECT_NE(err.str().find("--rule nonzero labels overlapping parts as their union"),
              std::string::npos)
        << err.str();
  }
  options.json = true;
  const Outcome json = run_file(options, dir_ / "points.txt");
  EXPECT_NE(json.out.find("\"intersecting_face_pairs\": 6, \"undecided_face_pairs\": 0"),
            std::string::npos)
      << json.out;
  options.mesh.self_intersection_check = SelfIntersectionCheck::never;
  const Outcome quiet = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(quiet.err, "");
  EXPECT_NE(quiet.out.find("\"intersecting_face_pairs\": null"), std::string::npos) << quiet.out;
}

// By default faces that intersect are looked for only where the labels are the parity
// solid's: not under nonzero (the default rule, which no intersection changes) unless
// asked, and where no rule is given but the faces are not oriented alike, after the build.
TEST_F(InsideCommand, LooksForIntersectingFacesByDefaultOnlyUnderParity) {
  write_file(dir_ / "two_cubes.obj", two_crossing_cubes_obj());
  write_file(dir_ / "two_cubes_turned.obj", two_crossing_cubes_obj("", 0, true));
  write_file(dir_ / "points.txt", "0.25 0.25 0.25\n");
  for (const unsigned threads : {2u, 1u}) {
    InsideCommandOptions options;
    options.json = true;
    options.mesh.threads = threads;
    options.mesh.path = (dir_ / "two_cubes.obj").string();
    const Outcome nonzero = run_file(options, dir_ / "points.txt");
    EXPECT_EQ(nonzero.err, "");
    EXPECT_NE(nonzero.out.find("\"intersecting_face_pairs\": null"), std::string::npos)
        << nonzero.out;
    options.mesh.self_intersection_check = SelfIntersectionCheck::always;
    const Outcome asked = run_file(options, dir_ / "points.txt");
    EXPECT_EQ(asked.err, "") << "under nonzero the count is reported, not warned of";
    EXPECT_NE(asked.out.find("\"intersecting_face_pairs\": 6"), std::string::npos) << asked.out;

    options.mesh.self_intersection_check = SelfIntersectionCheck::under_parity;
    options.mesh.path = (dir_ / "two_cubes_turned.obj").string();
    const Outcome turned_faces = run_file(options, dir_ / "points.txt");
    EXPECT_NE(turned_faces.out.find("\"intersecting_face_pairs\": 6"), std::string::npos)
        << turned_faces.out;
    EXPECT_NE(turned_faces.err.find("6 pairs of faces intersect"), std::string::npos)
        << turned_faces.err;
    options.mesh.self_intersection_check = SelfIntersectionCheck::never;
    const Outcome skipped = run_file(options, dir_ / "points.txt");
    EXPECT_NE(skipped.out.find("\"intersecting_face_pairs\": null"), std::string::npos)
        << skipped.out;
    EXPECT_EQ(skipped.err.find("pairs of faces intersect"), std::string::npos) << skipped.err;
  }
}

// The same two cubes after a flat pillow (two triangles on three collinear points, zero
// area, dropped by the classifier): the pairs are named by the file's face numbers (each
// shifted by the pillow's two faces), on two threads and on one, where the check once ran
// on the classifier's mesh without the pillow and named the wrong faces.
TEST_F(InsideCommand, IntersectingFacesAreNamedAsTheFileNumbersThemAfterFacesOfZeroArea) {
  write_file(dir_ / "pillow_and_cubes.obj",
             two_crossing_cubes_obj("v 5 0 0\nv 6 0 0\nv 7 0 0\nf 1 2 3\nf 1 3 2\n", 3));
  write_file(dir_ / "points.txt", "0.25 0.25 0.25\n");
  InsideCommandOptions options;
  options.mesh.path = (dir_ / "pillow_and_cubes.obj").string();
  options.mesh.rule = inside::FillRule::parity;
  for (const unsigned threads : {2u, 1u}) {
    options.mesh.threads = threads;
    const Outcome outcome = run_file(options, dir_ / "points.txt");
    ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
    EXPECT_NE(outcome.err.find("2 faces of zero area (first: 1, 2) bound nothing"),
              std::string::npos)
        << outcome.err;
    EXPECT_NE(outcome.err.find("6 pairs of faces intersect (first: 4-11, "), std::string::npos)
        << "threads " << threads << ": " << outcome.err;
  }
}

// Spot's control mesh: coarse, its quads far from planar, some neighbours bent through
// each other. By parity the intersecting pairs and the undecided ones are each said on
// their own, the undecided ones with what they are (all ten are neighbours) and what to
// do, in the file's numbering.
TEST_F(InsideCommand, SaysWhatUndecidedFacePairsAreAndWhatToDo) {
  write_file(dir_ / "points.txt", "0 0 0\n");
  InsideCommandOptions options;
  options.mesh.path = kMeshes + "spot/spot_control_mesh.obj";
  options.mesh.rule = inside::FillRule::parity;
  const Outcome outcome = run_file(options, dir_ / "points.txt");
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  const std::string prefix = "exactgeo inside: warning: " + options.mesh.path + ": ";
  EXPECT_NE(outcome.err.find(prefix + "8 pairs of faces intersect (first: 61-72, "),
            std::string::npos)
      << outcome.err;
  const std::size_t at = outcome.err.find(prefix + "10 pairs undecided (first: 37-38, 38-39, ");
  ASSERT_NE(at, std::string::npos) << outcome.err;
  const std::string undecided = outcome.err.substr(at, outcome.err.find('\n', at) - at);
  for (const char* part :
       {"could not decide (10 of the 10 share a corner)", "cannot tell touching from crossing",
        "If they only touch, the labels are right", "--rule nonzero labels by winding numbers",
        "`exactgeo info --mark OUT.ply` colours these faces magenta"}) {
    EXPECT_NE(undecided.find(part), std::string::npos) << part << " in " << undecided;
  }
  // By the default rule, intersections change no label: nothing is said about them.
  options.mesh.rule = std::nullopt;
  const Outcome nonzero = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(nonzero.err.find("undecided"), std::string::npos) << nonzero.err;
}

/// A cube of quads in OBJ with corners `lower` + `size` (0 or 1 per axis), its faces
/// counter-clockwise seen from outside (`reversed`: from inside), vertices numbered from
/// `first`; `flip_first` turns the first face alone.
std::string obj_cube(double lower, double size, int first, bool reversed = false,
                     bool flip_first = false) {
  std::string obj;
  for (int c = 0; c < 8; ++c)
    obj += "v " + std::to_string(lower + size * (c & 1)) + " " +
           std::to_string(lower + size * ((c >> 1) & 1)) + " " +
           std::to_string(lower + size * ((c >> 2) & 1)) + "\n";
  bool flip = flip_first;
  for (const auto& q : testing::kHexahedronFaces) {
    const bool turned = reversed != flip;
    flip = false;
    const std::array<VertexIndex, 4> c =
        turned ? std::array<VertexIndex, 4>{q[0], q[3], q[2], q[1]} : q;
    obj += "f";
    for (const VertexIndex v : c)
      obj.append(" ").append(std::to_string(static_cast<int>(v) + first));
    obj += "\n";
  }
  return obj;
}

// --winding prints the integers; the rules label by them (a shell in a shell alike: w = 2
// in the middle; a cube inside out: w = -1); the JSON says which rule labelled.
// Against an open surface --winding prints the generalized winding number: the open box
// (top face missing) holds 5/6 at its centre and 1/2 at the missing face's centre; above
// the hole at height 1/2, w = 4 asin(1/2) / 4 pi = 1/6. The value printed is the midpoint
// of the classifier's certified bounds, in the shortest decimal that reads back to it.
TEST_F(InsideCommand, WindingAgainstAnOpenSurfaceIsTheGeneralizedWindingNumber) {
  write_file(dir_ / "open_box.obj",
             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
             "f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n0.5 0.5 1\n0.5 0.5 1.5\n0.5 0.5 0\n");
  InsideCommandOptions options;
  options.mesh.path = (dir_ / "open_box.obj").string();
  options.winding = true;
  const Outcome r = run_file(options, dir_ / "points.txt");
  ASSERT_EQ(r.code, ExitCode::success) << r.err;
  std::istringstream lines(r.out);
  std::vector<std::string> printed;
  for (std::string line; std::getline(lines, line);)
    printed.push_back(line);
  ASSERT_EQ(printed.size(), 4u) << r.out;
  const std::vector<double> truth{5.0 / 6.0, 0.5, 1.0 / 6.0};
  const inside::Classifier classifier(mesh::load_mesh(options.mesh.path).mesh);
  const std::vector<Point3> points{{0.5, 0.5, 0.5}, {0.5, 0.5, 1}, {0.5, 0.5, 1.5}};
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const double w = std::stod(printed[i]);
    EXPECT_NEAR(w, truth[i], 1e-12) << printed[i];
    const auto bounds = classifier.generalized_winding_number(points[i]);
    ASSERT_TRUE(bounds);
    EXPECT_EQ(w, bounds->lower + (bounds->upper - bounds->lower) / 2) << printed[i];
  }
  EXPECT_EQ(printed[3], "boundary");
}

// --winding --json: the values beside the counts, in input order, null on the surface; the
// counts are the labels' (the open box's missing face centre, w = 1/2 exactly, is
// undecided, not rounded to a side by its printed value).
// The space cells are sized to the points the file holds: for a few points, a grid much
// coarser than the mesh's own; from standard input (count unknown), the mesh's own.
TEST_F(InsideCommand, SpaceCellsAreSizedToThePointsFile) {
  write_file(dir_ / "cube.obj", obj_cube(0, 1, 1));
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n2 2 2\n");
  InsideCommandOptions options;
  options.mesh.path = (dir_ / "cube.obj").string();
  options.json = true;
  const Outcome from_file = run_file(options, dir_ / "points.txt");
  ASSERT_EQ(from_file.code, ExitCode::success) << from_file.err;
  const auto cells = [](const std::string& json) {
    const std::size_t at = json.find("\"cells\": ");
    return at == std::string::npos ? 0ul : std::stoul(json.substr(at + 9));
  };
  // The grid the classifier builds for the mesh alone.
  const std::size_t by_mesh =
      inside::Classifier(mesh::load_mesh(options.mesh.path).mesh).space_cells()->cells;
  const std::size_t few = cells(from_file.out);
  EXPECT_GT(few, 0u) << from_file.out;
  EXPECT_LT(few, by_mesh / 8) << from_file.out;
  const Outcome from_stdin = run_stdin(options, "0.5 0.5 0.5\n2 2 2\n");
  ASSERT_EQ(from_stdin.code, ExitCode::success) << from_stdin.err;
  EXPECT_EQ(cells(from_stdin.out), by_mesh) << from_stdin.out;
  for (const Outcome* r : {&from_file, &from_stdin})
    EXPECT_NE(r->out.find("\"inside\": 1, \"outside\": 1"), std::string::npos) << r->out;
}

TEST_F(InsideCommand, WindingWithJsonHasTheValuesBesideTheCounts) {
  write_file(dir_ / "open_box.obj",
             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
             "f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  write_file(dir_ / "nested.obj", obj_cube(0, 1, 1) + obj_cube(0.25, 0.5, 9));
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n0.5 0.5 1\n2 2 2\n0 0.5 0.5\n");
  InsideCommandOptions options;
  options.winding = true;
  options.json = true;
  options.mesh.path = (dir_ / "open_box.obj").string();
  Outcome r = run_file(options, dir_ / "points.txt");
  ASSERT_EQ(r.code, ExitCode::success) << r.err;
  const double centre = 5.0 / 6.0;
  const double far = inside::Classifier(mesh::load_mesh(options.mesh.path).mesh)
                         .generalized_winding_number({2, 2, 2})
                         .value()
                         .lower;
  EXPECT_NE(r.out.find("\"points\": 4, \"inside\": 1, \"outside\": 1, \"boundary\": 1, "
                       "\"undecided\": 1,"),
            std::string::npos)
      << r.out;
  const std::size_t values = r.out.find("\"winding_numbers\": [");
  ASSERT_NE(values, std::string::npos) << r.out;
  std::istringstream list(r.out.substr(values + 20));
  std::vector<std::string> printed;
  for (std::string value; std::getline(list, value, ',');)
    printed.push_back(value.substr(value.find_first_not_of(' ')));
  ASSERT_EQ(printed.size(), 4u) << r.out;
  EXPECT_NEAR(std::stod(printed[0]), centre, 1e-12);
  EXPECT_EQ(std::stod(printed[1]), 0.5);
  EXPECT_NEAR(std::stod(printed[2]), far, 1e-12);
  EXPECT_EQ(printed[3], "null]}\n");
  write_file(dir_ / "nested_points.txt", "0.5 0.5 0.5\n0.1 0.5 0.5\n2 2 2\n0 0.5 0.5\n");
  options.mesh.path = (dir_ / "nested.obj").string();
  r = run_file(options, dir_ / "nested_points.txt");
  ASSERT_EQ(r.code, ExitCode::success) << r.err;
  EXPECT_NE(r.out.find("\"inside\": 2, \"outside\": 1, \"boundary\": 1"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"winding_numbers\": [2, 1, 0, null]}"), std::string::npos) << r.out;
}

TEST_F(InsideCommand, WindingNumbersAndRules) {
  write_file(dir_ / "nested.obj", obj_cube(0, 1, 1) + obj_cube(0.25, 0.5, 9));
  write_file(dir_ / "cavity.obj", obj_cube(0, 1, 1) + obj_cube(0.25, 0.5, 9, /*reversed=*/true));
  write_file(dir_ / "inverted.obj", obj_cube(0, 1, 1, /*reversed=*/true));
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n0.1 0.5 0.5\n2 2 2\n0 0.5 0.5\n");
  InsideCommandOptions options;
  options.winding = true;
  for (const auto& [file, windings] : std::vector<std::pair<std::string, std::string>>{
           {"nested.obj", "2\n1\n0\nboundary\n"},
           {"cavity.obj", "0\n1\n0\nboundary\n"},
           {"inverted.obj", "-1\n-1\n0\nboundary\n"}}) {
    options.mesh.path = (dir_ / file).string();
    const Outcome r = run_file(options, dir_ / "points.txt");
    ASSERT_EQ(r.code, ExitCode::success) << r.err;
    EXPECT_EQ(r.out, windings) << file;
    EXPECT_EQ(r.err, "") << file;
  }
  options.winding = false;
  options.mesh.self_intersection_check = SelfIntersectionCheck::never;
  const std::string both_inside = "inside\ninside\noutside\nboundary\n";
  const std::string middle_out = "outside\ninside\noutside\nboundary\n";
  const std::string all_out = "outside\noutside\noutside\nboundary\n";
  for (const auto& [file, rule, labels] :
       std::vector<std::tuple<std::string, inside::FillRule, std::string>>{
           {"nested.obj", inside::FillRule::nonzero, both_inside},
           {"nested.obj", inside::FillRule::parity, middle_out},
           {"nested.obj", inside::FillRule::positive, both_inside},
           {"inverted.obj", inside::FillRule::nonzero, both_inside},
           {"inverted.obj", inside::FillRule::parity, both_inside},
           {"inverted.obj", inside::FillRule::positive, all_out}}) {
    options.mesh.path = (dir_ / file).string();
    options.mesh.rule = rule;
    const Outcome r = run_file(options, dir_ / "points.txt");
    EXPECT_EQ(r.out, labels) << file << " " << to_string(rule);
  }
  options.json = true;
  const Outcome r = run_file(options, dir_ / "points.txt");
  EXPECT_NE(r.out.find("\"rule\": \"positive\""), std::string::npos) << r.out;
}

// A cube with one face turned: the default rule labels it by parity and says why; a
// winding rule asked for refuses it and names --rule parity; --winding refuses it; and
// --winding with the float ray baseline is refused before any work.
TEST_F(InsideCommand, FacesNotOrientedAlike) {
  write_file(dir_ / "turned.obj", obj_cube(0, 1, 1, /*reversed=*/false, /*flip_first=*/true));
  write_file(dir_ / "points.txt", "0.5 0.5 0.5\n2 0.5 0.5\n");
  InsideCommandOptions options;
  options.mesh.path = (dir_ / "turned.obj").string();
  Outcome r = run_file(options, dir_ / "points.txt");
  ASSERT_EQ(r.code, ExitCode::success) << r.err;
  EXPECT_EQ(r.out, "inside\noutside\n");
  EXPECT_NE(r.err.find("warning: " + options.mesh.path +
                       ": the faces are not oriented alike (some edge is used more often in one "
                       "direction than in the other), so they have no winding numbers: labelled "
                       "by crossing parity (--rule parity)"),
            std::string::npos)
      << r.err;
  options.mesh.rule = inside::FillRule::nonzero;
  r = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(r.code, ExitCode::input_error);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find(": faces not oriented alike: 4 edges are run the same way by two more faces "
                       "than the other way (first: 1-2, "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("(vertices and faces numbered from 1, as in the file); --rule parity, "
                       "which needs no orientation, accepts it"),
            std::string::npos)
      << r.err;
  options.mesh.rule.reset();
  options.winding = true;
  r = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(r.code, ExitCode::input_error);
  EXPECT_NE(r.err.find("no winding numbers"), std::string::npos) << r.err;
  options.mesh.float_rays = true;
  r = run_file(options, dir_ / "points.txt");
  EXPECT_EQ(r.code, ExitCode::input_error);
  EXPECT_NE(r.err.find("--winding needs the classifier"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace exactgeo::cli
