#pragma once

// What the self-intersection check's findings (mesh/self_intersection.hpp) mean for the
// labels, said to a user: only crossing parity is changed by faces that intersect (a
// winding number is the same whatever the surface's self-intersections), so only labels
// by parity are warned about. Intersecting pairs make the labels those of the parity
// solid; undecided pairs are contacts the exact check could not decide, said with what
// they are and what to do. The command line and Python say the same, each with its own
// option names.

#include <string>
#include <vector>

#include "exactgeo/inside/fill_rule.hpp"
#include "exactgeo/mesh/file_numbering.hpp"
#include "exactgeo/mesh/self_intersection.hpp"

namespace exactgeo::inside {

/// The warnings for labels by parity, faces named by `numbering` (the file's own):
/// "2 pairs of faces intersect (first: 1-2, 4-9) (faces numbered from 1, as in the file):
/// the labels are those of the parity solid ..." and "60 pairs of faces undecided (first:
/// ...) ...: ... what they are ... what to do", each a message of its own; none when
/// nothing was found. `oriented`: the faces are oriented alike, so that names.nonzero
/// would take the mesh.
std::vector<std::string> self_intersection_warnings(const mesh::SelfIntersections& found,
                                                    const mesh::FileNumbering& numbering,
                                                    bool oriented, const OptionNames& names);

}  // namespace exactgeo::inside
