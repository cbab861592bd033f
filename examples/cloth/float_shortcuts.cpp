#include "float_shortcuts.hpp"

#include <algorithm>
#include <cmath>

namespace exactgeo::cloth {
namespace {

/// Below it, squares of the inputs' differences may have lost their precision (a product
/// of two such squares may underflow).
constexpr double kTiny = 1e-280;

bool usable(double square) {
  return square > kTiny && std::isfinite(square);
}

}  // namespace

double world_min_angle(const Point3& p, const Point3& q, const Point3& r) {
  const auto angle_at = [](const Point3& o, const Point3& x, const Point3& y) {
    const double ux = x[0] - o[0], uy = x[1] - o[1], uz = x[2] - o[2];
    const double vx = y[0] - o[0], vy = y[1] - o[1], vz = y[2] - o[2];
    const double cross = std::hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
    return std::atan2(cross, ux * vx + uy * vy + uz * vz);
  };
  return std::min({angle_at(p, q, r), angle_at(q, r, p), angle_at(r, p, q)});
}

double world_min_angle_to_floor(const Point3& p, const Point3& q, const Point3& r) {
  static const double tan_squared = std::pow(std::tan(kMinAngle), 2);
  constexpr double kMargin = 1.0 + 1e-6;
  const auto clear = [&](const Point3& o, const Point3& x, const Point3& y) {
    const double ux = x[0] - o[0], uy = x[1] - o[1], uz = x[2] - o[2];
    const double vx = y[0] - o[0], vy = y[1] - o[1], vz = y[2] - o[2];
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    const double cross_squared = cx * cx + cy * cy + cz * cz;
    const double dot = ux * vx + uy * vy + uz * vz;
    if (!usable(cross_squared) || !std::isfinite(dot)) return false;
    if (dot <= 0.0) return true;
    const double dot_squared = dot * dot;
    return usable(dot_squared) && cross_squared >= kMargin * tan_squared * dot_squared;
  };
  if (clear(p, q, r) && clear(q, r, p) && clear(r, p, q)) return kMinAngle;
  return world_min_angle(p, q, r);
}

}  // namespace exactgeo::cloth
