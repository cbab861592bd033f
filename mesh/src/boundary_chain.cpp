#include "exactgeo/mesh/boundary_chain.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace exactgeo::mesh {

std::vector<BoundaryEdge> boundary_chain(const Mesh& mesh) {
  // Every use as (smaller, larger) with +1 when run from the smaller vertex, -1 otherwise.
  struct Use {
    VertexIndex low, high;
    std::int32_t way;
  };
  std::vector<Use> uses;
  uses.reserve(4 * mesh.faces.size());
  for (const Face& face : mesh.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      const VertexIndex a = face.corner(i), b = face.corner(i + 1);
      if (a != b) uses.push_back({std::min(a, b), std::max(a, b), a < b ? 1 : -1});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return std::pair(x.low, x.high) < std::pair(y.low, y.high);
  });
  std::vector<BoundaryEdge> chain;
  for (std::size_t begin = 0; begin < uses.size();) {
    std::size_t end = begin;
    std::int32_t net = 0;
    for (; end < uses.size() && uses[end].low == uses[begin].low &&
           uses[end].high == uses[begin].high;
         ++end) {
      net += uses[end].way;
    }
    const Use& u = uses[begin];
    if (net > 0) chain.push_back({u.low, u.high, net});
    if (net < 0) chain.push_back({u.high, u.low, -net});
    begin = end;
  }
  return chain;
}

}  // namespace exactgeo::mesh
