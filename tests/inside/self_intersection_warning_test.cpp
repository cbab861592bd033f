// What `inside` and Python say about the self-intersection check's findings under parity:
// intersecting pairs and undecided pairs each get a message of their own, in the file's
// numbering, the undecided ones saying what they are and what a user can do.

#include "exactgeo/inside/self_intersection_warning.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace exactgeo::inside {
namespace {

using mesh::FileNumbering;
using mesh::SelfIntersections;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(SelfIntersectionWarnings, NothingFoundNothingSaid) {
  EXPECT_TRUE(self_intersection_warnings({}, {}, true, kCommandLineNames).empty());
}

TEST(SelfIntersectionWarnings, IntersectingPairsMakeTheLabelsTheParitySolids) {
  SelfIntersections found;
  found.intersecting = {{1, 8}, {3, 6}};
  const std::vector<std::string> said =
      self_intersection_warnings(found, FileNumbering{1, {}}, true, kCommandLineNames);
  ASSERT_EQ(said.size(), 1u);
  EXPECT_EQ(said[0].rfind("2 pairs of faces intersect (first: 2-9, 4-7) (faces numbered from 1, "
                          "as in the file): the labels are those of the parity solid",
                          0),
            0u)
      << said[0];
  EXPECT_TRUE(has(said[0], "; --rule nonzero labels overlapping parts as their union")) << said[0];
  // Faces not oriented alike: no winding rule takes the mesh, and none is offered.
  const auto unoriented = self_intersection_warnings(found, {}, false, kCommandLineNames);
  ASSERT_EQ(unoriented.size(), 1u);
  EXPECT_FALSE(has(unoriented[0], "nonzero")) << unoriented[0];
}

TEST(SelfIntersectionWarnings, UndecidedPairsSayWhatTheyAreAndWhatToDo) {
  SelfIntersections found;
  found.intersecting = {{0, 4}};
  found.undecided = {{2, 3}, {2, 7}};
  found.undecided_neighbours = 1;
  const std::vector<std::string> said =
      self_intersection_warnings(found, FileNumbering{1, {}}, true, kCommandLineNames);
  ASSERT_EQ(said.size(), 2u);
  EXPECT_EQ(said[0].rfind("1 pair of faces intersects (first: 1-5)", 0), 0u) << said[0];
  EXPECT_FALSE(has(said[0], "undecided")) << said[0];
  const std::string& undecided = said[1];
  // Which faces, as the file numbers them.
  EXPECT_EQ(undecided.rfind("2 pairs undecided (first: 3-4, 3-8) (faces numbered from 1, as in "
                            "the file): ",
                            0),
            0u)
      << undecided;
  // What they are.
  EXPECT_TRUE(has(undecided, "could not decide (1 of the 2 share a corner)")) << undecided;
  EXPECT_TRUE(has(undecided, "cannot tell touching from crossing")) << undecided;
  EXPECT_TRUE(has(undecided, "a quad that is not planar")) << undecided;
  EXPECT_TRUE(has(undecided, "If they only touch, the labels are right")) << undecided;
  // What to do: the rule intersections do not matter to, a look, triangles.
  EXPECT_TRUE(has(undecided,
                  "--rule nonzero labels by winding numbers, which no intersection "
                  "changes"))
      << undecided;
  EXPECT_TRUE(has(undecided, "`exactgeo info --mark OUT.ply` colours these faces magenta"))
      << undecided;
  EXPECT_TRUE(has(undecided, "split into triangles")) << undecided;
  // Python's names.
  const auto python = self_intersection_warnings(found, {}, true, kPythonNames);
  ASSERT_EQ(python.size(), 2u);
  EXPECT_TRUE(has(python[1], "rule='nonzero' labels by winding numbers")) << python[1];
  EXPECT_TRUE(has(python[1], "(first: 2-3, 2-7)")) << python[1];
}

}  // namespace
}  // namespace exactgeo::inside
