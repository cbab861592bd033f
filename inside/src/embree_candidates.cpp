// Embree as a candidate finder: user geometry, one primitive per face, conservative float
// bounds (internal/float_frame.hpp), and callbacks that record faces without ever
// reporting a hit, so traversal visits every box the ray enters.

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/inside/internal/embree_error.hpp"
#include "exactgeo/inside/internal/float_frame.hpp"
#include "exactgeo/predicates/ray_directions.hpp"

namespace exactgeo::inside::internal {
namespace {

struct FloatBox {
  std::array<float, 3> lower;
  std::array<float, 3> upper;
};

/// The context Embree hands to the callbacks: its own part first, then the output list.
struct RecordingContext {
  RTCIntersectContext embree;
  std::vector<FaceIndex>* faces;
};

void face_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* boxes = static_cast<const FloatBox*>(args->geometryUserPtr);
  const FloatBox& b = boxes[args->primID];
  RTCBounds* out = args->bounds_o;
  out->lower_x = b.lower[0];
  out->lower_y = b.lower[1];
  out->lower_z = b.lower[2];
  out->upper_x = b.upper[0];
  out->upper_y = b.upper[1];
  out->upper_z = b.upper[2];
}

void record(int valid, RTCIntersectContext* context, unsigned primitive) {
  if (valid == 0) return;
  reinterpret_cast<RecordingContext*>(context)->faces->push_back(primitive);
}

void record_intersect(const RTCIntersectFunctionNArguments* args) {
  record(args->valid[0], args->context, args->primID);
}

void record_occluded(const RTCOccludedFunctionNArguments* args) {
  record(args->valid[0], args->context, args->primID);
}

}  // namespace

struct EmbreeCandidates::Scene {
  FloatFrame frame;
  std::vector<FloatBox> boxes;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;

  ~Scene() {
    if (scene != nullptr) rtcReleaseScene(scene);
    if (device != nullptr) rtcReleaseDevice(device);
  }
};

EmbreeCandidates::EmbreeCandidates(const mesh::Mesh& mesh) : scene_(std::make_unique<Scene>()) {
  if (mesh.faces.size() > std::numeric_limits<FaceIndex>::max()) {
    throw std::runtime_error("Embree: too many faces");
  }
  Point3 lower{}, upper{};
  lower.fill(std::numeric_limits<double>::infinity());
  upper.fill(-std::numeric_limits<double>::infinity());
  for (const mesh::Face& f : mesh.faces) {
    for (std::size_t k = 0; k < f.size(); ++k) {
      const Point3& p = mesh.vertices[f.corners[k]];
      for (int i = 0; i < 3; ++i) {
        lower[i] = std::min(lower[i], p[i]);
        upper[i] = std::max(upper[i], p[i]);
      }
    }
  }
  if (mesh.faces.empty()) lower = upper = Point3{};
  const FloatFrame frame(lower, upper);
  scene_->frame = frame;

  scene_->boxes.resize(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const mesh::Face& face = mesh.faces[f];
    FloatBox& box = scene_->boxes[f];
    for (int i = 0; i < 3; ++i) {
      double lo = std::numeric_limits<double>::infinity();
      double hi = -lo;
      for (std::size_t k = 0; k < face.size(); ++k) {
        lo = std::min(lo, mesh.vertices[face.corners[k]][i]);
        hi = std::max(hi, mesh.vertices[face.corners[k]][i]);
      }
      box.lower[i] = frame.lower_bound(i, lo);
      box.upper[i] = frame.upper_bound(i, hi);
    }
  }

  Scene& s = *scene_;
  s.device = rtcNewDevice(nullptr);
  if (s.device == nullptr) throw_embree_error(nullptr, "cannot create a device");
  s.scene = rtcNewScene(s.device);
  if (s.scene == nullptr) throw_embree_error(s.device, "cannot create a scene");
  rtcSetSceneFlags(s.scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(s.scene, RTC_BUILD_QUALITY_HIGH);

  RTCGeometry geometry = rtcNewGeometry(s.device, RTC_GEOMETRY_TYPE_USER);
  if (geometry == nullptr) throw_embree_error(s.device, "cannot create user geometry");
  rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(s.boxes.size()));
  rtcSetGeometryUserData(geometry, s.boxes.data());
  rtcSetGeometryBoundsFunction(geometry, face_bounds, nullptr);
  rtcSetGeometryIntersectFunction(geometry, record_intersect);
  rtcSetGeometryOccludedFunction(geometry, record_occluded);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(s.scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(s.scene);
  const RTCError error = rtcGetDeviceError(s.device);
  if (error != RTC_ERROR_NONE) throw_embree_error(error, "cannot build the scene");
}

EmbreeCandidates::~EmbreeCandidates() = default;
EmbreeCandidates::EmbreeCandidates(EmbreeCandidates&&) noexcept = default;
EmbreeCandidates& EmbreeCandidates::operator=(EmbreeCandidates&&) noexcept = default;

void EmbreeCandidates::find(const Point3& origin, std::size_t direction_index,
                            std::vector<FaceIndex>& out) const {
  out.clear();
  const Vector3 d = ray_direction(direction_index);
  RTCRay ray{};
  ray.org_x = scene_->frame.origin(0, origin[0]);
  ray.org_y = scene_->frame.origin(1, origin[1]);
  ray.org_z = scene_->frame.origin(2, origin[2]);
  ray.tnear = 0.0f;
  // Exact: kFloatExactRayDirections says which directions are floats. The frame's
  // scaling by a power of two keeps directions as they are.
  ray.dir_x = static_cast<float>(d[0]);
  ray.dir_y = static_cast<float>(d[1]);
  ray.dir_z = static_cast<float>(d[2]);
  ray.time = 0.0f;
  ray.tfar = std::numeric_limits<float>::infinity();
  ray.mask = std::numeric_limits<unsigned>::max();
  ray.flags = 0;

  RecordingContext context{};
  rtcInitIntersectContext(&context.embree);
  context.faces = &out;
  rtcOccluded1(scene_->scene, &context.embree, &ray);
  // A primitive may be visited more than once; parity must count it once.
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace exactgeo::inside::internal
