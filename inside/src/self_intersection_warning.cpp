#include "exactgeo/inside/self_intersection_warning.hpp"

#include <string>
#include <utility>

#include "exactgeo/mesh/check.hpp"

namespace exactgeo::inside {

std::vector<std::string> self_intersection_warnings(const mesh::SelfIntersections& found,
                                                    const mesh::FileNumbering& numbering,
                                                    bool oriented, const OptionNames& names) {
  std::vector<std::string> warnings;
  // mesh::self_intersection_problem names the pairs of one kind at a time.
  mesh::SelfIntersections one_kind;
  one_kind.intersecting = found.intersecting;
  if (const auto pairs = mesh::self_intersection_problem(one_kind, numbering)) {
    std::string text = *pairs;
    text.append(
        ": the labels are those of the parity solid (inside where rays cross the surface an "
        "odd number of times), which is not the solid such faces were meant to bound");
    if (oriented)
      text.append("; ").append(names.nonzero).append(" labels overlapping parts as their union");
    warnings.push_back(std::move(text));
  }
  one_kind.intersecting.clear();
  one_kind.undecided = found.undecided;
  if (const auto pairs = mesh::self_intersection_problem(one_kind, numbering)) {
    std::string text = *pairs;
    text.append(": faces the exact check could not decide (")
        .append(std::to_string(found.undecided_neighbours))
        .append(" of the ")
        .append(std::to_string(found.undecided.size()))
        .append(
            " share a corner). In each pair one face is a quad that is not planar (or planar "
            "but not convex), none of the separating planes tried clears the two, and an edge "
            "of one starts, ends or runs on the other, or its line passes through the other's "
            "boundary, as the edges from a shared corner do: the check cannot tell touching "
            "from crossing there. If they only touch, the labels are right; where they cross, "
            "they are those of the parity solid. ");
    if (oriented) {
      text.append(names.nonzero)
          .append(" labels by winding numbers, which no intersection changes; ");
    }
    text.append(
        "`exactgeo info --mark OUT.ply` colours these faces magenta to look at, and quads "
        "split into triangles in the file are decided exactly");
    warnings.push_back(std::move(text));
  }
  return warnings;
}

}  // namespace exactgeo::inside
