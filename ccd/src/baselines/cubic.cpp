#include "exactgeo/ccd/baselines/cubic.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace exactgeo::ccd {

namespace {

using V = std::array<double, 3>;

V operator+(const V& a, const V& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
V operator-(const V& a, const V& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V operator*(double s, const V& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
double dot(const V& a, const V& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double det(const V& a, const V& b, const V& c) {
  return dot(a, cross(b, c));
}
double norm(const V& a) {
  return std::sqrt(dot(a, a));
}

/// A few times, without the heap: at most 4 touching points, 3 roots between the
/// derivative's roots, the two ends and 15 samples.
class Times {
 public:
  void push(double t) noexcept {
    if (size_ < t_.size()) t_[size_++] = t;
  }
  const double* begin() const noexcept { return t_.data(); }
  const double* end() const noexcept { return t_.data() + size_; }
  double* begin() noexcept { return t_.data(); }
  double* end() noexcept { return t_.data() + size_; }

 private:
  std::array<double, 32> t_{};
  std::size_t size_ = 0;
};

/// Position at time t of a point moving linearly from p0 to p1.
V at(const Point3& p0, const Point3& p1, double t) {
  return p0 + t * (p1 - p0);
}

/// Coefficients c0 + c1 t + c2 t^2 + c3 t^3 of det(a(t), b(t), c(t)) for a(t) = a0 + t a1 etc.
std::array<double, 4> coplanarity_cubic(const V& a0, const V& a1, const V& b0, const V& b1,
                                        const V& c0, const V& c1) {
  return {det(a0, b0, c0), det(a1, b0, c0) + det(a0, b1, c0) + det(a0, b0, c1),
          det(a1, b1, c0) + det(a1, b0, c1) + det(a0, b1, c1), det(a1, b1, c1)};
}

double evaluate(const std::array<double, 4>& c, double t) {
  return ((c[3] * t + c[2]) * t + c[1]) * t + c[0];
}

/// Times in [lo, hi] where the cubic changes sign or nearly vanishes: the interval is cut
/// at the derivative's roots into monotone pieces, each searched by bisection.
Times coplanarity_times(const std::array<double, 4>& c, double lo, double hi, double zero) {
  Times cuts;
  cuts.push(lo);
  cuts.push(hi);
  // Derivative 3 c3 t^2 + 2 c2 t + c1.
  const double a = 3 * c[3], b = 2 * c[2], d = c[1];
  if (a != 0) {
    const double disc = b * b - 4 * a * d;
    if (disc >= 0) {
      const double s = std::sqrt(disc);
      for (const double r : {(-b - s) / (2 * a), (-b + s) / (2 * a)}) {
        if (r > lo && r < hi) cuts.push(r);
      }
    }
  } else if (b != 0) {
    const double r = -d / b;
    if (r > lo && r < hi) cuts.push(r);
  }
  std::sort(cuts.begin(), cuts.end());
  Times times;
  for (const double t : cuts) {
    if (std::fabs(evaluate(c, t)) <= zero) times.push(t);  // touches zero
  }
  for (const double* cut = cuts.begin(); cut + 1 < cuts.end(); ++cut) {
    double l = cut[0], r = cut[1];
    double fl = evaluate(c, l);
    if ((fl < 0) == (evaluate(c, r) < 0)) continue;
    for (int iteration = 0; iteration < 60; ++iteration) {
      const double m = 0.5 * (l + r);
      const double fm = evaluate(c, m);
      if ((fm < 0) == (fl < 0)) {
        l = m;
        fl = fm;
      } else {
        r = m;
      }
    }
    times.push(0.5 * (l + r));
  }
  return times;
}

/// Distance from p to the closest point of triangle (a, b, c) (Ericson, "Real-Time
/// Collision Detection", 5.1.5).
double point_triangle_distance(const V& p, const V& a, const V& b, const V& c) {
  const V ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return norm(ap);
  const V bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return norm(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return norm(p - (a + (d1 / (d1 - d3)) * ab));
  const V cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return norm(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return norm(p - (a + (d2 / (d2 - d6)) * ac));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return norm(p - (b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)));
  }
  const double denominator = 1 / (va + vb + vc);
  return norm(p - (a + (vb * denominator) * ab + (vc * denominator) * ac));
}

/// Distance between segments [p1, q1] and [p2, q2] (Ericson 5.1.9).
double segment_segment_distance(const V& p1, const V& q1, const V& p2, const V& q2) {
  const V d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a == 0 && e == 0) return norm(r);
  if (a == 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e == 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2), denominator = a * e - b * b;
      s = denominator != 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return norm((p1 + s * d1) - (p2 + t * d2));
}

/// The candidate times: the ends of the step, the coplanarity times, and, when the points
/// stay (numerically) coplanar throughout, a uniform sampling of the step.
template <class Points>
Times candidate_times(const Points& t0, const Points& t1, double tolerance) {
  const V a0 = t0[1] - t0[0], b0 = t0[2] - t0[0], c0 = t0[3] - t0[0];
  const V a1 = (t1[1] - t1[0]) - a0, b1 = (t1[2] - t1[0]) - b0, c1 = (t1[3] - t1[0]) - c0;
  const auto cubic = coplanarity_cubic(a0, a1, b0, b1, c0, c1);
  double scale = 0;
  for (const V& v : {a0, b0, c0, a0 + a1, b0 + b1, c0 + c1})
    scale = std::max(scale, norm(v));
  // "Zero" for a volume: the tolerance times the squared scale of the configuration.
  const double zero = tolerance * scale * scale;
  Times times = coplanarity_times(cubic, -tolerance, 1 + tolerance, zero);
  for (double& t : times)
    t = std::clamp(t, 0.0, 1.0);
  times.push(0.0);
  times.push(1.0);
  if (std::all_of(cubic.begin(), cubic.end(), [&](double c) { return std::fabs(c) <= zero; })) {
    for (int k = 1; k < 16; ++k)
      times.push(k / 16.0);
  }
  return times;
}

/// The method itself, for four points moving from t0 to t1 and a distance between the
/// two primitives they form (first point vs triangle, or segment vs segment).
template <class Distance>
bool touches_at_a_coplanarity_time(const std::array<V, 4>& t0, const std::array<V, 4>& t1,
                                   double tolerance, Distance distance) noexcept {
  for (const double t : candidate_times(t0, t1, tolerance)) {
    std::array<V, 4> p;
    for (int i = 0; i < 4; ++i)
      p[i] = at(t0[i], t1[i], t);
    if (distance(p) <= tolerance) return true;
  }
  return false;
}

}  // namespace

bool vertex_face_cubic(const VertexFaceQuery& q, const CubicOptions& options) noexcept {
  return touches_at_a_coplanarity_time(
      {q.v_t0, q.f0_t0, q.f1_t0, q.f2_t0}, {q.v_t1, q.f0_t1, q.f1_t1, q.f2_t1}, options.tolerance,
      [](const std::array<V, 4>& p) { return point_triangle_distance(p[0], p[1], p[2], p[3]); });
}

bool edge_edge_cubic(const EdgeEdgeQuery& q, const CubicOptions& options) noexcept {
  return touches_at_a_coplanarity_time(
      {q.ea0_t0, q.ea1_t0, q.eb0_t0, q.eb1_t0}, {q.ea0_t1, q.ea1_t1, q.eb0_t1, q.eb1_t1},
      options.tolerance,
      [](const std::array<V, 4>& p) { return segment_segment_distance(p[0], p[1], p[2], p[3]); });
}

}  // namespace exactgeo::ccd
