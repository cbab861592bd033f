#pragma once

// A cheap exact proof that a vertex-face or edge-edge pair of a pseudo-motion stays apart
// through the step, tried before exact CCD where a collapse into one end moves a single
// vertex (collapse.cpp, pseudo_motion.cpp).
//
// When exactly one corner m of the pair moves (from m0 to m1, on a straight line) and the
// others stand, the primitive with m sweeps conv(S + {m0, m1}), S its standing corners:
// each of its positions conv(S + {m(t)}) lies in that hull, as m(t) lies on m0 m1. (The
// sweep is the whole hull: a point of it with weight w > 0 on m0 and m1 together is a
// point of conv(S + {m(t)}) for the t that their weights' ratio gives.) The other
// primitive stands. So the pair touches at no time of the closed step when a plane
// through three points of one of the two sets has the rest of that set on one closed side
// and every point of the other strictly on the other side: the two hulls are apart.
// Every such side is an exact orient3d; three collinear points give zeros, which prove
// nothing, so no degenerate plane is ever used.
//
// This decides only "apart"; otherwise exact CCD decides as before, and since CCD counts
// touching in the closed step, it finds no contact where a plane keeps the hulls apart:
// the answers are CCD's (tests/remesh/one_mover_test.cpp, against a rational hull oracle).

#include "exactgeo/ccd/queries.hpp"

namespace exactgeo::remesh::internal {

/// Whether exactly one corner of the pair moves and a plane keeps its swept hull apart
/// from the other primitive (the header's argument); false when it cannot tell.
bool one_mover_apart(const ccd::VertexFaceQuery& q) noexcept;
bool one_mover_apart(const ccd::EdgeEdgeQuery& q) noexcept;

}  // namespace exactgeo::remesh::internal
