#pragma once

// The exact rays at magnitude 1, whatever the mesh's magnitude.
//
// Every sign an exact ray takes is the sign of a polynomial homogeneous in the offsets
// corner - point, for each power of the direction apart (docs/predicates.md, "The filter
// and its constants"): multiplying the mesh's vertices and the query point by one power
// of two, the direction left as it is, changes no sign, no crossing and no label. The
// filters, though, certify only where every group's largest input lies in their guard
// (2^±242 for det3, 2^±96 for phi). At 2^±1000 or 1e300 every sign of a ray missed them,
// and since the direction's coordinates (3/16, 9/256, 1, ...) are exact in a few bits
// while the offsets are near the mesh's size, the inputs of one sign spanned more binades
// than one common scaling of the expansion stage covers (about 650 for det3): GMP
// rationals decided every sign (docs/inside.md has the cost, measured).
//
// So when the largest extent X of the box of the faces' corners lies outside
// [2^-64, 2^64] (the window in which CCD leaves its queries as they are too,
// predicates/kernel/unit_magnitude.hpp), the rays see the vertices and the query point
// multiplied by 2^-e, X in [2^(e-1), 2^e): every offset of a point of the box then lies
// below 1 in magnitude, as for a mesh of size 1, and a sign's group maxima fall out of the
// filters' guards only where they would at size 1 (a point within 2^-96 of a face's
// corners, relative to the box). Inside the window nothing is done: offsets below 2^64
// are inside every guard's upper end (phi's 2^96 is the lowest), and a group maximum below
// a guard's lower end (2^-96 at the highest) is then a point within 2^-32 of a face's
// corners relative to the box, rare, and decided by expansions (the direction and the
// offsets are within one scaling's reach), not by rationals.
//
// Only exact products are used (kernel::ExactPowerOfTwo): the frame is off unless every
// corner of every face maps exactly, and a query point whose coordinates do not all map
// exactly casts its rays as given, against the vertices as given (exact, and as slow as
// before). A coordinate fails to map only if it lies about 1,000 binades below X (it
// would become subnormal and lose bits: 2^1000 and 1e-300 in one mesh) or more than
// 2^1024 X from 0 (it would overflow: only along an axis on which the box is flat).

#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "exactgeo/mesh/check.hpp"
#include "exactgeo/mesh/mesh.hpp"
#include "exactgeo/predicates/kernel/power_of_two.hpp"
#include "exactgeo/predicates/kernel/unit_magnitude.hpp"
#include "exactgeo/predicates/point.hpp"

namespace exactgeo::inside::internal {

class UnitFrame {
 public:
  /// Off: the rays see the mesh as given.
  UnitFrame() = default;

  /// The frame of `mesh`, whose faces' corners have the box `box` (finite bounds).
  UnitFrame(const mesh::Mesh& mesh, const mesh::Box& box) {
    double extent = 0.0;  // infinite when the box is wider than DBL_MAX
    for (int i = 0; i < 3; ++i)
      extent = std::fmax(extent, box.upper[i] - box.lower[i]);
    if (kernel::near_unit_magnitude(extent)) return;
    exponent_ = -kernel::unit_exponent(extent);  // extent 2^exponent_ in [1/2, 1)
    scale_ = kernel::ExactPowerOfTwo(exponent_);
    std::vector<Point3> vertices(mesh.vertices.size());
    std::vector<char> exact(mesh.vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      bool all = true;
      for (int i = 0; i < 3; ++i)
        vertices[v][i] = scale_(mesh.vertices[v][i], all);
      exact[v] = all ? 1 : 0;
    }
    // Only faces' corners are read by a ray; a vertex no face uses may map as it does.
    for (const mesh::Face& f : mesh.faces) {
      for (std::size_t k = 0; k < f.size(); ++k) {
        if (exact[f.corners[k]] == 0) return;
      }
    }
    vertices_ = std::move(vertices);
  }

  bool on() const noexcept { return !vertices_.empty(); }
  /// The power of two the frame multiplies by, as an exponent (0 when off).
  int exponent() const noexcept { return on() ? exponent_ : 0; }
  /// The mesh's vertices in the frame. Precondition: on().
  std::span<const Point3> vertices() const noexcept { return vertices_; }

  /// `p` in the frame, when the frame is on and maps it exactly.
  std::optional<Point3> map(const Point3& p) const noexcept {
    if (!on()) return std::nullopt;
    bool exact = true;
    const Point3 q{scale_(p[0], exact), scale_(p[1], exact), scale_(p[2], exact)};
    if (!exact) return std::nullopt;
    return q;
  }

 private:
  int exponent_ = 0;
  kernel::ExactPowerOfTwo scale_{0};
  std::vector<Point3> vertices_;
};

}  // namespace exactgeo::inside::internal
