// The Eigen adapter hands the same numbers to MeshCcd as the plain arrays do, for every
// storage order, and refuses malformed matrices.

#include "exactgeo/ccd/mesh/eigen.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "support/seed.hpp"

namespace exactgeo::ccd {
namespace {

using RowMajorPositions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// A soup of small triangles, each moving on its own, with collisions among them.
struct Soup {
  Eigen::MatrixXd v0, v1;  // column-major, Eigen's default
  Eigen::MatrixXi faces;
};

Soup random_soup(int triangles, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> centre(0.0, 1.0), jitter(-0.08, 0.08);
  Soup soup{Eigen::MatrixXd(3 * triangles, 3), Eigen::MatrixXd(3 * triangles, 3),
            Eigen::MatrixXi(triangles, 3)};
  for (int t = 0; t < triangles; ++t) {
    const Eigen::RowVector3d c(centre(rng), centre(rng), centre(rng));
    const Eigen::RowVector3d motion(jitter(rng), jitter(rng), jitter(rng));
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = c + Eigen::RowVector3d(jitter(rng), jitter(rng), jitter(rng));
      soup.v0.row(3 * t + k) = p;
      soup.v1.row(3 * t + k) = p + motion;
      soup.faces(t, k) = 3 * t + k;
    }
  }
  return soup;
}

MeshCcdResult plain_arrays(const Soup& soup, const MeshCcdOptions& options) {
  std::vector<double> x0, x1;
  for (Eigen::Index i = 0; i < soup.v0.rows(); ++i) {
    for (int k = 0; k < 3; ++k) {
      x0.push_back(soup.v0(i, k));
      x1.push_back(soup.v1(i, k));
    }
  }
  std::vector<Triangle> faces;
  for (Eigen::Index f = 0; f < soup.faces.rows(); ++f) {
    faces.push_back({static_cast<VertexIndex>(soup.faces(f, 0)),
                     static_cast<VertexIndex>(soup.faces(f, 1)),
                     static_cast<VertexIndex>(soup.faces(f, 2))});
  }
  return find_collisions(faces, {x0, x1}, options);
}

void expect_same(const MeshCcdResult& a, const MeshCcdResult& b) {
  EXPECT_EQ(a.vertex_face, b.vertex_face);
  EXPECT_EQ(a.edge_edge, b.edge_edge);
  EXPECT_EQ(a.candidates(), b.candidates());
}

TEST(EigenAdapter, EveryStorageOrderGivesThePlainArrayAnswer) {
  auto rng = testing::seeded_engine("EigenAdapter.storage");
  const Soup soup = random_soup(200, rng);
  const MeshCcdOptions options{Method::exact, std::nullopt, 1};
  const MeshCcdResult expected = plain_arrays(soup, options);
  ASSERT_TRUE(expected.collision()) << "the soup should collide somewhere";

  MeshCcd col_major = eigen::make_mesh_ccd(soup.v0.rows(), soup.faces);
  expect_same(eigen::step(col_major, soup.v0, soup.v1, options), expected);

  const RowMajorPositions r0 = soup.v0, r1 = soup.v1;
  MeshCcd row_major = eigen::make_mesh_ccd(r0.rows(), soup.faces);
  expect_same(eigen::step(row_major, r0, r1, options), expected);

  // An expression (a block of a larger matrix) is copied, not misread.
  Eigen::MatrixXd wide(soup.v0.rows(), 6);
  wide << soup.v0, soup.v1;
  MeshCcd blocks = eigen::make_mesh_ccd(wide.rows(), soup.faces);
  expect_same(eigen::step(blocks, wide.leftCols(3), wide.rightCols(3), options), expected);
}

TEST(EigenAdapter, RowMajorPositionsAreNotCopied) {
  const RowMajorPositions v = RowMajorPositions::Random(5, 3);
  std::vector<double> copy;
  const std::span<const double> view = eigen::positions(v, copy);
  EXPECT_EQ(view.data(), v.data());
  EXPECT_EQ(view.size(), 15u);
  EXPECT_TRUE(copy.empty());

  const Eigen::MatrixXd c = v;
  const std::span<const double> copied = eigen::positions(c, copy);
  ASSERT_EQ(copied.size(), 15u);
  EXPECT_EQ(copied[3 * 2 + 1], c(2, 1));
}

TEST(EigenAdapter, MalformedMatricesAreRefused) {
  Eigen::MatrixXi four_columns(1, 4);
  four_columns << 0, 1, 2, 3;
  EXPECT_THROW(eigen::triangles(four_columns), std::invalid_argument);
  Eigen::MatrixXi negative(1, 3);
  negative << 0, -1, 2;
  EXPECT_THROW(eigen::triangles(negative), std::invalid_argument);
  std::vector<double> copy;
  EXPECT_THROW(eigen::positions(Eigen::MatrixXd(4, 2), copy), std::invalid_argument);
  Eigen::MatrixXi ok(1, 3);
  ok << 0, 1, 2;
  EXPECT_THROW(eigen::make_mesh_ccd(2, ok), std::invalid_argument);  // vertex 2 of 2
}

}  // namespace
}  // namespace exactgeo::ccd
