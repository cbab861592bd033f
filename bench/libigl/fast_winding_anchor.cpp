// libigl's fast winding number for triangle soups (Barill et al. 2018; order 2, accuracy
// 2): the float approximation most users pick. Usage: fast_winding MESH.bin POINTS.bin
// OUT.bin (anchor_io.hpp); prints the build and query seconds.
#include <igl/fast_winding_number.h>

#include <cstdio>

#include "anchor_io.hpp"

int main(int argc, char** argv) {
  if (argc != 4) return 2;
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  const auto begin = std::chrono::steady_clock::now();  // end to end: reading included
  anchor::read_mesh(argv[1], V, F);
  const Eigen::MatrixXd Q = anchor::read_points(argv[2]);
  const auto start = std::chrono::steady_clock::now();
  igl::FastWindingNumberBVH bvh;
  igl::fast_winding_number(V, F, 2, bvh);
  const double build = anchor::seconds_since(start);
  const auto query_start = std::chrono::steady_clock::now();
  Eigen::VectorXd W;
  igl::fast_winding_number(bvh, 2.0f, Q, W);
  const double query = anchor::seconds_since(query_start);
  anchor::write_answers(argv[3], W);
  std::printf("build %.4f s query %.4f s total %.4f s\n", build, query,
              anchor::seconds_since(begin));
}
