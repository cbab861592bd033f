// Embree as a candidate finder: user geometry, one primitive per face, conservative float
// bounds (internal/float_frame.hpp), and callbacks that record faces without ever
// reporting a hit, so traversal visits every box the ray enters.

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "exactgeo/boxes/float_box.hpp"
#include "exactgeo/inside/internal/candidates.hpp"
#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/inside/internal/embree_scene.hpp"
#include "exactgeo/inside/internal/float_frame.hpp"
#include "exactgeo/predicates/ray_directions.hpp"

namespace exactgeo::inside::internal {
namespace {

/// The context Embree hands to the callbacks: its own part first, then the output list.
struct RecordingContext {
  RTCIntersectContext embree;
  std::vector<FaceIndex>* faces;
};

void face_bounds(const RTCBoundsFunctionArguments* args) {
  const auto* boxes = static_cast<const boxes::FloatBox*>(args->geometryUserPtr);
  const boxes::FloatBox& b = boxes[args->primID];
  RTCBounds* out = args->bounds_o;
  out->lower_x = b.lo[0];
  out->lower_y = b.lo[1];
  out->lower_z = b.lo[2];
  out->upper_x = b.hi[0];
  out->upper_y = b.hi[1];
  out->upper_z = b.hi[2];
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
  std::vector<boxes::FloatBox> boxes;
  EmbreeScene embree;
};

EmbreeCandidates::EmbreeCandidates(const mesh::Mesh& mesh, const mesh::Box& box)
    : scene_(std::make_unique<Scene>()) {
  if (mesh.faces.size() > std::numeric_limits<FaceIndex>::max()) {
    throw std::runtime_error("Embree: too many faces");
  }
  const FloatFrame frame(box.lower, box.upper);
  scene_->frame = frame;

  scene_->boxes.resize(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const mesh::Box b = corner_box(mesh, mesh.faces[f]);
    for (int i = 0; i < 3; ++i) {
      scene_->boxes[f].lo[i] = frame.lower_bound(i, b.lower[i]);
      scene_->boxes[f].hi[i] = frame.upper_bound(i, b.upper[i]);
    }
  }

  Scene& s = *scene_;
  const EmbreeFunctions& rtc = s.embree.rtc();
  rtc.rtcSetSceneBuildQuality(s.embree.scene(), RTC_BUILD_QUALITY_HIGH);
  RTCGeometry geometry = rtc.rtcNewGeometry(s.embree.device(), RTC_GEOMETRY_TYPE_USER);
  if (geometry == nullptr) throw_embree_error(s.embree.device(), "cannot create user geometry");
  rtc.rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(s.boxes.size()));
  rtc.rtcSetGeometryUserData(geometry, s.boxes.data());
  rtc.rtcSetGeometryBoundsFunction(geometry, face_bounds, nullptr);
  rtc.rtcSetGeometryIntersectFunction(geometry, record_intersect);
  rtc.rtcSetGeometryOccludedFunction(geometry, record_occluded);
  rtc.rtcCommitGeometry(geometry);
  rtc.rtcAttachGeometry(s.embree.scene(), geometry);
  rtc.rtcReleaseGeometry(geometry);
  s.embree.commit();
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
  scene_->embree.rtc().rtcOccluded1(scene_->embree.scene(), &context.embree, &ray);
  // A primitive may be visited more than once; parity must count it once.
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace exactgeo::inside::internal
