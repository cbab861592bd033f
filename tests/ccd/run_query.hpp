#pragma once

// One CCD query of either kind, for tests written once for both: `run` with options,
// `separated` with a minimum separation only.

#include "exactgeo/ccd/ccd.hpp"

namespace exactgeo::ccd {

inline Result run(const VertexFaceQuery& q, const Options& o) {
  return vertex_face_ccd(q, o);
}
inline Result run(const EdgeEdgeQuery& q, const Options& o) {
  return edge_edge_ccd(q, o);
}

template <class Query>
Result separated(const Query& q, double delta) {
  Options o;
  o.min_separation = delta;
  return run(q, o);
}

}  // namespace exactgeo::ccd
