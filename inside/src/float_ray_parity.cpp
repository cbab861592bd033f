// The float ray-casting baseline: Embree's native quads and triangles in the float frame,
// one ray per point, an intersection filter that counts every hit and rejects it so that
// traversal goes on to the next.

#include "exactgeo/inside/float_ray_parity.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "exactgeo/inside/internal/corner_boxes.hpp"
#include "exactgeo/inside/internal/embree_scene.hpp"
#include "exactgeo/inside/internal/float_frame.hpp"
#include "exactgeo/mesh/check.hpp"
#include "exactgeo/predicates/ray_directions.hpp"

namespace exactgeo::inside {
namespace {

/// The context Embree hands to the filter: its own part first, then the hit count.
struct HitCountingContext {
  RTCIntersectContext embree;
  unsigned hits;
};

/// Counts the hit and rejects it, so that Embree looks for the next one. rtcIntersect1
/// traces one ray: N is 1.
void count_and_reject(const RTCFilterFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  ++reinterpret_cast<HitCountingContext*>(args->context)->hits;
  args->valid[0] = 0;
}

void require_valid_indices(const mesh::Mesh& mesh) {
  if (mesh.vertices.size() > std::numeric_limits<unsigned>::max() ||
      mesh.faces.size() > std::numeric_limits<unsigned>::max()) {
    throw std::invalid_argument("FloatRayParity: too many vertices or faces for Embree");
  }
  for (const mesh::Face& f : mesh.faces)
    for (std::size_t k = 0; k < f.size(); ++k)
      if (f.corners[k] >= mesh.vertices.size()) {
        throw std::invalid_argument("FloatRayParity: a face corner index is out of range");
      }
}

/// The faces with `corners` corners (3 or 4) as one Embree geometry of that type over
/// every vertex, with the counting filter; nothing if there are none.
void attach_faces(const internal::EmbreeScene& embree, const mesh::Mesh& mesh,
                  const std::vector<std::array<float, 3>>& vertices, std::size_t corners) {
  const auto count = static_cast<std::size_t>(
      std::count_if(mesh.faces.begin(), mesh.faces.end(),
                    [&](const mesh::Face& f) { return f.size() == corners; }));
  if (count == 0) return;
  const bool quads = corners == 4;
  const internal::EmbreeFunctions& rtc = embree.rtc();
  const RTCDevice device = embree.device();
  RTCGeometry geometry =
      rtc.rtcNewGeometry(device, quads ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
  if (geometry == nullptr) internal::throw_embree_error(device, "cannot create a geometry");

  auto* vertex_buffer = static_cast<float*>(rtc.rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
  auto* index_buffer = static_cast<unsigned*>(rtc.rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, quads ? RTC_FORMAT_UINT4 : RTC_FORMAT_UINT3,
      corners * sizeof(unsigned), count));
  if (vertex_buffer == nullptr || index_buffer == nullptr) {
    const RTCError error = rtc.rtcGetDeviceError(device);
    rtc.rtcReleaseGeometry(geometry);
    internal::throw_embree_error(error, "cannot allocate a geometry buffer");
  }
  for (const std::array<float, 3>& v : vertices) {
    vertex_buffer = std::copy(v.begin(), v.end(), vertex_buffer);
  }
  // Corners in boundary order: Embree's quad (v0, v1, v2, v3) is the triangles v0 v1 v3
  // and v2 v3 v1.
  for (const mesh::Face& f : mesh.faces) {
    if (f.size() != corners) continue;
    index_buffer = std::copy_n(f.corners.begin(), corners, index_buffer);
  }
  rtc.rtcSetGeometryIntersectFilterFunction(geometry, count_and_reject);
  rtc.rtcCommitGeometry(geometry);
  rtc.rtcAttachGeometry(embree.scene(), geometry);
  rtc.rtcReleaseGeometry(geometry);
}

}  // namespace

struct FloatRayParity::Scene {
  std::optional<mesh::Box> box;  ///< of the faces' corners; none without faces
  internal::FloatFrame frame;
  internal::EmbreeScene embree;
};

FloatRayParity::FloatRayParity(const mesh::Mesh& mesh) : scene_(std::make_unique<Scene>()) {
  require_valid_indices(mesh);
  Scene& s = *scene_;
  s.box = internal::corner_box(mesh);
  if (s.box) s.frame = internal::FloatFrame(s.box->lower, s.box->upper);

  std::vector<std::array<float, 3>> vertices(mesh.vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (int i = 0; i < 3; ++i)
      vertices[v][static_cast<std::size_t>(i)] = s.frame.origin(i, mesh.vertices[v][i]);

  if (s.embree.rtc().rtcGetDeviceProperty(s.embree.device(),
                                          RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) == 0) {
    throw std::runtime_error("Embree: this build has no filter functions");
  }
  attach_faces(s.embree, mesh, vertices, 4);
  attach_faces(s.embree, mesh, vertices, 3);
  s.embree.commit();
}

FloatRayParity::~FloatRayParity() = default;
FloatRayParity::FloatRayParity(FloatRayParity&&) noexcept = default;
FloatRayParity& FloatRayParity::operator=(FloatRayParity&&) noexcept = default;

Location FloatRayParity::classify(const Point3& point) const {
  const Scene& s = *scene_;
  if (!s.box || internal::strictly_outside(*s.box, point)) return Location::outside;

  // Exact in float: the first direction of the sequence is (1, 3/16, 9/256).
  const Vector3 d = ray_direction(0);
  RTCRayHit rayhit{};
  rayhit.ray.org_x = s.frame.origin(0, point[0]);
  rayhit.ray.org_y = s.frame.origin(1, point[1]);
  rayhit.ray.org_z = s.frame.origin(2, point[2]);
  rayhit.ray.dir_x = static_cast<float>(d[0]);
  rayhit.ray.dir_y = static_cast<float>(d[1]);
  rayhit.ray.dir_z = static_cast<float>(d[2]);
  rayhit.ray.tnear = 0.0f;
  rayhit.ray.tfar = std::numeric_limits<float>::infinity();
  rayhit.ray.mask = std::numeric_limits<unsigned>::max();
  rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;

  HitCountingContext context{};
  rtcInitIntersectContext(&context.embree);
  s.embree.rtc().rtcIntersect1(s.embree.scene(), &context.embree, &rayhit);
  return context.hits % 2 == 1 ? Location::inside : Location::outside;
}

}  // namespace exactgeo::inside
