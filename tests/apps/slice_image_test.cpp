// `exactgeo inside MESH --slice AXIS=VALUE --image FILE.png` end to end (run_inside on mesh
// files, the picture read back with libpng): the size asked for, up is up, every pixel the
// colour of the classifier's label of its centre (recomputed point by point), the outline
// on the plane's intersection with the faces (against an oracle that samples each face
// densely, quads skew or flat, and triangles), and errors that leave no file behind.

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli/inside_command.hpp"
#include "cli/output_file.hpp"
#include "cli/png_image.hpp"
#include "cli/slice_image.hpp"
#include "cli/slice_options.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "support/hexahedron.hpp"
#include "support/scratch_dir.hpp"

namespace exactgeo::cli {
namespace {

namespace fs = std::filesystem;
using inside::Location;

const std::string kSpot =
    std::string(EXACTGEO_TEST_DATA_DIR) + "/meshes/spot/spot_quadrangulated.obj";

/// A hexahedron with the given corners (corner (i, j, k) is vertex i + 2j + 4k), in quads
/// or with every quad split along c0-c2 into two triangles.
mesh::Mesh hexahedron(const std::array<Point3, 8>& corners, bool triangles = false) {
  mesh::Mesh m;
  m.vertices.assign(corners.begin(), corners.end());
  for (const auto& q : testing::kHexahedronFaces) {
    if (triangles) {
      m.faces.push_back(mesh::make_triangle(q[0], q[1], q[2]));
      m.faces.push_back(mesh::make_triangle(q[0], q[2], q[3]));
    } else {
      m.faces.push_back(mesh::make_quad(q[0], q[1], q[2], q[3]));
    }
  }
  return m;
}

/// The unit cube with corner (1, 1, 1) raised to z = 1.5: its top quad and two side quads
/// are skew bilinear patches.
mesh::Mesh twisted_cube() {
  auto corners = testing::unit_cube_corners();
  corners[7][2] = 1.5;
  return hexahedron(corners);
}

/// A frustum: x in [0, 2] at y = 0 narrowing to [0.5, 1.5] at y = 1, z in [0, 1]. A slice
/// z = c is a trapezoid wider at the bottom, which tells up from down.
mesh::Mesh frustum(bool triangles = false) {
  std::array<Point3, 8> corners;
  for (int c = 0; c < 8; ++c) {
    const int i = c & 1, j = (c >> 1) & 1, k = (c >> 2) & 1;
    corners[static_cast<std::size_t>(c)] = {j == 0 ? 2.0 * i : 0.5 + i, double(j), double(k)};
  }
  return hexahedron(corners, triangles);
}

void write_obj(const fs::path& path, const mesh::Mesh& m) {
  std::ofstream out(path);
  char line[128];
  for (const Point3& v : m.vertices) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v[0], v[1], v[2]);
    out << line;
  }
  for (const mesh::Face& f : m.faces) {
    out << "f";
    for (std::size_t i = 0; i < f.size(); ++i)
      out << " " << f.corners[i] + 1;
    out << "\n";
  }
}

/// The PNG file read back with libpng, as 8-bit RGB.
RgbImage read_png(const fs::path& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, path.c_str()) == 0) {
    ADD_FAILURE() << path << ": " << png.message;
    return {};
  }
  png.format = PNG_FORMAT_RGB;
  RgbImage image{png.width, png.height, std::vector<std::uint8_t>(PNG_IMAGE_SIZE(png))};
  if (png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr) == 0) {
    ADD_FAILURE() << path << ": " << png.message;
    return {};
  }
  return image;
}

Rgb pixel_at(const RgbImage& image, std::size_t column, std::size_t row) {
  const std::size_t i = 3 * (row * image.width + column);
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

/// The number after "key": in a JSON object (-1 if it is missing).
double json_number(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return -1;
  return std::stod(json.substr(at + key.size() + 4));
}

struct Outcome {
  ExitCode code;
  std::string out, err;
};

class SliceImage : public ::testing::Test {
 protected:
  const testing::ScratchDir scratch_{"exactgeo_slice"};
  const fs::path& dir_ = scratch_.path;

  /// Runs `inside MESH --slice TEXT --image dir/NAME --resolution N --json` as the binary would.
  Outcome run(const std::string& mesh_path, const std::string& slice, unsigned resolution,
              const std::string& name = "slice.png", unsigned threads = 2,
              bool float_rays = false) {
    InsideCommandOptions options;
    options.mesh.path = mesh_path;
    std::string error;
    options.slice.plane = parse_slice(slice, error);
    EXPECT_TRUE(options.slice.plane) << error;
    options.slice.image = (dir_ / name).string();
    options.slice.resolution = resolution;
    options.mesh.threads = threads;
    options.mesh.float_rays = float_rays;
    options.json = true;
    std::istringstream in;
    std::ostringstream out, err;
    const ExitCode code = run_inside(options, in, "-", out, err);
    return {code, out.str(), err.str()};
  }

  fs::path mesh_file(const mesh::Mesh& m, const std::string& name) {
    const fs::path path = dir_ / name;
    write_obj(path, m);
    return path;
  }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

/// Renders `mesh` at the plane and checks every pixel against the classifier's label of
/// the pixel's centre, computed here one point at a time: a pixel not on the outline has
/// exactly its label's colour, an outline pixel is black and its centre not on the
/// surface (boundary pixels stay visible). The JSON counts are the labels' counts.
void expect_pixels_are_labels(const Outcome& outcome, const fs::path& png, const mesh::Mesh& m,
                              const std::string& slice, unsigned resolution) {
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  std::string error;
  const SliceGrid grid = slice_grid(m, *parse_slice(slice, error), resolution);
  const RgbImage image = read_png(png);
  ASSERT_EQ(image.width, grid.width);
  ASSERT_EQ(image.height, grid.height);
  const inside::Classifier classifier(m);
  std::array<double, 4> counts{};
  std::size_t outline = 0;
  for (std::size_t row = 0; row < grid.height; ++row) {
    for (std::size_t column = 0; column < grid.width; ++column) {
      const Location label = classifier.classify(grid.pixel_centre(column, row));
      counts[static_cast<std::size_t>(label)] += 1;
      const Rgb colour = pixel_at(image, column, row);
      if (colour == colour_of(PixelKind::outline)) {
        ++outline;
        EXPECT_NE(label, Location::boundary) << "pixel " << column << ", " << row;
      } else {
        EXPECT_EQ(colour, colour_of(pixel_kind(label, false)))
            << slice << ": pixel " << column << ", " << row << " labelled " << to_string(label);
      }
    }
  }
  EXPECT_EQ(json_number(outcome.out, "inside"), counts[1]) << outcome.out;
  EXPECT_EQ(json_number(outcome.out, "outside"), counts[0]) << outcome.out;
  EXPECT_EQ(json_number(outcome.out, "boundary"), counts[2]) << outcome.out;
  EXPECT_EQ(json_number(outcome.out, "undecided"), counts[3]) << outcome.out;
  EXPECT_EQ(json_number(outcome.out, "outline"), double(outline)) << outcome.out;
  EXPECT_GT(outline, 0u);
}

TEST(SliceOption, ParsesAxisAndExactValue) {
  std::string error;
  auto plane = parse_slice("z=0.3", error);
  ASSERT_TRUE(plane) << error;
  EXPECT_EQ(plane->axis, Axis::z);
  EXPECT_EQ(plane->value, 0.3);
  plane = parse_slice("x=-0x1.8p-2", error);
  ASSERT_TRUE(plane) << error;
  EXPECT_EQ(plane->axis, Axis::x);
  EXPECT_EQ(plane->value, -0.375);
  plane = parse_slice("y=4.9406564584124654e-324", error);  // the smallest subnormal
  ASSERT_TRUE(plane) << error;
  EXPECT_EQ(plane->axis, Axis::y);
  EXPECT_EQ(plane->value, 0x1p-1074);
  for (const char* bad :
       {"",     "z",    "z=",    "=1",    "w=1",   "Z=1",    "zz=1",    "z==1", "z=1=2", " z=1",
        "z=1 ", "z= 1", "z=abc", "z=nan", "z=inf", "z=-inf", "z=1e999", "z=0x", "z=1,5", "z=--1"}) {
    error.clear();
    EXPECT_FALSE(parse_slice(bad, error)) << "'" << bad << "'";
    EXPECT_NE(error, "") << "'" << bad << "'";
  }
}

TEST(SliceGridRule, CoversTheBoxWithSquarePixelsAndTheAxesOfTheRule) {
  const mesh::Mesh m = frustum();  // x in [0, 2], y in [0, 1], z in [0, 1]
  const SliceGrid z = slice_grid(m, {Axis::z, 0.5}, 64);
  // The longer side (x, 2 + 2 * 2/32) has 64 pixels; y needs ceil(1.125 / pixel) of them.
  EXPECT_EQ(z.width, 64u);
  EXPECT_EQ(z.height, 34u);
  EXPECT_DOUBLE_EQ(z.pixel, 2.125 / 64);
  // Right is +x, up is +y, the first row on top; the box lies inside the picture.
  const Point3 top_left = z.pixel_centre(0, 0), bottom_right = z.pixel_centre(63, 33);
  EXPECT_LT(top_left[0], 0.0);
  EXPECT_GT(top_left[1], 1.0);
  EXPECT_GT(bottom_right[0], 2.0);
  EXPECT_LT(bottom_right[1], 0.0);
  EXPECT_EQ(top_left[2], 0.5);
  // x = c: right is +y, up is +z; y = c: right is +x, up is +z.
  const SliceGrid x = slice_grid(m, {Axis::x, 1.0}, 32);
  EXPECT_LT(x.pixel_centre(0, 0)[1], x.pixel_centre(1, 0)[1]);
  EXPECT_GT(x.pixel_centre(0, 0)[2], x.pixel_centre(0, 1)[2]);
  EXPECT_EQ(x.pixel_centre(5, 7)[0], 1.0);
  const SliceGrid y = slice_grid(m, {Axis::y, 0.25}, 32);
  EXPECT_LT(y.pixel_centre(0, 0)[0], y.pixel_centre(1, 0)[0]);
  EXPECT_GT(y.pixel_centre(0, 0)[2], y.pixel_centre(0, 1)[2]);
  EXPECT_EQ(y.width, 32u);
  EXPECT_EQ(y.height, 17u);
}

TEST_F(SliceImage, SizeAndColoursFollowTheGeometry) {
  const fs::path mesh_path = mesh_file(frustum(), "frustum.obj");
  const Outcome outcome = run(mesh_path.string(), "z=0.5", 64);
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  const RgbImage image = read_png(dir_ / "slice.png");
  ASSERT_EQ(image.width, 64u);
  ASSERT_EQ(image.height, 34u);
  // Pixel (column, row) covers x in left + [column, column + 1] * pixel, y in top -
  // [row + 1, row] * pixel, with pixel = 2.125 / 64 and the picture centred on the box.
  const double pixel = 2.125 / 64, left = 1.0 - 32 * pixel, top = 0.5 + 17 * pixel;
  const auto at = [&](double x, double y) {
    return pixel_at(image, std::size_t((x - left) / pixel), std::size_t((top - y) / pixel));
  };
  const Rgb inside = colour_of(PixelKind::inside), outside = colour_of(PixelKind::outside);
  EXPECT_EQ(at(1.0, 0.5), inside);
  EXPECT_EQ(at(0.2, 0.1), inside);   // the wide bottom
  EXPECT_EQ(at(0.2, 0.9), outside);  // beside the narrow top: up is up
  EXPECT_EQ(at(1.8, 0.9), outside);
  EXPECT_EQ(at(0.6, 0.9), inside);
  EXPECT_EQ(at(-0.05, 0.5), outside);
  EXPECT_EQ(at(1.0, 1.05), outside);
  EXPECT_EQ(pixel_at(image, 0, 0), outside);
  EXPECT_EQ(pixel_at(image, 63, 33), outside);
  for (const char* key :
       {"\"width\": 64", "\"height\": 34", "\"plane\": {\"axis\": \"z\", \"value\": 0.5}",
        "\"horizontal\": {\"axis\": \"x\"", "\"vertical\": {\"axis\": \"y\"",
        "\"plane_meets_box\": true", "\"method\": \"exact\""}) {
    EXPECT_NE(outcome.out.find(key), std::string::npos) << key << " in " << outcome.out;
  }
  EXPECT_EQ(files(), (std::vector<std::string>{"frustum.obj", "slice.png"}));
}

TEST_F(SliceImage, EveryPixelIsTheLabelOfItsCentre) {
  struct Case {
    mesh::Mesh mesh;
    std::string name, slice;
    unsigned resolution;
  };
  const mesh::Mesh spot = mesh::load_mesh(kSpot).mesh;
  const std::vector<Case> cases{
      {frustum(), "frustum.obj", "z=0.3", 40},
      {frustum(true), "frustum_triangles.obj", "x=0.7", 40},
      {twisted_cube(), "twisted.obj", "z=1.2", 48},
      {twisted_cube(), "twisted.obj", "y=0.75", 48},
      {spot, "spot.obj", "z=0.1", 64},
      {spot, "spot.obj", "x=0x1.8p-3", 64},
      {spot, "spot.obj", "y=-0.5", 64},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name + " " + c.slice);
    const fs::path path = mesh_file(c.mesh, c.name);
    const Outcome outcome = run(path.string(), c.slice, c.resolution);
    expect_pixels_are_labels(outcome, dir_ / "slice.png", c.mesh, c.slice, c.resolution);
  }
}

TEST_F(SliceImage, AFaceInThePlaneShowsItsPointsAsBoundary) {
  // z = 1 is the cube's top face: the pixel centres on it are exactly on the surface.
  auto corners = testing::unit_cube_corners();
  const mesh::Mesh cube = hexahedron(corners);
  const fs::path path = mesh_file(cube, "cube.obj");
  const Outcome outcome = run(path.string(), "z=1", 32);
  expect_pixels_are_labels(outcome, dir_ / "slice.png", cube, "z=1", 32);
  const RgbImage image = read_png(dir_ / "slice.png");
  EXPECT_EQ(pixel_at(image, 16, 16), colour_of(PixelKind::boundary));
  EXPECT_GT(json_number(outcome.out, "boundary"), 0.5 * 32 * 32);
  EXPECT_EQ(json_number(outcome.out, "inside"), 0);
}

TEST_F(SliceImage, AnOpenBoxCutAtItsMissingFaceShowsUndecidedPixels) {
  // The unit cube without its top face (z = 1): from a point of the plane z = 1 inside the
  // hole the five other faces fill half of the sphere, so w = 1/2 exactly, which no
  // precision settles. The picture has its own colour for those pixels.
  mesh::Mesh box = hexahedron(testing::unit_cube_corners());
  box.faces.erase(box.faces.begin() + 1);  // {4, 5, 7, 6}, z = upper
  const fs::path path = mesh_file(box, "open_box.obj");
  const Outcome outcome = run(path.string(), "z=1", 16);
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  const RgbImage image = read_png(dir_ / "slice.png");
  EXPECT_EQ(pixel_at(image, 8, 8), colour_of(PixelKind::undecided));
  EXPECT_EQ(colour_of(PixelKind::undecided), (Rgb{204, 121, 167}));
  EXPECT_GT(json_number(outcome.out, "undecided"), 0.5 * 16 * 16) << outcome.out;
  EXPECT_EQ(json_number(outcome.out, "inside"), 0) << outcome.out;
}

/// The text of docs/inside.md, where the picture's colours and JSON keys are documented.
std::string inside_docs() {
  std::ifstream in(std::string(EXACTGEO_DOCS_DIR) + "/inside.md");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The rows of the Markdown table whose header row is `header`, up to its first blank line.
std::vector<std::string> table_rows(const std::string& text, const std::string& header) {
  std::vector<std::string> rows;
  std::size_t at = text.find(header);
  if (at == std::string::npos) return rows;
  at = text.find('\n', at);
  for (std::size_t end = text.find('\n', at + 1); end != std::string::npos;
       at = end, end = text.find('\n', at + 1)) {
    std::string line = text.substr(at + 1, end - at - 1);
    line.erase(0, line.find_first_not_of(' '));
    if (line.empty() || line[0] != '|') break;
    rows.push_back(line);
  }
  return rows;
}

TEST(SliceDocs, TheColourTableHasEveryPixelKindInItsColour) {
  const std::vector<std::string> rows = table_rows(inside_docs(), "| pixel | colour | RGB |");
  ASSERT_FALSE(rows.empty()) << "no colour table in docs/inside.md";
  // Each kind's row is found by what it says; its last cell is the colour's RGB.
  const std::vector<std::pair<PixelKind, std::string>> kinds{{PixelKind::inside, "`inside`"},
                                                             {PixelKind::outside, "`outside`"},
                                                             {PixelKind::boundary, "`boundary`"},
                                                             {PixelKind::undecided, "`undecided`"},
                                                             {PixelKind::outline, "cross-section"}};
  for (const auto& [kind, says] : kinds) {
    const Rgb c = colour_of(kind);
    const std::string rgb = "| " + std::to_string(c.red) + ", " + std::to_string(c.green) + ", " +
                            std::to_string(c.blue) + " |";
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const std::string& r) {
      return r.find(says) != std::string::npos;
    });
    ASSERT_NE(row, rows.end()) << "no row for " << says << " in docs/inside.md's colour table";
    EXPECT_EQ(row->substr(row->size() - rgb.size()), rgb) << *row;
  }
  EXPECT_EQ(rows.size(), kinds.size() + 1);  // and the separator row
}

TEST_F(SliceImage, TheDocsListTheJsonKeysInOrder) {
  const fs::path path = mesh_file(frustum(), "frustum.obj");
  const Outcome outcome = run(path.string(), "z=0.5", 16);
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  // The object's own keys: those at nesting depth 1.
  std::vector<std::string> keys;
  int depth = 0;
  for (std::size_t i = 0; i < outcome.out.size(); ++i) {
    const char c = outcome.out[i];
    if (c == '{') ++depth;
    if (c == '}') --depth;
    if (c == '"' && depth == 1) {
      const std::size_t end = outcome.out.find('"', i + 1);
      if (outcome.out.compare(end, 3, "\": ") == 0)
        keys.push_back(outcome.out.substr(i + 1, end - i - 1));
      i = end;
    }
  }
  // "--json` prints them as one object (`image`, `width`, ...)" in docs/inside.md.
  const std::string docs = inside_docs();
  const std::size_t start = docs.find("prints them as one\n  object (");
  ASSERT_NE(start, std::string::npos) << "the slice's JSON keys are no longer listed there";
  const std::size_t end = docs.find(')', start);
  std::vector<std::string> listed;
  for (std::size_t at = docs.find('`', start); at < end; at = docs.find('`', at + 1)) {
    const std::size_t close = docs.find('`', at + 1);
    listed.push_back(docs.substr(at + 1, close - at - 1));
    at = close;
  }
  EXPECT_EQ(listed, keys) << outcome.out;
}

/// Points of the faces' intersection with the plane, sampled densely and independently of
/// the drawing: on a face p(u, v), for each of n values of u, f = p[axis] - value is
/// linear in v between its values on the edges v = 0 and v = 1, so its zero there is
/// found by interpolation; the same for each v. Returned in pixel units.
std::vector<std::array<double, 2>> cross_section_samples(const mesh::Mesh& m, const SliceGrid& grid,
                                                         int n) {
  const std::size_t axis = static_cast<std::size_t>(grid.plane.axis);
  const ImageAxes axes = image_axes(grid.plane.axis);
  std::vector<std::array<double, 2>> samples;
  for (const mesh::Face& face : m.faces) {
    const BilinearPatch p = mesh::patch_of(m, face);
    const auto point = [&](double u, double v) {
      Point3 q;
      for (std::size_t c = 0; c < 3; ++c) {
        q[c] = (1 - u) * (1 - v) * p.p00[c] + u * (1 - v) * p.p10[c] + u * v * p.p11[c] +
               (1 - u) * v * p.p01[c];
      }
      return q;
    };
    const auto add = [&](const Point3& q) {
      samples.push_back({(q[axes.horizontal] - grid.left) / grid.pixel,
                         (grid.top - q[axes.vertical]) / grid.pixel});
    };
    for (int i = 0; i <= n; ++i) {
      const double t = double(i) / n;
      // u = t: f(t, 0) = a, f(t, 1) = b.
      double a = point(t, 0)[axis] - grid.plane.value, b = point(t, 1)[axis] - grid.plane.value;
      if (a != b && (a <= 0) == (b >= 0)) add(point(t, a / (a - b)));
      a = point(0, t)[axis] - grid.plane.value;
      b = point(1, t)[axis] - grid.plane.value;
      if (a != b && (a <= 0) == (b >= 0)) add(point(a / (a - b), t));
    }
  }
  return samples;
}

/// The pixels whose squares lie within `reach` pixel units of `s`.
std::vector<std::size_t> pixels_near(const SliceGrid& grid, const std::array<double, 2>& s,
                                     double reach) {
  std::vector<std::size_t> near;
  const auto first = [](double x) { return long(std::floor(x)); };
  for (long row = first(s[1] - reach); row <= first(s[1] + reach); ++row) {
    for (long column = first(s[0] - reach); column <= first(s[0] + reach); ++column) {
      if (row < 0 || column < 0 || row >= long(grid.height) || column >= long(grid.width)) continue;
      const double dx = std::max({double(column) - s[0], 0.0, s[0] - double(column + 1)});
      const double dy = std::max({double(row) - s[1], 0.0, s[1] - double(row + 1)});
      if (std::hypot(dx, dy) <= reach)
        near.push_back(std::size_t(row) * grid.width + std::size_t(column));
    }
  }
  return near;
}

TEST_F(SliceImage, OutlineLiesWhereThePlaneCrossesTheFaces) {
  struct Case {
    mesh::Mesh mesh;
    std::string name, slice;
    unsigned resolution;
  };
  const std::vector<Case> cases{
      {frustum(), "frustum.obj", "z=0.3", 64},
      {frustum(true), "frustum_triangles.obj", "z=0.3", 64},
      {frustum(true), "frustum_triangles.obj", "x=0.3", 64},
      {twisted_cube(), "twisted.obj", "z=1.2", 96},
      {twisted_cube(), "twisted.obj", "x=0.6", 96},
      {mesh::load_mesh(kSpot).mesh, "spot.obj", "z=0.1", 128},
      {mesh::load_mesh(kSpot).mesh, "spot.obj", "y=-0.5", 128},
  };
  // Pixel units. An outline pixel must hold a point of the curve (up to rounding and the
  // samples' spacing); every point of the curve must be that close to an outline pixel,
  // or, where the 1-pixel line steps diagonally past a pixel's corner, within 1/4 pixel.
  constexpr double kOnCurve = 0.05, kCornerCut = 0.26;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name + " " + c.slice);
    const fs::path path = mesh_file(c.mesh, c.name);
    const Outcome outcome = run(path.string(), c.slice, c.resolution);
    ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
    std::string error;
    const SliceGrid grid = slice_grid(c.mesh, *parse_slice(c.slice, error), c.resolution);
    const RgbImage image = read_png(dir_ / "slice.png");
    ASSERT_EQ(image.width, grid.width);
    const auto samples = cross_section_samples(c.mesh, grid, 4096);
    ASSERT_GT(samples.size(), 100u);
    // Near: pixels within reach of the curve. Every outline pixel must be one, and every
    // point of the curve must have an outline (or boundary) pixel within reach.
    std::vector<bool> near(grid.pixels(), false);
    std::size_t uncovered = 0;
    for (const auto& s : samples) {
      bool covered = false;
      for (const std::size_t i : pixels_near(grid, s, kOnCurve))
        near[i] = true;
      for (const std::size_t i : pixels_near(grid, s, kCornerCut)) {
        const Rgb colour = pixel_at(image, i % grid.width, i / grid.width);
        covered |=
            colour == colour_of(PixelKind::outline) || colour == colour_of(PixelKind::boundary);
      }
      if (!covered && ++uncovered <= 5) {
        ADD_FAILURE() << "no outline pixel at the curve's point (" << s[0] << ", " << s[1]
                      << ") px";
      }
    }
    EXPECT_EQ(uncovered, 0u);
    std::size_t outline = 0, far = 0;
    for (std::size_t i = 0; i < grid.pixels(); ++i) {
      if (pixel_at(image, i % grid.width, i / grid.width) != colour_of(PixelKind::outline))
        continue;
      ++outline;
      if (!near[i] && ++far <= 5) {
        ADD_FAILURE() << "outline pixel " << i % grid.width << ", " << i / grid.width
                      << " is not on the curve";
      }
    }
    EXPECT_EQ(far, 0u);
    EXPECT_GT(outline, std::size_t(c.resolution));
  }
}

TEST_F(SliceImage, APlaneAboveTheMeshIsAllOutside) {
  const fs::path path = mesh_file(twisted_cube(), "twisted.obj");
  const Outcome outcome = run(path.string(), "z=1.75", 32);
  ASSERT_EQ(outcome.code, ExitCode::success) << outcome.err;
  const RgbImage image = read_png(dir_ / "slice.png");
  ASSERT_EQ(image.width, 32u);
  ASSERT_EQ(image.height, 32u);
  for (std::size_t row = 0; row < 32; ++row) {
    for (std::size_t column = 0; column < 32; ++column) {
      ASSERT_EQ(pixel_at(image, column, row), colour_of(PixelKind::outside))
          << column << ", " << row;
    }
  }
  EXPECT_EQ(json_number(outcome.out, "outside"), 32 * 32);
  EXPECT_EQ(json_number(outcome.out, "outline"), 0);
  EXPECT_NE(outcome.out.find("\"plane_meets_box\": false"), std::string::npos) << outcome.out;
}

TEST_F(SliceImage, ThreadsAndMethodsGiveTheSamePicture) {
  const fs::path path = mesh_file(frustum(), "frustum.obj");
  ASSERT_EQ(run(path.string(), "y=0.4", 200, "one.png", 1).code, ExitCode::success);
  ASSERT_EQ(run(path.string(), "y=0.4", 200, "three.png", 3).code, ExitCode::success);
  // The float ray baseline agrees on a box far from its vertices and edges.
  const Outcome embree = run(path.string(), "y=0.4", 200, "embree.png", 2, true);
  ASSERT_EQ(embree.code, ExitCode::success) << embree.err;
  EXPECT_NE(embree.out.find("\"method\": \"embree\""), std::string::npos) << embree.out;
  const auto bytes = [&](const char* name) {
    std::ifstream in(dir_ / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes("one.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_EQ(bytes("one.png"), bytes("three.png"));
  EXPECT_EQ(bytes("one.png"), bytes("embree.png"));
}

TEST_F(SliceImage, ErrorsLeaveNoFileBehind) {
  const fs::path path = mesh_file(frustum(), "frustum.obj");
  // A directory that does not exist: exit 2, the file named, nothing on stdout.
  Outcome outcome = run(path.string(), "z=0.5", 32, "missing/slice.png");
  EXPECT_EQ(outcome.code, ExitCode::input_error);
  EXPECT_EQ(outcome.out, "");
  EXPECT_NE(outcome.err.find("cannot write '" + (dir_ / "missing/slice.png").string() + "': "),
            std::string::npos)
      << outcome.err;
  // A mesh that cannot be read: no image, and the temporary file removed.
  outcome = run((dir_ / "nonexistent.obj").string(), "z=0.5", 32);
  EXPECT_EQ(outcome.code, ExitCode::input_error);
  EXPECT_EQ(outcome.out, "");
  EXPECT_NE(outcome.err.find("nonexistent.obj"), std::string::npos) << outcome.err;
  // The image's name taken by a directory: the rename fails, nothing else is left.
  fs::create_directory(dir_ / "taken.png");
  outcome = run(path.string(), "z=0.5", 32, "taken.png");
  EXPECT_EQ(outcome.code, ExitCode::input_error);
  EXPECT_EQ(outcome.out, "");
  EXPECT_NE(outcome.err.find("taken.png"), std::string::npos) << outcome.err;
  EXPECT_TRUE(fs::is_empty(dir_ / "taken.png"));
  EXPECT_EQ(files(), (std::vector<std::string>{"frustum.obj", "taken.png"}));
}

TEST_F(SliceImage, PngFileIsWholeOrAbsent) {
  const fs::path path = dir_ / "image.png";
  EXPECT_THROW((void)png_bytes(RgbImage{4, 4, std::vector<std::uint8_t>(47)}),
               std::invalid_argument);
  {
    OutputFile png(path.string());  // dropped unwritten: nothing stays
    EXPECT_EQ(files().size(), 1u);  // the temporary file, reserved
  }
  EXPECT_TRUE(files().empty());
  OutputFile png(path.string());
  png.commit(png_bytes(RgbImage{2, 1, {255, 0, 0, 0, 0, 255}}));
  EXPECT_THROW(png.commit("again"), OutputFileError);
  const RgbImage back = read_png(path);
  EXPECT_EQ(back.width, 2u);
  EXPECT_EQ(back.height, 1u);
  EXPECT_EQ(back.pixels, (std::vector<std::uint8_t>{255, 0, 0, 0, 0, 255}));
  EXPECT_EQ(files(), std::vector<std::string>{"image.png"});
}

}  // namespace
}  // namespace exactgeo::cli
