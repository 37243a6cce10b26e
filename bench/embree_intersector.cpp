#include "bench/embree_intersector.h"

#include <chrono>
#include <cstddef>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace meshtrace::bench {

bool EmbreeIntersector::monitor(void* self, ssize_t bytes, bool /*post*/) {
  static_cast<EmbreeIntersector*>(self)->held_ += bytes;
  return true;
}

EmbreeIntersector::EmbreeIntersector(const Scene& scene, RTCBuildQuality quality)
    : scene_ref_(scene) {
  if (!supports(scene)) throw std::invalid_argument("Embree backend: meshes and planes only");
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("rtcNewDevice failed");
  // The build: vertex conversion, geometry set-up and commit (not the
  // device, which the full-run figure includes).
  const auto start = std::chrono::steady_clock::now();
  rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeIntersector::monitor, this);
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, quality);
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(g, quality);
    auto* v =
        static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                    3 * sizeof(float), mesh.vertices().size()));
    for (std::size_t i = 0; i < mesh.vertices().size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(mesh.vertices()[i][k]);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               mesh.triangles().data(), 0, sizeof(TriangleIndices),
                               mesh.triangles().size());
    sharedBytes_ += mesh.triangles().size() * sizeof(TriangleIndices);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene_, g, static_cast<unsigned>(m));
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(scene_);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeIntersector::~EmbreeIntersector() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

RTCRayHit EmbreeIntersector::prepare(const Ray& ray, double tMin, double tMax) {
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(ray.origin.x);
  rh.ray.org_y = static_cast<float>(ray.origin.y);
  rh.ray.org_z = static_cast<float>(ray.origin.z);
  rh.ray.dir_x = static_cast<float>(ray.direction.x);
  rh.ray.dir_y = static_cast<float>(ray.direction.y);
  rh.ray.dir_z = static_cast<float>(ray.direction.z);
  rh.ray.tnear = static_cast<float>(tMin);
  rh.ray.tfar = tMax < std::numeric_limits<float>::max() ? static_cast<float>(tMax)
                                                         : std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// RTCRay is twelve 4-byte fields and RTCRay4 the same twelve, in the same
// order, as arrays of four (rtcore_ray.h): packing is a transposition.
static_assert(sizeof(RTCRay) == 12 * 4 && offsetof(RTCRay, flags) == 11 * 4);
static_assert(sizeof(RTCRay4) == 12 * 16 && offsetof(RTCRay4, flags) == 11 * 16);
RTCRayHit4 EmbreeIntersector::pack(const RTCRayHit* rays) {
  RTCRayHit4 p{};
  auto* to = reinterpret_cast<unsigned char*>(&p.ray);
  for (int r = 0; r < 4; ++r) {
    const auto* from = reinterpret_cast<const unsigned char*>(&rays[r].ray);
    for (int field = 0; field < 12; ++field)
      std::memcpy(to + 16 * field + 4 * r, from + 4 * field, 4);
    p.hit.geomID[r] = RTC_INVALID_GEOMETRY_ID;
    p.hit.instID[0][r] = RTC_INVALID_GEOMETRY_ID;
  }
  return p;
}

bool EmbreeIntersector::closestHit(const Ray& ray, double tMin, Hit& hit, Counters& c) const {
  bool found = false;
  for (std::uint32_t i = 0; i < scene_ref_.planes.size(); ++i) {
    ++c.planeTests;
    if (intersect(scene_ref_.planes[i], ray, tMin, hit.t)) {
      hit.ref = {ObjectKind::Plane, i, 0};
      found = true;
    }
  }
  RTCRayHit rh = prepare(ray, tMin, hit.t);
  if (!intersect1(rh)) return found;
  hit.t = rh.ray.tfar;
  hit.ref = {ObjectKind::Mesh, rh.hit.geomID, rh.hit.primID};
  hit.beta = rh.hit.u;
  hit.gamma = rh.hit.v;
  return true;
}

bool EmbreeIntersector::occluded(const Ray& ray, double tMin, double tMax, Counters& c) const {
  for (const Plane& p : scene_ref_.planes) {
    ++c.planeTests;
    double t = tMax;
    if (intersect(p, ray, tMin, t)) return true;
  }
  RTCRay r = prepare(ray, tMin, tMax).ray;
  return occluded1(r);
}

}  // namespace meshtrace::bench
