// The fill rules (fill_rule.hpp): their names, the rule a classifier takes when none is
// asked for, what keeps each rule from a mesh (rule_problem, face_soup_problem) on meshes
// whose defects are planted by hand, and the refusal: a refused mesh is explained once,
// with everything wrong and every way out that would take it (tried, not guessed), in the
// file's numbering, and in the same words on the command line and in Python (only the
// options' spelling differs).

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <string>

#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/obj_reader.hpp"

namespace exactgeo::inside {
namespace {

const std::string kCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

/// The cube with more lines after it.
std::string cube_and(const std::string& more) {
  std::string text = kCube;
  return text.append(more);
}

mesh::LoadedMesh obj(const std::string& text) {
  return mesh::read_obj(text, "m.obj", {});
}

std::string refused(const std::string& text, FillRule rule, bool allow_non_manifold = false,
                    const OptionNames& names = kCommandLineNames) {
  return refusal(obj(text), rule, allow_non_manifold, names).value_or("(accepted)");
}

void expect_has(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "lacks: " << part << "\nin: " << message;
}

constexpr std::array kRules{FillRule::nonzero, FillRule::parity, FillRule::positive};

/// The cube's faces, each with its own four vertices (a face soup): open as it is, closed
/// once the 16 vertices that repeat another's coordinates are merged.
std::string cube_soup() {
  std::string soup =
      "v 0 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 1 0 0\nv 1 1 0\nv 1 1 1\nv 1 0 1\n"
      "v 1 1 0\nv 0 1 0\nv 0 1 1\nv 1 1 1\nv 0 1 0\nv 0 0 0\nv 0 0 1\nv 0 1 1\n";
  for (int f = 0; f < 6; ++f) {
    soup.append("f");
    for (int c = 1; c <= 4; ++c)
      soup.append(" ").append(std::to_string(4 * f + c));
    soup.append("\n");
  }
  return soup;
}

/// The cube with its first face turned: closed, four edges misoriented.
std::string turned_cube() {
  std::string turned = kCube;
  return turned.replace(turned.find("f 1 4 3 2"), 9, "f 1 2 3 4");
}

/// The cube without its last face: open, four boundary edges.
std::string open_cube() {
  std::string open = kCube;
  return open.erase(open.find("f 4 1 5 8"));
}

TEST(FillRule, NamesRoundTripAndOthersAreRefused) {
  for (const FillRule rule : kRules)
    EXPECT_EQ(parse_fill_rule(to_string(rule)), rule);
  EXPECT_EQ(parse_fill_rule("even-odd"), std::nullopt);
  EXPECT_EQ(parse_fill_rule(""), std::nullopt);
  EXPECT_TRUE(holds(FillRule::nonzero, -2));
  EXPECT_FALSE(holds(FillRule::parity, -2));
  EXPECT_TRUE(holds(FillRule::parity, -3));
  EXPECT_FALSE(holds(FillRule::positive, -1));
  EXPECT_TRUE(holds(FillRule::positive, 2));
}

TEST(FillRule, TheDefaultIsParityOnlyForAClosedSurfaceNotOrientedAlike) {
  const mesh::MeshCheck cube = mesh::check_mesh(obj(kCube).mesh);
  const mesh::MeshCheck turned = mesh::check_mesh(obj(turned_cube()).mesh);
  const mesh::MeshCheck open = mesh::check_mesh(obj(open_cube()).mesh);
  ASSERT_TRUE(cube.closed() && cube.misoriented_edges.count == 0);
  ASSERT_TRUE(turned.closed() && turned.misoriented_edges.count == 4);
  ASSERT_FALSE(open.closed());
  EXPECT_EQ(rule_for(cube, std::nullopt), FillRule::nonzero);
  EXPECT_EQ(rule_for(turned, std::nullopt), FillRule::parity);
  EXPECT_EQ(rule_for(open, std::nullopt), FillRule::nonzero);
  // A rule asked for is taken, whatever the mesh (refusing it is rule_problem's job).
  for (const FillRule rule : kRules) {
    for (const mesh::MeshCheck* check : {&cube, &turned, &open})
      EXPECT_EQ(rule_for(*check, rule), rule) << to_string(rule);
  }
}

TEST(FillRule, EachRuleRefusesWhatItCannotClassify) {
  const mesh::MeshCheck cube = mesh::check_mesh(obj(kCube).mesh);
  const mesh::MeshCheck turned = mesh::check_mesh(obj(turned_cube()).mesh);
  const mesh::MeshCheck open = mesh::check_mesh(obj(open_cube()).mesh);
  for (const FillRule rule : kRules)
    EXPECT_EQ(rule_problem(cube, rule, false), std::nullopt) << to_string(rule);
  // Parity needs no orientation, but a closed surface; the winding rules the reverse.
  EXPECT_EQ(rule_problem(turned, FillRule::parity, false), std::nullopt);
  EXPECT_EQ(rule_problem(open, FillRule::nonzero, false), std::nullopt);
  EXPECT_EQ(rule_problem(open, FillRule::positive, false), std::nullopt);
  for (const FillRule rule : {FillRule::nonzero, FillRule::positive}) {
    const auto problem = rule_problem(turned, rule, false);
    ASSERT_TRUE(problem.has_value()) << to_string(rule);
    expect_has(*problem, "faces not oriented alike");
  }
  const auto not_closed = rule_problem(open, FillRule::parity, true);
  ASSERT_TRUE(not_closed.has_value());
  expect_has(*not_closed, "not closed");
  // With the file, in its numbering: OBJ counts from 1.
  const auto named = rule_problem(open, FillRule::parity, false, obj(open_cube()));
  ASSERT_TRUE(named.has_value());
  expect_has(*named, "numbered from 1, as in the file");
  EXPECT_EQ(rule_problem(cube, FillRule::parity, false, obj(kCube)), std::nullopt);
}

TEST(FillRule, AFaceSoupThatWeldingClosesNamesWelding) {
  const auto problem = face_soup_problem(obj(cube_soup()), std::nullopt, kCommandLineNames);
  ASSERT_TRUE(problem.has_value());
  expect_has(*problem, "not closed");
  expect_has(*problem, "; with --weld, which merges the 16 vertices");
  const auto python = face_soup_problem(obj(cube_soup()), FillRule::nonzero, kPythonNames);
  ASSERT_TRUE(python.has_value());
  expect_has(*python, "; with weld=True, which merges the 16 vertices");
  // Parity refuses the soup as not closed already; a closed cube is no soup; an open box
  // stays open welded.
  EXPECT_EQ(face_soup_problem(obj(cube_soup()), FillRule::parity, kCommandLineNames), std::nullopt);
  EXPECT_EQ(face_soup_problem(obj(kCube), std::nullopt, kCommandLineNames), std::nullopt);
  EXPECT_EQ(face_soup_problem(obj(open_cube()), std::nullopt, kCommandLineNames), std::nullopt);
}

TEST(Refusal, AFinIsExplainedOnceWithEveryWayOut) {
  const std::string fin = cube_and("v 2 2 2\nf 1 2 9\n");  // a triangle on the cube's edge 1-2
  const std::string message = refused(fin, FillRule::parity);
  // Not "non-manifold" now and "not closed" after --allow-non-manifold: both at once.
  expect_has(message, "mesh is not closed: 3 edges used by an odd number of faces");
  expect_has(message, "1 non-manifold edge (used by more than two faces; first: 1-2)");
  expect_has(message, "(vertices and faces numbered from 1, as in the file)");
  expect_has(message, "; --rule nonzero accepts it as an open surface");
  expect_has(message, "`exactgeo info --mark OUT.ply`");
  EXPECT_EQ(message.find("--allow-non-manifold"), std::string::npos) << message;  // still odd
  EXPECT_EQ(refused(fin, FillRule::nonzero), "(accepted)");
}

TEST(Refusal, TwoCubesOnAnEdgeNameBothOptionsThatTakeThem) {
  // The second cube shares the first one's edge 3-7 (vertices (1,1,0)-(1,1,1)): that edge
  // has four faces, every edge an even number.
  const std::string second =
      "v 2 1 0\nv 2 2 0\nv 1 2 0\nv 2 1 1\nv 2 2 1\nv 1 2 1\n"
      "f 3 11 10 9\nf 7 12 13 14\nf 3 9 12 7\nf 9 10 13 12\nf 10 11 14 13\nf 11 3 7 14\n";
  const std::string message = refused(cube_and(second), FillRule::parity);
  expect_has(message, "1 non-manifold edge");
  expect_has(message, "; --allow-non-manifold accepts it");
  expect_has(message, "; --rule nonzero accepts it");
  EXPECT_EQ(refused(cube_and(second), FillRule::parity, true), "(accepted)");
}

TEST(Refusal, ATurnedFaceNamesParityAndASoupNamesWelding) {
  std::string turned = kCube;
  turned.replace(turned.find("f 1 4 3 2"), 9, "f 1 2 3 4");
  const std::string message = refused(turned, FillRule::nonzero);
  expect_has(message, "faces not oriented alike");
  expect_has(message, "; --rule parity, which needs no orientation, accepts it");

  // The cube's faces, each with its own four vertices: parity refuses the soup as open,
  // and welding closes it.
  std::string soup =
      "v 0 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 1 0 0\nv 1 1 0\nv 1 1 1\nv 1 0 1\n"
      "v 1 1 0\nv 0 1 0\nv 0 1 1\nv 1 1 1\nv 0 1 0\nv 0 0 0\nv 0 0 1\nv 0 1 1\n";
  for (int f = 0; f < 6; ++f) {
    soup.append("f");
    for (int c = 1; c <= 4; ++c)
      soup.append(" ").append(std::to_string(4 * f + c));
    soup.append("\n");
  }
  expect_has(refused(soup, FillRule::parity),
             "; with --weld, which merges the 16 vertices that repeat another's coordinates, "
             "it is accepted");
}

TEST(Refusal, AnOptionNotOfferedIsNotNamed) {
  OptionNames no_rules = kCommandLineNames;
  no_rules.parity = no_rules.nonzero = "";
  const std::string message =
      refused(cube_and("v 2 2 2\nf 1 2 9\n"), FillRule::parity, false, no_rules);
  expect_has(message, "1 non-manifold edge");
  EXPECT_EQ(message.find("--rule"), std::string::npos) << message;
}

TEST(Refusal, PythonSaysTheSameWithItsOwnSpelling) {
  const std::string fin = cube_and("v 2 2 2\nf 1 2 9\n");
  std::string command_line = refused(fin, FillRule::parity);
  const std::string python = refused(fin, FillRule::parity, false, kPythonNames);
  command_line.replace(command_line.find("--rule nonzero"), 14, "rule='nonzero'");
  EXPECT_EQ(python, command_line);
}

}  // namespace
}  // namespace exactgeo::inside
