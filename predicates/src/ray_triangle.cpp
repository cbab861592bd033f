#include "exactgeo/predicates/ray_triangle.hpp"

#include "exactgeo/predicates/internal/ray_triangle_core.hpp"

namespace exactgeo {

RayTriangleHit classify_ray_triangle(const Point3& origin, const Vector3& direction,
                                     const Point3& a, const Point3& b, const Point3& c,
                                     Arithmetic arithmetic) noexcept {
  using kernel::Offset;
  return kernel::with_signs(arithmetic, [&](const auto& signs) {
    return internal::classify_ray_triangle_offsets(
        signs, Offset::between(origin, a), Offset::between(origin, b), Offset::between(origin, c),
        Offset::vector(direction));
  });
}

}  // namespace exactgeo
