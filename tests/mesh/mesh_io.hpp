#pragma once

// What the mesh readers' tests share: files written from a Mesh (OBJ, OFF, PLY in any
// layout and byte order), the binary values they hold, the mesh_io fixture (a test with its
// own temporary directory, loading what it writes there), and the messages of the errors
// thrown (EXPECT_MESSAGE_HAS: every part is in the message).

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/mesh.hpp"

namespace exactgeo::mesh::test_io {

namespace fs = std::filesystem;

inline std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// "%.17g": the shortest form that always reads back as the same double.
inline std::string decimal(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// The pieces, appended (chained std::string + trips a false GCC 12 -Wrestrict warning).
template <class... Parts>
std::string cat(const Parts&... parts) {
  std::string s;
  (s.append(parts), ...);
  return s;
}

// The message of the InputError `f` throws; a test failure if it throws nothing else.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return {};
  }
  ADD_FAILURE() << "no error";
  return {};
}

#define EXPECT_MESSAGE_HAS(message, ...)                                                    \
  do {                                                                                      \
    const std::string message_ = (message);                                                 \
    /* Strings, not views: a part may be a temporary (std::to_string) of this statement. */ \
    const std::initializer_list<std::string> parts_ = {__VA_ARGS__};                        \
    for (const std::string& part_ : parts_) {                                               \
      EXPECT_NE(message_.find(part_), std::string::npos)                                    \
          << "message: " << message_ << "\nlacks: " << part_;                               \
    }                                                                                       \
  } while (0)

inline void expect_same_mesh(const Mesh& actual, const Mesh& expected) {
  ASSERT_EQ(actual.vertices.size(), expected.vertices.size());
  for (std::size_t v = 0; v < expected.vertices.size(); ++v) {
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(bits(actual.vertices[v][i]), bits(expected.vertices[v][i]))
          << "vertex " << v << " coordinate " << i << ": " << actual.vertices[v][i] << " vs "
          << expected.vertices[v][i];
    }
  }
  EXPECT_TRUE(actual.faces == expected.faces);
}

// A test with its own temporary directory.
class mesh_io : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = "exactgeo_mesh_io_";
    name.append(std::to_string(::getpid()));
    name.push_back('_');
    name.append(::testing::UnitTest::GetInstance()->current_test_info()->name());
    dir_ = fs::temp_directory_path() / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  std::string write(const std::string& name, std::string_view bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(out.good()) << path;
    return path.string();
  }

  LoadedMesh load(const std::string& name, std::string_view bytes, LoadOptions options = {}) {
    return load_mesh(write(name, bytes), options);
  }

  std::string load_error(const std::string& name, std::string_view bytes,
                         LoadOptions options = {}) {
    const std::string path = write(name, bytes);
    return error_of([&] { (void)load_mesh(path, options); });
  }

  fs::path dir_;
};

// One quad and one triangle, with coordinates that are floats (so a float PLY holds them).

inline Mesh quad_and_triangle() {
  Mesh mesh;
  mesh.vertices = {{0, 0, 0},
                   {1, 0, 0},
                   {1, 1, static_cast<double>(0.1f)},
                   {0, 1, 0},
                   {static_cast<double>(-1.5e-3f), 2, -0.25}};
  mesh.faces = {make_quad(0, 1, 2, 3), make_triangle(3, 2, 4)};
  return mesh;
}

inline std::string to_obj(const Mesh& mesh) {
  std::string s = "# quad and triangle\r\nmtllib x.mtl\no thing\n";
  for (const auto& p : mesh.vertices) {
    s.append(cat("v ", decimal(p[0]), " ", decimal(p[1]), " ", decimal(p[2]), "\n"));
  }
  s.append("vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n\ng group\nusemtl m\ns off\n");
  for (const Face& f : mesh.faces) {
    s.append("f");
    for (std::size_t c = 0; c < f.size(); ++c) {
      // Every corner syntax: i, i/t, i//n, i/t/n.
      const std::string i = std::to_string(f.corners[c] + 1);
      const char* const forms[] = {"", "/1", "//1", "/2/1"};
      s.append(cat(" ", i, forms[c % 4]));
    }
    s.append("\n");
  }
  s.append("l 1 2\n");
  return s;
}

inline std::string to_off(const Mesh& mesh) {
  std::string s = cat("OFF\n# a comment\n", std::to_string(mesh.vertices.size()), " ",
                      std::to_string(mesh.faces.size()), " 0\n\n");
  for (const auto& p : mesh.vertices) {
    s.append(cat(decimal(p[0]), " ", decimal(p[1]), " ", decimal(p[2]), "\n"));
  }
  for (const Face& f : mesh.faces) {
    s.append(std::to_string(f.size()));
    for (std::size_t c = 0; c < f.size(); ++c)
      s.append(cat(" ", std::to_string(f.corners[c])));
    s.append(" 255 0 0\n");  // a colour
  }
  return s;
}

struct PlyLayout {
  std::string format;  // ascii, binary_little_endian, binary_big_endian
  std::string coordinate_type = "double";
  std::string count_type = "uchar";
  std::string index_type = "int";
};

template <class T>
void put(std::string& out, T value, bool big_endian) {
  auto raw = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
  out.append(raw.data(), raw.size());
}

// Writes `value` as PLY type `type` (binary), or as text.
inline void put_value(std::string& out, const std::string& type, double value, bool binary,
                      bool big) {
  if (!binary) {
    out.append(decimal(value));
    out.push_back(' ');
  } else if (type == "double" || type == "float64") {
    put(out, value, big);
  } else if (type == "float" || type == "float32") {
    put(out, static_cast<float>(value), big);
  } else if (type == "uchar" || type == "uint8") {
    put(out, static_cast<std::uint8_t>(value), big);
  } else if (type == "int" || type == "int32") {
    put(out, static_cast<std::int32_t>(value), big);
  } else if (type == "uint" || type == "uint32") {
    put(out, static_cast<std::uint32_t>(value), big);
  } else if (type == "short" || type == "int16") {
    put(out, static_cast<std::int16_t>(value), big);
  } else {
    ADD_FAILURE() << "type " << type;
  }
}

// The mesh as PLY, with a skipped vertex property, a skipped element with a list property
// between vertices and faces, and a skipped face property.
inline std::string to_ply(const Mesh& mesh, const PlyLayout& layout) {
  const bool binary = layout.format != "ascii";
  const bool big = layout.format == "binary_big_endian";
  const std::string& c = layout.coordinate_type;
  std::string s = cat("ply\nformat ", layout.format, " 1.0\ncomment written by a test\n");
  s.append(cat("obj_info nothing\nelement vertex ", std::to_string(mesh.vertices.size()), "\n"));
  s.append(cat("property ", c, " x\nproperty uchar red\nproperty ", c, " y\nproperty ", c, " z\n"));
  s.append("element edge 2\nproperty list uchar int vertex_pair\nproperty float weight\n");
  s.append(cat("element face ", std::to_string(mesh.faces.size()), "\n"));
  s.append(cat("property list ", layout.count_type, " ", layout.index_type, " vertex_indices\n"));
  s.append("property short flags\nend_header\n");
  auto line_end = [&] {
    if (!binary) {
      s.pop_back();
      s.push_back('\n');
    }
  };
  for (const auto& p : mesh.vertices) {
    put_value(s, c, p[0], binary, big);
    put_value(s, "uchar", 200, binary, big);
    put_value(s, c, p[1], binary, big);
    put_value(s, c, p[2], binary, big);
    line_end();
  }
  for (int e = 0; e < 2; ++e) {
    put_value(s, "uchar", 2, binary, big);
    put_value(s, "int", e, binary, big);
    put_value(s, "int", e + 1, binary, big);
    put_value(s, "float", 0.5, binary, big);
    line_end();
  }
  for (const Face& f : mesh.faces) {
    put_value(s, layout.count_type, static_cast<double>(f.size()), binary, big);
    for (std::size_t k = 0; k < f.size(); ++k) {
      put_value(s, layout.index_type, f.corners[k], binary, big);
    }
    put_value(s, "short", -7, binary, big);
    line_end();
  }
  return s;
}

// A PLY header of vertices x y z of type `coordinate` and faces of list type `list`.
inline std::string ply_header(const std::string& format, std::uint64_t vertices,
                              std::uint64_t faces, const std::string& coordinate = "float",
                              const std::string& list = "uchar int") {
  return cat("ply\nformat ", format, " 1.0\nelement vertex ", std::to_string(vertices),
             "\nproperty ", coordinate, " x\nproperty ", coordinate, " y\nproperty ", coordinate,
             " z\nelement face ", std::to_string(faces), "\nproperty list ", list,
             " vertex_indices\nend_header\n");
}

}  // namespace exactgeo::mesh::test_io
