#include "exactgeo/predicates/orient3d.hpp"

#include "exactgeo/predicates/kernel/signs.hpp"

namespace exactgeo {

namespace {

template <class Signs>
Sign orient3d_with(const Signs& signs, const Point3& a, const Point3& b, const Point3& c,
                   const Point3& d) noexcept {
  using kernel::Offset;
  return signs.det3_by_axis(Offset::between(a, b), Offset::between(a, c), Offset::between(a, d));
}

}  // namespace

Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) noexcept {
  return orient3d_with(kernel::ExactSigns{}, a, b, c, d);
}

Sign orient2d_along(int axis, const Point3& a, const Point3& b, const Point3& c) noexcept {
  using kernel::Offset;
  return kernel::ExactSigns{}.cross2(axis, Offset::between(a, b), Offset::between(a, c));
}

bool collinear(const Point3& p, const Point3& q, const Point3& r) noexcept {
  return orient2d_along(0, p, q, r) == Sign::zero && orient2d_along(1, p, q, r) == Sign::zero &&
         orient2d_along(2, p, q, r) == Sign::zero;
}

Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
              Arithmetic arithmetic) noexcept {
  return kernel::with_signs(arithmetic,
                            [&](const auto& signs) { return orient3d_with(signs, a, b, c, d); });
}

}  // namespace exactgeo
