// Every numeric field of every text mesh reader, with every sign spelling: one sign is read
// as written ("+2" is 2), two signs are refused naming the field's line ("+-2" was once
// read as -2), in coordinates, counts, indices and the fields that are checked but not used
// (OBJ's texture and normal indices, OFF's face colours, STL's normals). And the spellings
// a writer can put in an STL normal slot.

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "exactgeo/io/input_error.hpp"
#include "exactgeo/mesh/obj_reader.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/mesh/ply_reader.hpp"
#include "exactgeo/mesh/stl_reader.hpp"

namespace exactgeo::mesh {
namespace {

using Reader = LoadedMesh (*)(std::string_view, const std::string&, const LoadOptions&);

/// A file whose numeric fields are written '@', with each field's unsigned value.
struct Template {
  const char* name;
  Reader reader;
  std::string text;
  std::vector<std::string> values;

  /// The text with field `k` written `field` and every other as its value.
  std::string with(std::size_t k, const std::string& field) const {
    std::string out;
    std::size_t next = 0;
    for (const char c : text) {
      if (c != '@') {
        out.push_back(c);
        continue;
      }
      out.append(next == k ? field : values.at(next));
      ++next;
    }
    return out;
  }

  /// The line (from 1) of field `k`.
  std::size_t line_of(std::size_t k) const {
    std::size_t line = 1, field = 0;
    for (const char c : text) {
      if (c == '\n') ++line;
      if (c == '@' && field++ == k) return line;
    }
    ADD_FAILURE() << "no field " << k;
    return 0;
  }

  std::size_t fields() const { return values.size(); }
};

std::vector<Template> templates() {
  const std::vector<std::string> triangle = {"0", "0", "0", "1", "0", "0", "0", "1", "0"};
  const auto plus = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  return {
      {"t.obj", read_obj, "v @ @ @\nv @ @ @\nv @ @ @ @\nvt 0 0\nvn 0 0 1\nf @/@/@ @//@ @/@\n",
       plus(triangle, {"1", "1", "1", "1", "2", "1", "3", "1"})},  // w, then the face
      {"t.off", read_off, "OFF\n@ @ @\n@ @ @\n@ @ @\n@ @ @\n@ @ @ @ @ @ @\n",
       plus(plus({"3", "1", "0"}, triangle), {"3", "0", "1", "2", "255", "0", "0"})},
      {"t.ply",
       read_ply,
       "ply\nformat ascii 1.0\nelement vertex @\nproperty double x\nproperty float y\n"
       "property int z\nproperty uchar red\nelement face @\n"
       "property list uchar int vertex_indices\nproperty short flags\nend_header\n"
       "@ @ @ @\n@ @ @ @\n@ @ @ @\n@ @ @ @ @\n",
       {"3", "1", "0", "0", "0", "9", "1", "0", "0", "9", "0", "1", "0", "9", "3", "0", "1", "2",
        "7"}},
      {"t.stl", read_stl,
       "solid s\nfacet normal @ @ @\nouter loop\nvertex @ @ @\nvertex @ @ @\nvertex @ @ @\n"
       "endloop\nendfacet\nendsolid s\n",
       plus({"0", "0", "1"}, triangle)},
  };
}

Mesh read(const Template& t, const std::string& text) {
  return t.reader(text, t.name, {}).mesh;
}

TEST(NumericFields, OneSignIsReadAsWritten) {
  for (const Template& t : templates()) {
    const Mesh plain = read(t, t.with(t.fields(), ""));  // every field its value
    for (std::size_t k = 0; k < t.fields(); ++k) {
      const Mesh signed_plus = read(t, t.with(k, "+" + t.values[k]));
      EXPECT_EQ(signed_plus.vertices, plain.vertices) << t.name << " field " << k;
      EXPECT_TRUE(signed_plus.faces == plain.faces) << t.name << " field " << k;
    }
  }
}

TEST(NumericFields, TwoSignsAreRefusedNamingTheLine) {
  for (const Template& t : templates()) {
    for (std::size_t k = 0; k < t.fields(); ++k) {
      for (const char* two : {"+-", "-+", "++", "--"}) {
        const std::string text = t.with(k, two + t.values[k]);
        const std::string where = std::string(t.name) + ":" + std::to_string(t.line_of(k)) + ":";
        try {
          (void)read(t, text);
          ADD_FAILURE() << t.name << " field " << k << " as " << two << t.values[k] << " was read";
        } catch (const io::InputError& e) {
          EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u)
              << t.name << " field " << k << ": " << e.what();
        }
      }
    }
  }
}

TEST(NumericFields, AnySignAloneOrInsideIsRefused) {
  for (const Template& t : templates()) {
    for (std::size_t k = 0; k < t.fields(); ++k) {
      for (const std::string& bad : {std::string("+"), std::string("-"), t.values[k] + "-",
                                     "+ " + t.values[k], std::string("1+1")}) {
        bool refused = false;
        try {
          (void)read(t, t.with(k, bad));
        } catch (const io::InputError&) {
          refused = true;
        }
        // "+ 1" splits into two fields: refused for the count of fields, if not the sign.
        EXPECT_TRUE(refused) << t.name << " field " << k << " as '" << bad << "'";
      }
    }
  }
}

/// An STL facet with the normal written `normal`.
std::string stl_with_normal(std::string_view normal) {
  std::string s = "solid s\nfacet normal ";
  s.append(normal);
  s.append("\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
  return s;
}

TEST(StlNormals, EveryFloatAWriterPrintsIsTaken) {
  // glibc and MSVC since 2015, older MSVC (%f, %e, %g), Java, in several cases; numbers
  // beyond the double range (the normal is not used).
  const std::vector<std::string> spellings = {"nan",
                                              "-nan",
                                              "NAN",
                                              "inf",
                                              "-INF",
                                              "Infinity",
                                              "-nan(ind)",
                                              "nan(snan)",
                                              "nan(0x7fc00000)",
                                              "-NaN(IND)",
                                              "1.#INF00",
                                              "-1.#IND00",
                                              "1.#QNAN0",
                                              "1.#SNAN0",
                                              "-1.#INF",
                                              "1.#IND",
                                              "1.#INF00e+000",
                                              "-1.#QNAN0E-000",
                                              "1.#qnan",
                                              "1e400",
                                              "-1e-400",
                                              "0x1p-1080",
                                              "+0",
                                              "-0.0"};
  for (const std::string& spelling : spellings) {
    const std::string normal = spelling + " " + spelling + " " + spelling;
    try {
      const LoadedMesh m = read_stl(stl_with_normal(normal), "n.stl", {});
      EXPECT_EQ(m.mesh.vertices.size(), 3u) << spelling;
    } catch (const io::InputError& e) {
      ADD_FAILURE() << spelling << ": " << e.what();
    }
  }
}

TEST(StlNormals, WhatNoWriterPrintsIsRefused) {
  for (const char* bad :
       {"a", "1,5", "0x", "1.#", "1.#INFX", "1.#IN", "2.#INF", "1.#INF00e", "1.#INF00e+", "nan(",
        "nan(a b)", "nan()x", "infinit", "+-1", "--nan", "1.#QNAN0-"}) {
    const std::string normal = std::string("0 ") + bad + " 0";
    try {
      (void)read_stl(stl_with_normal(normal), "n.stl", {});
      ADD_FAILURE() << bad << " was taken";
    } catch (const io::InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("n.stl:2:", 0), 0u) << message;
      EXPECT_NE(message.find("the normal"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace exactgeo::mesh
