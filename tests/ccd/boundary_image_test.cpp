// The image of the CCD domain's boundary (internal/boundary_image.hpp): the corner images
// are views of the query's own points, in the documented order and exactly the
// differences of those points (GMP); the faces are the domain's faces, found here from
// the corners' parameters, each once, in boundary order with the documented parameters;
// faces marked as parallelograms are parallelograms for every query; the time slices'
// corners are the rounded images in order around their polygon.

#include "exactgeo/ccd/internal/boundary_image.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <vector>

#include "ccd/query_transforms.hpp"
#include "support/generators.hpp"
#include "support/seed.hpp"

namespace exactgeo::ccd::internal {
namespace {

using testing::Rng;
using Parameters = std::array<int, 3>;  ///< (t, i, j) of a corner of the domain

/// The domain's corner k: vertex-face 3t + j (time, triangle corner), i unused (0);
/// edge-edge 4t + 2i + j (time, end of edge a, end of edge b).
template <std::size_t C>
Parameters parameters(std::size_t k) {
  if constexpr (C == 6) {
    return {static_cast<int>(k / 3), 0, static_cast<int>(k % 3)};
  } else {
    return {static_cast<int>(k / 4), static_cast<int>(k / 2 % 2), static_cast<int>(k % 2)};
  }
}

/// A face's corners in boundary order (a triangle's three, a patch's p00, p10, p11, p01).
std::vector<VertexIndex> boundary_order(const SurfaceFace& f) {
  if (f.is_triangle()) return {f.corners[0], f.corners[1], f.corners[2]};
  return {f.corners[0], f.corners[1], f.corners[3], f.corners[2]};  // tensor order x0 x1 x2 x3
}

/// The faces of the domain from its corners' parameters: vertex-face, the two time
/// triangles and, per edge of the triangle, the side with those two corners at both
/// times; edge-edge, the six faces of the cube (a coordinate fixed at 0 or 1).
template <std::size_t C>
std::set<std::set<VertexIndex>> domain_faces() {
  std::set<std::set<VertexIndex>> faces;
  if constexpr (C == 6) {
    faces.insert({0, 1, 2});
    faces.insert({3, 4, 5});
    for (const auto& [a, b] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{0, 2}}) {
      faces.insert({static_cast<VertexIndex>(a), static_cast<VertexIndex>(b),
                    static_cast<VertexIndex>(3 + a), static_cast<VertexIndex>(3 + b)});
    }
  } else {
    for (int axis = 0; axis < 3; ++axis) {
      for (int value = 0; value < 2; ++value) {
        std::set<VertexIndex> face;
        for (std::size_t k = 0; k < C; ++k) {
          if (parameters<C>(k)[axis] == value) face.insert(static_cast<VertexIndex>(k));
        }
        faces.insert(face);
      }
    }
  }
  return faces;
}

/// The parameters in which two corners differ.
template <std::size_t C>
std::vector<int> changed(std::size_t a, std::size_t b) {
  std::vector<int> axes;
  for (int axis = 0; axis < 3; ++axis) {
    if (parameters<C>(a)[axis] != parameters<C>(b)[axis]) axes.push_back(axis);
  }
  return axes;
}

template <std::size_t C>
void expect_the_domains_faces() {
  constexpr auto& faces = kDomainFaces<C>;
  std::set<std::set<VertexIndex>> listed;
  for (const SurfaceFace& f : faces) {
    const std::vector<VertexIndex> corners = boundary_order(f);
    listed.insert(std::set<VertexIndex>(corners.begin(), corners.end()));
    for (const VertexIndex k : corners)
      EXPECT_LT(k, C);
    if (f.is_triangle()) continue;
    // Boundary order: every side of the patch is an edge of the domain, along one
    // parameter; p10 - p00 and p01 - p00 along two different ones (the patch's (s, r)).
    for (std::size_t s = 0; s < 4; ++s) {
      EXPECT_EQ(changed<C>(corners[s], corners[(s + 1) % 4]).size(), 1u)
          << "a side of a patch that is not an edge of the domain";
    }
    const std::vector<int> first = changed<C>(corners[0], corners[1]);
    const std::vector<int> second = changed<C>(corners[0], corners[3]);
    ASSERT_EQ(first.size(), 1u);
    ASSERT_EQ(second.size(), 1u);
    EXPECT_NE(first[0], second[0]);
    // The comments' convention: a side face's first parameter is time.
    bool time_face = true;
    for (const VertexIndex k : corners)
      time_face = time_face && parameters<C>(k)[0] == parameters<C>(corners[0])[0];
    if (!time_face) {
      EXPECT_EQ(first[0], 0) << "side faces are parametrized (t, ...)";
    }
  }
  EXPECT_EQ(listed, domain_faces<C>()) << "each face of the domain, once";
  EXPECT_EQ(listed.size(), faces.size());
  // The time faces come first: the start's slice, then the end's.
  for (std::size_t slice = 0; slice < 2; ++slice) {
    for (const VertexIndex k : boundary_order(faces[slice]))
      EXPECT_EQ(parameters<C>(k)[0], static_cast<int>(slice));
  }
}

TEST(BoundaryImage, PrismFacesAreTheDomainsFaces) {
  EXPECT_TRUE(std::equal(kDomainFaces<6>.begin(), kDomainFaces<6>.end(), kPrismFaces.begin(),
                         [](const SurfaceFace& a, const SurfaceFace& b) {
                           return a.kind == b.kind && a.corners == b.corners;
                         }));
  expect_the_domains_faces<6>();
  int triangles = 0;
  for (const SurfaceFace& f : kPrismFaces)
    triangles += f.is_triangle();
  EXPECT_EQ(triangles, 2);
}

TEST(BoundaryImage, HexahedronFacesAreTheDomainsFaces) {
  EXPECT_TRUE(std::equal(kDomainFaces<8>.begin(), kDomainFaces<8>.end(), kHexahedronFaces.begin(),
                         [](const SurfaceFace& a, const SurfaceFace& b) {
                           return a.kind == b.kind && a.corners == b.corners;
                         }));
  expect_the_domains_faces<8>();
  for (const SurfaceFace& f : kHexahedronFaces)
    EXPECT_FALSE(f.is_triangle());
}

using Exact = std::array<mpq_class, 3>;

Exact exact_difference(const Point3& head, const Point3& tail) {
  return {mpq_class(head[0]) - mpq_class(tail[0]), mpq_class(head[1]) - mpq_class(tail[1]),
          mpq_class(head[2]) - mpq_class(tail[2])};
}

Exact exact_value(const Offset& o) {
  return exact_difference(o.head_point(), o.tail_point());
}

/// Corner k views head - tail of the two named points of q, themselves (not copies).
void expect_view(const Offset& o, const Point3& head, const Point3& tail, std::size_t k) {
  EXPECT_EQ(&o.head_point(), &head) << "corner " << k;
  EXPECT_EQ(&o.tail_point(), &tail) << "corner " << k;
  EXPECT_FALSE(o.is_exact_vector());
  EXPECT_TRUE(exact_value(o) == exact_difference(head, tail)) << "corner " << k;
}

/// The slices' corners: the rounded images, in the time face's boundary order.
template <std::size_t C>
void expect_slices(const Offsets<C>& a) {
  for (std::size_t slice = 0; slice < 2; ++slice) {
    const auto x = slice_corners<C>(a, slice);
    const std::vector<VertexIndex> around = boundary_order(kDomainFaces<C>[slice]);
    ASSERT_EQ(around.size(), x.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
      const Offset& o = a[around[k]];
      for (int axis = 0; axis < 3; ++axis)
        EXPECT_EQ(x[k][axis], o.head(axis) - o.tail(axis)) << "slice " << slice << " corner " << k;
    }
  }
}

/// Every face marked as a parallelogram is one, exactly: p00 + p11 = p10 + p01.
template <std::size_t C>
int expect_parallelograms(const Offsets<C>& a) {
  int marked = 0;
  for (const SurfaceFace& f : kDomainFaces<C>) {
    if (f.kind != SurfaceFace::Kind::parallelogram) continue;
    ++marked;
    const auto& c = f.corners;  // tensor order: p00, p10, p01, p11
    const Exact p00 = exact_value(a[c[0]]), p10 = exact_value(a[c[1]]), p01 = exact_value(a[c[2]]),
                p11 = exact_value(a[c[3]]);
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(p00[axis] + p11[axis], p10[axis] + p01[axis]);
  }
  return marked;
}

TEST(BoundaryImage, VertexFaceCornersAreTheDifferencesInOrder) {
  Rng rng = testing::seeded_engine("boundary-image-vf");
  for (int i = 0; i < 500; ++i) {
    const VertexFaceQuery q = varied_query<VertexFaceQuery>(rng, i);
    const Offsets<6> a = corner_images(q);
    // c_tj = v(t) - fj(t) at index 3t + j.
    const std::array<const Point3*, 6> faces{&q.f0_t0, &q.f1_t0, &q.f2_t0,
                                             &q.f0_t1, &q.f1_t1, &q.f2_t1};
    for (std::size_t k = 0; k < 6; ++k)
      expect_view(a[k], k < 3 ? q.v_t0 : q.v_t1, *faces[k], k);
    expect_slices<6>(a);
    EXPECT_EQ(expect_parallelograms<6>(a), 0);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(BoundaryImage, EdgeEdgeCornersAreTheDifferencesInOrder) {
  Rng rng = testing::seeded_engine("boundary-image-ee");
  for (int i = 0; i < 500; ++i) {
    const EdgeEdgeQuery q = varied_query<EdgeEdgeQuery>(rng, i);
    const Offsets<8> a = corner_images(q);
    // c_tij = eai(t) - ebj(t) at index 4t + 2i + j.
    const std::array<std::array<const Point3*, 2>, 2> ea{
        {{&q.ea0_t0, &q.ea1_t0}, {&q.ea0_t1, &q.ea1_t1}}};
    const std::array<std::array<const Point3*, 2>, 2> eb{
        {{&q.eb0_t0, &q.eb1_t0}, {&q.eb0_t1, &q.eb1_t1}}};
    for (std::size_t k = 0; k < 8; ++k) {
      const Parameters p = parameters<8>(k);
      expect_view(a[k], *ea[p[0]][p[1]], *eb[p[0]][p[2]], k);
    }
    expect_slices<8>(a);
    EXPECT_EQ(expect_parallelograms<8>(a), 2) << "both time slices";
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace exactgeo::ccd::internal
