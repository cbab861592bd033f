// Winding numbers and fill rules on closed oriented surfaces whose truth is known from
// their construction: boxes with small integer bounds that overlap, nest, duplicate each
// other, touch along edges and faces, some turned inside out, welded by exact position
// (so that shared edges are shared by four or more faces). The winding number of a point
// is the sum of +1 for each outward box holding it in its interior and -1 for each
// inward one; a point on any face is on the surface. Every rule's label follows from it,
// with and without space cells, with Embree and brute-force candidates. And the refusals:
// the winding rules need every edge used as often in each direction, parity only an even
// number of faces per edge; the default rule is nonzero, or parity where faces are not
// oriented alike.

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "exactgeo/inside/batch.hpp"
#include "exactgeo/inside/classifier.hpp"
#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/inside/location.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/load.hpp"
#include "exactgeo/mesh/off_reader.hpp"
#include "exactgeo/predicates/bilinear_patch.hpp"
#include "exactgeo/predicates/ray_directions.hpp"
#include "exactgeo/predicates/ray_triangle.hpp"
#include "inside/polycube.hpp"
#include "inside/scaled_cube.hpp"
#include "mesh/hexahedron.hpp"
#include "support/generators.hpp"
#include "support/hexahedron.hpp"
#include "support/polygon_oracle.hpp"
#include "support/rational_oracle.hpp"
#include "support/seed.hpp"
#include "support/solid_angle_oracle.hpp"

namespace exactgeo::inside::winding {
namespace {

using mesh::Mesh;

struct Box {
  Point3 lower, upper;
  int sign = 1;  ///< +1: faces outward; -1: turned inside out
};

/// The boxes as one mesh, vertices welded by exact position, each box's six quads
/// counter-clockwise seen from outside (or from inside, for sign -1).
Mesh boxes_mesh(const std::vector<Box>& boxes) {
  Mesh mesh;
  std::map<Point3, VertexIndex> index;
  const auto vertex = [&](const Point3& p) {
    const auto [it, added] = index.try_emplace(p, static_cast<VertexIndex>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(p);
    return it->second;
  };
  for (const Box& b : boxes) {
    std::array<VertexIndex, 8> corner;
    for (int c = 0; c < 8; ++c) {
      Point3 p;
      for (int i = 0; i < 3; ++i)
        p[i] = (c >> i) & 1 ? b.upper[i] : b.lower[i];
      corner[static_cast<std::size_t>(c)] = vertex(p);
    }
    for (const auto& q : testing::kHexahedronFaces) {
      mesh.faces.push_back(
          b.sign > 0 ? mesh::make_quad(corner[q[0]], corner[q[1]], corner[q[2]], corner[q[3]])
                     : mesh::make_quad(corner[q[0]], corner[q[3]], corner[q[2]], corner[q[1]]));
    }
  }
  return mesh;
}

/// The truth: nullopt on some box's boundary, else the sum of the signs of the boxes
/// holding the point in their interior.
std::optional<std::int64_t> winding_truth(const std::vector<Box>& boxes, const Point3& p) {
  std::int64_t w = 0;
  for (const Box& b : boxes) {
    bool closed = true, open = true;
    for (int i = 0; i < 3; ++i) {
      closed = closed && b.lower[i] <= p[i] && p[i] <= b.upper[i];
      open = open && b.lower[i] < p[i] && p[i] < b.upper[i];
    }
    if (closed && !open) return std::nullopt;
    if (open) w += b.sign;
  }
  return w;
}

Location label(FillRule rule, const std::optional<std::int64_t>& w) {
  if (!w) return Location::boundary;
  return holds(rule, *w) ? Location::inside : Location::outside;
}

constexpr std::array kRules{FillRule::nonzero, FillRule::parity, FillRule::positive};

std::string text(const Point3& p) {
  return "(" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
         ")";
}

/// Random boxes on a small integer grid (overlapping, nested, duplicated, sharing faces,
/// edges and corners), a quarter of them inside out; points on a grid of halves, many of
/// them on faces, many first rays through edges and corners.
TEST(WindingNumber, OverlappingBoxesHaveTheirKnownWindingNumbers) {
  auto rng = testing::seeded_engine("WindingNumber.Boxes");
  std::map<std::int64_t, int> seen;
  int four_face_edges = 0;
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Box> boxes;
    const int count = testing::uniform_int(rng, 1, 5);
    for (int b = 0; b < count; ++b) {
      Box box;
      for (int i = 0; i < 3; ++i) {
        box.lower[i] = testing::uniform_int(rng, -3, 0);
        box.upper[i] = testing::uniform_int(rng, static_cast<int>(box.lower[i]) + 2, 3);
      }
      box.sign = testing::uniform_int(rng, 0, 3) == 0 ? -1 : 1;
      boxes.push_back(box);
    }
    const Mesh mesh = boxes_mesh(boxes);
    const mesh::MeshCheck check = mesh::check_mesh(mesh);
    ASSERT_EQ(check.unbalanced_edges.count, 0u);
    four_face_edges += check.non_manifold_edges.count > 0;
    std::vector<Classifier> classifiers;
    for (const FillRule rule : kRules) {
      ClassifierOptions options;
      options.rule = rule;
      options.allow_non_manifold = true;
      classifiers.emplace_back(mesh, options);
    }
    ClassifierOptions brute;
    brute.candidates = CandidateSearch::brute_force;
    brute.space_cells = false;
    const Classifier reference(mesh, brute);
    for (int q = 0; q < 60; ++q) {
      const Point3 p = testing::scaled(testing::integer_point(rng, 7), -1);
      const std::optional<std::int64_t> truth = winding_truth(boxes, p);
      const std::string what = "trial " + std::to_string(trial) + " point " + text(p);
      ASSERT_EQ(reference.winding_number(p), truth) << what;
      for (const Classifier& c : classifiers) {
        ASSERT_EQ(c.winding_number(p), truth) << what << " " << to_string(c.rule());
        ASSERT_EQ(c.classify(p), label(c.rule(), truth)) << what << " " << to_string(c.rule());
        ASSERT_EQ(c.classify(p, Arithmetic::rational), label(c.rule(), truth)) << what;
      }
      if (truth) ++seen[*truth];
    }
  }
  for (const std::int64_t w : {-1, 0, 1, 2})
    EXPECT_GT(seen[w], 40) << "winding number " << w;
  EXPECT_GT(four_face_edges, 3);
}

/// The cases the rules are for, by hand: two overlapping cubes, a shell inside a shell
/// both ways, a solid turned inside out, a duplicated solid.
TEST(WindingNumber, NestedOverlappingAndTurnedSolidsByHand) {
  struct Case {
    const char* name;
    std::vector<Box> boxes;
    Point3 probe;
    std::int64_t winding;
  };
  const Box outer{{-2, -2, -2}, {2, 2, 2}, 1};
  const Box inner{{-1, -1, -1}, {1, 1, 1}, 1};
  const Box cavity{{-1, -1, -1}, {1, 1, 1}, -1};
  const std::vector<Case> cases{
      {"overlap of two cubes",
       {{{0, 0, 0}, {2, 2, 2}, 1}, {{1, 1, 1}, {3, 3, 3}, 1}},
       {1.5, 1.5, 1.5},
       2},
      {"only the first cube",
       {{{0, 0, 0}, {2, 2, 2}, 1}, {{1, 1, 1}, {3, 3, 3}, 1}},
       {0.5, 0.5, 0.5},
       1},
      {"a shell in a shell, alike", {outer, inner}, {0.5, 0.25, 0}, 2},
      {"a cavity (inner shell reversed)", {outer, cavity}, {0.5, 0.25, 0}, 0},
      {"between cavity and outer shell", {outer, cavity}, {1.5, 0.25, 0}, 1},
      {"a cube turned inside out", {cavity}, {0.5, 0.25, 0}, -1},
      {"a cube given twice", {inner, inner}, {0.5, 0.25, 0}, 2},
  };
  for (const Case& c : cases) {
    const Mesh mesh = boxes_mesh(c.boxes);
    for (const FillRule rule : kRules) {
      ClassifierOptions options;
      options.rule = rule;
      options.allow_non_manifold = true;
      const Classifier classifier(mesh, options);
      EXPECT_EQ(classifier.winding_number(c.probe), c.winding) << c.name;
      EXPECT_EQ(classifier.classify(c.probe), label(rule, c.winding))
          << c.name << ", rule " << to_string(rule);
    }
  }
}

/// One face of a cube turned: closed, but not oriented. Parity classifies it; the winding
/// rules refuse it and say why; no winding number is given.
TEST(WindingNumber, UnorientedMeshesAreForParityOnly) {
  Mesh mesh = boxes_mesh({{{0, 0, 0}, {1, 1, 1}, 1}});
  auto& f = mesh.faces[2].corners;
  std::swap(f[1], f[3]);
  const mesh::MeshCheck check = mesh::check_mesh(mesh);
  EXPECT_EQ(check.unbalanced_edges.count, 4u);
  EXPECT_EQ(check.misoriented_edges.count, 4u);
  const auto problem = mesh::orientable_surface_problem(check);
  ASSERT_TRUE(problem.has_value());
  EXPECT_NE(problem->find("4 edges are run the same way by two more faces than the other way"),
            std::string::npos)
      << *problem;
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    ClassifierOptions options;
    options.rule = rule;
    try {
      const Classifier classifier(mesh, options);
      ADD_FAILURE() << "accepted by " << to_string(rule);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("faces not oriented alike: 4 edges are run the same "
                                           "way by two more faces than the other way"),
                std::string::npos)
          << e.what();
    }
  }
  ClassifierOptions parity;
  parity.rule = FillRule::parity;
  const Classifier classifier(mesh, parity);
  EXPECT_FALSE(classifier.oriented());
  // The default rule takes parity for such a mesh, and says so.
  EXPECT_EQ(Classifier(mesh).rule(), FillRule::parity);
  EXPECT_EQ(Classifier(boxes_mesh({{{0, 0, 0}, {1, 1, 1}, 1}})).rule(), FillRule::nonzero);
  EXPECT_EQ(classifier.classify({0.5, 0.25, 0.75}), Location::inside);
  EXPECT_EQ(classifier.classify({1.5, 0.25, 0.75}), Location::outside);
  EXPECT_EQ(classifier.classify({1, 0.25, 0.75}), Location::boundary);
  EXPECT_THROW((void)classifier.winding_number({0.5, 0.25, 0.75}), std::logic_error);
  const std::vector<Point3> points(1500, Point3{0.5, 0.25, 0.75});
  std::vector<std::optional<std::int64_t>> windings(points.size());
  EXPECT_THROW(winding_number_batch(classifier, points, windings, Arithmetic::exact, 2),
               std::logic_error);
}

/// An open box is refused by parity, as not closed; the winding rules take it as an open
/// surface (the open_surface section below checks its labels).
TEST(WindingNumber, OpenMeshesAreRefusedByParityOnly) {
  Mesh mesh = boxes_mesh({{{0, 0, 0}, {1, 1, 1}, 1}});
  mesh.faces.pop_back();
  for (const FillRule rule : kRules) {
    ClassifierOptions options;
    options.rule = rule;
    if (rule != FillRule::parity) {
      const Classifier classifier(mesh, options);
      EXPECT_TRUE(classifier.open());
      EXPECT_EQ(classifier.boundary().size(), 4u);
      EXPECT_THROW((void)classifier.winding_number({0.5, 0.25, 0.75}), std::logic_error);
      continue;
    }
    try {
      const Classifier classifier(mesh, options);
      ADD_FAILURE() << "accepted by " << to_string(rule);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace exactgeo::inside::winding
