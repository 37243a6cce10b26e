#pragma once
// Embree 3 answering our queries: the meshes go to Embree (float vertices,
// robust mode), infinite planes are tested by our own code as in SceneBvh.
// Spheres and cylinders are not supported (the benchmark scenes are meshes).
#include <embree3/rtcore.h>

#include <atomic>
#include <vector>

#include "meshtrace/accel/intersector.h"

namespace meshtrace::bench {

class EmbreeIntersector : public ExternalIntersector {
 public:
  // Builds with RTC_SCENE_FLAG_ROBUST at the given quality.
  EmbreeIntersector(const Scene& scene, RTCBuildQuality quality);
  ~EmbreeIntersector() override;
  EmbreeIntersector(const EmbreeIntersector&) = delete;
  EmbreeIntersector& operator=(const EmbreeIntersector&) = delete;

  static bool supports(const Scene& scene) {
    return scene.spheres.empty() && scene.cylinders.empty();
  }

  bool closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters) const override;
  bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters) const override;

  // The bare calls, for throughput: the ray is prepared beforehand.
  bool intersect1(RTCRayHit& rayHit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene_, &context, &rayHit);
    return rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }
  // Four rays as one packet (`valid`: -1 for a ray to trace, 0 to skip).
  void intersect4(const int* valid, RTCRayHit4& rayHit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect4(valid, scene_, &context, &rayHit);
  }
  bool occluded1(RTCRay& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;
  }
  static RTCRayHit prepare(const Ray& ray, double tMin, double tMax);
  // Four prepared rays in the packet layout.
  static RTCRayHit4 pack(const RTCRayHit* rays);

  double buildSeconds() const { return buildSeconds_; }
  // Memory Embree holds after the build (its BVH and vertex buffers), plus
  // the index buffers it shares with our meshes.
  std::size_t bytes() const { return builtBytes() + sharedBytes_; }
  // What Embree allocated itself: its BVH, triangle leaves and float vertices.
  std::size_t builtBytes() const { return static_cast<std::size_t>(held_.load()); }

 private:
  static bool monitor(void* self, ssize_t bytes, bool post);

  const Scene& scene_ref_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  double buildSeconds_ = 0.0;
  std::atomic<long long> held_{0};
  std::size_t sharedBytes_ = 0;
};

}  // namespace meshtrace::bench
