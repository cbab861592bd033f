#include "exactgeo/ccd/root_parity.hpp"

#include "exactgeo/ccd/internal/root_parity_core.hpp"
#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo::ccd {

RootParityResult vertex_face_root_parity(const VertexFaceQuery& query,
                                         Arithmetic arithmetic) noexcept {
  const auto corners = internal::corner_images(query);
  return exactgeo::kernel::with_signs(
      arithmetic, [&](const auto& signs) { return internal::root_parity(signs, corners); });
}

RootParityResult edge_edge_root_parity(const EdgeEdgeQuery& query, Arithmetic arithmetic) noexcept {
  const auto corners = internal::corner_images(query);
  return exactgeo::kernel::with_signs(
      arithmetic, [&](const auto& signs) { return internal::root_parity(signs, corners); });
}

}  // namespace exactgeo::ccd
