// libigl's Antipodal method (igl::WindingNumberAntipodalScene): the winding number as the
// signed count of one ray's crossings plus a term over the open boundary. libigl's own
// ray intersector needs Embree 4; this one counts signed hits of float rays with Debian's
// Embree 3 in an occlusion filter, as libigl's does. Usage: antipodal MESH.bin POINTS.bin
// OUT.bin (anchor_io.hpp); prints the build and query seconds.
#include <embree3/rtcore.h>

// Before libigl's header, which uses cross products without including it.
#include <Eigen/Geometry>

#include <igl/WindingNumberAntipodalScene.h>

#include <cstdio>

#include "anchor_io.hpp"

namespace {

/// The intersector the scene asks for: signed hit counts along a float ray.
class Embree3SignedHits {
 public:
  using OriginType = Eigen::RowVector3f;
  using DirectionType = Eigen::RowVector3f;

  Embree3SignedHits(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F)
      : device_(rtcNewDevice(nullptr)), scene_(rtcNewScene(device_)) {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), V.rows()));
    for (Eigen::Index i = 0; i < V.rows(); ++i)
      for (int k = 0; k < 3; ++k)
        vertices[3 * i + k] = static_cast<float>(V(i, k));
    auto* triangles = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), F.rows()));
    for (Eigen::Index i = 0; i < F.rows(); ++i)
      for (int k = 0; k < 3; ++k)
        triangles[3 * i + k] = static_cast<unsigned>(F(i, k));
    // Every hit adds the sign of its normal along the ray, and traversal goes on.
    rtcSetGeometryOccludedFilterFunction(geometry, [](const RTCFilterFunctionNArguments* a) {
      const auto& ray = *reinterpret_cast<const RTCRay*>(a->ray);
      const auto& hit = *reinterpret_cast<const RTCHit*>(a->hit);
      const float along = ray.dir_x * hit.Ng_x + ray.dir_y * hit.Ng_y + ray.dir_z * hit.Ng_z;
      reinterpret_cast<Context*>(a->context)->sum += along > 0 ? 1 : -1;
      a->valid[0] = 0;
    });
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
  }
  ~Embree3SignedHits() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  Embree3SignedHits(const Embree3SignedHits&) = delete;
  Embree3SignedHits& operator=(const Embree3SignedHits&) = delete;

  int signedIntersectionsRay(OriginType origin, DirectionType direction, float tnear = 0,
                             float tfar = 1e30f, int mask = -1) const {
    Context context;
    rtcInitIntersectContext(&context.base);
    RTCRay ray{};
    ray.org_x = origin[0], ray.org_y = origin[1], ray.org_z = origin[2];
    ray.dir_x = direction[0], ray.dir_y = direction[1], ray.dir_z = direction[2];
    ray.tnear = tnear, ray.tfar = tfar, ray.mask = static_cast<unsigned>(mask);
    rtcOccluded1(scene_, &context.base, &ray);
    return context.sum;
  }

 private:
  struct Context {
    RTCIntersectContext base;  // first, so that Embree's pointer is this one's
    int sum = 0;
  };
  RTCDevice device_;
  RTCScene scene_;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) return 2;
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  const auto begin = std::chrono::steady_clock::now();  // end to end: reading included
  anchor::read_mesh(argv[1], V, F);
  const Eigen::MatrixXd Q = anchor::read_points(argv[2]);
  const auto start = std::chrono::steady_clock::now();
  const Embree3SignedHits hits(V, F);
  igl::WindingNumberAntipodalScene<double> scene(V, F);
  const double build = anchor::seconds_since(start);
  const auto query_start = std::chrono::steady_clock::now();
  Eigen::VectorXd W;
  scene.winding_number(hits, Q, W);
  const double query = anchor::seconds_since(query_start);
  anchor::write_answers(argv[3], W);
  std::printf("build %.4f s query %.4f s total %.4f s\n", build, query,
              anchor::seconds_since(begin));
}
