#pragma once

// The boundary of a surface as a chain: what the generalized winding number of an open
// surface needs beyond its faces (exactgeo/predicates/boundary_term.hpp).

#include <vector>

#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/boundary_term.hpp"

namespace exactgeo::mesh {

/// Every edge used more often in one direction than in the other, oriented the way more
/// faces run it, with the difference as its multiplicity, in the order of the edges'
/// smaller then larger vertex index. Empty for a closed oriented surface. Edges of a
/// repeated corner (a -> a) join nothing and are left out. Precondition: corner indices
/// in range.
std::vector<BoundaryEdge> boundary_chain(const Mesh& mesh);

}  // namespace exactgeo::mesh
