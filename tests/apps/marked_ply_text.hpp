#pragma once

// Reads back the ASCII PLY files that `--mark` writes, colours included (the mesh readers
// skip colours): the tests check every element's colour against what it should show.

#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "cli/colour.hpp"

namespace exactgeo::testing {

using cli::Rgb;

struct MarkedPlyText {
  std::vector<std::string> legend;  ///< the "comment legend ..." lines, without "comment "
  std::vector<Rgb> vertex_colours;  ///< empty when the vertices have none
  std::vector<std::vector<std::size_t>> faces;
  std::vector<Rgb> face_colours;
  std::vector<std::array<std::size_t, 2>> edges;
  std::vector<Rgb> edge_colours;
  bool complete = false;  ///< the header and every declared element were read
};

inline Rgb read_rgb(std::istream& in) {
  int r = -1, g = -1, b = -1;
  in >> r >> g >> b;
  return {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b)};
}

inline MarkedPlyText read_marked_ply(const std::string& text) {
  MarkedPlyText ply;
  std::istringstream in(text);
  std::string line;
  std::size_t vertices = 0, faces = 0, edges = 0;
  bool vertex_colours = false;
  std::string element;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "comment" && line.rfind("comment legend ", 0) == 0)
      ply.legend.push_back(line.substr(8));
    if (word == "element") {
      std::size_t count = 0;
      words >> element >> count;
      (element == "vertex" ? vertices : element == "face" ? faces : edges) = count;
    }
    if (word == "property" && element == "vertex" && line == "property uchar red") {
      vertex_colours = true;
    }
  }
  for (std::size_t v = 0; v < vertices && std::getline(in, line); ++v) {
    std::istringstream words(line);
    double x, y, z;
    words >> x >> y >> z;
    if (vertex_colours) ply.vertex_colours.push_back(read_rgb(words));
  }
  for (std::size_t f = 0; f < faces && std::getline(in, line); ++f) {
    std::istringstream words(line);
    std::size_t n = 0;
    words >> n;
    std::vector<std::size_t> corners(n);
    for (std::size_t& c : corners)
      words >> c;
    ply.faces.push_back(corners);
    ply.face_colours.push_back(read_rgb(words));
  }
  for (std::size_t e = 0; e < edges && std::getline(in, line); ++e) {
    std::istringstream words(line);
    std::array<std::size_t, 2> edge{};
    words >> edge[0] >> edge[1];
    ply.edges.push_back(edge);
    ply.edge_colours.push_back(read_rgb(words));
  }
  ply.complete = ply.faces.size() == faces && ply.edges.size() == edges && !in.fail() &&
                 !std::getline(in, line);
  return ply;
}

}  // namespace exactgeo::testing
