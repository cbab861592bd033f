#pragma once

// Minimum separation as polynomial sign conditions in time, one conjunction per feature.
//
// The distance from a point v to a closed triangle T is at most δ exactly when, for some
// feature of T, the point's projection onto that feature's affine hull lies in the feature
// and is within δ. With w = v - a, e = b - a for an edge (a, b), and
// n = (f1 - f0) x (f2 - f0) for the face:
//
//   vertex a:  |w|^2 - δ^2 <= 0
//   edge ab:   e.e > 0, w.e >= 0, e.e - w.e >= 0 (the projection lies on the segment),
//              |w|^2 e.e - (w.e)^2 - δ^2 e.e <= 0 (e.e times the squared distance to the
//              line, Lagrange's identity, minus e.e δ^2)
//   face:      n.n > 0, n.((f1 - f0) x (v - f0)) >= 0 and its two cyclic shifts (the
//              projection's barycentric coordinates times n.n: v - q is parallel to n for
//              the projection q, so replacing q by v adds a vector orthogonal to n),
//              (n.(v - f0))^2 - δ^2 n.n <= 0
//
// Each conjunction exhibits a point of T within δ of v. Conversely the point of T closest
// to v lies in the relative interior of a vertex, of an edge of nonzero length, or of the
// face of a triangle with n != 0; that feature's conjunction holds. A degenerate triangle
// (n = 0) is a segment or a point, covered by its edges and vertices; an edge of length
// zero is covered by its vertices. That is why the weights e.e and n.n must be strictly
// positive: at n = 0 every face condition reads 0 <= 0.
//
// Two segments a0 + s da and b0 + u db are within δ when an endpoint pair is, or an
// endpoint and the other segment are (as vertex and edge above), or, with r = b0 - a0 and
// w = da x db != 0, the closest points of the two lines, at s = (r x db).w / w.w and
// u = (r x da).w / w.w, lie on the segments and (w.r)^2 - δ^2 w.w <= 0. Parallel segments
// (w = 0) have a closest pair with an endpoint, so the endpoint features cover them.
//
// Every point moves linearly in time, so over a piece of the step every quantity is a
// polynomial in the piece's own time s in [0, 1], of degree at most 6. The polynomials
// are kept in the homogeneous Bernstein basis (1 - s)^(n-k) s^k: a linear function is its
// values at the two ends, a product is a convolution of coefficients (no binomials, so no
// rounding beyond the products), and all coefficients of one sign prove that sign on the
// whole piece (the basis functions are positive inside it). The scalar type is a
// parameter: exact rationals for the exact decision, bounded doubles for the filter.

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>

namespace exactgeo::ccd::internal {

/// sum_k c[k] (1 - s)^(degree - k) s^k, degree <= 6.
template <class T>
struct Homogeneous {
  static constexpr int kMaxDegree = 6;
  int degree = 0;
  std::array<T, kMaxDegree + 1> c{};

  static Homogeneous constant(const T& x) {
    Homogeneous p;
    p.c[0] = x;
    return p;
  }
  static Homogeneous linear(const T& at_start, const T& at_end) {
    Homogeneous p;
    p.degree = 1;
    p.c[0] = at_start;
    p.c[1] = at_end;
    return p;
  }
  const T& at_start() const { return c[0]; }
  const T& at_end() const { return c[degree]; }
};

/// The same polynomial written in degree `to` (times ((1 - s) + s)^(to - degree)).
template <class T>
Homogeneous<T> elevated(Homogeneous<T> p, int to) {
  while (p.degree < to) {
    Homogeneous<T> q;
    q.degree = p.degree + 1;
    q.c[0] = p.c[0];
    for (int k = 1; k <= p.degree; ++k)
      q.c[k] = p.c[k - 1] + p.c[k];
    q.c[q.degree] = p.c[p.degree];
    p = q;
  }
  return p;
}

template <class T>
Homogeneous<T> operator+(const Homogeneous<T>& a, const Homogeneous<T>& b) {
  const int n = std::max(a.degree, b.degree);
  Homogeneous<T> x = elevated(a, n);
  const Homogeneous<T> y = elevated(b, n);
  for (int k = 0; k <= n; ++k)
    x.c[k] = x.c[k] + y.c[k];
  return x;
}

template <class T>
Homogeneous<T> operator-(const Homogeneous<T>& a, const Homogeneous<T>& b) {
  const int n = std::max(a.degree, b.degree);
  Homogeneous<T> x = elevated(a, n);
  const Homogeneous<T> y = elevated(b, n);
  for (int k = 0; k <= n; ++k)
    x.c[k] = x.c[k] - y.c[k];
  return x;
}

template <class T>
Homogeneous<T> operator*(const Homogeneous<T>& a, const Homogeneous<T>& b) {
  Homogeneous<T> x;
  x.degree = a.degree + b.degree;
  assert(x.degree <= Homogeneous<T>::kMaxDegree);
  for (int i = 0; i <= a.degree; ++i) {
    for (int j = 0; j <= b.degree; ++j) {
      const T product = a.c[i] * b.c[j];
      x.c[i + j] = x.c[i + j] + product;
    }
  }
  return x;
}

template <class T>
using Moving = std::array<Homogeneous<T>, 3>;  ///< a point or vector over the piece

template <class T>
Moving<T> operator-(const Moving<T>& a, const Moving<T>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

template <class T>
Homogeneous<T> dot(const Moving<T>& a, const Moving<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class T>
Moving<T> cross(const Moving<T>& a, const Moving<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// One feature's conjunction: gap <= 0, every in_feature[i] >= 0 (the projection lies in
/// the feature) and weight > 0 (weight is the constant 1 for a vertex).
template <class T>
struct Feature {
  Homogeneous<T> gap;
  std::array<Homogeneous<T>, 4> in_feature{};
  int in_feature_count = 0;
  Homogeneous<T> weight;
};

/// Point p against the point a.
template <class T>
Feature<T> vertex_feature(const Moving<T>& p, const Moving<T>& a, const T& delta2) {
  const Moving<T> w = p - a;
  Feature<T> f;
  f.gap = dot(w, w) - Homogeneous<T>::constant(delta2);
  f.weight = Homogeneous<T>::constant(T(1));
  return f;
}

/// Point p against the segment (a, b).
template <class T>
Feature<T> edge_feature(const Moving<T>& p, const Moving<T>& a, const Moving<T>& b,
                        const T& delta2) {
  const Moving<T> e = b - a;
  const Moving<T> w = p - a;
  const Homogeneous<T> ee = dot(e, e);
  const Homogeneous<T> we = dot(w, e);
  Feature<T> f;
  f.weight = ee;
  f.in_feature = {we, ee - we};
  f.in_feature_count = 2;
  f.gap = dot(w, w) * ee - we * we - Homogeneous<T>::constant(delta2) * ee;
  return f;
}

/// Point p against the inside of the triangle (a, b, c).
template <class T>
Feature<T> face_feature(const Moving<T>& p, const Moving<T>& a, const Moving<T>& b,
                        const Moving<T>& c, const T& delta2) {
  const Moving<T> n = cross(b - a, c - a);
  const Homogeneous<T> nn = dot(n, n);
  const Homogeneous<T> height = dot(n, p - a);
  Feature<T> f;
  f.weight = nn;
  f.in_feature = {dot(n, cross(b - a, p - a)), dot(n, cross(c - b, p - b)),
                  dot(n, cross(a - c, p - c))};
  f.in_feature_count = 3;
  f.gap = height * height - Homogeneous<T>::constant(delta2) * nn;
  return f;
}

/// The insides of the segments (a0, a1) and (b0, b1).
template <class T>
Feature<T> segments_feature(const Moving<T>& a0, const Moving<T>& a1, const Moving<T>& b0,
                            const Moving<T>& b1, const T& delta2) {
  const Moving<T> da = a1 - a0;
  const Moving<T> db = b1 - b0;
  const Moving<T> r = b0 - a0;
  const Moving<T> w = cross(da, db);
  const Homogeneous<T> ww = dot(w, w);
  const Homogeneous<T> s = dot(cross(r, db), w);
  const Homogeneous<T> u = dot(cross(r, da), w);
  const Homogeneous<T> height = dot(w, r);
  Feature<T> f;
  f.weight = ww;
  f.in_feature = {s, ww - s, u, ww - u};
  f.in_feature_count = 4;
  f.gap = height * height - Homogeneous<T>::constant(delta2) * ww;
  return f;
}

inline constexpr std::size_t kVertexFaceFeatures = 7;
inline constexpr std::size_t kEdgeEdgeFeatures = 9;

/// Feature i < 7 of a vertex-face query (the vertices, the edges, the face); x holds v,
/// f0, f1, f2 over the piece. One at a time: a decision often needs only a few.
template <class T>
Feature<T> vertex_face_feature(std::size_t i, const std::array<Moving<T>, 4>& x, const T& delta2) {
  const auto& [v, f0, f1, f2] = x;
  switch (i) {
    case 0:
      return vertex_feature(v, f0, delta2);
    case 1:
      return vertex_feature(v, f1, delta2);
    case 2:
      return vertex_feature(v, f2, delta2);
    case 3:
      return edge_feature(v, f0, f1, delta2);
    case 4:
      return edge_feature(v, f1, f2, delta2);
    case 5:
      return edge_feature(v, f2, f0, delta2);
    default:
      return face_feature(v, f0, f1, f2, delta2);
  }
}

/// Feature i < 9 of an edge-edge query (endpoint pairs, endpoints against segments, the
/// insides); x holds a0, a1, b0, b1 over the piece.
template <class T>
Feature<T> edge_edge_feature(std::size_t i, const std::array<Moving<T>, 4>& x, const T& delta2) {
  const auto& [a0, a1, b0, b1] = x;
  switch (i) {
    case 0:
      return vertex_feature(a0, b0, delta2);
    case 1:
      return vertex_feature(a0, b1, delta2);
    case 2:
      return vertex_feature(a1, b0, delta2);
    case 3:
      return vertex_feature(a1, b1, delta2);
    case 4:
      return edge_feature(a0, b0, b1, delta2);
    case 5:
      return edge_feature(a1, b0, b1, delta2);
    case 6:
      return edge_feature(b0, a0, a1, delta2);
    case 7:
      return edge_feature(b1, a0, a1, delta2);
    default:
      return segments_feature(a0, a1, b0, b1, delta2);
  }
}

}  // namespace exactgeo::ccd::internal
