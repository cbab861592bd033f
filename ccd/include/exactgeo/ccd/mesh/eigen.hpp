#pragma once

// Eigen adapter for mesh-level CCD (mesh_ccd.hpp): vertex positions as #V x 3 double
// matrices and faces as a #F x 3 integer matrix, the layout of libigl and most
// simulators. Header-only; include it only where Eigen 3 is available (the exactgeo
// libraries themselves do not depend on Eigen).
//
// Row-major #V x 3 matrices are handed over without a copy; any other layout (Eigen's
// default column-major, expressions, blocks) is copied once into x, y, z per vertex.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "exactgeo/ccd/mesh/mesh_ccd.hpp"

namespace exactgeo::ccd::eigen {

/// The rows of F as triangles. Throws std::invalid_argument when F does not have 3
/// columns or holds a negative or too large index.
template <class DerivedF>
std::vector<Triangle> triangles(const Eigen::MatrixBase<DerivedF>& F) {
  static_assert(std::is_integral_v<typename DerivedF::Scalar>, "face indices must be integers");
  if (F.cols() != 3) throw std::invalid_argument("faces: 3 columns (one triangle per row) needed");
  std::vector<Triangle> faces(static_cast<std::size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (Eigen::Index k = 0; k < 3; ++k) {
      const auto v = F(f, k);
      bool out_of_range = static_cast<unsigned long long>(v) > 0xffffffffull;
      if constexpr (std::is_signed_v<typename DerivedF::Scalar>) out_of_range |= v < 0;
      if (out_of_range) {
        throw std::invalid_argument("faces: row " + std::to_string(f) + " has index " +
                                    std::to_string(v));
      }
      faces[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)] = static_cast<VertexIndex>(v);
    }
  }
  return faces;
}

/// A view of V's coordinates as x, y, z per vertex: V's own storage when it is already laid
/// out that way, otherwise `copy` (filled here).
template <class DerivedV>
std::span<const double> positions(const Eigen::MatrixBase<DerivedV>& V, std::vector<double>& copy) {
  static_assert(std::is_same_v<typename DerivedV::Scalar, double>, "positions must be double");
  if (V.cols() != 3) throw std::invalid_argument("positions: 3 columns (x, y, z) needed");
  const auto rows = static_cast<std::size_t>(V.rows());
  if constexpr (std::is_base_of_v<Eigen::PlainObjectBase<DerivedV>, DerivedV> &&
                static_cast<bool>(DerivedV::IsRowMajor)) {
    return {V.derived().data(), 3 * rows};
  } else {
    copy.resize(3 * rows);
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      for (Eigen::Index k = 0; k < 3; ++k)
        copy[3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(k)] = V(i, k);
    }
    return copy;
  }
}

/// A MeshCcd for #vertex_count vertices and the faces F.
template <class DerivedF>
MeshCcd make_mesh_ccd(Eigen::Index vertex_count, const Eigen::MatrixBase<DerivedF>& F) {
  if (vertex_count < 0) throw std::invalid_argument("negative vertex count");
  return MeshCcd(static_cast<std::size_t>(vertex_count), triangles(F));
}

/// ccd.step for positions V0 (start of the step) and V1 (end), both #V x 3.
template <class DerivedV0, class DerivedV1>
MeshCcdResult step(MeshCcd& ccd, const Eigen::MatrixBase<DerivedV0>& V0,
                   const Eigen::MatrixBase<DerivedV1>& V1, const MeshCcdOptions& options = {}) {
  std::vector<double> copy0, copy1;
  return ccd.step({positions(V0, copy0), positions(V1, copy1)}, options);
}

}  // namespace exactgeo::ccd::eigen
